#!/usr/bin/python3
"""Figures and Richardson extrapolations of a bench/accuracy_map.sh results.csv.

    /usr/bin/python3 bench/plot_accuracy.py [results.csv] [--figures DIR]

Writes into DIR (default doc/figures):
  accuracy_inplane.png    peak force, contact duration and top deflection
                          against the in-plane node spacing: no limit
                          (the paper's point contact force, u ~ 1/r);
  accuracy_thickness.png  |change| against nz (40x20 in plane, dt = 1 us),
                          relative to the Richardson extrapolation;
  accuracy_dt.png         |change| against dt on 40x20x4 and 40x20x8,
                          relative to the Richardson extrapolation (or to
                          the smallest dt where the sequence has no order);
  accuracy_cost.png       error of the 5 mm in-plane runs (relative to the
                          thickness- and dt-converged values) against wall
                          time, the presets marked.
Prints the observed orders, the extrapolated values and each run's error
as Markdown tables (doc/accuracy.md quotes them).
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

QUANTITIES = [  # column, label, unit
    ("peak_contact_force_N", "peak force", "N"),
    ("contact_duration_us", "contact duration", "us"),
    ("departure_velocity_m_s", "departure velocity", "m/s"),
    ("max_midplane_deflection_um", "max mid-plane deflection", "um"),
    ("impulse_N_s", "impulse", "N s"),
]

# The presets of source/problem/accuracy_preset.cc: (nx, ny, nz, dt_us).
PRESETS = {"fast": (40, 20, 2, 2.0), "standard": (40, 20, 4, 1.0),
           "accurate": (40, 20, 16, 1.0)}


def read(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("nx", "ny", "nz", "degree", "n_dofs"):
                r[k] = int(r[k])
            for k in r:
                if k not in ("label", "group", "mode") and isinstance(r[k], str):
                    r[k] = float(r[k])
            rows.append(r)
    return rows


def select(rows, **kw):
    out = [r for r in rows
           if all(r[k] == v for k, v in kw.items())]
    return out


def series(rows, key, **kw):
    """Rows matching kw, sorted by key, duplicates removed."""
    seen, out = set(), []
    for r in sorted(select(rows, **kw), key=lambda r: r[key]):
        if r[key] not in seen:
            seen.add(r[key])
            out.append(r)
    return out


def richardson(f_coarse, f_mid, f_fine, ratio=2.0):
    """Observed order and extrapolated value from three levels refined by
    `ratio`; (None, None) if the differences do not decrease monotonically
    (no asymptotic order: no extrapolation)."""
    d1, d2 = f_mid - f_coarse, f_fine - f_mid
    if d2 == 0 or d1 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None, None
    p = math.log(d1 / d2) / math.log(ratio)
    return p, f_fine + d2 / (ratio ** p - 1)


def orders(vals):
    """Observed order of every three successive levels (None: no order)."""
    return [richardson(*vals[i:i + 3])[0] for i in range(len(vals) - 2)]


def extrapolate(seq, col):
    """Richardson on the last three entries of seq (coarse to fine), only
    where the sequence shows an order: the last two observed orders exist
    and agree within 0.5. Returns (order, value, value with p = 2) or
    (None, None, None)."""
    vals = [r[col] for r in seq]
    o = orders(vals)
    if len(o) < 2 or None in o[-2:] or abs(o[-1] - o[-2]) > 0.5:
        return None, None, None
    p, ext = richardson(*vals[-3:])
    return p, ext, vals[-1] + (vals[-1] - vals[-2]) / 3.


def fmt_orders(vals):
    return ", ".join("%.2f" % p if p else "-" for p in orders(vals))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", nargs="?", default="output/accuracy/results.csv")
    parser.add_argument("--figures", default="doc/figures")
    args = parser.parse_args()
    rows_all = read(args.csv)
    # The preset runs repeat runs of the knobs (through the Accuracy
    # entry): only in the error table.
    rows = [r for r in rows_all if r["group"] != "preset"]
    os.makedirs(args.figures, exist_ok=True)
    q1 = dict(degree=1, mode="graded")

    # ---------------------------------------------------------- thickness
    thick = series(rows, "nz", nx=40, ny=20, dt_us=1.0, **q1)  # coarse first
    print("## Through the thickness (40x20, dt = 1 us)\n")
    print("| quantity | " + " | ".join("nz = %d" % r["nz"] for r in thick)
          + " | orders | extrapolated (observed p; p = 2) |")
    print("|---|" + "---|" * (len(thick) + 2))
    thick_ref, thick_extrapolated = {}, {}
    for col, label, unit in QUANTITIES:
        vals = [r[col] for r in thick]
        p, ext, ext2 = extrapolate(thick, col)
        thick_ref[col] = ext if ext is not None else vals[-1]
        thick_extrapolated[col] = ext is not None
        print("| %s [%s] | %s | %s | %s |" % (
            label, unit, " | ".join("%.6g" % v for v in vals),
            fmt_orders(vals), "%.6g; %.6g" % (ext, ext2) if ext else
            "no order: finest %.6g" % vals[-1]))

    # ---------------------------------------------------------- time step
    dt_ref = {}
    print("\n## Time step\n")
    for nz in (4, 8):
        seq = sorted(series(rows, "dt_us", nx=40, ny=20, nz=nz, **q1),
                     key=lambda r: -r["dt_us"])  # coarse (large dt) first
        print("40x20x%d, dt = %s us\n" % (nz, ", ".join(
            "%g" % r["dt_us"] for r in seq)))
        print("| quantity | values | orders | extrapolated or finest |")
        print("|---|---|---|---|")
        dt_ref[nz] = {}
        for col, label, unit in QUANTITIES:
            vals = [r[col] for r in seq]
            p, ext, _ = extrapolate(seq, col)
            dt_ref[nz][col] = (ext if ext is not None else vals[-1],
                               ext is not None)
            print("| %s [%s] | %s | %s | %s |" % (
                label, unit, ", ".join("%.7g" % v for v in vals),
                fmt_orders(vals),
                ("%.7g" % ext) if ext is not None else
                "no order: finest %.7g" % vals[-1]))
        print()

    # Thickness- and dt-converged reference at 5 mm in plane: the thickness
    # extrapolation (dt = 1 us) plus the dt correction measured on 40x20x8.
    ref = {}
    for col, _, _ in QUANTITIES:
        dt8 = select(rows, nx=40, ny=20, nz=8, dt_us=1.0, **q1)[0][col]
        ref[col] = thick_ref[col] + (dt_ref[8][col][0] - dt8)
    print("## Reference (5 mm in plane, thickness and dt converged)\n")
    for col, label, unit in QUANTITIES:
        print("- %s: %.6g %s" % (label, ref[col], unit))

    # ------------------------------------------------- errors of 5 mm runs
    five = [r for r in rows_all if r["nx"] == 40 and r["ny"] == 20
            and r["degree"] == 1]
    print("\n## Errors of the Q1 40x20 runs against the reference\n")
    print("| run | nz | dt us | mode | wall s | " +
          " | ".join(q[1] for q in QUANTITIES) + " |")
    print("|---|---|---|---|---|" + "---|" * len(QUANTITIES))
    for r in sorted(five, key=lambda r: (r["mode"], r["nz"], -r["dt_us"])):
        preset = [k for k, v in PRESETS.items()
                  if v == (r["nx"], r["ny"], r["nz"], r["dt_us"])
                  and r["mode"] == "graded" and r["group"] != "preset"]
        print("| %s%s | %d | %g | %s | %.2f | %s |" % (
            r["label"], " (%s)" % preset[0] if preset else "", r["nz"],
            r["dt_us"], r["mode"], r["wall_time_s"],
            " | ".join("%+.3f %%" % (100 * (r[c] / ref[c] - 1))
                       for c, _, _ in QUANTITIES)))

    # ------------------------------------------------------------ figures
    # In plane: peak force, contact duration, top deflection against the
    # node spacing under the ball (a / (nx p), mm).
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    sets = [
        ("Q1, nz = 4", sorted(select(rows, nz=4, dt_us=1.0, **q1),
                              key=lambda r: r["nx"]), "o-"),
        ("Q1, the Q2 meshes' node layout", sorted(
            [r for r in select(rows, dt_us=1.0, **q1)
             if (r["nx"], r["nz"]) in ((20, 4), (40, 8), (80, 8))],
            key=lambda r: r["nx"]), "s--"),
        ("Q2, nz = 2", sorted(select(rows, degree=2, nz=2, dt_us=1.0),
                              key=lambda r: r["nx"]), "^-"),
        ("Q2, nz = 4", sorted(select(rows, degree=2, nz=4, dt_us=1.0),
                              key=lambda r: r["nx"]), "v-"),
    ]
    for ax, (col, label, unit) in zip(
            axes, [QUANTITIES[0], QUANTITIES[1],
                   ("max_top_deflection_um", "max top deflection", "um")]):
        for name, seq, style in sets:
            x = [200.0 / (r["nx"] * r["degree"]) for r in seq]
            y = [r[col] for r in seq]
            ax.plot(x, y, style, label=name)
            for r, xi, yi in zip(seq, x, y):
                ax.annotate("%dx%dx%d" % (r["nx"], r["ny"], r["nz"]),
                            (xi, yi), fontsize=6, textcoords="offset points",
                            xytext=(3, 3))
        ax.set_xscale("log", base=2)
        ticks = [10, 5, 2.5, 1.25]
        ax.set_xticks(ticks)
        ax.set_xticklabels(["%g" % t for t in ticks])
        ax.minorticks_off()
        ax.invert_xaxis()
        ax.set_xlabel("in-plane node spacing under the ball [mm]")
        ax.set_ylabel("%s [%s]" % (label, unit))
        ax.grid(True, which="both", alpha=0.3)
    q1_4 = sets[0][1]
    steps = ", ".join("%+.1f %%" % (100 * (b["peak_contact_force_N"] /
                                           a["peak_contact_force_N"] - 1))
                      for a, b in zip(q1_4, q1_4[1:]))
    axes[0].set_title("Q1 nz = 4, per halving: " + steps, fontsize=9)
    axes[0].legend(fontsize=7)
    fig.suptitle("Default scene: in-plane refinement does not converge "
                 "(point contact force, u ~ 1/r)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "accuracy_inplane.png"), dpi=120)
    plt.close(fig)

    # Thickness: |f(nz) / f_extrapolated - 1| against nz.
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for col, label, unit in QUANTITIES:
        x = [r["nz"] for r in thick]
        y = [abs(r[col] / thick_ref[col] - 1) for r in thick]
        if thick_extrapolated[col]:
            ax.loglog(x, y, "o-", label=label)
        else:  # relative to the finest: drop it
            ax.loglog(x[:-1], y[:-1], "s:",
                      label=label + " (vs nz = %d, no order)" % x[-1])
    x0 = [thick[0]["nz"], thick[-1]["nz"]]
    for p, style in ((1, ":"), (2, "--")):
        y0 = 0.1
        ax.loglog(x0, [y0, y0 * (x0[0] / x0[1]) ** p], "k" + style, lw=0.8,
                  label="order %d" % p)
    ax.set_xscale("log", base=2)
    ax.set_xticks([r["nz"] for r in thick])
    ax.set_xticklabels(["%d" % r["nz"] for r in thick])
    ax.minorticks_off()
    ax.set_xlabel("elements through the thickness nz (40x20 in plane)")
    ax.set_ylabel("|relative change| vs Richardson extrapolation")
    ax.set_title("Through the thickness: converges; peak force observed "
                 "orders " + fmt_orders([r["peak_contact_force_N"]
                                         for r in thick]), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "accuracy_thickness.png"),
                dpi=120)
    plt.close(fig)

    # Time step: |f(dt) / f_ref - 1| on both meshes.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, nz in zip(axes, (4, 8)):
        seq = sorted(series(rows, "dt_us", nx=40, ny=20, nz=nz, **q1),
                     key=lambda r: r["dt_us"])
        for col, label, unit in QUANTITIES:
            rv, extrapolated = dt_ref[nz][col]
            pts = [(r["dt_us"], abs(r[col] / rv - 1)) for r in seq
                   if extrapolated or r["dt_us"] != seq[0]["dt_us"]]
            pts = [(x, y) for x, y in pts if y > 0]
            if pts:
                ax.loglog(*zip(*pts), "o-" if extrapolated else "s:",
                          label=label + ("" if extrapolated else
                                         " (vs smallest dt, no order)"))
        xs = [0.5, 4]
        ax.loglog(xs, [1e-5, 1e-5 * 64], "k--", lw=0.8, label="order 2")
        ax.set_xticks([0.5, 1, 2, 4])
        ax.set_xticklabels(["0.5", "1", "2", "4"])
        ax.minorticks_off()
        ax.set_xlabel("time step [us]")
        ax.set_title("40x20x%d" % nz, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("|relative change| vs extrapolation or smallest dt")
    axes[0].legend(fontsize=7)
    axes[1].legend(fontsize=7)
    fig.suptitle("Time step: below 1e-3 relative from dt = 2 us (mid-plane "
                 "deflection: 2e-3); no stable order", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "accuracy_dt.png"), dpi=120)
    plt.close(fig)

    # Cost: error against wall time, 5 mm in-plane graded Q1 runs.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    g = [r for r in five if r["mode"] == "graded" and r["group"] != "preset"]
    for ax, (col, label, unit) in zip(axes, [QUANTITIES[0], QUANTITIES[3]]):
        if col == "max_midplane_deflection_um":
            label += " (reference +-0.1 %)"
        for nz, marker in ((2, "v"), (4, "o"), (8, "s"), (16, "D"),
                           (32, "^")):
            pts = sorted([(r["wall_time_s"], abs(r[col] / ref[col] - 1),
                           r["dt_us"]) for r in g if r["nz"] == nz])
            if not pts:
                continue
            ax.loglog([p[0] for p in pts], [max(p[1], 1e-6) for p in pts],
                      marker, label="nz = %d" % nz)
            for t, e, dt in pts:
                ax.annotate("%g us" % dt, (t, max(e, 1e-6)), fontsize=6,
                            textcoords="offset points", xytext=(3, 2))
        for name in PRESETS:
            # The preset's own run (through the Accuracy entry).
            r = select(rows_all, label="preset-" + name)
            if r:
                e = max(abs(r[0][col] / ref[col] - 1), 1e-6)
                ax.annotate(name, (r[0]["wall_time_s"], e), fontsize=8,
                            color="C3", textcoords="offset points",
                            xytext=(-10, -12), weight="bold")
        ax.set_xlabel("wall time [s] (shared 2-core machine: repeats "
                      "differ by up to 50 %)")
        ax.set_ylabel("|error| vs the thickness/dt-converged value")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(label + " (40x20 in plane, 5 mm)", fontsize=10)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "accuracy_cost.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
