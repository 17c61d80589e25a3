#!/usr/bin/python3
"""Table and plot of bench/mpi_scaling.sh's results (issue 5).

    /usr/bin/python3 bench/plot_mpi_scaling.py output/mpi_scaling/results.csv

Prints a Markdown table (time per step, speed-up and parallel efficiency on
2 ranks against 1 rank of the same path and mesh; weak scaling against the
1-rank run of half the size) and writes doc/figures/mpi_scaling.png.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1] if len(sys.argv) > 1 else
                                "output/mpi_scaling/results.csv")))
rows = [r for r in rows if r.get("time_per_step_ms")]


def find(path, ranks, n_dofs):
    for r in rows:
        if (r["path"] == path and int(r["ranks"]) == ranks
                and int(r["n_dofs"]) == n_dofs):
            return r
    return None


print("| study | path | mesh | DoFs | ranks | setup s | factorization s "
      "| ms/step | speed-up | efficiency | peak RSS MB (largest rank) |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
strong = {}
for r in rows:
    ranks, n = int(r["ranks"]), int(r["n_dofs"])
    tps = float(r["time_per_step_ms"])
    speedup = efficiency = ""
    if r["study"] == "strong" and ranks == 2:
        base = find(r["path"], 1, n)
        if base:
            s = float(base["time_per_step_ms"]) / tps
            speedup, efficiency = f"{s:.2f}", f"{s / 2:.0%}"
            strong[(r["path"], n)] = s
    if r["study"] == "weak":
        # Weak: twice the DoFs on twice the ranks; efficiency = t1 / t2
        # scaled by the DoF ratio (ideal: the same time per step).
        base = [b for b in rows if b["path"] == r["path"]
                and int(b["ranks"]) == 1 and b["study"] == "strong"
                and int(b["n_dofs"]) < n]
        if base:
            b = min(base, key=lambda b: abs(2 * int(b["n_dofs"]) - n))
            e = (float(b["time_per_step_ms"]) * n / int(b["n_dofs"])
                 / (2 * tps))
            efficiency = f"{e:.0%} (vs {int(b['n_dofs']):,} DoFs on 1)"
    print(f"| {r['study']} | {r['path']} | {r['mesh']} | {n:,} | {ranks} | "
          f"{float(r['setup_s']):.2f} | {float(r['factorization_s']):.2f} | "
          f"{tps:.2f} | {speedup} | {efficiency} | "
          f"{r['peak_rss_MB_largest_rank']} |")

if strong:
    fig, ax = plt.subplots(figsize=(7, 4))
    labels = [f"{p}\n{n:,} DoFs" for (p, n) in strong]
    ax.bar(range(len(strong)), list(strong.values()), color="tab:blue")
    ax.axhline(2.0, color="k", ls="--", lw=1, label="ideal (2 ranks)")
    ax.axhline(1.7, color="tab:red", ls=":", lw=1, label="target 1.7")
    ax.set_xticks(range(len(strong)))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("speed-up of the time per step, 2 ranks vs 1")
    ax.set_title("fgimpact strong scaling on this 2-core machine")
    ax.legend()
    fig.tight_layout()
    os.makedirs("doc/figures", exist_ok=True)
    fig.savefig("doc/figures/mpi_scaling.png", dpi=120)
    print("\nwrote doc/figures/mpi_scaling.png")
