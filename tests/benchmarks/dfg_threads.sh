#!/usr/bin/env bash
# Benchmark: the 256 x 256 DFG table on 1 rank x 1 thread, 1 rank x 2 threads and 2 ranks x 1 thread.
# Threads and ranks should be worth the same: 1x2 within 5 % of 2x1. Reports the median of REPEATS runs
# of the whole mpirun command and of the job's own elapsed time. mpirun binds each rank to one core by
# default, so the 1x2 run is launched with --bind-to none.
# Usage: tests/benchmarks/dfg_threads.sh [path/to/pbrfit]    (REPEATS=5 by default)
set -euo pipefail
cd "$(dirname "$0")/../.."
PBRFIT=${1:-build/pbrfit}
REPEATS=${REPEATS:-5}
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
JOB=tests/benchmarks/dfg-256.yaml

median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

# Prints "wall_median job_elapsed_median" for RANKS ranks x THREADS threads.
measure() {
  local ranks=$1 threads=$2 i start end
  : > "$OUT/wall"; : > "$OUT/elapsed"
  for ((i = 0; i < REPEATS; i++)); do
    rm -f "$OUT"/r.h5*
    start=$(date +%s.%N)
    mpirun "${FLAGS[@]}" --bind-to none -np "$ranks" "$PBRFIT" run "$JOB" --output "$OUT/r.h5" --threads "$threads" -q
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}' >> "$OUT/wall"
    /usr/bin/python3 -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r').attrs['elapsed_seconds'])" "$OUT/r.h5" >> "$OUT/elapsed"
  done
  echo "$(median < "$OUT/wall") $(median < "$OUT/elapsed")"
}

echo "pbrfit DFG 256 ranks x threads: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo "| ranks x threads | wall s (median of $REPEATS) | job elapsed s |"
echo "|---|---|---|"
for config in "1 1" "1 2" "2 1"; do
  read -r ranks threads <<< "$config"
  read -r wall elapsed < <(measure "$ranks" "$threads")
  echo "| $ranks x $threads | $wall | $elapsed |"
done
