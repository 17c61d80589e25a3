#!/usr/bin/python3
"""Overlay the time histories of several fgimpact runs, like Figs. 3-8 of
Asemi & Salami (2015), with their energies, force-indentation curves and
probes.

Usage:
  plot_histories.py --out DIR [--title T] [--departure] [--data]
                    [--format png|pdf|svg] [--time-window T0 T1]
                    [--label L1] run_dir1 [--label L2] run_dir2 ...
  plot_histories.py --help

Each run_dir must contain the history.csv written by fgimpact (and, for
--departure, summary.txt and parameters.prm). A "--label L" applies to the
run directory that follows it; without it the label is the directory's
basename. --format picks the file type (default png); --time-window T0 T1
(in us, T0 < T1) restricts every time axis and the force-approach
curves to T0 <= t <= T1. --data writes beside each figure NAME.EXT the
curves it draws, NAME.data.csv (columns figure,axes,curve,x,y: one row
per plotted point, in the figure's units; axes numbers the panels and a
second y axis), for re-plotting elsewhere. Exit code 0, or 2 with one error line for a bad
command line or a missing/malformed file.

Writes into DIR (created if missing), EXT = the --format:
  contact_force.EXT        contact force F (N) vs t (us)          Figs. 3a, 6a, 8a
  impactor_velocity.EXT    projectile velocity (m/s) vs t (us)    Fig. 3b
  midplane_deflection.EXT  w at (a/2, b/2, h/2) (um) vs t (us)    Figs. 4a, 6b, 8b
  top_deflection.EXT       w at (a/2, b/2, h) (um) vs t (us)      Fig. 4b
  sigma_yy.EXT             sigma_yy at the mid-plane centre (MPa)  Fig. 5a
  sigma_zz.EXT             sigma_zz at the mid-plane centre (MPa)  Fig. 5b
  energy.EXT               impactor, plate kinetic, strain, contact energy
                           and the plastic work (when history.csv has
                           energy_plastic_J) vs t (us): for one run stacked
                           areas whose top is the total, with the balance
                           error (total - initial) on a second axis; for
                           several runs lines
  force_approach.EXT       contact force F (N) vs the measured approach
                           (um): the ball's displacement minus the
                           mid-plane's deflection under it (history.csv's
                           approach_um, every contact model), in contact
                           (F > 0), loading and unloading
and if a run_dir holds vtu/contact_peak.vtu (Contact/Model = resolved
sphere with VTU output: the contact nodes at the peak force's snapshot):
  contact_pressure_profile.EXT
                           the nodes' contact pressure p (MPa) against
                           their distance r (mm) from the impact point,
                           and for an elastic plate Hertz's
                           p0 (1 - r^2/a^2)^(1/2), a = (3 F R / (4 E*))^(1/3),
                           p0 = 3 F / (2 pi a^2), with summary.txt's peak
                           force F and contact_modulus_Q_Pa E* and the
                           Impactor/Radius R
and if a run_dir holds probes.csv (Output/Probe points):
  probes.EXT               per probe point u_z (um) and sigma_xx, sigma_zz
                           (MPa) vs t, and the support reaction (N) vs t
and with --departure:
  departure_velocity.EXT   departure velocity vs V0 (and their ratio), Fig. 7
The paths written are printed, one per line.

Needs only the csv module and matplotlib (Agg backend, imported only to
plot: --help and the argument checks work without it); run it with
/usr/bin/python3, whose matplotlib is installed.
"""

import csv
import math
import os
import sys

plt = None  # matplotlib.pyplot, imported by load_matplotlib()


def load_matplotlib():
    global plt
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as pyplot
    except ImportError:
        fail("matplotlib is not installed for "
                 "%s; run /usr/bin/python3 scripts/plot_histories.py"
                 % sys.executable)
    plt = pyplot


