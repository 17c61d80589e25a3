#include <deal.II/base/config.h>

#include <fgimpact/app/command_line.h>
#include <fgimpact/version.h>

#include <cstdlib>
#include <ctime>
#include <string>
#include <unistd.h>

namespace fgimpact
{
  namespace CommandLine
  {
    namespace
    {
      /// --resume DIR: the run's own expanded parameters, with
      /// Output/Directory set to DIR (wherever the run was started from);
      /// false (an error in options) if a parameter file was given too.
      bool
      resume_input(Options &options)
      {
        if (!options.prm_file.empty())
          {
            options.action = Action::error;
            options.error  = "--resume takes the parameters from " +
                            options.resume_directory +
                            "/parameters.prm: give no parameter file";
            return false;
          }
        options.prm_file = options.resume_directory + "/parameters.prm";
        options.overrides.insert(options.overrides.begin(),
                                 "Output/Directory=" +
                                   options.resume_directory);
        return true;
      }

      /// The options followed by a value.
      bool
      takes_argument(const std::string &arg)
      {
        return arg == "-s" || arg == "--set" || arg == "--resume" ||
               arg == "--study" || arg == "--study-case";
      }

      /// What a missing value of the option should have been.
      std::string
      argument_description(const std::string &arg)
      {
        if (arg == "--resume")
          return "an output directory";
        if (arg == "--study" || arg == "--study-case")
          return "an argument";
        return "an argument \"Section/Entry=value\"";
      }

      /// Stores the option's value; false (with the error set) if it is
      /// not valid.
      bool
      take_argument(const std::string &arg,
                    const std::string &value,
                    Options           &options)
      {
        if (arg == "--resume")
          options.resume_directory = value;
        else if (arg == "--study")
          options.study.push_back(value);
        else if (arg == "--study-case")
          {
            char      *end = nullptr;
            const long k   = std::strtol(value.c_str(), &end, 10);
            if (value.empty() || *end != '\0' || k < 0 || k > 99999)
              {
                options.action = Action::error;
                options.error =
                  "--study-case needs a case number, not '" + value + "'";
                return false;
              }
            options.study_case = static_cast<int>(k);
          }
        else
          options.overrides.emplace_back(value);
        return true;
      }
    } // namespace



    namespace
    {
      /// An error in the command line: Action::error with its message;
      /// false (parse() stops).
      bool
      refuse(Options &options, const std::string &error)
      {
        options.action = Action::error;
        options.error  = error;
        return false;
      }

      /// Argument i (and the next one, for an option that takes it) into
      /// options; whether parse() goes on.  --help, --version and
      /// --print-parameters win over the rest.
      bool
      parse_argument(int               &i,
                     const int          argc,
                     const char *const *argv,
                     Options           &options)
      {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help")
          options.action = Action::help;
        else if (arg == "--version")
          options.action = Action::version;
        else if (arg == "-p" || arg == "--print-parameters")
          options.action = Action::print_parameters;
        else if (takes_argument(arg))
          {
            if (i + 1 == argc)
              return refuse(options,
                            "option '" + arg + "' needs " +
                              argument_description(arg));
            if (!take_argument(arg, argv[++i], options))
              return false;
          }
        else if (arg == "--validate")
          {
            if (options.action == Action::run)
              options.action = Action::validate;
          }
        else if (arg.size() > 1 && arg[0] == '-')
          return refuse(options, "unknown option '" + arg + "'");
        else if (options.prm_file.empty())
          options.prm_file = arg;
        else
          return refuse(options,
                        "more than one parameter file given ('" +
                          options.prm_file + "', '" + arg + "')");
        return options.action != Action::help &&
               options.action != Action::version &&
               options.action != Action::print_parameters;
      }
    } // namespace



    Options
    parse(const int argc, const char *const *argv)
    {
      Options options;
      if (argc < 2)
        {
          refuse(options, "no parameter file given");
          options.show_usage = true;
          return options;
        }
      for (int i = 1; i < argc; ++i)
        if (!parse_argument(i, argc, argv, options))
          return options;
      if (!options.resume_directory.empty() && !resume_input(options))
        return options;
      if (options.prm_file.empty())
        refuse(options, "no parameter file given");
      return options;
    }



