// Subsection "Output": the output directory, the files' intervals and
// formats, checkpoints, VTU fields and probe points (OutputParameters,
// declared in monitor.h).

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/output/monitor.h>

#include <algorithm>

namespace fgimpact
{
  namespace
  {
    /// The names of Output/VTU compression: zlib's levels.
    const SelectionTable<DataOutBase::VtkFlags::ZlibCompressionLevel> &
    compression_names()
    {
      using F = DataOutBase::VtkFlags;
      static const SelectionTable<DataOutBase::VtkFlags::ZlibCompressionLevel>
        names = {{"none", F::no_compression},
                 {"speed", F::best_speed},
                 {"default", F::default_compression},
                 {"best", F::best_compression}};
      return names;
    }
  } // namespace



  namespace
  {
    /// Output/Snapshot times: a list of times, not a member as it stands.
    void
    declare_snapshot_times(ParameterHandler &prm)
    {
      std::string times;
      for (const double t : OutputParameters().snapshot_times)
        times += (times.empty() ? "" : ", ") + prm_string(t);
      prm.declare_entry(
        "Snapshot times",
        times,
        Patterns::List(Patterns::Double(0.), 0, 10000, ","),
        "Impact runs: extra VTU snapshots at these times (s, as End time; "
        "comma-separated, e.g. 50e-6, 1.2e-4), also with VTU interval = 0: "
        "the plate, ball and "
        "contact between the two time steps that hold the time, "
        "interpolated (u, v and the ball by cubic Hermite interpolation, a "
        "linearly, the forces by the parabola through three steps), as "
        "vtu/solution_tNNNNNNNNN.pvtu (the time in ns); solution.pvd lists "
        "them in time order with the regular ones.");
    }
  } // namespace



  namespace
  {
    /// The directory, its files and their intervals.
    void
    add_file_rows(ParameterTable<OutputParameters> &t)
    {
      using P = OutputParameters;

      t.add("Directory",
            &P::directory,
            Patterns::DirectoryName(),
            "Directory for history.csv, summary.txt, "
            "parameters.prm and the VTU/PVD files; created if "
            "missing.");
      t.add("VTU interval",
            &P::vtu_interval,
            Patterns::Integer(0, 100000000),
            "Write VTU every this many time steps (and the "
            "initial state); 0 = no VTU output.");
      t.add("Snapshot at peak force",
            &P::peak_snapshot,
            Patterns::Bool(),
            "Impact runs with VTU output (VTU interval > 0 or Snapshot times): "
            "also a snapshot at the time of the peak contact force "
            "(vtu/solution_peak.pvtu, sphere_peak, contact_peak), interpolated "
            "as Snapshot times to time_of_peak_force_us of summary.txt (the "
            "vertex of the parabola through the largest sample and its two "
            "neighbours).");
      t.add("VTU compression",
            &P::vtu_compression,
            compression_names(),
            "How the VTU data are stored: zlib-compressed at the level speed "
            "(the default: zlib's fastest, about 2.5 times smaller than none), "
            "default (zlib's compromise) or best (smallest files, several "
            "times slower to write), or none (raw binary, the fastest to write "
            "and read).  The values in the files are the same at every level.");
      t.add(
        "Overwrite",
        &P::overwrite,
        Patterns::Bool(),
        "true: before writing, remove exactly the files this "
        "program writes from Directory (history.csv, probes.csv, "
        "summary.txt, parameters.prm, input.prm, log.txt, "
        "frequencies.csv, the PVD files, peak_fields.pvtu, the VTU pieces "
        "in vtu/, contact_pressure.csv, checkpoint/), so that no file of an "
        "earlier run is mixed "
        "with the new ones. false: refuse a Directory that "
        "is not empty.");
      t.add("Checkpoint interval",
            &P::checkpoint_interval,
            Patterns::Integer(0, 100000000),
            "Write a checkpoint (Directory/checkpoint/, the complete state, "
            "replacing the last one only when complete) every this many time "
            "steps, and when SIGINT or SIGTERM stops the run; 0 = only then. "
            "`fgimpact --resume Directory` continues the run bit for bit.");
    }

    /// What the run says on the screen and at its end.
    void
    add_screen_rows(ParameterTable<OutputParameters> &t)
    {
      using P = OutputParameters;
      t.add("Log interval",
            &P::log_interval,
            Patterns::Integer(0, 100000000),
            "Print a progress line every this many steps; 0 = "
            "none.");
      t.add("Print timing",
            &P::print_timing,
            Patterns::Bool(),
            "Print the wall-clock timing table at the end and a "
            "progress line (elapsed time, estimate of the time "
            "left) at every tenth of the time steps, and the "
            "modal iteration's estimated and measured cost (turn "
            "off for reproducible logs).");
      t.add("Instrumentation",
            &P::instrumentation,
            Patterns::Bool(),
            "Measure the reference costs of one matrix-vector "
            "product and one solve with the time step's matrix "
            "(spmv_ms, solve_ms in summary.txt, for the "
            "benchmarks in bench/); costs 20 products and 3 "
            "solves at set-up.");
      t.add(
        "Report",
        &P::report,
        Patterns::Bool(),
        "At the end of the run: report.html, one self-contained page (the "
        "scene, the headline numbers with their error estimates, the "
        "validity verdicts, the time histories as plots, the pictures of "
        "scripts/render.sh if made, a converged run's convergence table, a "
        "study's cases), written by scripts/report.py with the python3 on "
        "PATH (standard library only; about 0.1 s); a note in the log if it "
        "cannot be. scripts/report.py DIR writes it again, e.g. after "
        "scripts/render.sh.");
    }

    /// The entries of OutputParameters that set a member as they stand.
    const ParameterTable<OutputParameters> &
    output_table()
    {
      using P                              = OutputParameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        add_file_rows(t);
        add_screen_rows(t);
        return t;
      }();
      return table;
    }
  } // namespace



  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      output_table().declare(prm);
      declare_snapshot_times(prm);
      VtuFields::declare_parameters(prm);
      ProbePoints::declare_parameters(prm);
    }
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    output_table().parse(prm, *this);
    snapshot_times.clear();
    for (const std::string &time :
         Utilities::split_string_list(prm.get("Snapshot times")))
      snapshot_times.push_back(Utilities::string_to_double(time));
    std::sort(snapshot_times.begin(), snapshot_times.end());

    vtu_fields.parse_parameters(prm);
    probe_points.parse_parameters(prm);
    prm.leave_subsection();
  }
} // namespace fgimpact