# (file name, history.csv column, y-axis label, title)
FIGURES = [
    ("contact_force", "contact_force_N", "Contact force $F$ (N)",
     "Contact force"),
    ("impactor_velocity", "impactor_velocity_m_s",
     "Projectile velocity (m/s)\n(positive towards the plate)",
     "Projectile velocity"),
    ("midplane_deflection", "midplane_deflection_um",
     r"Mid-plane deflection $w(a/2,\,b/2,\,h/2)$ ($\mu$m)",
     "Mid-plane deflection at the plate centre"),
    ("top_deflection", "top_deflection_um",
     r"Top deflection $w(a/2,\,b/2,\,h)$ ($\mu$m)",
     "Top-surface deflection at the plate centre"),
    ("sigma_yy", "sigma_yy_mid_MPa",
     r"In-plane stress $\sigma_{yy}$ (MPa)",
     r"In-plane stress $\sigma_{yy}$ at $(a/2,\,b/2,\,h/2)$"),
    ("sigma_zz", "sigma_zz_mid_MPa",
     r"Peel stress $\sigma_{zz}$ (MPa)",
     r"Peel stress $\sigma_{zz}$ at $(a/2,\,b/2,\,h/2)$"),
]

TIME_LABEL = r"Time $t$ ($\mu$s)"


def fail(message):
    """A missing or malformed input: one line, exit 2."""
    sys.stderr.write("plot_histories.py: error: %s\n" % message)
    sys.exit(2)


def usage(message=None):
    """--help: the whole text, exit 0; an error: one line, exit 2."""
    if message is None:
        sys.stdout.write(__doc__.strip() + "\n")
        sys.exit(0)
    sys.stderr.write("plot_histories.py: error: %s (see --help)\n" % message)
    sys.exit(2)


def parse_arguments(argv):
    out = None
    title = None
    departure = False
    options = {"format": "png", "window": None, "data": False}
    runs = []  # (label, directory)
    pending_label = None
    i = 0
    while i < len(argv):
        arg = argv[i]
        if arg in ("-h", "--help"):
            usage()
        elif arg in ("--out", "--label", "--title"):
            if i + 1 >= len(argv):
                usage("%s needs a value" % arg)
            value = argv[i + 1]
            i += 2
            if arg == "--out":
                out = value
            elif arg == "--title":
                title = value
            else:
                if pending_label is not None:
                    usage("two --label options without a run directory "
                          "between them ('%s', '%s')" % (pending_label, value))
                pending_label = value
            continue
        elif arg.startswith("--out="):
            out = arg.split("=", 1)[1]
        elif arg.startswith("--label="):
            pending_label = arg.split("=", 1)[1]
        elif arg.startswith("--title="):
            title = arg.split("=", 1)[1]
        elif arg == "--departure":
            departure = True
        elif arg == "--data":
            options["data"] = True
        elif arg == "--format" or arg.startswith("--format="):
            if arg == "--format":
                if i + 1 >= len(argv):
                    usage("--format needs a value (png, pdf or svg)")
                i += 1
                value = argv[i]
            else:
                value = arg.split("=", 1)[1]
            if value not in ("png", "pdf", "svg"):
                usage("--format '%s': use png, pdf or svg" % value)
            options["format"] = value
        elif arg == "--time-window":
            if i + 2 >= len(argv):
                usage("--time-window needs two times T0 T1 (us)")
            t0, t1 = to_float(argv[i + 1]), to_float(argv[i + 2])
            if not (t0 < t1):  # also NaN
                usage("--time-window '%s' '%s': need numbers T0 < T1 (us)"
                      % (argv[i + 1], argv[i + 2]))
            options["window"] = (t0, t1)
            i += 3
            continue
        elif arg.startswith("--"):
            usage("unknown option '%s'" % arg)
        else:
            label = pending_label
            if label is None:
                label = study_case_label(arg)
            runs.append((label, arg))
            pending_label = None
        i += 1
    if out is None:
        usage("--out DIR is required")
    if not runs:
        usage("no run directories given")
    if pending_label is not None:
        usage("--label '%s' is not followed by a run directory" % pending_label)
    return out, title, departure, runs, options


def read_history(run_dir, name="history.csv"):
    """Columns of run_dir/name (a CSV written by fgimpact) as a dict
    name -> list of floats."""
    path = os.path.join(run_dir, name)
    if not os.path.isfile(path):
        fail("%s not found" % path)
    with open(path, newline="") as f:
        reader = csv.reader(f, skipinitialspace=True)
        header = [h.strip() for h in next(reader)]
        columns = {h: [] for h in header}
        for row in reader:
            if not row:
                continue
            if len(row) != len(header):
                fail("%s: a row has %d fields, "
                         "the header %d" % (path, len(row), len(header)))
            for h, value in zip(header, row):
                columns[h].append(float(value))
    if not columns.get("t_us"):
        fail("%s has no data rows" % path)
    return columns


