#!/usr/bin/python3
"""Markdown table of a bench/run_benchmark.sh results.csv (to stdout).

    /usr/bin/python3 bench/make_table.py output/bench/results.csv
"""
import csv
import sys

LABELS = {
    "cholmod": "implicit, CHOLMOD",
    "cg_jacobi": "implicit, CG + Jacobi",
    "cg_amg": "implicit, CG + AMG (ML)",
    "klu": "implicit, KLU",
    "mumps": "implicit, MUMPS",
    "explicit": "explicit (auto dt)",
}


def path_label(row):
    if row["group"] != "scaling":
        return row["id"]
    return LABELS.get(row["id"].rsplit("_", 1)[0], row["id"])


def fmt(value, spec):
    if value in ("", None):
        return "–"
    try:
        return format(float(value), spec)
    except ValueError:
        return value


def main(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    head = ["scheme / solver", "mesh", "DoFs", "simulated (steps, dt)",
            "setup s", "factor. s", "ms / step", "step / SpMV",
            "step / solve", "wall s", "400 µs run s (proj.)",
            "peak RSS MB", "F_max N", "contact µs", "note"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        if r["note"].startswith("skipped"):
            print(f"| {path_label(r)} | {r['mesh']} | | | | | | | | | | | | | "
                  f"{r['note']} |")
            continue
        if r["n_dofs"] == "":
            print(f"| {path_label(r)} | {r['mesh']} | | | | | | | | | | | | | "
                  f"{r['note']} |")
            continue
        full = r["contact_duration_us"] != ""
        print("| " + " | ".join([
            path_label(r),
            r["mesh"],
            f"{int(r['n_dofs']):,}",
            f"{fmt(r['end_time_us'], '.0f')} µs ({r['n_time_steps']}, "
            f"{fmt(r['dt_us'], '.3g')} µs)",
            fmt(r["setup_s"], ".2f"),
            fmt(r["factorization_s"], ".2f"),
            fmt(r["time_per_step_ms"], ".3g"),
            fmt(r["step_per_spmv"], ".2f"),
            fmt(r["step_per_solve"], ".2f"),
            fmt(r["elapsed_s"], ".1f"),
            fmt(r["projected_400us_s"], ".3g"),
            fmt(r["peak_rss_MB"], ".0f"),
            fmt(r["peak_contact_force_N"], ".1f") if full else "–",
            fmt(r["contact_duration_us"], ".2f") if full else "–",
            r["note"],
        ]) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "output/bench/results.csv")
