#ifndef fgimpact_input_file_h
#define fgimpact_input_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The executable's one reader of its input: a .prm from a file or standard
   * input ("-"), with every `include` line replaced by the included file's
   * text, the included path resolved relative to the directory of the file
   * that contains the line (deal.II itself resolves it against the working
   * directory; a path found only there is still accepted, for files written
   * that way).  Every file is read robustly: what is not a regular readable
   * file (a directory, /dev/zero, a FIFO) or is larger than 16 MiB is
   * refused, as is an include chain that is recursive or deeper than 32
   * files; a UTF-8 byte-order mark and Windows (CRLF) or old Mac (CR) line
   * ends are removed, so line numbers stay those of the file.  A file named
   * *.xml or *.json is read the same way (no include expansion) and given to
   * deal.II's XML or JSON reader.  Parsing it into a ParameterHandler,
   * command-line overrides ("Section/Entry=value") on top, and one-line
   * errors that name the entry and suggest the closest declared name ("did
   * you mean").
   */
  class InputFile
  {
  public:
    /// Read `filename` ("-": standard input) and expand its includes;
    /// throws ExcMessage (one line, naming the file and line) on a missing,
    /// unreadable or non-regular file, an include loop or a chain deeper
    /// than 32 files.
    explicit InputFile(const std::string &filename);

    /// An input given as text (e.g. broadcast from rank 0); no origins.
    InputFile(const std::string &name, const std::string &expanded_text);

    /// The input's name: the file's, or "standard input".
    const std::string &
    input_name() const;

    /// The text as given (the top-level file, byte for byte: includes not
    /// expanded, a byte-order mark or CRLF line ends kept).
    const std::string &
    original() const;

    /// The text with the includes expanded and line ends cleaned (what
    /// deal.II parses).
    const std::string &
    expanded() const;

    /**
     * Parse the expanded text into prm (whose entries are declared), then
     * apply the overrides in order.  Throws ExcMessage with a one-line
     * message naming the file and line or the override, and for an
     * undeclared entry or subsection the closest declared names.
     */
    void
    parse_into(ParameterHandler               &prm,
               const std::vector<std::string> &overrides) const;

  private:
    /// Where each line of the expanded text comes from.
    struct Origin
    {
      std::string  file;
      unsigned int line;
    };

    /// Append text (of file `filename`, "standard input" for stdin) to
    /// the expanded text, expanding its includes; chain holds the files
    /// being read (canonical paths), to find recursion.
    void
    expand(const std::string        &filename,
           const std::string        &text,
           std::vector<std::string> &chain);

    /// The first undeclared subsection or entry of the expanded text, as a
    /// message with a suggestion; empty if every name is declared.
    std::string
    find_undeclared_name(const ParameterHandler &prm) const;

    std::string         name;
    bool                xml_or_json = false; // given to deal.II as is
    std::string         original_text;
    std::string         expanded_text;
    std::vector<Origin> origins;
  };



  /**
   * Set one entry from "Section/Sub/Entry=value" (a top-level entry has no
   * '/').  Throws ExcMessage naming the override: an undeclared path (with
   * the closest declared names) or a value the entry's pattern rejects;
   * `option` is where the user wrote it ("-s", "--study",
   * "Study/Entries").
   */
  void
  apply_override(ParameterHandler  &prm,
                 const std::string &assignment,
                 const std::string &option = "-s");
} // namespace fgimpact

#endif