def read_summary(run_dir):
    """summary.txt as a dict name -> string value."""
    path = os.path.join(run_dir, "summary.txt")
    result = {}
    if not os.path.isfile(path):
        return result
    with open(path) as f:
        for line in f:
            if "=" in line:
                key, value = line.split("=", 1)
                result[key.strip()] = value.strip()
    return result


def read_parameter(run_dir, section, name):
    """Value of 'set name = value' inside 'subsection section' of the
    parameters.prm that fgimpact writes into its output directory."""
    path = os.path.join(run_dir, "parameters.prm")
    if not os.path.isfile(path):
        return None
    stack = []
    with open(path) as f:
        for line in f:
            text = line.split("#", 1)[0].strip()
            if not text:
                continue
            words = text.split(None, 1)
            if words[0] == "subsection":
                stack.append(words[1].strip())
            elif words[0] == "end":
                if stack:
                    stack.pop()
            elif words[0] == "set" and stack and stack[-1] == section:
                key, _, value = words[1].partition("=")
                if key.strip() == name:
                    return value.strip()
    return None


def to_float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def study_case_label(run_dir):
    """The varied values of a study case (its row of the study.csv beside
    it, the entries without their subsection), else the directory's name."""
    name = os.path.basename(os.path.normpath(run_dir))
    study = os.path.join(os.path.dirname(os.path.normpath(run_dir)),
                         "study.csv")
    if not os.path.isfile(study):
        return name
    import csv
    with open(study, newline="") as f:
        for row in csv.DictReader(f):
            case = row.get("case", "")
            if case.isdigit() and "case_%03d" % int(case) == name:
                varied = [k for k in row if "/" in k]
                if varied:
                    # The units of plot_study.py, beside this script.
                    sys.path.insert(0, os.path.dirname(os.path.abspath(
                        __file__)))
                    from plot_study import UNITS
                    return ", ".join(
                        ("%s = %s %s" % (k.split("/")[-1], row[k],
                                         UNITS.get(k.split("/")[-1], ""))
                         ).strip() for k in varied)
    return name


def style_axes(ax, title, xlabel, ylabel):
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.axhline(0.0, color="0.6", linewidth=0.6, zorder=0)


def in_window(t, window):
    return window is None or window[0] <= t <= window[1]


def set_time_axis(ax, histories, window):
    if window is not None:
        ax.set_xlim(*window)
    else:
        ax.set_xlim(0.0, max(h["t_us"][-1] for h in histories))


def save(fig, out, name, options):
    """Writes the figure (and with --data its curves' points)."""
    fig.tight_layout()
    path = os.path.join(out, "%s.%s" % (name, options["format"]))
    fig.savefig(path, dpi=130)
    written = [path]
    if options["data"]:
        data = os.path.join(out, "%s.data.csv" % name)
        with open(data, "w", newline="") as f:
            writer = csv.writer(f, lineterminator="\n")
            writer.writerow(["figure", "axes", "curve", "x", "y"])
            for k, ax in enumerate(fig.axes):
                for line in ax.get_lines():
                    curve = line.get_label()
                    if curve.startswith("_"):  # guides, not data
                        continue
                    for x, y in zip(line.get_xdata(), line.get_ydata()):
                        writer.writerow([name, k, curve, repr(float(x)),
                                         repr(float(y))])
        written.append(data)
    plt.close(fig)
    return written


def column(history, name, run_dir, file_name="history.csv"):
    if name not in history:
        fail("%s/%s has no column '%s'" % (run_dir, file_name, name))
    return history[name]


def plot_time_histories(out, title, runs, histories, options):
    written = []
    for file_name, name, ylabel, fig_title in FIGURES:
        fig, ax = plt.subplots(figsize=(7.5, 4.8))
        for (label, run_dir), history in zip(runs, histories):
            ax.plot(history["t_us"], column(history, name, run_dir),
                    label=label, linewidth=1.4)
        style_axes(ax, fig_title if not title else "%s\n%s" % (title, fig_title),
                   TIME_LABEL, ylabel)
        set_time_axis(ax, histories, options["window"])
        ax.legend(loc="best", fontsize="small", framealpha=0.85)
        written += save(fig, out, file_name, options)
    return written


ENERGIES = [("energy_impactor_J", "impactor"),
            ("energy_plate_kinetic_J", "plate kinetic"),
            ("energy_strain_J", "strain"),
            ("energy_contact_J", "contact"),
            ("energy_total_J", "total"),
            # Drawn only when history.csv has it (a plastic plate, issue
            # 23): the work dissipated by plasticity.
            ("energy_plastic_J", "plastic work")]
