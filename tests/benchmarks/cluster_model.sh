#!/usr/bin/env bash
# Benchmark: the cluster model for every shipped job (docs/BENCHMARKS.md, "Scale past one machine").
#  1. tests/benchmarks/coordinator_rate.sh: rank 0's time per item and the stage boundary at 2-16 ranks;
#  2. every job in jobs/ on 2 ranks with `pbrfit run -v` (stopped by SIGTERM after CAP seconds: the stages
#     it finished are what the model sees), jobs that read another job's result after it;
#  3. tests/benchmarks/cluster_model.py: each job's predicted wall time, busy ranks and rank 0's
#     coordinating load at 64, 256 and 1,024 ranks.
# Usage: tests/benchmarks/cluster_model.sh [build]   (CAP=90 seconds a job; JOBS="ltc-ggx quickstart" for some;
#        KEEP=1 keeps the logs)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
CAP=${CAP:-90}
FLAGS=(-np 2)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
if [[ -n ${KEEP:-} ]]; then echo "logs kept in $OUT"; else trap 'rm -rf "$OUT"' EXIT; fi

echo "pbrfit cluster model: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), $(git rev-parse --short HEAD)"
echo
tests/benchmarks/coordinator_rate.sh "$BUILD/tests/pbrfit_runtime_probe" | tee "$OUT/rate.md"
echo

# Jobs that read another job's result (a `results/...` path other than their output) run after the others,
# reading that job's result from here.
readers=() others=()
for job in ${JOBS:-$(ls jobs/*.yaml | xargs -n1 basename | sed 's/\.yaml$//')}; do
  if grep -vE '^\s*(#|output:)' "jobs/$job.yaml" | grep -q 'results/'; then readers+=("$job"); else others+=("$job"); fi
done
logs=()
for job in "${others[@]}" "${readers[@]}"; do
  sed "s#results/#$OUT/#g" "jobs/$job.yaml" > "$OUT/$job.yaml"
  start=$(date +%s.%N)
  code=0
  timeout --signal=TERM --kill-after=60 "$CAP" mpirun "${FLAGS[@]}" "$BUILD/pbrfit" run -v "$OUT/$job.yaml" \
    2> "$OUT/$job.log" > /dev/null || code=$?
  end=$(date +%s.%N)
  [[ $code == 124 ]] && echo "# stopped at the cap of $CAP s" >> "$OUT/$job.log"
  if grep -q 'r0\] debug: stage [0-9]*: ' "$OUT/$job.log"; then
    logs+=("$OUT/$job.log")
    awk -v j="$job" -v a="$start" -v b="$end" -v c="$code" 'BEGIN {printf "ran %s: %.1f s, exit %s%s\n", j, b - a, c, c == 124 ? " (stopped at the cap)" : ""}'
  else
    echo "ran $job: no stage finished (exit $code): $(grep -m1 -E '\] (error|critical): |: error: ' "$OUT/$job.log" || true)"
  fi
done
echo
/usr/bin/python3 tests/benchmarks/cluster_model.py --rate "$OUT/rate.md" "${logs[@]}"
