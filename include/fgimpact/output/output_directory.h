#ifndef fgimpact_app_output_directory_h
#define fgimpact_app_output_directory_h

#include <string>

namespace fgimpact
{
  using namespace dealii;

  struct OutputParameters;

  /**
   * @name The output directory: one writer, cleaned by its manifests
   */
  /** @{ */

  /**
   * One writer per output directory: create it if needed and take an
   * exclusive advisory lock (flock) on its lock file, held until this
   * process ends (the kernel releases it on any death) or
   * release_output_directory_locks() removes it, with the process
   * id in the file.  A directory another process holds: ExcMessage naming
   * Output/Directory and the holder's process id.  Call on one rank before
   * anything is written there (a fresh run or a resume).
   */
  void
  lock_output_directory(const std::string &directory);

  /// At the end of a run, however it ended (not at a kill): remove the lock
  /// files this process holds and release them, so that a finished output
  /// directory holds only the run's files.  A run killed leaves its lock
  /// file, which the next run takes over.
  void
  release_output_directory_locks();

  /// Whether name is a directory this program writes runs into, inside an
  /// output directory: a study's case_N, Accuracy = converged's
  /// convergence and its level_N or base_NXxNYxNZ_level_N.
  bool
  is_run_subdirectory(const std::string &name);

  /// Before the set-up: refuse at once (ExcMessage, as
  /// lock_output_directory()) a directory another process holds; writes
  /// nothing.  lock_output_directory() takes the lock later.
  void
  check_output_directory_free(const std::string &directory);

  /**
   * Before the set-up (and with --validate): refuse an output directory
   * that cannot be used, writing nothing: a name longer than 1024
   * characters, a path through a file or a symbolic-link loop, a
   * directory (or the nearest existing ancestor) that is not writable or
   * on a virtual file system (/proc, /sys).  ExcMessage naming
   * Output/Directory.
   */
  void
  check_output_directory_usable(const std::string &directory);

  /**
   * Create the output directory, check that a byte can be written there,
   * and clean it: with Output/Overwrite remove exactly the files this
   * program writes, by their exact names (history.csv, summary.txt,
   * parameters.prm, input.prm, log.txt, frequencies.csv, study.csv, the
   * PVD files, solution_DDDDD.pvtu, solution_DDDDD.R.vtu,
   * sphere_DDDDD.vtu, contact_DDDDD.vtu, peak_fields.pvtu and .R.vtu,
   * leftover *.tmp, and the rank_DDDD.bin files of the checkpoint
   * directories, which go only if nothing else is in them), otherwise
   * refuse a non-empty directory (the lock file aside).  Call on one rank,
   * before the run opens its log.txt there; throws ExcMessage naming
   * Output/Directory or Output/Overwrite.
   */
  void
  prepare_output_directory(const OutputParameters &output);
  /** @} */
} // namespace fgimpact

#endif
