#!/usr/bin/env bash
# Benchmarks of the symbolic-regression kind (figures in docs/BENCHMARKS.md):
#  1. exact recovery of Nguyen-1..8 with Koza's operators and no constants (jobs/nguyen7.yaml's settings),
#     SEEDS seeds each on 2 ranks: recovered = a front member with RMSE < 1e-9 on 10,000 fresh points,
#     within LIMIT seconds of wall time (the run stops itself once an island's training error is ~0);
#  2. evaluations per second on 1 and 2 ranks: the Nguyen-7 search (20 rows, short epochs) and the DFG case
#     study's search (16,384 rows) for a fixed number of generations;
#  3. the DFG case studies, when their results exist (results/dfg-symreg*.h5): per output, the most accurate
#     front member whose cost is at most the anchor's, beside the anchor.
# Usage: tests/benchmarks/symreg_benchmark.sh [path/to/pbrfit]   (SEEDS=10, LIMIT=60, PROBLEMS="1 2 ... 8")
set -euo pipefail
cd "$(dirname "$0")/../.."
PBRFIT=$(realpath "${1:-build/pbrfit}")
SEEDS=${SEEDS:-10}
LIMIT=${LIMIT:-60}
PROBLEMS=${PROBLEMS:-"1 2 3 4 5 6 7 8"}
ROOT=$PWD
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
cd "$OUT"

nguyen_job() {  # problem seed generations target
  sed -e "s/^seed: .*/seed: $2/" -e "s/generator: nguyen7/generator: nguyen$1/" -e "s/generations: 3000/generations: $3/" \
      -e "s/target_error: 1.0e-12/target_error: $4/" -e "s|^output: .*|output: run.h5|" "$ROOT/jobs/nguyen7.yaml" > job.yaml
}

echo "pbrfit symbolic-regression benchmarks: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo
echo "## Nguyen-1..8, exact recovery within $LIMIT s on 2 ranks ($SEEDS seeds each)"
echo "| problem | recovered | median s | max s | example |"
echo "|---|---|---|---|---|"
for p in $PROBLEMS; do
  : > times
  recovered=0 example=""
  for ((seed = 1; seed <= SEEDS; seed++)); do
    nguyen_job "$p" "$seed" 100000 1.0e-12
    rm -f run.h5*
    start=$(date +%s.%N)
    timeout --signal=TERM "$LIMIT" mpirun "${FLAGS[@]}" -np 2 "$PBRFIT" run job.yaml -q > /dev/null 2>&1 || true
    end=$(date +%s.%N)
    seconds=$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}')
    echo "$seconds" >> times
    line=$(/usr/bin/python3 - <<'PY' 2>/dev/null || true
import h5py
f = h5py.File("run.h5", "r")
if f.attrs["state"] == "complete":
    exact = [m for m in f["y/front"][...] if m["test_rmse"] < 1e-9]
    if exact: print(exact[0]["expression"].decode())
PY
)
    if [[ -n $line ]]; then recovered=$((recovered + 1)); [[ -n $example ]] || example=$line; fi
  done
  median=$(sort -g times | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}')
  echo "| Nguyen-$p | $recovered/$SEEDS | $median | $(sort -g times | tail -1) | \`$example\` |"
done

# Prints the 1- and 2-rank evaluation rates of job.yaml (all outputs' log tables).
rates() {
  for ranks in 1 2; do
    rm -f "r$ranks.h5"*
    mpirun "${FLAGS[@]}" -np "$ranks" "$PBRFIT" run job.yaml --threads 1 -q --output "r$ranks.h5" > /dev/null
  done
  /usr/bin/python3 - <<'PY'
import h5py
rates = []
for ranks in (1, 2):
    f = h5py.File(f"r{ranks}.h5", "r")
    evaluations = sum(int(f[g]["log"][...]["evaluations"].sum()) for g in f if g != "subexpressions")
    rates.append(evaluations / f.attrs["elapsed_seconds"])
    print(f"| {ranks} rank{'s' if ranks > 1 else ''} | {evaluations} evaluations | {f.attrs['elapsed_seconds']:.2f} s | {rates[-1]:.4g}/s |")
print(f"2 ranks / 1 rank: {rates[1] / rates[0]:.2f}x")
PY
}

echo
echo "## Evaluations per second, Nguyen-7 search without a target (300 generations, 20 rows)"
nguyen_job 7 1 300 0
rates
echo
echo "## Evaluations per second, the DFG case study's search for 30 generations (2 outputs, 16384 rows each)"
sed -e "s|^output: .*|output: lut.h5|" "$ROOT/jobs/dfg-narkowicz.yaml" > lut.yaml
mpirun "${FLAGS[@]}" -np 2 "$PBRFIT" run lut.yaml -q > /dev/null
sed -e "s|result: results/dfg-narkowicz.h5|result: lut.h5|" -e "s/generations: 400/generations: 30/" "$ROOT/jobs/dfg-symreg.yaml" > job.yaml
rates

for result in "$ROOT"/results/dfg-symreg.h5 "$ROOT"/results/dfg-symreg-course.h5; do
  [[ -f $result ]] || continue
  echo
  echo "## DFG case study: $(basename "$result")"
  /usr/bin/python3 - "$result" <<'PY'
import sys, h5py
f = h5py.File(sys.argv[1], "r")
print("| output | anchor | anchor cost | anchor RMSE | best member at cost <= anchor's | its cost | its RMSE | its max abs |")
print("|---|---|---|---|---|---|---|---|")
for output in ("bias", "scale"):
    front = f[output + "/front"][...]
    for a in f[output + "/anchors"][...]:
        fit = [m for m in front if m["cost"] <= a["cost"]]
        best = min(fit, key=lambda m: m["rmse"]) if fit else None
        text = best["expression"].decode() if best is not None else "none"
        print(f"| {output} | {a['name'].decode()} | {a['cost']:.0f} | {a['rmse']:.4g} | `{text}` | "
              f"{best['cost'] if best is not None else float('nan'):.0f} | {best['rmse'] if best is not None else float('nan'):.4g} | "
              f"{best['max_abs_error'] if best is not None else float('nan'):.4g} |")
PY
done
