// Checkpoint and resume on one MPI rank, running the executable as a
// process: an uninterrupted run against a run killed with SIGKILL at a
// pseudo-random step (fixed seed) and continued with `fgimpact --resume`;
// history.csv must be identical byte for byte and summary.txt line for
// line (except the provenance comments and the wall-clock timings), and
// the PVD files identical.  Cases: Hertz node (implicit and explicit), a
// resolved sphere whose candidate set grows during the run, and SIGTERM
// (a checkpoint at the stop only), and a plastic plate (Material/
// Plasticity = J2) with the resolved sphere, and a thermal environment.
// Also: resume with a changed
// parameter, on a different number of MPI ranks, or without a checkpoint is
// refused with one line naming the cause, exit code 1, nothing changed;
// so is a resume with End time before the checkpoint, or whose probes.csv
// is shorter than at the checkpoint.

#include "checkpoint_resume.h"

namespace fgimpact_unit_tests::checkpoint_resume
{

  using namespace checkpoint_test;

  namespace
  {
    const std::string small_plate =
      "subsection Geometry\n set Subdivisions x = 20\n set Subdivisions y = "
      "10\n set Subdivisions z = 2\n"
      // The whole plate (as these runs' timing assumes: a SIGTERM must find
      // the run still going).
      " set Symmetry = none\nend\n";

    /// SIGTERM once history.csv exists plus delay_ms; a checkpoint is
    /// written at the stop although the interval is 0.
    bool
    terminate_and_resume(const std::string &prm, const unsigned int delay_ms)
    {
      const std::string name = "sigterm", reference = "ref_" + name,
                        stopped = "stopped_" + name;
      {
        std::ofstream out(name + ".prm");
        out << prm << "subsection Output\n set Directory = " << reference
            << "\n set Checkpoint interval = 0\n set Log interval = 0\n set "
               "Print timing = false\nend\n";
      }
      fs::remove_all(reference);
      fs::remove_all(stopped);
      const int   reference_exit = run({name + ".prm"}, 1, reference + ".log");
      const pid_t pid =
        start({name + ".prm", "-s", "Output/Directory=" + stopped},
              1,
              stopped + ".log");
      for (unsigned int i = 0;
           i < 6000 && !fs::exists(stopped + "/history.csv");
           ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
      kill(pid, SIGTERM);
      const int         stop_exit = wait_for(pid);
      const std::string message   = read_text(stopped + ".log");
      const bool hint = message.find("continue with: fgimpact --resume " +
                                     stopped) != std::string::npos;
      const int  resume_exit =
        run({"--resume", stopped}, 1, stopped + ".resume.log");
      const Comparison c = compare(reference, stopped);
      std::printf("SIGTERM, checkpoint interval 0: exit %d, resume hint on "
                  "stderr %s, resumed (exit %d); %s\n",
                  stop_exit,
                  hint ? "yes" : "NO",
                  resume_exit,
                  c.text().c_str());
      return reference_exit == 0 && stop_exit == 128 + SIGTERM && hint &&
             resume_exit == 0 && c.identical();
    }

    /// Every file of a directory (and of its vtu/ and checkpoint/) but
    /// log.txt, which a refused resume continues, and the lock: name ->
    /// content.
    std::map<std::string, std::string>
    contents(const std::string &directory)
    {
      std::map<std::string, std::string> files;
      for (const auto &entry : fs::recursive_directory_iterator(directory))
        {
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() && name != "log.txt" && name[0] != '.')
            files[entry.path().string()] = read_text(entry.path().string());
        }
      return files;
    }

