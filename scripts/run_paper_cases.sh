#!/usr/bin/env bash
# Run every case of Asemi & Salami (2015), sections 4.1-4.2, with the built
# fgimpact and draw the comparison figures (the analogues of Figs. 3-8).
#
# Usage (from anywhere; the script changes to the repository root):
#   scripts/run_paper_cases.sh              run all cases, then plot
#   scripts/run_paper_cases.sh --plot-only  only redraw figures and table from
#                                           the existing output/paper/<case>/
# Environment:
#   FGIMPACT  path of the executable (default: build/fgimpact, relative to the
#             repository root)
#   PYTHON    interpreter with matplotlib (default: /usr/bin/python3)
#
# Results:  output/paper/<case>/{history.csv,summary.txt,parameters.prm,run.log}
# Figures:  output/paper/figures/{index,velocity,density}/*.png
#           output/paper/summary_table.txt (the summary numbers of all cases)
set -euo pipefail

plot_only=false
case "${1:-}" in
  "") ;;
  --plot-only) plot_only=true ;;
  -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
  *) echo "error: unknown argument '$1' (use --plot-only or nothing)" >&2; exit 2 ;;
esac

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# The paper files include prm/default.prm, which deal.II opens relative to
# the working directory: run from the repository root.
cd "$repo_root"
. scripts/fgimpact_lib.sh

fgimpact="${FGIMPACT:-build/fgimpact}"
python="${PYTHON:-/usr/bin/python3}"
plot="scripts/plot_histories.py"

if ! $plot_only && [[ ! -x "$fgimpact" ]]; then
  echo "error: fgimpact executable '$fgimpact' not found or not executable" \
       "(set FGIMPACT or build it into build/)" >&2
  exit 1
fi
if ! "$python" -c 'import matplotlib' 2>/dev/null; then
  echo "error: '$python' cannot import matplotlib (set PYTHON)" >&2
  exit 1
fi

cases=(
  homogeneous_verification
  index_n1 index_n3 index_n5
  velocity_v1 velocity_v2 velocity_v3 velocity_v4
  density_7800 density_8900 density_9850 density_11300
)

# Output/Directory of a prm file (every paper prm sets it).
output_dir_of() {
  sed -n 's/^[[:space:]]*set[[:space:]]\+Directory[[:space:]]*=[[:space:]]*\([^#[:space:]]*\).*/\1/p' "$1" | tail -n 1
}

declare -A out_dir
for c in "${cases[@]}"; do
  prm="prm/$c.prm"
  [[ -f "$prm" ]] || { echo "error: $prm is missing" >&2; exit 1; }
  dir="$(output_dir_of "$prm")"
  [[ -n "$dir" ]] || { echo "error: $prm does not set Output/Directory" >&2; exit 1; }
  out_dir[$c]="$dir"
done

warnings=0
for c in "${cases[@]}"; do
  dir="${out_dir[$c]}"
  if $plot_only; then
    [[ -f "$dir/history.csv" && -f "$dir/summary.txt" ]] ||
      { echo "error: --plot-only but $dir has no results; run without it" >&2; exit 1; }
    if grep -qs 'WARNING' "$dir/run.log"; then warnings=$((warnings + 1)); fi
    continue
  fi
  mkdir -p "$dir"
  echo "=== $c  ->  $dir"
  # Remove results of an earlier run so that a failed run cannot be plotted
  # with stale data.
  rm -f "$dir/history.csv" "$dir/summary.txt"
  if ! "$fgimpact" "prm/$c.prm" > "$dir/run.log" 2>&1; then
    echo "error: fgimpact failed for $c; log:" >&2
    tail -n 20 "$dir/run.log" >&2
    exit 1
  fi
  grep -E '^  (peak force|max indentation|energy drift|wall time)' "$dir/run.log" || true
  if grep -q 'WARNING' "$dir/run.log"; then
    grep 'WARNING' "$dir/run.log" >&2
    warnings=$((warnings + 1))
  fi
  grep 'note:' "$dir/run.log" || true
done

fig_root="output/paper/figures"

echo "=== figures"
"$python" "$plot" --out "$fig_root/index" \
  --title 'Effect of the volume fraction index $n$ (cf. Figs. 2-5)' \
  --label 'homogeneous ($E$ = 70 GPa)' "${out_dir[homogeneous_verification]}" \
  --label '$n$ = 1' "${out_dir[index_n1]}" \
  --label '$n$ = 3' "${out_dir[index_n3]}" \
  --label '$n$ = 5' "${out_dir[index_n5]}"

"$python" "$plot" --out "$fig_root/velocity" --departure \
  --title 'Effect of the initial velocity $V_0$, $n$ = 1 (cf. Figs. 6-7)' \
  --label '$V_0$ = 1 m/s' "${out_dir[velocity_v1]}" \
  --label '$V_0$ = 2 m/s' "${out_dir[velocity_v2]}" \
  --label '$V_0$ = 3 m/s' "${out_dir[velocity_v3]}" \
  --label '$V_0$ = 4 m/s' "${out_dir[velocity_v4]}"

"$python" "$plot" --out "$fig_root/density" \
  --title 'Effect of the projectile mass, $n$ = 1, $V_0$ = 1 m/s (cf. Fig. 8)' \
  --label '$\rho_i$ = 7800 kg/m$^3$ ($m_p$ = 110 g)' "${out_dir[density_7800]}" \
  --label '$\rho_i$ = 8900 kg/m$^3$ ($m_p$ = 126 g)' "${out_dir[density_8900]}" \
  --label '$\rho_i$ = 9850 kg/m$^3$ ($m_p$ = 139 g)' "${out_dir[density_9850]}" \
  --label '$\rho_i$ = 11300 kg/m$^3$ ($m_p$ = 160 g)' "${out_dir[density_11300]}"

# One table of the summary numbers of all cases.
table="output/paper/summary_table.txt"
keys=(peak_contact_force_N time_of_peak_force_us contact_duration_us
      departure_velocity_m_s max_midplane_deflection_um max_top_deflection_um
      n_impacts max_relative_energy_drift wall_time_s)
{
  printf '%-26s' case
  printf ' %s' "${keys[@]}"
  printf '\n'
  for c in "${cases[@]}"; do
    printf '%-26s' "$c"
    for k in "${keys[@]}"; do
      v="$(summary_value "${out_dir[$c]}" "$k")" || v='?'
      printf ' %s' "$v"
    done
    printf '\n'
  done
} > "$table"
column -t "$table" 2>/dev/null || cat "$table"

echo
echo "Run directories: output/paper/<case>/ (history.csv, summary.txt, run.log)"
echo "Summary table:   $repo_root/$table"
echo "Figures:"
for d in index velocity density; do
  echo "  $repo_root/$fig_root/$d/"
done
if (( warnings > 0 )); then
  echo "WARNING: $warnings case(s) ended still in contact; raise their End time." >&2
  exit 3
fi
