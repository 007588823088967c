#!/usr/bin/env bash
# Benchmark of the multi-versioned kernels (issue: speed near the machine's limit, part 2), side by side in
# one run: each kernel set this CPU has (PBRFIT_KERNELS=generic|avx2|avx512), and optionally an older
# pbrfit binary (the scalar code before the vector kernels) as the baseline.
#  1. the 128 x 128 DFG table at 1e-6 (tests/benchmarks/dfg-128.yaml) on 2 ranks: median wall time of
#     REPEATS runs (the whole mpirun command) and the job's own time; the engine alone on one core in the
#     machine's best set (test_engines "[.benchmark]", height-correlated table; the test binary does not
#     read PBRFIT_KERNELS);
#  2. the 64 x 64 GGX LTC table (jobs/ltc-ggx.yaml) on 2 ranks: median wall time of LTC_REPEATS runs;
#  3. what differs between the sets' results: the DFG tables' largest difference, and whether the LTC
#     tables are bitwise the same (they must be: their kernels have no transcendental function).
# Usage: tests/benchmarks/kernel_sets_benchmark.sh [BUILD] [BASELINE_PBRFIT]   (REPEATS=5, LTC_REPEATS=3)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
BASELINE=${2:-}
REPEATS=${REPEATS:-5}
LTC_REPEATS=${LTC_REPEATS:-3}
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
PY=/usr/bin/python3

median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

# Prints "wall_median elapsed_median" of BINARY running JOB on 2 ranks N times, the last result kept as OUT/NAME.h5.
measure() {
  local binary=$1 job=$2 n=$3 name=$4 i start end
  : > "$OUT/wall"; : > "$OUT/elapsed"
  for ((i = 0; i < n; i++)); do
    start=$(date +%s.%N)
    mpirun "${FLAGS[@]}" -np 2 "$binary" run "$job" --output "$OUT/$name.h5" --force -q
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}' >> "$OUT/wall"
    $PY -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r').attrs['elapsed_seconds'])" "$OUT/$name.h5" >> "$OUT/elapsed"
  done
  echo "$(median < "$OUT/wall") $(median < "$OUT/elapsed")"
}

engine_seconds() {  # the height-correlated table's line of the engine benchmark
  "$BUILD/tests/test_engines" "[.benchmark]" 2>/dev/null | sed -n 's/^visibility 2: \([0-9.]*\) s wall.*/\1/p'
}

sets=$("$BUILD/pbrfit" --version | sed -n 's/.*this machine has \([^;]*\);.*/\1/p' | tr -d ',')
[[ -n $sets ]] || sets="generic avx2 avx512"
echo "pbrfit kernel sets benchmark: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo "sets: $sets; baseline: ${BASELINE:-none}; REPEATS=$REPEATS, LTC_REPEATS=$LTC_REPEATS"
echo
echo "DFG engine alone, one core, best set: $(engine_seconds) s"
echo
echo "| binary | DFG 128 x 128, 2 ranks: wall s | job s | GGX LTC 64 x 64, 2 ranks: wall s | job s |"
echo "|---|---|---|---|---|"
if [[ -n $BASELINE ]]; then
  read -r dw de < <(measure "$BASELINE" tests/benchmarks/dfg-128.yaml "$REPEATS" dfg-baseline)
  read -r lw le < <(measure "$BASELINE" jobs/ltc-ggx.yaml "$LTC_REPEATS" ltc-baseline)
  echo "| baseline (scalar) | $dw | $de | $lw | $le |"
fi
for set in $sets; do
  export PBRFIT_KERNELS=$set
  read -r dw de < <(measure "$BUILD/pbrfit" tests/benchmarks/dfg-128.yaml "$REPEATS" "dfg-$set")
  read -r lw le < <(measure "$BUILD/pbrfit" jobs/ltc-ggx.yaml "$LTC_REPEATS" "ltc-$set")
  echo "| $set | $dw | $de | $lw | $le |"
  unset PBRFIT_KERNELS
done
echo
$PY - "$OUT" $sets ${BASELINE:+baseline} <<'PY'
import sys, h5py, numpy as np
out, names = sys.argv[1], sys.argv[2:]
def numeric(path, group):
    data = {}
    with h5py.File(path, "r") as f:
        f[group].visititems(lambda n, o: data.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) and o.dtype.kind in "fiu" else None)
    return data
first = names[0]
dfg0, ltc0 = numeric(f"{out}/dfg-{first}.h5", "dfg"), numeric(f"{out}/ltc-{first}.h5", "ltc")
for name in names[1:]:
    dfg, ltc = numeric(f"{out}/dfg-{name}.h5", "dfg"), numeric(f"{out}/ltc-{name}.h5", "ltc")
    largest = max(float(np.max(np.abs(dfg[k].astype(float) - dfg0[k].astype(float)))) for k in ("scale", "bias"))
    differing = [k for k in ltc0 if ltc0[k].tobytes() != ltc[k].tobytes()]
    print(f"{name} against {first}: DFG scale and bias differ by at most {largest:.2e}; "
          f"LTC tables: {'bitwise the same' if not differing else 'differ in ' + ', '.join(differing[:5])} "
          f"({len(ltc0)} numeric datasets)")
PY