    /// A refused resume: exit code 1, one line naming `expected`, every file
    /// of the directory but log.txt untouched (summary.txt and
    /// parameters.prm too).
    bool
    refused(const std::string              &what,
            const std::vector<std::string> &args,
            const unsigned int              n_ranks,
            const std::string              &directory,
            const std::string              &expected)
    {
      const auto        before = contents(directory);
      const int         code   = run(args, n_ranks, "refused.log");
      const std::string log    = read_text("refused.log");
      unsigned int      ours   = 0;
      for (const auto &line : lines_of(log))
        ours += (line.rfind("fgimpact: error", 0) == 0);
      const bool named     = log.find(expected) != std::string::npos;
      const auto after     = contents(directory);
      const bool untouched = after == before && !before.empty();
      std::printf("resume %s: exit code %d, one error line %s, names '%s' "
                  "%s, every file but log.txt untouched %s\n",
                  what.c_str(),
                  code,
                  ours == 1 ? "yes" : "NO",
                  expected.c_str(),
                  named ? "yes" : "NO",
                  untouched ? "yes" : "NO");
      if (!(code == 1 && ours == 1 && named && untouched))
        {
          std::printf("  %s\n", log.c_str());
          for (const auto &[name, text] : after)
            if (before.count(name) == 0 || before.at(name) != text)
              std::printf("  changed: %s\n", name.c_str());
        }
      return code == 1 && ours == 1 && named && untouched;
    }

    /**
     * One writer per output directory: a run holds the directory; a second
     * run and a resume of it, a run into a run subdirectory inside it and
     * one into the study directory above it (issue 40: a study in out and a
     * run in out/case_001 both ran) exit 1 at once with one line naming the
     * directory and the holder's process id, and write nothing; once the
     * holder is killed (SIGKILL: the kernel releases the lock), a new run
     * there completes.
     */
    bool
    one_writer(const std::string &prm)
    {
      // A study's case directory: runs into the study's directory and into
      // one inside the case overlap it.
      const std::string directory = "locked/case_001";
      fs::remove_all("locked");
      {
        std::ofstream out("locked.prm");
        out << prm << "subsection Output\n set Directory = " << directory
            << "\n set Log interval = 0\n set Print timing = false\nend\n";
      }
      const pid_t holder = start({"locked.prm"}, 1, "holder.log");
      for (unsigned int i = 0;
           i < 6000 && !fs::exists(directory + "/history.csv");
           ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      const std::string before = read_text(directory + "/history.csv");
      const std::string id     = "process id " + std::to_string(holder);
      bool              ok     = true;
      // A run inside the holder's directory and one into the study's
      // directory above it: they may clean or write each other's files.
      const std::string inside = directory + "/convergence";
      for (const auto &[args, what, named_directory] :
           {std::tuple<std::vector<std::string>, std::string, std::string>{
              {"locked.prm"}, "run", directory},
            {{"--resume", directory}, "resume", directory},
            {{"locked.prm", "-s", "Output/Directory=" + inside},
             "run inside it",
             inside},
            {{"locked.prm", "-s", "Output/Directory=locked"},
             "run into the directory above it",
             "locked"}})
        {
          const int         code = run(args, 1, "second.log");
          const std::string log  = read_text("second.log");
          const bool named = log.find("Output/Directory '" + named_directory +
                                      "'") != std::string::npos &&
                             log.find(id) != std::string::npos;
          const bool one = lines_of(log).size() == 1;
          std::printf("a second %s on a directory in use: exit code %d, one "
                      "line %s, names the directory and the holder's process "
                      "id %s\n",
                      what.c_str(),
                      code,
                      one ? "yes" : "NO",
                      named ? "yes" : "NO");
          ok = ok && code == 1 && one && named;
        }
      ok = ok && !fs::exists(inside);
      kill(holder, SIGKILL);
      const bool killed = wait_for(holder) == -SIGKILL;
      // What the second runs wrote: nothing (history.csv is the holder's,
      // which may have grown, never shrunk or restarted).
      const std::string after = read_text(directory + "/history.csv");
      const bool untouched    = after.compare(0, before.size(), before) == 0;
      const int  third =
        run({"locked.prm", "-s", "Time integration/End time=20e-6"},
            1,
            "third.log");
      // The run that ended removed its lock file (the killed holder's,
      // which it took over): the directory holds the run's files only.
      const bool lock_removed = !fs::exists(directory + "/.fgimpact.lock");
      std::printf("holder killed %s, its history.csv untouched by them %s; a "
                  "new run after the holder's death: exit code %d, its lock "
                  "file removed at its end %s\n",
                  killed ? "yes" : "NO",
                  untouched ? "yes" : "NO",
                  third,
                  lock_removed ? "yes" : "NO");
      return ok && killed && untouched && third == 0 && lock_removed;
    }

    /// A lock file that is a symbolic link to a user's file: refused (exit
    /// code 1, one line naming it), the user's file unchanged.
    bool
    symlinked_lock(const std::string &prm)
    {
      fs::remove_all("linked");
      fs::create_directory("linked");
      std::ofstream("users_file.txt") << "a user's data\n";
      fs::create_symlink(fs::absolute("users_file.txt"),
                         "linked/.fgimpact.lock");
      {
        std::ofstream out("linked.prm");
        out << prm << "subsection Output\n set Directory = linked\nend\n";
      }
      const int         code = run({"linked.prm"}, 1, "linked.log");
      const std::string log  = read_text("linked.log");
      const bool        one  = lines_of(log).size() == 1 &&
                       log.find("symbolic link") != std::string::npos;
      const bool kept = read_text("users_file.txt") == "a user's data\n";
      std::printf("a lock file linked to a user's file: exit code %d, one line "
                  "naming the link %s, the user's file unchanged %s\n",
                  code,
                  one ? "yes" : "NO",
                  kept ? "yes" : "NO");
      return code == 1 && one && kept;
    }

    /// A damaged byte in a checkpoint's header (its step) is refused as
    /// damaged, not read as another step.
    bool
    damaged_header(const std::string &directory)
    {
      const std::string file = directory + "/checkpoint/rank_0000.bin";
      std::string       data = read_text(file);
      if (data.size() < 32)
        return false;
      data[20] = static_cast<char>(data[20] ^ 0x5a);
      fs::remove_all("damaged");
      fs::copy(directory, "damaged", fs::copy_options::recursive);
      std::ofstream("damaged/checkpoint/rank_0000.bin", std::ios::binary)
        << data;
      return refused("with byte 20 of the checkpoint changed",
                     {"--resume", "damaged"},
                     1,
                     "damaged",
                     "is damaged");
    }
  } // namespace