OPTIONAL_ENERGIES = {"energy_plastic_J"}
LINESTYLES = ["-", "--", ":", "-."]


def plot_energy_stacked(out, title, run, history, options):
    """One run: the energies as stacked areas, as Abaqus draws ALLKE, ALLSE,
    ALLPD and ETOTAL (the ball's and the plate's kinetic energy, the strain
    energy, the contact's and the plastic work, bottom to top; their top
    is energy_total_J), and on a second axis the balance error, the total
    minus its first value (J). Each area's upper edge is drawn as a curve
    named "stack: ..." (what --data writes)."""
    label, run_dir = run
    t = history["t_us"]
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    below = [0.0] * len(t)
    for c, (name, what) in enumerate(ENERGIES):
        if name == "energy_total_J" or (name in OPTIONAL_ENERGIES
                                        and name not in history):
            continue
        above = [b + e for b, e in zip(below, column(history, name, run_dir))]
        ax.fill_between(t, below, above, color="C%d" % c, alpha=0.55,
                        linewidth=0, label=what)
        ax.plot(t, above, color="C%d" % c, linewidth=0.6,
                label="stack: " + what)
        below = above
    total = column(history, "energy_total_J", run_dir)
    ax.plot(t, total, color="k", linestyle="--", linewidth=1.0,
            label="total (energy_total_J)")
    style_axes(ax, "Energies, stacked: %s" % label if not title
               else "%s\nEnergies, stacked: %s" % (title, label),
               TIME_LABEL, "Energy (J)")
    set_time_axis(ax, [history], options["window"])
    handles, labels = ax.get_legend_handles_labels()
    keep = [(h, l) for h, l in zip(handles, labels)
            if not l.startswith("stack: ")]
    error_ax = ax.twinx()
    error_ax.plot(t, [e - total[0] for e in total], color="C7",
                  linewidth=0.9, label="balance error")
    error_ax.set_ylabel("Balance error: total - initial (J)", color="C7")
    error_ax.tick_params(axis="y", labelcolor="C7")
    h2, l2 = error_ax.get_legend_handles_labels()
    # Below the axes: the areas fill the plot.
    ax.legend([h for h, _ in keep] + h2, [l for _, l in keep] + l2,
              loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=4,
              fontsize="x-small", frameon=False)
    return save(fig, out, "energy", options)


def plot_energy(out, title, runs, histories, options):
    """One run: stacked areas (plot_energy_stacked). Several: lines;
    colours the energy, line styles the run."""
    if len(runs) == 1:
        return plot_energy_stacked(out, title, runs[0], histories[0], options)
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for k, ((label, run_dir), history) in enumerate(zip(runs, histories)):
        for c, (name, what) in enumerate(ENERGIES):
            if name in OPTIONAL_ENERGIES and name not in history:
                continue
            ax.plot(history["t_us"], column(history, name, run_dir),
                    color="C%d" % c, linestyle=LINESTYLES[k % 4],
                    linewidth=1.6 if what == "total" else 1.2,
                    label="%s, %s" % (what, label) if len(runs) > 1 else what)
    style_axes(ax, "Energies" if not title else "%s\nEnergies" % title,
               TIME_LABEL, "Energy (J)")
    set_time_axis(ax, histories, options["window"])
    ax.legend(loc="best", fontsize="x-small", framealpha=0.85)
    return save(fig, out, "energy", options)


def plot_force_approach(out, title, runs, histories, options):
    """The measured approach, the same for every contact model: the ball's
    displacement minus the mid-plane's deflection under the ball
    (approach_um), not indentation_um (for resolved sphere the Hertz
    estimate (F/K)^(2/3), a function of F alone, and for hertz node the
    approach to one node under a point force, which grows without bound
    as the mesh is refined). In contact (F > 0): the loading branch, and
    the unloading one, which ends at the crater in a plastic run."""
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for (label, run_dir), history in zip(runs, histories):
        approach = column(history, "approach_um", run_dir)
        force = column(history, "contact_force_N", run_dir)
        points = [(a, f) for t, a, f in
                  zip(history["t_us"], approach, force)
                  if f > 0 and in_window(t, options["window"])]
        ax.plot([p[0] for p in points], [p[1] for p in points], label=label,
                linewidth=1.4)
    style_axes(ax, "Force-approach" if not title
               else "%s\nForce-approach" % title,
               r"Approach $\delta = w_{ball} - w_{mid}$ ($\mu$m)",
               "Contact force $F$ (N)")
    ax.legend(loc="best", fontsize="small", framealpha=0.85)
    return save(fig, out, "force_approach", options)


