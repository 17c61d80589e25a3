#!/usr/bin/python3
"""Plots and fitted exponents of a bench/run_benchmark.sh results.csv.

    /usr/bin/python3 bench/plot_benchmark.py [results.csv] [--figures DIR]

Writes DIR/time_per_step.png (log-log time per step against DoFs, one line
per solver path, with the exponent p of t = C N^p fitted by least squares
of log t against log N), DIR/step_per_spmv.png (time per step divided by
one SpMV of the same run) and DIR/memory_and_run.png (peak RSS and the
projected whole 400 us run).  DIR defaults to doc/figures.  Prints the
exponents as a Markdown table.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PATHS = [  # id prefix, label, style
    ("cholmod", "implicit, CHOLMOD", "o-"),
    ("cg_jacobi", "implicit, CG + Jacobi", "s-"),
    ("cg_amg", "implicit, CG + AMG", "^-"),
    ("klu", "implicit, KLU", "v-"),
    ("mumps", "implicit, MUMPS", "x-"),
    ("explicit", "explicit (auto dt)", "D-"),
]


def load(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f)
                if r["group"] == "scaling" and r["n_dofs"] != ""
                and r["time_per_step_ms"] != ""]
    data = {}
    for pid, _, _ in PATHS:
        sel = [r for r in rows if r["id"].rsplit("_", 1)[0] == pid]
        sel.sort(key=lambda r: int(r["n_dofs"]))
        if sel:
            data[pid] = {k: np.array([float(r[k]) if r[k] != "" else np.nan
                                      for r in sel])
                         for k in ("n_dofs", "time_per_step_ms", "spmv_ms",
                                   "step_per_spmv", "peak_rss_MB",
                                   "projected_400us_s", "dt_us")}
    return data


def fit(n, t):
    """Least squares of log t = log C + p log N; returns (p, C)."""
    if len(n) < 2:
        return np.nan, np.nan
    p, logc = np.polyfit(np.log(n), np.log(t), 1)
    return p, np.exp(logc)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv", nargs="?", default="output/bench/results.csv")
    ap.add_argument("--figures", default="doc/figures")
    args = ap.parse_args()
    os.makedirs(args.figures, exist_ok=True)
    data = load(args.csv)

    # --- time per step
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    print("| path | DoF range | points | exponent p (t ~ N^p) |")
    print("|---|---|---|---|")
    for pid, label, style in PATHS:
        if pid not in data:
            continue
        d = data[pid]
        n, t = d["n_dofs"], d["time_per_step_ms"]
        p, c = fit(n, t)
        lines = ax.loglog(n, t, style, label=f"{label}: p = {p:.2f}"
                          if np.isfinite(p) else label)
        if np.isfinite(p):
            nn = np.geomspace(n.min(), n.max(), 20)
            ax.loglog(nn, c * nn**p, ":", color=lines[0].get_color(),
                      lw=1)
        print(f"| {label} | {int(n.min()):,}–{int(n.max()):,} | {len(n)} | "
              f"{p:.2f} |")
    # SpMV of the explicit runs (K), for reference.
    if "explicit" in data:
        d = data["explicit"]
        ax.loglog(d["n_dofs"], d["spmv_ms"], "k--", lw=1,
                  label="one SpMV (same runs)")
    nref = np.array([1e4, 1.1e6])
    ax.loglog(nref, 0.5 * (nref / 1e4)**1.2, color="0.6", lw=3, alpha=0.4,
              label="slope 1.2 (target limit)")
    ax.set_xlabel("DoFs N")
    ax.set_ylabel("wall time per step [ms]")
    ax.set_title("fgimpact, default scene: time per step (2 cores, shared)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "time_per_step.png"), dpi=130)

    # --- time per step / SpMV
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    for pid, label, style in PATHS:
        if pid not in data:
            continue
        d = data[pid]
        ax.semilogx(d["n_dofs"], d["step_per_spmv"], style, label=label)
    ax.axhline(2, color="0.5", ls="--", lw=1)
    ax.text(1.1e4, 2.2, "explicit target: 2 SpMV", fontsize=8, color="0.4")
    ax.set_yscale("log")
    ax.set_xlabel("DoFs N")
    ax.set_ylabel("time per step / one SpMV (same run)")
    ax.set_title("Cost of a step in SpMVs of the step's matrix")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "step_per_spmv.png"), dpi=130)

    # --- peak memory and the projected whole run
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for pid, label, style in PATHS:
        if pid not in data:
            continue
        d = data[pid]
        a1.loglog(d["n_dofs"], d["peak_rss_MB"], style, label=label)
        a2.loglog(d["n_dofs"], d["projected_400us_s"], style, label=label)
    a1.axhline(20 * 1024, color="0.5", ls="--", lw=1)
    a1.text(1.3e4, 20 * 1024 * 1.08, "20 GiB budget (24 GiB machine)",
            fontsize=8, color="0.4")
    a1.set_xlabel("DoFs N")
    a1.set_ylabel("peak RSS [MB]")
    a1.set_title("Peak memory (GNU time)")
    a2.set_xlabel("DoFs N")
    a2.set_ylabel("setup + factorization + 400 µs of steps [s]")
    a2.set_title("Whole default run (400 µs), projected")
    for a in (a1, a2):
        a.grid(True, which="both", alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "memory_and_run.png"), dpi=130)


if __name__ == "__main__":
    main()
