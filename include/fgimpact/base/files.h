#ifndef fgimpact_base_files_h
#define fgimpact_base_files_h

#include <istream>
#include <set>
#include <string>

namespace fgimpact
{
  using namespace dealii;



  /**
   * @name Files never half-written
   */
  /** @{ */

  /// Write text to filename through filename.tmp and a rename, checking
  /// every step; throws ExcOutputFailure naming the file.
  void
  write_file_atomically(const std::string &filename, const std::string &text);

  /// The lock file of an output directory (lock_output_directory()).
  inline constexpr const char *lock_file_name = ".fgimpact.lock";

  /// The manifest of a directory this program writes into: the names of
  /// the files its runs wrote there, one per line (record_output_file()).
  inline constexpr const char *manifest_file_name = ".fgimpact.files";

  /**
   * Note, before it is created, that this run writes `path`: its name is
   * appended (once per process) to the manifest of the directory that
   * holds it.  The cleaning of a later run with Output/Overwrite removes
   * the files a manifest lists and no other (a user's file named like
   * ours stays).  Thread-safe; a manifest that cannot be written throws
   * ExcOutputFailure naming it.
   */
  void
  record_output_file(const std::string &path);

  /// The names the manifest of `directory` lists; empty if it has none.
  std::set<std::string>
  read_manifest(const std::string &directory);

  /// Start the manifest of `directory` afresh (a new run, after cleaning).
  void
  reset_manifest(const std::string &directory);

  /// All of in as text, refusing more than 16 MiB (standard input may be
  /// endless: /dev/zero); what names the input in the one-line message.
  std::string
  read_text(std::istream &in, const std::string &what);

  /**
   * The text of a file the input names (a parameter file, a profile),
   * refusing what is missing, a directory (not `kind`), not a regular
   * file (a device, FIFO or socket: they may block or never end) or larger
   * than 16 MiB; what names it in the one-line message.
   */
  std::string
  read_named_file(const std::string &filename,
                  const std::string &what,
                  const std::string &kind);
  /** @} */
} // namespace fgimpact

#endif
