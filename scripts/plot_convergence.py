#!/usr/bin/python3
"""The convergence of an Accuracy = converged run: each headline number of
convergence.csv against the element size under the ball (one point per
contact refinement level on the input's mesh at its time step, the runs
on refined base meshes as points, the final run at half the step marked
apart), with the final value and its estimated error band from
summary.txt.

An adaptive run's directory (Geometry/Adaptive refinement cycles, its
adaptation.csv) gives instead each headline number against the DoFs of
its runs: the pilot runs and the final one (no error band: the run
prints no estimate), figures/adaptation.<format>.

Usage: /usr/bin/python3 scripts/plot_convergence.py OUTPUT_DIR
           [--format png|pdf|svg] [--data]
Writes OUTPUT_DIR/figures/convergence.<format> (or adaptation.<format>;
with --data also adaptation.data.csv, the points drawn: columns
figure,axes,curve,x,y).  Needs matplotlib (Debian's /usr/bin/python3
with python3-matplotlib)."""

import argparse
import csv
import os
import sys

# (convergence.csv column, axis label, summary.txt key prefix)
QUANTITIES = [
    ("peak_contact_force_N", "peak contact force (N)", "peak_contact_force"),
    ("contact_duration_us", "contact duration (µs)", "contact_duration"),
    ("departure_velocity_m_s", "departure velocity (m/s)", "departure_velocity"),
    ("max_midplane_deflection_um", "max mid-plane deflection (µm)",
     "max_midplane_deflection"),
    ("max_approach_um", "max approach of ball and mid-plane (µm)", "max_approach"),
]


def summary(directory):
    values = {}
    with open(os.path.join(directory, "summary.txt")) as f:
        for line in f:
            if " = " in line and not line.startswith("#"):
                key, value = line.split(" = ", 1)
                values[key.strip()] = value.strip()
    return values


def save(fig, directory, name, fmt, points):
    """figures/NAME.FMT and, with points, NAME.data.csv."""
    out = os.path.join(directory, "figures")
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, f"{name}.{fmt}")
    fig.savefig(path, dpi=150)
    if points is not None:
        with open(os.path.join(out, f"{name}.data.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["figure", "axes", "curve", "x", "y"])
            for row in points:
                w.writerow([name] + [repr(v) if isinstance(v, float) else v
                                     for v in row])
    print(path)


def plot_adaptation(args, plt):
    """Each headline number against the DoFs of the adaptive runs."""
    with open(os.path.join(args.directory, "adaptation.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    s = summary(args.directory)
    pilots, final = rows[:-1], rows[-1]
    points = []
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(3.6 * len(QUANTITIES), 3.4))
    for k, (ax, (column, label, key)) in enumerate(zip(axes, QUANTITIES)):
        for curve, runs, style in (("pilot runs", pilots, "o-"),
                                   ("final run", [final], "s")):
            x = [float(r["n_dofs"]) for r in runs]
            y = [float(r[column]) for r in runs]
            ax.plot(x, y, style, label=curve)
            points += [(k, curve, a, b) for a, b in zip(x, y)]
        ax.set_xscale("log")
        ax.set_xlabel("DoFs")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=6)
    fig.suptitle(f"adaptive mesh, {s.get('adaptive_refinement_cycles', '?')} cycles "
                 f"of fraction {s.get('adaptive_refinement_fraction', '?')}: "
                 f"{args.directory}", fontsize=9)
    fig.tight_layout()
    save(fig, args.directory, "adaptation", args.format,
         points if args.data else None)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", help="Output/Directory of the run")
    parser.add_argument("--format", default="png", choices=["png", "pdf", "svg"])
    parser.add_argument("--data", action="store_true",
                        help="also write the points drawn, NAME.data.csv")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plot_convergence.py: matplotlib is missing (use /usr/bin/python3)")
    if os.path.exists(os.path.join(args.directory, "adaptation.csv")):
        plot_adaptation(args, plt)
        return
    with open(os.path.join(args.directory, "convergence.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    final = rows[-1]
    mesh = lambda r: (r.get("subdivisions_x"), r.get("subdivisions_y"),
                      r.get("subdivisions_z"))
    # The contact levels on the input's mesh, and the runs on other base
    # meshes (their element size under the ball is that of their mesh).
    levels = [r for r in rows[:-1] if mesh(r) == mesh(rows[0])]
    bases = [r for r in rows[:-1] if mesh(r) != mesh(rows[0])]
    s = summary(args.directory)
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(3.6 * len(QUANTITIES), 3.4))
    for ax, (column, label, key) in zip(axes, QUANTITIES):
        h = [float(r["element_size_under_ball_mm"]) for r in levels]
        ax.plot(h, [float(r[column]) for r in levels], "o-",
                label=f"levels, dt = {levels[0]['time_step_us']} µs")
        if bases:
            ax.plot([float(r["element_size_under_ball_mm"]) for r in bases],
                    [float(r[column]) for r in bases], "^", alpha=0.7,
                    label="other base meshes (convergence.csv)")
        value = float(final[column])
        ax.plot([float(final["element_size_under_ball_mm"])], [value], "s",
                label=f"final, dt = {final['time_step_us']} µs")
        error = abs(value) * float(s.get(f"{key}_error_estimate", "nan"))
        ax.axhspan(value - error, value + error, alpha=0.2,
                   label=f"estimated error ({s.get(key + '_error_method', '?')})")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("element size under the ball (mm)")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=6)
    fig.suptitle(f"Accuracy = converged, tolerance {float(s['accuracy_tolerance']):.2%}: "
                 f"{args.directory}", fontsize=9)
    fig.tight_layout()
    save(fig, args.directory, "convergence", args.format, None)


if __name__ == "__main__":
    main()
