#!/usr/bin/env bash
# Measures what docs/ensembles.md §6 reports as the cost of one run per law: the paper's case a of
# each egg to rest (or to the law's pole), one run per law, samples at 0.01 s kept in memory, as an
# ensemble runs it. The CPU time (user + system) of the whole process, less that of a process that
# runs 1 ms of motion (start-up, study, scenario), over the run's RHS calls: ns per RHS call. CPU
# time, not wall time: the figure must not depend on what else the machine runs. The least of
# REPS repetitions is kept. Usage: data/studies/bench/law-cost.sh [BUILD_DIR] [REPS] (build, 3).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scenarios=$(cd "$here/../../scenarios" && pwd)
build=${1:-build}
reps=${2:-3}
exe=$(cd "$build" && pwd)/frictionlab
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs) ($(nproc) cores); $(date -u +%FT%TZ); load: $(cut -d' ' -f1-3 /proc/loadavg)"

col() {  # col FILE NAME: the value of column NAME in the first row of a runs.csv
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next } NR == 2 { print $c }' "$1"
}
cpu_of() {  # cpu_of STUDY: least CPU seconds of REPS runs of the study on one thread
  local best="" i cpu
  for ((i = 0; i < reps; i++)); do
    rm -rf "$tmp/out"
    # bash's `times` in a subshell: the children's user and system time, to the millisecond
    cpu=$( ("$exe" ensemble "$1" --out "$tmp/out" --threads 1 --no-figures >/dev/null 2>&1; times) | tail -1 |
          awk '{ split($1, u, /[ms]/); split($2, s, /[ms]/); print 60 * u[1] + u[2] + 60 * s[1] + s[2] }')
    if [ -z "$best" ] || (( $(echo "$cpu < $best" | bc -l) )); then best=$cpu; fi
  done
  echo "$best"
}
study() {  # study NAME EGG LAW [SET...]: writes a one-run study file
  local name=$1 egg=$2 law=$3; shift 3
  local set='"run.output_dt=0.01"' s
  for s in "$@"; do set="$set, \"$s\""; done
  printf 'name = "%s"\nscenario = "%s/egg-%s-a.toml"\nlaws = ["%s"]\nset = [%s]\n' \
         "$name" "$scenarios" "$egg" "$law" "$set" > "$tmp/$name.toml"
}

study startup printed exact "run.t_end=0.001"
startup=$(cpu_of "$tmp/startup.toml")
echo "start-up (1 ms of motion): $startup s CPU"
printf '%-12s %-20s %-18s %9s %8s %11s %8s %12s\n' egg law reason t_final steps rhs_calls "CPU (s)" "ns/RHS call"
for egg in printed homogeneous; do
  for law in exact pade-reconstructed pade-printed moller-ellipsoidal; do
    study "$egg-$law" "$egg" "$law"
    cpu=$(cpu_of "$tmp/$egg-$law.toml")
    csv="$tmp/out/runs.csv"
    run_cpu=$(echo "$cpu - $startup" | bc -l)
    printf '%-12s %-20s %-18s %9.2f %8s %11s %8.3f %12.0f\n' "$egg" "$law" "$(col "$csv" reason)" "$(col "$csv" t_final)" \
           "$(col "$csv" steps)" "$(col "$csv" rhs_calls)" "$run_cpu" "$(echo "1000000000 * $run_cpu / $(col "$csv" rhs_calls)" | bc -l)"
  done
done
