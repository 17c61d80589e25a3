#!/usr/bin/python3
"""Overlay the time histories of several fgimpact runs, like Figs. 3-8 of
Asemi & Salami (2015).

Usage:
  plot_histories.py --out DIR [--title T] [--departure]
                    [--label L1] run_dir1 [--label L2] run_dir2 ...

Each run_dir must contain the history.csv written by fgimpact (and, for
--departure, summary.txt and parameters.prm). A "--label L" applies to the
run directory that follows it; without it the label is the directory's
basename.

Writes into DIR (created if missing):
  contact_force.png        contact force F (N) vs t (us)          Figs. 3a, 6a, 8a
  impactor_velocity.png    projectile velocity (m/s) vs t (us)    Fig. 3b
  midplane_deflection.png  w at (a/2, b/2, h/2) (um) vs t (us)    Figs. 4a, 6b, 8b
  top_deflection.png       w at (a/2, b/2, h) (um) vs t (us)      Fig. 4b
  sigma_yy.png             sigma_yy at the mid-plane centre (MPa)  Fig. 5a
  sigma_zz.png             sigma_zz at the mid-plane centre (MPa)  Fig. 5b
and with --departure:
  departure_velocity.png   departure velocity vs V0 (and their ratio), Fig. 7

Needs only the csv module and matplotlib (Agg backend); run it with
/usr/bin/python3, whose matplotlib is installed.
"""

import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


# (file name, history.csv column, y-axis label, title)
FIGURES = [
    ("contact_force.png", "contact_force_N", "Contact force $F$ (N)",
     "Contact force"),
    ("impactor_velocity.png", "impactor_velocity_m_s",
     "Projectile velocity (m/s)\n(positive towards the plate)",
     "Projectile velocity"),
    ("midplane_deflection.png", "midplane_deflection_um",
     r"Mid-plane deflection $w(a/2,\,b/2,\,h/2)$ ($\mu$m)",
     "Mid-plane deflection at the plate centre"),
    ("top_deflection.png", "top_deflection_um",
     r"Top deflection $w(a/2,\,b/2,\,h)$ ($\mu$m)",
     "Top-surface deflection at the plate centre"),
    ("sigma_yy.png", "sigma_yy_mid_MPa",
     r"In-plane stress $\sigma_{yy}$ (MPa)",
     r"In-plane stress $\sigma_{yy}$ at $(a/2,\,b/2,\,h/2)$"),
    ("sigma_zz.png", "sigma_zz_mid_MPa",
     r"Peel stress $\sigma_{zz}$ (MPa)",
     r"Peel stress $\sigma_{zz}$ at $(a/2,\,b/2,\,h/2)$"),
]

TIME_LABEL = r"Time $t$ ($\mu$s)"


def usage(message=None, status=2):
    stream = sys.stderr if message else sys.stdout
    if message:
        stream.write("plot_histories.py: error: %s\n\n" % message)
    stream.write(__doc__.split("\nWrites")[0].strip() + "\n")
    sys.exit(status)


def parse_arguments(argv):
    out = None
    title = None
    departure = False
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
        elif arg.startswith("--"):
            usage("unknown option '%s'" % arg)
        else:
            label = pending_label
            if label is None:
                label = os.path.basename(os.path.normpath(arg))
            runs.append((label, arg))
            pending_label = None
        i += 1
    if out is None:
        usage("--out DIR is required")
    if not runs:
        usage("no run directories given")
    if pending_label is not None:
        usage("--label '%s' is not followed by a run directory" % pending_label)
    return out, title, departure, runs


def read_history(run_dir):
    """Columns of run_dir/history.csv as a dict name -> list of floats."""
    path = os.path.join(run_dir, "history.csv")
    if not os.path.isfile(path):
        sys.exit("plot_histories.py: error: %s not found" % path)
    with open(path, newline="") as f:
        reader = csv.reader(f, skipinitialspace=True)
        header = [h.strip() for h in next(reader)]
        columns = {h: [] for h in header}
        for row in reader:
            if not row:
                continue
            if len(row) != len(header):
                sys.exit("plot_histories.py: error: %s: a row has %d fields, "
                         "the header %d" % (path, len(row), len(header)))
            for h, value in zip(header, row):
                columns[h].append(float(value))
    if not columns.get("t_us"):
        sys.exit("plot_histories.py: error: %s has no data rows" % path)
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


def style_axes(ax, title, xlabel, ylabel):
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.axhline(0.0, color="0.6", linewidth=0.6, zorder=0)


def plot_time_histories(out, title, runs, histories):
    written = []
    t_max = max(h["t_us"][-1] for h in histories)
    for file_name, column, ylabel, fig_title in FIGURES:
        fig, ax = plt.subplots(figsize=(7.5, 4.8))
        for (label, run_dir), history in zip(runs, histories):
            if column not in history:
                sys.exit("plot_histories.py: error: %s/history.csv has no "
                         "column '%s'" % (run_dir, column))
            ax.plot(history["t_us"], history[column], label=label,
                    linewidth=1.4)
        style_axes(ax, fig_title if not title else "%s\n%s" % (title, fig_title),
                   TIME_LABEL, ylabel)
        ax.set_xlim(0.0, t_max)
        ax.legend(loc="best", fontsize="small", framealpha=0.85)
        fig.tight_layout()
        path = os.path.join(out, file_name)
        fig.savefig(path, dpi=130)
        plt.close(fig)
        written.append(path)
    return written


def plot_departure(out, title, runs):
    points = []  # (V0, V_departure, label)
    for label, run_dir in runs:
        v0 = to_float(read_parameter(run_dir, "Impactor", "Initial velocity"))
        vd = to_float(read_summary(run_dir).get("departure_velocity_m_s"))
        if math.isnan(v0):
            sys.exit("plot_histories.py: error: cannot read Impactor/Initial "
                     "velocity from %s/parameters.prm" % run_dir)
        if math.isnan(vd):
            sys.stderr.write("plot_histories.py: warning: %s has no departure "
                             "velocity (still in contact at the end time?); "
                             "left out of departure_velocity.png\n" % run_dir)
            continue
        points.append((v0, vd, label))
    if not points:
        sys.stderr.write("plot_histories.py: warning: no departure velocities; "
                         "departure_velocity.png not written\n")
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
    fig.tight_layout()
    path = os.path.join(out, "departure_velocity.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return [path]


def main(argv):
    out, title, departure, runs = parse_arguments(argv)
    histories = [read_history(run_dir) for _, run_dir in runs]
    os.makedirs(out, exist_ok=True)
    written = plot_time_histories(out, title, runs, histories)
    if departure:
        written += plot_departure(out, title, runs)
    for path in written:
        print(path)


if __name__ == "__main__":
    main(sys.argv[1:])
