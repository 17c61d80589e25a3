#!/usr/bin/env bash
# The price of the converged answer (issue 24): whole-process wall time and
# peak RSS, in one run of this script, of the default scene
# (prm/default.prm, End time = auto) with
#   hertz-node       the paper's model on its own mesh (the reference);
#   converged-1%     resolved sphere, Accuracy = converged, tolerance 0.01;
#   converged-0.2%   the same at 0.002;
#   modes-1%         converged-1% with Finite element/Incompatible modes;
#   adaptive-1, -2   resolved sphere, Geometry/Adaptive refinement cycles
#                    = 1 and 2 (no estimate: doc/performance.md, section 30);
#   modes-adaptive-1 adaptive-1 with the incompatible modes;
#   adaptive-1-estimate, modes-adaptive-1-estimate  the two with Geometry/
#                    Adaptive refinement estimate (section 31: its three
#                    check runs cost 11-12 times the sequence);
# the converged runs without probes, as doc/performance.md's tables (the
# probes' peak stresses would steer them: section 29);
#   level7-resolved  resolved sphere at 7 contact refinement levels;
#   level7-node      hertz node on the same level-7 mesh (the plate alone);
# the two level-7 runs end at 400 us: with End time = auto the point
# force's longer contact made the hertz-node run 180 s against the
# resolved run's 83 s (doc/performance.md, section 28), a comparison of
# step counts, not of the contact's cost;
# N rounds, interleaved (the machine is shared: compare ratios within one
# run); the medians, and each one's ratio to hertz-node.  Prints the
# converged runs' peak force with its error estimate.
# Usage: bench/converged_accuracy.sh [N]   (default 1; about 7 min a round)
#        FGIMPACT=path/to/fgimpact to use another executable.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
exe=$(copy_executable "$(mktemp -d)")
need_gnu_time
n=${1:-1}
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
labels=(hertz-node converged-1% converged-0.2% modes-1% adaptive-1 adaptive-2
  modes-adaptive-1 adaptive-1-estimate modes-adaptive-1-estimate
  level7-resolved level7-node)
options=(
  ""
  "-s Contact/Model=resolved?sphere -s Accuracy=converged -s Accuracy?tolerance=0.01 -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Accuracy=converged -s Accuracy?tolerance=0.002 -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Accuracy=converged -s Accuracy?tolerance=0.01 -s Finite?element/Incompatible?modes=true -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Geometry/Adaptive?refinement?cycles=1 -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Geometry/Adaptive?refinement?cycles=2 -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Geometry/Adaptive?refinement?cycles=1 -s Finite?element/Incompatible?modes=true -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Geometry/Adaptive?refinement?cycles=1 -s Geometry/Adaptive?refinement?estimate=true -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Geometry/Adaptive?refinement?cycles=1 -s Geometry/Adaptive?refinement?estimate=true -s Finite?element/Incompatible?modes=true -s Output/Probe?points="
  "-s Contact/Model=resolved?sphere -s Geometry/Contact?refinement?levels=7 -s Time?integration/End?time=400e-6"
  "-s Geometry/Contact?refinement?levels=7 -s Time?integration/End?time=400e-6"
)
for ((run = 0; run < n; ++run)); do
  for k in "${!labels[@]}"; do
    dir="$root/${labels[$k]}"
    timed_default_run "$exe" "$dir" "$root/${labels[$k]//%/}.txt" \
      "${options[$k]}" -s "Output/VTU interval=0"
    if [ -f "$dir/convergence.csv" ]; then
      echo "${labels[$k]}: peak force $(summary_value "$dir" peak_contact_force_N) N," \
        "estimate $(summary_value "$dir" peak_contact_force_error_estimate)," \
        "levels $(cut -d, -f2 "$dir/convergence.csv" | tail -n +2 | tr '\n' ' ')"
    fi
    if [ -f "$dir/adaptation.csv" ]; then
      echo "${labels[$k]}: peak force $(summary_value "$dir" peak_contact_force_N) N," \
        "departure $(summary_value "$dir" departure_velocity_m_s) m/s," \
        "mid-plane $(summary_value "$dir" max_midplane_deflection_um) um," \
        "DoFs $(cut -d, -f3 "$dir/adaptation.csv" | tail -n +2 | tr '\n' ' ')"
    fi
    if [ -f "$dir/adaptive_estimate.csv" ]; then
      echo "${labels[$k]}: largest estimate $(summary_value "$dir" largest_error_estimate)," \
        "checks $(summary_value "$dir" adaptive_estimate_wall_time_s) s"
    fi
  done
done
reference=$(cut -d' ' -f1 "$root/hertz-node.txt" | median)
reference_rss=$(cut -d' ' -f2 "$root/hertz-node.txt" | median)
echo "| run | whole process (s, median of $n) | / hertz-node | peak RSS (MB) | / hertz-node |"
echo "|---|---|---|---|---|"
for label in "${labels[@]}"; do
  wall=$(cut -d' ' -f1 "$root/${label//%/}.txt" | median)
  rss=$(cut -d' ' -f2 "$root/${label//%/}.txt" | median)
  awk -v l="$label" -v w="$wall" -v r="$rss" -v w0="$reference" -v r0="$reference_rss" \
    'BEGIN {printf "| %s | %.2f | %.1f | %.0f | %.2f |\n", l, w, w / w0, r / 1024, r / r0}'
done
