#!/usr/bin/env bash
# Measures what docs/ensembles.md §6 reports: the cost of one run to rest, the throughput on 1 and 2
# threads and 1 and 2 MPI ranks, rank 0's coordination cost, and the memory of each process for
# 20 and 200 runs. Usage: data/studies/bench/measure.sh [BUILD_DIR] [OUT_DIR] (defaults: build,
# /tmp/frictionlab-measure). Prints a summary; the folders stay in OUT_DIR.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:-build}
out=${2:-/tmp/frictionlab-measure}
exe=$(cd "$build" && pwd)/frictionlab
mpirun=(mpirun --allow-run-as-root --oversubscribe)
rm -rf "$out" && mkdir -p "$out"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs) ($(nproc) cores); $(date -u +%FT%TZ); load: $(cut -d' ' -f1-3 /proc/loadavg)"

col() {  # col FILE NAME: the values of column NAME of a runs.csv
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next } { print $c }' "$1"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "== one run to rest, no trajectory (5 repetitions; wall_time of runs.csv; user CPU of the process)"
for egg in printed homogeneous; do
  walls=()
  for i in 1 2 3 4 5; do
    d="$out/one-$egg-$i"
    /usr/bin/time -f "%U" -o "$d.cpu" "$exe" ensemble "$here/egg-$egg-a-exact.toml" --out "$d" --threads 1 --no-figures >/dev/null 2>&1
    walls+=("$(col "$d/runs.csv" wall_time)")
  done
  echo "egg-$egg-a exact: wall_time ${walls[*]} s (median $(printf '%s\n' "${walls[@]}" | median)); user CPU $(cat "$out"/one-$egg-*.cpu | xargs) s;" \
       "$(col "$out/one-$egg-1/runs.csv" reason) at t = $(col "$out/one-$egg-1/runs.csv" t_final) s, $(col "$out/one-$egg-1/runs.csv" rhs_calls) RHS calls"
done

echo "== throughput: 200 runs (scaling.toml)"
run() {  # run LABEL COMMAND...: wall time of the whole job, runs/s, CPU per run, the stderr kept
  local label=$1; shift
  local start end
  start=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$out/$label.cpu" "$@" > "$out/$label.out" 2> "$out/$label.err"
  end=$(date +%s.%N)
  local wall cpu
  wall=$(echo "$end - $start" | bc -l)
  cpu=$(awk '{ print $1 + $2 }' "$out/$label.cpu")
  # CPU per run (user + system of every process of the job, ranks included): what the job costs
  # whatever else the machine runs; runs/s depends on the cores the job actually got.
  printf '%-16s %6.1f s  %5.2f runs/s  %6.1f s CPU (%.3f s a run)  load %s   %s\n' "$label" "$wall" \
         "$(echo "200 / $wall" | bc -l)" "$cpu" "$(echo "$cpu / 200" | bc -l)" "$(cut -d' ' -f1 /proc/loadavg)" \
         "$(grep -h 'coordination' "$out/$label.err" | sed 's/^ensemble: //')"
}
run threads-1 "$exe" ensemble "$here/scaling.toml" --out "$out/threads-1" --threads 1 --no-figures
run threads-2 "$exe" ensemble "$here/scaling.toml" --out "$out/threads-2" --threads 2 --no-figures
run mpi-1 "${mpirun[@]}" -np 1 "$exe" ensemble "$here/scaling.toml" --out "$out/mpi-1" --no-figures
run mpi-2 "${mpirun[@]}" -np 2 "$exe" ensemble "$here/scaling.toml" --out "$out/mpi-2" --no-figures
echo "sum of the runs' wall_time (s of one core): $(col "$out/threads-1/runs.csv" wall_time | paste -sd+ | bc -l);" \
     "median run $(col "$out/threads-1/runs.csv" wall_time | median) s"

echo "== memory: maximum resident set of each process (KB), 20 and 200 runs"
for study in scaling-small scaling; do
  /usr/bin/time -f "threads-1 $study: %M KB" "$exe" ensemble "$here/$study.toml" --out "$out/mem-$study-t" --threads 1 --no-figures >/dev/null 2>"$out/mem-$study-t.err"
  tail -1 "$out/mem-$study-t.err"
  "${mpirun[@]}" -np 2 /usr/bin/time -f "mpi rank: $study: %M KB" "$exe" ensemble "$here/$study.toml" --out "$out/mem-$study-m" --no-figures >/dev/null 2>"$out/mem-$study-m.err"
  grep -h "mpi rank" "$out/mem-$study-m.err"
done
