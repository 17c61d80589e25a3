#!/usr/bin/python3
"""Figures of a parameter study (fgimpact --study ...): the peak contact
force, the largest mid-plane deflection and the contact duration against
each varied entry of study.csv, one line per combination of the other
varied entries; with Accuracy = converged, each point with an error bar
of its estimated error (study.csv's *_error_estimate, relative).

Usage: /usr/bin/python3 scripts/plot_study.py OUTPUT/study.csv
           [--format png|pdf|svg] [--out DIR]
Writes DIR/study_<entry>.<format> (DIR: OUTPUT/figures by default) for each
varied entry (the study.csv columns whose name holds a '/').  Needs
matplotlib (Debian's /usr/bin/python3 with python3-matplotlib)."""

import argparse
import csv
import os
import re
import sys

# (column, axis label, the summary key of its relative error estimate,
# present with Accuracy = converged: drawn as error bars).
QUANTITIES = [
    ("peak_contact_force_N", "peak contact force (N)",
     "peak_contact_force_error_estimate"),
    ("max_midplane_deflection_um", "max mid-plane deflection (µm)",
     "max_midplane_deflection_error_estimate"),
    ("contact_duration_us", "contact duration (µs)",
     "contact_duration_error_estimate"),
]


# The units of the entries a study usually varies (the .prm's units).
UNITS = {
    "Initial velocity": "m/s", "Radius": "m", "Density": "kg/m³",
    "Young's modulus": "Pa", "Thickness h": "m", "Length a": "m",
    "Width b": "m", "Time step": "s", "End time": "s",
    "Metal Young's modulus": "Pa", "Ceramic Young's modulus": "Pa",
    "Metal density": "kg/m³", "Ceramic density": "kg/m³",
}


def with_unit(entry):
    """'Impactor/Initial velocity' -> 'Initial velocity (m/s)'; an entry
    without a unit (an index, a count, a selection) keeps its name."""
    name = entry.split("/")[-1]
    return "%s (%s)" % (name, UNITS[name]) if name in UNITS else name


def number(text):
    try:
        return float(text)
    except ValueError:
        return float("nan")


def read_study(filename):
    with open(filename, newline="") as f:
        rows = [[cell.strip() for cell in row] for row in csv.reader(f)]
    header, body = rows[0], [r for r in rows[1:] if r]
    return header, [dict(zip(header, r)) for r in body]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("study_csv", help="study.csv written by fgimpact")
    parser.add_argument("--format", default="png", choices=["png", "pdf", "svg"])
    parser.add_argument("--out", default=None,
                        help="directory of the figures (default: figures/ "
                             "beside study.csv)")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plot_study.py: matplotlib is missing (use /usr/bin/python3)")

    header, rows = read_study(args.study_csv)
    varied = [h for h in header if "/" in h]
    if not varied:
        sys.exit("plot_study.py: no varied entry (a column with '/') in "
                 + args.study_csv)
    out = args.out or os.path.join(os.path.dirname(args.study_csv) or ".",
                                   "figures")
    os.makedirs(out, exist_ok=True)
    for entry in varied:
        others = [v for v in varied if v != entry]
        series = {}
        for r in rows:
            key = ", ".join(
                f"{o.split('/')[-1]} = {r[o]}"
                + (f" {UNITS[o.split('/')[-1]]}" if o.split('/')[-1] in UNITS
                   else "") for o in others)
            series.setdefault(key, []).append(r)
        fig, axes = plt.subplots(1, len(QUANTITIES),
                                 figsize=(4.2 * len(QUANTITIES), 3.6))
        for ax, (column, label, error) in zip(axes, QUANTITIES):
            for key, members in series.items():
                members = sorted(members, key=lambda r: number(r[entry]))
                x = [number(r[entry]) for r in members]
                y = [number(r.get(column, "nan")) for r in members]
                if error in header:
                    bars = [abs(v) * number(r[error]) for v, r in zip(y, members)]
                    ax.errorbar(x, y, yerr=bars, fmt="o-", capsize=3,
                                label=key or None)
                else:
                    ax.plot(x, y, "o-", label=key or None)
            ax.set_xlabel(with_unit(entry))
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
            ax.tick_params(axis="x", labelrotation=30)
        if others:
            axes[0].legend(fontsize=7)
        fig.tight_layout()
        slug = re.sub(r"[^A-Za-z0-9]+", "_", entry).strip("_").lower()
        name = os.path.join(out, f"study_{slug}.{args.format}")
        fig.savefig(name, dpi=150)
        plt.close(fig)
        print(name)


if __name__ == "__main__":
    main()
