# Shared helpers of the bench/*.sh and scripts/*.sh drivers (bash).
# Source it from the repository root, after the script's own
#   cd "$(dirname "$0")/.."
#   . scripts/fgimpact_lib.sh
#
#   write_prm OUT BASE [PATH=VALUE ...]
#       Write the parameter file OUT: "include BASE", then one "set" per
#       override.  PATH is Section/Entry, nested subsections joined by '/'
#       (Time integration/Time step), or a bare Entry at the top level
#       (Accuracy).  Overrides of one subsection are grouped, in the order
#       their subsections first appear; a later override of the same entry
#       wins (deal.II reads the lines in order).  BASE is usually
#       prm/default.prm; an empty BASE writes no include.  BASE is a path
#       from the working directory of the caller; the include line holds its
#       absolute path, so OUT can live anywhere (fgimpact resolves a relative
#       include against the including file's directory).  write_prm fails
#       when BASE does not exist.
#   summary_value DIR KEY
#       Print the value of KEY in DIR/summary.txt ("key = value" lines);
#       print an error naming the file and return 1 when the file or the key
#       is missing.
#   copy_executable DIR
#       Copy $FGIMPACT (default build/fgimpact) to DIR/fgimpact_bench, so that
#       a rebuild during a benchmark does not change it, and print that path.
#   need_gnu_time
#       Install GNU time (/usr/bin/time, for the peak RSS) if it is missing.
#   gnu_time_rss_mb FILE [FORMAT]
#   gnu_time_elapsed_s FILE
#       Maximum resident set size in MB (printf FORMAT, default %.0f) and
#       elapsed wall-clock seconds from the report of `/usr/bin/time -v`.
#   allow_local_mpirun
#       Export what Open MPI needs to start local ranks as root, oversubscribed,
#       on a machine without ssh/rsh.

write_prm() {
  if [ $# -lt 2 ]; then
    echo "usage: write_prm OUT BASE [Section/Entry=value ...]" >&2
    return 2
  fi
  local out=$1 base=$2 arg key section seen indent part
  shift 2
  if [ -n "$base" ] && [ ! -f "$base" ]; then
    echo "write_prm: base $base not found in $(pwd)" >&2
    return 1
  fi
  [ -n "$base" ] && base="$(cd "$(dirname "$base")" && pwd)/$(basename "$base")"
  local -a sections=()
  for arg in "$@"; do
    key=${arg%%=*}
    if [ "$key" = "$arg" ] || [ -z "$key" ] || [ "${key##*/}" = "" ]; then
      echo "write_prm: '$arg' is not Section/Entry=value" >&2
      return 2
    fi
    section=""
    [[ $key == */* ]] && section=${key%/*}
    seen=0
    for part in "${sections[@]}"; do [ "$part" = "$section" ] && seen=1; done
    [ $seen -eq 1 ] || sections+=("$section")
  done
  {
    [ -n "$base" ] && echo "include $base"
    for section in "${sections[@]}"; do
      indent=""
      local -a parts=()
      [ -n "$section" ] && IFS=/ read -ra parts <<< "$section"
      for part in "${parts[@]}"; do
        echo "${indent}subsection $part"
        indent="$indent  "
      done
      for arg in "$@"; do
        key=${arg%%=*}
        [[ $key == */* ]] || key=/$key
        [ "${key%/*}" = "$section" ] || continue
        echo "${indent}set ${key##*/} = ${arg#*=}"
      done
      for part in "${parts[@]}"; do
        indent=${indent#  }
        echo "${indent}end"
      done
    done
  } > "$out"
}

summary_value() {
  if [ $# -ne 2 ]; then
    echo "usage: summary_value DIR KEY" >&2
    return 2
  fi
  local file=$1/summary.txt
  if [ ! -f "$file" ]; then
    echo "summary_value: $file not found" >&2
    return 1
  fi
  awk -F' = ' -v k="$2" '$1 == k {print $2; found = 1; exit}
                         END {exit !found}' "$file" ||
    { echo "summary_value: no '$2' in $file" >&2; return 1; }
}

copy_executable() {
  local src=${FGIMPACT:-build/fgimpact}
  if [ ! -x "$src" ]; then
    echo "no executable $src (build first, or set FGIMPACT)" >&2
    return 1
  fi
  cp "$src" "$1/fgimpact_bench"
  echo "$1/fgimpact_bench"
}

need_gnu_time() {
  [ -x /usr/bin/time ] && return 0
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get install -y --no-install-recommends time
}

# One run of EXE on prm/default.prm into DIR, timed by GNU time: appends
# "wall_s peak_KB" to FILE.  OPTIONS: one string of "-s Entry=value"
# words, '?' standing for a space inside a word; further arguments go to
# the program as they are.  Quiet (no timing, log or screen output).
timed_default_run() {
  local exe=$1 dir=$2 file=$3 options=$4 word
  shift 4
  local args=()
  for word in $options; do args+=("${word//\?/ }"); done
  /usr/bin/time -f "%e %M" -o "$file.time" "$exe" prm/default.prm \
    -s "Output/Directory=$dir" -s "Output/Print timing=false" \
    -s "Output/Log interval=0" "$@" "${args[@]}" >/dev/null
  cat "$file.time" >>"$file"
  rm -f "$file.time"
}

# The median of the numbers on standard input, one per line.
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

gnu_time_rss_mb() {
  awk -F': ' -v f="${2:-%.0f}" \
    '/Maximum resident set size/ {printf f, $2 / 1024}' "$1"
}

gnu_time_elapsed_s() {
  awk -F': ' '/Elapsed \(wall clock\)/ {
    n = split($2, p, ":"); s = 0
    for (i = 1; i <= n; ++i) s = 60 * s + p[i]
    print s }' "$1"
}

allow_local_mpirun() {
  # mpirun refuses to start as root unless told (CI runs as root), and ranks
  # may share the machine's cores with other processes.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_rmaps_base_oversubscribe=1
  # Local ranks only: Open MPI 4 refuses to start without ssh/rsh on PATH
  # (a fresh Debian has neither) unless the remote agent is unset.
  export OMPI_MCA_plm_rsh_agent=
}
