#ifndef fgimpact_command_line_h
#define fgimpact_command_line_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>
#include <vector>

namespace fgimpact
{
  /**
   * The executable's command line: options, usage, version and provenance
   * texts, and the MPI start-up environment.  The input file itself (read,
   * includes, overrides, "did you mean") is in input_file.h.
   */
  namespace CommandLine
  {
    /// What the command line asks for.
    enum class Action
    {
      run,              // simulate prm_file
      validate,         // parse and check prm_file, run nothing
      help,             // print the usage, exit 0
      version,          // print the version, exit 0
      print_parameters, // print the documented defaults, exit 0
      error             // print `error` and the usage hint, exit 1
    };

    struct Options
    {
      Action                   action = Action::run;
      std::string              prm_file;  // "-": standard input
      std::vector<std::string> overrides; // "Section/Entry=value", in order
      std::vector<std::string> study;     // "Section/Entry=v1,v2,...", --study
      int                      study_case = -1; // --study-case K
      std::string              error;
      /// --resume DIR: prm_file is DIR/parameters.prm and the first
      /// override sets Output/Directory = DIR.
      std::string resume_directory;
      bool        show_usage = false; // no argument at all: print the usage
    };

    /// The options of argv; no argument at all is an error (usage, exit 1).
    Options
    parse(const int argc, const char *const *argv);

    /// The text of `fgimpact --help`.
    std::string
    usage();

    /**
     * Program version, git commit (at configure time), deal.II and Trilinos
     * versions, one line each (`fgimpact --version`).
     */
    std::string
    version_text();

    /**
     * The provenance block at the top of log.txt and summary.txt: the
     * version lines, the date (UTC), the host, the number of MPI ranks and
     * the exact command line, each line starting with "# ".
     */
    std::string
    provenance(const int          argc,
               const char *const *argv,
               const unsigned int n_mpi_ranks);

    /**
     * `fgimpact --print-parameters`: the documented .prm of prm (deal.II's
     * PRM style, readable by parse_input()) with a comment line before
     * every entry giving its allowed values or range (the entry's
     * Patterns description).  In source/app/parameter_listing.cc.
     */
    void
    print_parameters(const dealii::ParameterHandler &prm, std::ostream &out);

    /**
     * Before MPI_Init: a process not started by an MPI launcher (no
     * OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_RANK in the environment) is an
     * Open MPI singleton, whose default start-up launches a runtime helper
     * (about 0.3 s).  Set OMPI_MCA_ess_singleton_isolated=1,
     * OMPI_MCA_btl=self,vader and OMPI_MCA_pml=ob1 unless already set, so
     * that single-rank runs and --help start at once.  Runs under mpirun
     * are unchanged.
     */
    void
    prepare_mpi_environment();
  } // namespace CommandLine
} // namespace fgimpact

#endif
