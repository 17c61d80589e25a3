// Parameter studies: the cases, their grouping by shared plate, running
// them, and study.csv.  The Study subsection and the expansion of its
// entries are in study_parameters.cc, the convolution engine in
// impact_study_engine.cc.

#include <deal.II/base/utilities.h>

#include <fgimpact/app/run.h>
#include <fgimpact/app/study.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/output/output_directory.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/run_report.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/study/impact_study_engine.h>
#include <fgimpact/study/simulator.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// A case, parsed and checked.
    struct ParsedCase
    {
      StudyCase   study_case;
      Parameters  parameters;
      std::string prm_text; // parameters.prm
      // The checkpoints' copy (PRM | Short), as main.cc stores it, so that
      // the resume command printed after a signal (--resume case_NNN,
      // which reads parameters.prm) finds the same parameters.
      std::string checkpoint_text;
      std::string group; // the plate's key
    };

    /**
     * The entries that leave the plate, its mesh and the time step alone:
     * the impactor (unless an automatic contact refinement radius makes
     * the mesh depend on it), the Hertz law's constants, Newton's control.
     */
    bool
    is_case_entry(const std::string &path, const Parameters &p)
    {
      static const std::set<std::string> impactor = {
        "Impactor/Radius",
        "Impactor/Density",
        "Impactor/Mass",
        "Impactor/Initial velocity",
        "Impactor/Material",
        "Impactor/Young's modulus",
        "Impactor/Poisson's ratio"};
      static const std::set<std::string> others = {"Contact/Plate modulus",
                                                   "Contact/Swanson beta",
                                                   "Contact/Contact stiffness",
                                                   "Newton/Tolerance",
                                                   "Newton/Max iterations"};
      const bool                         mesh_follows_impactor =
        (p.geometry.contact_refinement_levels > 0 &&
         p.geometry.contact_refinement_radius == 0.) ||
        (p.geometry.contact_refinement_auto && p.uses_resolved_contact());
      return others.count(path) > 0 ||
             (impactor.count(path) > 0 && !mesh_follows_impactor);
    }

    std::string
    case_directory(const std::string &base, const unsigned int i)
    {
      char name[32];
      std::snprintf(name, sizeof(name), "/case_%03u", i);
      return base + name;
    }

    /// Parse every case (input errors: before anything is written).
    std::vector<ParsedCase>
    parse_cases(const StudyParameters          &study,
                const InputFile                &input,
                const std::vector<std::string> &overrides,
                const std::string              &base_directory)
    {
      std::vector<ParsedCase> parsed;
      const auto              cases = expand_study(study);
      for (unsigned int i = 0; i < cases.size(); ++i)
        {
          ParameterHandler prm;
          ParsedCase       c;
          c.study_case = cases[i];
          read_run_parameters(
            input, overrides, prm, c.parameters, [&](ParameterHandler &prm) {
              for (unsigned int e = 0; e < cases[i].paths.size(); ++e)
                apply_override(prm,
                               cases[i].assignment(e),
                               cases[i].origins[e]);
              apply_override(prm,
                             "Output/Directory=" +
                               case_directory(base_directory, i));
              apply_override(prm, "Study/Entries=");
              if (!study.write_vtu)
                apply_override(prm, "Output/VTU interval=0");
            });
          std::ostringstream text;
          prm.print_parameters(text, ParameterHandler::PRM);
          c.prm_text = text.str();
          std::ostringstream short_text;
          prm.print_parameters(short_text,
                               ParameterHandler::OutputStyle(
                                 ParameterHandler::PRM |
                                 ParameterHandler::Short));
          c.checkpoint_text = short_text.str();
          for (unsigned int e = 0; e < cases[i].paths.size(); ++e)
            if (!is_case_entry(cases[i].paths[e], c.parameters))
              c.group += cases[i].assignment(e) + ";";
          parsed.push_back(std::move(c));
        }
      return parsed;
    }

    /// The case's output directory with parameters.prm and input.prm.
    void
    start_case_files(const ParsedCase &c, const InputFile &input)
    {
      run_on_root(MPI_COMM_WORLD, [&]() {
        prepare_output_directory(c.parameters.output);
        write_file_atomically(c.parameters.output.directory + "/parameters.prm",
                              c.prm_text);
        write_file_atomically(c.parameters.output.directory + "/input.prm",
                              input.original());
      });
    }

    /// A case through the normal set-up and time loop.
    void
    run_time_loop(const ParsedCase &c,
                  const InputFile  &input,
                  SummaryEntries   &summary)
    {
      Simulator          simulator(c.parameters, MPI_COMM_WORLD);
      CheckpointSettings checkpoint;
      checkpoint.parameters_text = c.checkpoint_text;
      simulator.set_checkpointing(checkpoint);
      try
        {
          simulator.setup();
          start_case_files(c, input);
          simulator.run();
        }
      catch (const RunInterrupted &)
        {
          summary = simulator.summary().entries();
          throw;
        }
      catch (...)
        {
          // A failed set-up has no summary.txt yet: the simulator's.
          simulator.write_failed_summary();
          summary = simulator.summary().entries();
          throw;
        }
      summary = simulator.summary().entries();
    }

    /// "case_NNN" of a case's output directory.
    std::string
    case_name(const std::string &directory)
    {
      return directory.substr(directory.find_last_of('/') + 1);
    }

    /// One case of a group: by the engine if given, else through the time
    /// loop; a failure is added to failures (name, one-line reason), and
    /// the case's summary to summaries (by its directory).
    void
    run_case(const ParsedCase                                 &c,
             const InputFile                                  &input,
             ImpactStudyEngine                                *engine,
             std::vector<std::pair<std::string, std::string>> &failures,
             std::map<std::string, SummaryEntries>            &summaries)
    {
      ConditionalOStream pcout(
        std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
      const std::string &directory = c.parameters.output.directory;
      // The convolution case's summary.txt (a time-loop case's is its
      // simulator's).
      SummaryFile summary(directory, MPI_COMM_WORLD);
      try
        {
          if (engine)
            {
              start_case_files(c, input);
              engine->run_case(c.parameters, summary);
              summaries[directory] = summary.entries();
            }
          else
            run_time_loop(c, input, summaries[directory]);
        }
      catch (const RunInterrupted &)
        {
          throw; // a signal stops the study
        }
      catch (...)
        {
          // The case failed (its summary.txt says so); the others run.
          failures.push_back(
            {case_name(directory), failure_message(std::current_exception())});
          pcout << "  study case failed: " << failures.back().second << '\n';
          if (engine)
            {
              // As a single run that failed: status = failed.
              SummaryWriter failed;
              failed.add_text("status", "failed");
              summary.write_failed(failed);
              summaries[directory] = summary.entries();
            }
        }
    }

    /// The group's cases: by convolution if the engine applies; a case
    /// that fails is added to failures (name, one-line reason).
    void
    run_group(const StudyParameters                            &study,
              const std::vector<const ParsedCase *>            &cases,
              const InputFile                                  &input,
              const Timer                                      &study_timer,
              std::vector<std::pair<std::string, std::string>> &failures,
              std::map<std::string, SummaryEntries>            &summaries)
    {
      ConditionalOStream pcout(
        std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
      const Parameters &first = cases[0]->parameters;
      std::string       reason;
      if (study.method == StudyParameters::Method::time_loop)
        reason = "Study/Method = time loop";
      std::unique_ptr<Simulator>         plate_owner;
      std::unique_ptr<ImpactStudyEngine> engine;
      if (reason.empty())
        {
          plate_owner = std::make_unique<Simulator>(first, MPI_COMM_WORLD);
          const PlateModel &plate = plate_owner->setup_plate();
          for (const auto *c : cases)
            if (reason.empty())
              reason = ImpactStudyEngine::unsupported(c->parameters, plate);
          if (reason.empty())
            {
              engine = std::make_unique<ImpactStudyEngine>(plate, study_timer);
              if (!engine->prepare(first))
                reason = engine->fallback_reason();
              else
                pcout << "  study: " << cases.size()
                      << " case(s) by convolution of the plate's unit "
                         "response ("
                      << engine->preparation_timing() << ")\n";
            }
        }
      if (!reason.empty())
        {
          engine.reset();
          pcout << "  study: " << cases.size()
                << " case(s) through the time loop: " << reason << '\n';
        }
      for (const auto *c : cases)
        {
          throw_if_stop_signal(MPI_COMM_WORLD,
                               "before study case " +
                                 c->parameters.output.directory +
                                 ": the cases before it are whole; run the "
                                 "study again.");
          pcout << "study case " << c->parameters.output.directory << ":";
          for (unsigned int e = 0; e < c->study_case.paths.size(); ++e)
            pcout << ' ' << c->study_case.assignment(e) << ';';
          pcout << '\n';
          run_case(*c, input, engine.get(), failures, summaries);
        }
    }

    /// study.csv from the cases' summaries in memory (study_csv()).
    void
    write_study_csv(const std::vector<ParsedCase>               &cases,
                    const std::map<std::string, SummaryEntries> &summaries,
                    const std::string                           &filename)
    {
      std::vector<std::vector<std::string>> values;
      std::vector<SummaryEntries>           entries;
      for (const auto &c : cases)
        {
          values.push_back(c.study_case.values);
          const auto found = summaries.find(c.parameters.output.directory);
          entries.push_back(found == summaries.end() ? SummaryEntries() :
                                                       found->second);
        }
      write_file_atomically(
        filename, study_csv(cases[0].study_case.paths, values, entries));
    }

    /// The study's directory checked, locked and cleaned; an unusable one
    /// is bad input (exit code 1, as for a single run), 0 if all went well.
    int
    prepare_study_directory(const OutputParameters &output, const bool root)
    {
      try
        {
          run_on_root(MPI_COMM_WORLD, [&]() {
            check_output_directory_usable(output.directory);
            lock_output_directory(output.directory);
            prepare_output_directory(output);
          });
        }
      catch (const ExcOutputFailure &)
        {
          throw;
        }
      catch (...)
        {
          return report_failure(std::current_exception(), root, 1);
        }
      return 0;
    }

    /// Every case's memory estimate against the memory available, before
    /// the study's directory is touched: a case that cannot fit is bad
    /// input, refused in one line naming it (a 3-case study of a 400 x 200
    /// x 40 plate ran its first case for minutes, issue 40).
    void
    check_cases_fit(const std::vector<ParsedCase> &cases)
    {
      for (unsigned int i = 0; i < cases.size(); ++i)
        try
          {
            check_memory_before_setup(cases[i].parameters, MPI_COMM_WORLD);
          }
        catch (const ExceptionBase &e)
          {
            std::string      assignments;
            const StudyCase &c = cases[i].study_case;
            for (unsigned int k = 0; k < c.paths.size(); ++k)
              assignments += (k == 0 ? "" : ", ") + c.assignment(k);
            AssertThrow(false,
                        ExcMessage("study case " + std::to_string(i) + " (" +
                                   assignments + "): " + message_of(e)));
          }
    }

    /// The cases grouped by their plate (ParsedCase::group), the groups in
    /// the order of their first case.
    std::vector<std::vector<const ParsedCase *>>
    groups_of(const std::vector<ParsedCase> &cases)
    {
      std::vector<std::string>                               order;
      std::map<std::string, std::vector<const ParsedCase *>> groups;
      for (const auto &c : cases)
        {
          if (groups.count(c.group) == 0)
            order.push_back(c.group);
          groups[c.group].push_back(&c);
        }
      std::vector<std::vector<const ParsedCase *>> ordered;
      for (const auto &key : order)
        ordered.push_back(groups[key]);
      return ordered;
    }

    /// study.csv, report.html (the cases, each linked to its own report)
    /// and the study's last line.
    void
    finish_study(const std::vector<ParsedCase>               &cases,
                 const std::map<std::string, SummaryEntries> &summaries,
                 const OutputParameters                      &output,
                 const double                                 wall_time)
    {
      run_on_root(MPI_COMM_WORLD, [&]() {
        write_study_csv(cases, summaries, output.directory + "/study.csv");
      });
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      if (output.report)
        if (const std::string note = write_run_report(output.directory);
            !note.empty())
          std::cout << "  note: " << note << '\n';
      std::cout << "fgimpact: study of " << cases.size() << " cases in "
                << wall_time << " s; results in " << output.directory
                << " (study.csv; figures: scripts/plot_study.py "
                << output.directory << "/study.csv)\n";
    }


    /// The study's cases, each checked to fit the memory, and the base
    /// case's parameters into `base` (bad input throws).  --study-case
    /// (`only_case` >= 0) writes the case's VTU.
    std::vector<ParsedCase>
    read_cases(const StudyParameters          &study,
               const InputFile                &input,
               const std::vector<std::string> &overrides,
               const int                       only_case,
               Parameters                     &base)
    {
      ParameterHandler prm;
      read_run_parameters(input, overrides, prm, base);
      StudyParameters rerun = study;
      rerun.write_vtu       = rerun.write_vtu || only_case >= 0;
      std::vector<ParsedCase> cases =
        parse_cases(rerun, input, overrides, base.output.directory);
      AssertThrow(only_case < static_cast<int>(cases.size()),
                  ExcMessage("--study-case " + std::to_string(only_case) +
                             ": the study has " + std::to_string(cases.size()) +
                             " cases"));
      check_cases_fit(cases);
      return cases;
    }


    /// --study-case: case `c` alone by the time loop, into its directory.
    int
    run_one_case(const ParsedCase &c, const InputFile &input, const bool root)
    {
      SummaryEntries summary;
      run_time_loop(c, input, summary);
      if (root)
        std::cout << "fgimpact: results in " << c.parameters.output.directory
                  << '\n';
      return 0;
    }
  } // namespace



  int
  run_study(const StudyParameters          &study,
            const InputFile                &input,
            const std::vector<std::string> &overrides,
            const int                       only_case,
            const std::string              &provenance,
            Logger                         &logger)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    Timer      study_timer;
    std::vector<ParsedCase> cases;
    Parameters              base;
    try
      {
        cases = read_cases(study, input, overrides, only_case, base);
      }
    catch (...)
      {
        return report_failure(std::current_exception(),
                              root,
                              1,
                              "error in " + input.input_name());
      }

    try
      {
        if (only_case >= 0)
          return run_one_case(cases[only_case], input, root);
        if (const int code = prepare_study_directory(base.output, root))
          return code;
        run_on_root(MPI_COMM_WORLD, [&]() {
          logger.open(base.output.directory + "/log.txt", provenance);
          SummaryWriter::set_preamble(provenance);
        });
        if (root)
          std::cout << "fgimpact: study of " << cases.size() << " cases\n";
        std::vector<std::pair<std::string, std::string>> failures;
        std::map<std::string, SummaryEntries>            summaries;
        for (const auto &group : groups_of(cases))
          run_group(study, group, input, study_timer, failures, summaries);
        finish_study(cases, summaries, base.output, study_timer.wall_time());
        // Every case ran; the failed ones make the study a failed run.
        AssertThrow(failures.empty(),
                    ExcNumericalFailure(
                      std::to_string(failures.size()) + " of " +
                      std::to_string(cases.size()) +
                      " study cases failed (study.csv gives every case's "
                      "status); " +
                      failures[0].first + ": " + failures[0].second));
      }
    catch (...)
      {
        return report_failure(std::current_exception(), root, 2);
      }
    return 0;
  }
} // namespace fgimpact