def read_contact_vtu(path):
    """Points (m) and contact_pressure_MPa of an ASCII contact VTU (the
    contact_*.vtu fgimpact writes)."""
    import xml.etree.ElementTree as ET
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        fail("%s: %s" % (path, e))
    piece = root.find("UnstructuredGrid/Piece")
    arrays = {a.get("Name"): [float(v) for v in a.text.split()]
              for a in piece.iter("DataArray") if a.get("Name")}
    coordinates = [float(v) for v in
                   piece.find("Points/DataArray").text.split()]
    points = [coordinates[i:i + 3] for i in range(0, len(coordinates), 3)]
    if "contact_pressure_MPa" not in arrays:
        fail("%s has no contact_pressure_MPa" % path)
    return points, arrays["contact_pressure_MPa"]


def impact_point(run_dir):
    """The impact point (x, y) in m: Impactor/Impact point x, y, -1 for
    the plate's centre."""
    point = []
    for name, size in (("x", "Length a"), ("y", "Width b")):
        value = to_float(read_parameter(run_dir, "Impactor",
                                        "Impact point " + name))
        if value < 0:
            value = 0.5 * to_float(read_parameter(run_dir, "Geometry", size))
        point.append(value)
    return point


def plot_contact_pressure(out, title, runs, options):
    """p(r) of the contact nodes at the peak snapshot, with Hertz's
    elliptic distribution for the same force for an elastic plate."""
    found = [(label, run_dir) for label, run_dir in runs
             if os.path.isfile(os.path.join(run_dir, "vtu", "contact_peak.vtu"))]
    if not found:
        return []
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for label, run_dir in found:
        points, pressure = read_contact_vtu(
            os.path.join(run_dir, "vtu", "contact_peak.vtu"))
        x0, y0 = impact_point(run_dir)
        nodes = sorted((1e3 * math.hypot(x - x0, y - y0), p)
                       for (x, y, _), p in zip(points, pressure))
        line = ax.plot([n[0] for n in nodes], [n[1] for n in nodes], "o",
                       markersize=3, label=label + " (nodes)")[0]
        summary = read_summary(run_dir)
        elastic = read_parameter(run_dir, "Material", "Plasticity") in (
            None, "none")
        F = to_float(summary.get("peak_contact_force_N"))
        E = to_float(summary.get("contact_modulus_Q_Pa"))
        R = to_float(read_parameter(run_dir, "Impactor", "Radius"))
        if elastic and F > 0 and E > 0 and R > 0:
            a = (3 * F * R / (4 * E)) ** (1.0 / 3)
            p0 = 3 * F / (2 * math.pi * a * a)
            r = [a * k / 200 for k in range(201)]
            ax.plot([1e3 * v for v in r],
                    [1e-6 * p0 * math.sqrt(max(0.0, 1 - (v / a) ** 2))
                     for v in r],
                    "--", color=line.get_color(), linewidth=1.2,
                    label="%s: Hertz, F = %.1f N (a = %.3f mm, p0 = %.0f MPa)"
                    % (label, F, 1e3 * a, 1e-6 * p0))
    style_axes(ax, "Contact pressure at the peak force" if not title
               else "%s\nContact pressure at the peak force" % title,
               "Distance from the impact point $r$ (mm)",
               "Contact pressure $p$ (MPa)")
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    ax.legend(loc="best", fontsize="small", framealpha=0.85)
    return save(fig, out, "contact_pressure_profile", options)


def probe_names(probes):
    """The probe names of a probes.csv, in column order."""
    return [c[:-len("_uz_um")] for c in probes if c.endswith("_uz_um")]