    std::string
    usage()
    {
      return "Usage: fgimpact [options] parameter_file.prm\n"
             "       fgimpact [options] -      (read the .prm from standard "
             "input)\n"
             "\n"
             "Simulates a sphere striking a functionally graded plate (3D "
             "elasticity,\n"
             "graded 8-node bricks, modified Hertz contact, Newmark + "
             "Newton) and\n"
             "writes history.csv, summary.txt, parameters.prm (expanded), "
             "input.prm\n"
             "(the input as given), log.txt and optional VTU/PVD files into "
             "the\n"
             "output directory named in the parameter file.  A parameter "
             "file\n"
             "needs only the entries that differ from the defaults; an "
             "`include`\n"
             "line is resolved relative to the file that contains it.\n"
             "\n"
             "Options:\n"
             "  -s, --set \"Section/Entry=value\"\n"
             "                          set an entry after reading the file, "
             "as if\n"
             "                          edited there (repeatable; nested "
             "subsections\n"
             "                          joined by '/', e.g. \"Impactor/"
             "Initial velocity=2\")\n"
             "  --study \"Section/Entry=v1,v2,...\"\n"
             "                          a parameter study over these "
             "values (repeatable:\n"
             "                          cartesian product; see the Study "
             "subsection);\n"
             "                          writes Directory/case_NNN/ and "
             "Directory/study.csv\n"
             "  --study-case K          rerun case K of the study alone, "
             "fully (VTU as\n"
             "                          in the input), into "
             "Directory/case_K\n"
             "  --resume DIR            continue the impact run in DIR "
             "from its last\n"
             "                          checkpoint (DIR/parameters.prm; "
             "same MPI ranks)\n"
             "  --validate              read and check the input (mesh "
             "included),\n"
             "                          print its size, run nothing\n"
             "  -p, --print-parameters  print the full documented default "
             ".prm and exit\n"
             "  --version               print the program, git, deal.II and "
             "Trilinos\n"
             "                          versions and exit\n"
             "  -h, --help              print this text and exit\n";
    }



    std::string
    version_text()
    {
      return std::string("fgimpact ") + FGIMPACT_VERSION + "\n" +
             "git commit " + FGIMPACT_GIT_COMMIT + "\n" + "deal.II " +
             DEAL_II_PACKAGE_VERSION + "\n" + "Trilinos " +
             std::to_string(DEAL_II_TRILINOS_VERSION_MAJOR) + "." +
             std::to_string(DEAL_II_TRILINOS_VERSION_MINOR) + "." +
             std::to_string(DEAL_II_TRILINOS_VERSION_SUBMINOR) + "\n";
    }



    namespace
    {
      /// A shell word: quoted when it holds anything but safe characters.
      std::string
      shell_quote(const std::string &word)
      {
        const std::string safe = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOP"
                                 "QRSTUVWXYZ0123456789_-./=:,+@%";
        if (!word.empty() && word.find_first_not_of(safe) == std::string::npos)
          return word;
        std::string quoted = "'";
        for (const char c : word)
          quoted += (c == '\'' ? std::string("'\\''") : std::string(1, c));
        return quoted + "'";
      }
    } // namespace



    std::string
    provenance(const int          argc,
               const char *const *argv,
               const unsigned int n_mpi_ranks)
    {
      std::string text;
      std::string lines = version_text();
      for (std::size_t start = 0, end; start < lines.size(); start = end + 1)
        {
          end = lines.find('\n', start);
          text += "# " + lines.substr(start, end - start) + "\n";
        }
      char              date[64];
      const std::time_t now = std::time(nullptr);
      std::strftime(date,
                    sizeof(date),
                    "%Y-%m-%dT%H:%M:%SZ",
                    std::gmtime(&now));
      char host[256] = "unknown";
      if (gethostname(host, sizeof(host) - 1) != 0)
        host[0] = '\0';
      host[sizeof(host) - 1] = '\0';
      text += std::string("# date ") + date + "\n# host " + host + "\n";
      text += "# MPI ranks " + std::to_string(n_mpi_ranks) + "\n";
      text += "# command";
      for (int i = 0; i < argc; ++i)
        text += " " + shell_quote(argv[i]);
      return text + "\n";
    }



    void
    prepare_mpi_environment()
    {
      for (const char *launcher_variable :
           {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(launcher_variable) != nullptr)
          return;
      // The last argument 0: a value already in the environment wins.
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      setenv("OMPI_MCA_btl", "self,vader", 0);
      setenv("OMPI_MCA_pml", "ob1", 0);
    }
  } // namespace CommandLine
} // namespace fgimpact