  int
  test_main(int, char **)
  {
    Lcg  random{20261123};
    bool ok = true;

    const std::string hertz =
      small_plate + "subsection Time integration\n set End time = 200e-6\nend\n"
                    "subsection Output\n set Checkpoint interval = 15\nend\n";
    ok = kill_and_resume("hertz_node", hertz, 1, random.kill_point(100)) && ok;

    const std::string explicit_scheme =
      small_plate +
      "subsection Time integration\n set Scheme = explicit\n set Time step = "
      "0\n set End time = 200e-6\nend\n"
      "subsection Output\n set Checkpoint interval = 25\nend\n";
    ok =
      kill_and_resume("explicit", explicit_scheme, 1, random.kill_point(120)) &&
      ok;

    // The candidate set (0.6 mm) grows during the run: the resumed run
    // regrows it and factorizes its K_eff again.  VTU on: the PVD files are
    // cut back to the checkpoint's entries.
    const std::string resolved =
      small_plate +
      "subsection Geometry\n set Contact refinement levels = 1\nend\n"
      "subsection Contact\n set Model = resolved sphere\n set Candidate "
      "radius = 0.0006\nend\n"
      "subsection Time integration\n set End time = 120e-6\nend\n"
      "subsection Output\n set Checkpoint interval = 10\n set VTU interval = "
      "25\n set Fields = displacement\nend\n";
    ok =
      kill_and_resume("resolved_sphere", resolved, 1, random.kill_point(60)) &&
      ok;
    // (deal.II's PVD has a comment with the time of day: not compared.)
    const auto pvd_entries = [](const std::string &file) {
      std::string entries;
      for (const auto &line : lines_of(read_text(file)))
        if (line.find("generated by the deal.II library") == std::string::npos)
          entries += line + '\n';
      return entries;
    };
    bool same_pvd = true;
    for (const std::string pvd : {"solution.pvd", "sphere.pvd", "contact.pvd"})
      same_pvd = same_pvd && fs::exists("ref_resolved_sphere/" + pvd) &&
                 pvd_entries("ref_resolved_sphere/" + pvd) ==
                   pvd_entries("killed_resolved_sphere/" + pvd);
    std::printf("resolved sphere: solution.pvd, sphere.pvd, contact.pvd "
                "identical (but deal.II's date comment) %s\n",
                same_pvd ? "yes" : "NO");
    ok = ok && same_pvd;

    ok = terminate_and_resume(small_plate + "subsection Time integration\n set "
                                            "End time = 800e-6\nend\n",
                              100 + random.next(200)) &&
         ok;

    // A plastic plate: the plastic state at the Gauss points is part of the
    // state (and the first-yield bookkeeping of the summary); the peak
    // fields (peak_fields.pvtu) are the maxima over the whole run, the
    // snapshots before the kill included.
    ok = kill_and_resume("plastic",
                         resolved +
                           "subsection Material\n set Plasticity = J2\nend\n"
                           "subsection Output\n set Fields = displacement, "
                           "peak\nend\n",
                         1,
                         random.kill_point(60)) &&
         ok;

    // A thermal environment (issue 42): the resumed run repeats the
    // thermal step (temperature-dependent constituents, immovable sides,
    // the geometric stiffness in K, the total stress in the validity
    // scan), which must give the same state.
    ok = kill_and_resume("thermal",
                         hertz + thermal_environment(),
                         1,
                         random.kill_point(100)) &&
         ok;

    // Refusals, on the killed Hertz node run's directory.
    ok =
      refused(
        "with Impactor/Initial velocity changed",
        {"--resume", "killed_hertz_node", "-s", "Impactor/Initial velocity=2"},
        1,
        "killed_hertz_node",
        "Impactor/Initial velocity (1 -> 2)") &&
      ok;
    ok = refused("on 2 MPI ranks (written on 1)",
                 {"--resume", "killed_hertz_node"},
                 2,
                 "killed_hertz_node",
                 "written by 1 MPI ranks") &&
         ok;
    fs::remove_all("no_checkpoint");
    fs::create_directory("no_checkpoint");
    fs::copy_file("killed_hertz_node/parameters.prm",
                  "no_checkpoint/parameters.prm");
    ok = refused("without a checkpoint",
                 {"--resume", "no_checkpoint"},
                 1,
                 "no_checkpoint",
                 "no checkpoint") &&
         ok;

    ok = damaged_header("killed_hertz_node") && ok;
    // Refused once the set-up knows the step count: before parameters.prm
    // or summary.txt is written.
    ok = refused("with End time before the checkpoint",
                 {"--resume",
                  "killed_hertz_node",
                  "-s",
                  "Time integration/End time=4e-6"},
                 1,
                 "killed_hertz_node",
                 "after Time integration/End time") &&
         ok;
    // A file that cannot be continued: no file is cut back to its
    // checkpoint length (history.csv was), summary.txt keeps its status.
    fs::remove_all("short_probes");
    fs::copy("killed_hertz_node", "short_probes", fs::copy_options::recursive);
    fs::resize_file("short_probes/probes.csv", 10);
    ok = refused("with probes.csv shorter than at the checkpoint",
                 {"--resume", "short_probes"},
                 1,
                 "short_probes",
                 "probes.csv is shorter than at the checkpoint") &&
         ok;
    ok = symlinked_lock(small_plate) && ok;
    ok = one_writer(small_plate + "subsection Time integration\n set End time "
                                  "= 50000e-6\nend\n") &&
         ok;

    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::checkpoint_resume