def plot_probes(out, title, runs, options):
    """probes.csv of the runs that have one: colours the probe, line styles
    the run."""
    tables = [(label, run_dir, read_history(run_dir, "probes.csv"))
              for label, run_dir in runs
              if os.path.isfile(os.path.join(run_dir, "probes.csv"))]
    if not tables:
        return []
    panels = [("_uz_um", r"$u_z$ ($\mu$m)"),
              ("_sigma_xx_MPa", r"$\sigma_{xx}$ (MPa)"),
              ("_sigma_zz_MPa", r"$\sigma_{zz}$ (MPa)")]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    axes = axes.flatten()
    for k, (label, run_dir, probes) in enumerate(tables):
        style = LINESTYLES[k % 4]
        suffix = ", %s" % label if len(tables) > 1 else ""
        for c, name in enumerate(probe_names(probes)):
            for ax, (ending, _) in zip(axes, panels):
                ax.plot(probes["t_us"],
                        column(probes, name + ending, run_dir, "probes.csv"),
                        color="C%d" % c, linestyle=style,
                        label=name + suffix)
        axes[3].plot(probes["t_us"],
                     column(probes, "support_reaction_z_N", run_dir,
                            "probes.csv"),
                     color="C0", linestyle=style, label="reaction" + suffix)
    for ax, (_, ylabel) in zip(axes, panels + [(None, "Support reaction (N)")]):
        style_axes(ax, ylabel, TIME_LABEL, ylabel)
        set_time_axis(ax, [t[2] for t in tables], options["window"])
        ax.legend(loc="best", fontsize="x-small", framealpha=0.85)
    if title:
        fig.suptitle(title)
    return save(fig, out, "probes", options)


def plot_departure(out, title, runs, options):
    points = []  # (V0, V_departure, label)
    for label, run_dir in runs:
        v0 = to_float(read_parameter(run_dir, "Impactor", "Initial velocity"))
        vd = to_float(read_summary(run_dir).get("departure_velocity_m_s"))
        if math.isnan(v0):
            fail("cannot read Impactor/Initial "
                     "velocity from %s/parameters.prm" % run_dir)
        if math.isnan(vd):
            sys.stderr.write("plot_histories.py: warning: %s has no departure "
                             "velocity (still in contact at the end time?); "
                             "left out of departure_velocity\n" % run_dir)
            continue
        points.append((v0, vd, label))
    if not points:
        sys.stderr.write("plot_histories.py: warning: no departure velocities; "
                         "departure_velocity not written\n")
        return []
    points.sort()
    v0s = [p[0] for p in points]
    vds = [p[1] for p in points]
    ratios = [vd / v0 for v0, vd in zip(v0s, vds)]

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10.5, 4.5))
    ax1.plot(v0s, vds, "o-", label="departure velocity")
    v_top = max(v0s) * 1.1
    ax1.plot([0, v_top], [0, v_top], "--", color="0.5", linewidth=0.8,
             label="departure = initial")
    for v0, vd in zip(v0s, vds):
        ax1.annotate("%.3f" % vd, (v0, vd), textcoords="offset points",
                     xytext=(4, -12), fontsize="small")
    ax1.set_xlim(0, v_top)
    ax1.set_ylim(0, v_top)
    style_axes(ax1, "Departure vs initial velocity",
               r"Initial velocity $V_0$ (m/s)",
               "Departure velocity of the projectile (m/s)")
    ax1.legend(loc="upper left", fontsize="small")

    ax2.plot(v0s, ratios, "s-", color="C1")
    for v0, r in zip(v0s, ratios):
        ax2.annotate("%.4f" % r, (v0, r), textcoords="offset points",
                     xytext=(4, 4), fontsize="small")
    style_axes(ax2, "Ratio departure / initial velocity",
               r"Initial velocity $V_0$ (m/s)",
               r"$V_\mathrm{departure} / V_0$ (-)")
    lo, hi = min(ratios), max(ratios)
    pad = max(0.02, 0.25 * (hi - lo))
    ax2.set_ylim(lo - pad, hi + pad)
    if title:
        fig.suptitle(title)
    return save(fig, out, "departure_velocity", options)


def main(argv):
    out, title, departure, runs, options = parse_arguments(argv)
    histories = [read_history(run_dir) for _, run_dir in runs]
    load_matplotlib()
    os.makedirs(out, exist_ok=True)
    written = plot_time_histories(out, title, runs, histories, options)
    written += plot_energy(out, title, runs, histories, options)
    written += plot_force_approach(out, title, runs, histories, options)
    written += plot_contact_pressure(out, title, runs, options)
    written += plot_probes(out, title, runs, options)
    if departure:
        written += plot_departure(out, title, runs, options)
    for path in written:
        print(path)


if __name__ == "__main__":
    main(sys.argv[1:])
