#!/usr/bin/env bash
# Benchmark: the 128 x 128 DFG table at 1e-6 on 1 and 2 ranks (and the quickstart job, which adds the
# multiple-scattering terms). Reports the median of REPEATS runs: wall time of the whole mpirun command
# (start-up included), the job's own elapsed time, the 2-rank speedup and integrand evaluations per entry.
# Usage: tests/benchmarks/dfg_lut.sh [path/to/pbrfit]    (REPEATS=5 by default)
set -euo pipefail
cd "$(dirname "$0")/../.."
PBRFIT=${1:-build/pbrfit}
REPEATS=${REPEATS:-5}
# One machine: shared memory only, as `make demo` runs it (OpenMPI's network probing costs ~0.2 s).
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

# Prints "wall_median job_elapsed_median" for JOB on RANKS ranks.
measure() {
  local job=$1 ranks=$2 i start end
  : > "$OUT/wall" ; : > "$OUT/elapsed"
  for ((i = 0; i < REPEATS; i++)); do
    rm -f "$OUT/r.h5"
    start=$(date +%s.%N)
    mpirun "${FLAGS[@]}" -np "$ranks" "$PBRFIT" run "$job" --output "$OUT/r.h5" -q
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}' >> "$OUT/wall"
    /usr/bin/python3 -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r').attrs['elapsed_seconds'])" "$OUT/r.h5" >> "$OUT/elapsed"
  done
  echo "$(median < "$OUT/wall") $(median < "$OUT/elapsed")"
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }

evaluations() {
  /usr/bin/python3 -c "
import h5py, sys
e = h5py.File(sys.argv[1], 'r')['dfg/evaluations'][()]
print(f'{e.mean():.0f} {e.max():.0f}')" "$OUT/r.h5"
}

echo "pbrfit DFG benchmark: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo "| job | ranks | wall s (median of $REPEATS) | job elapsed s | evaluations/entry mean | max |"
echo "|---|---|---|---|---|---|"
for job in tests/benchmarks/dfg-128.yaml jobs/quickstart.yaml; do
  read -r wall1 elapsed1 < <(measure "$job" 1)
  read -r mean max < <(evaluations)
  echo "| $job | 1 | $wall1 | $elapsed1 | $mean | $max |"
  read -r wall2 elapsed2 < <(measure "$job" 2)
  echo "| $job | 2 | $wall2 | $elapsed2 | $mean | $max |"
  echo "| $job | speedup 2 vs 1 | $(ratio "$wall1" "$wall2") | $(ratio "$elapsed1" "$elapsed2") | | |"
done
