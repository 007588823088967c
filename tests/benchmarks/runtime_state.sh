#!/usr/bin/env bash
# Benchmark: state instead of history (docs/BENCHMARKS.md). Runs the synthetic chain workload through
# the real runtime on 2 ranks and reports, from rank 0:
#  1. 500 stages x 64 items x 64 KiB results, each stage superseding the one before (a checkpoint after
#     every stage): checkpoint size, bytes written per checkpoint and peak RSS at stages 10, 100, 500;
#  2. one stage of 1,048,576 single-value items (a 1024 x 1024 table): peak RSS and bytes per checkpoint.
# Usage: tests/benchmarks/runtime_state.sh [path/to/pbrfit_runtime_probe]
set -euo pipefail
cd "$(dirname "$0")/../.."
PROBE=${1:-build/tests/pbrfit_runtime_probe}
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "pbrfit runtime state benchmark: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo
echo "500 stages x 64 items x 64 KiB (2 ranks, checkpoint after each stage)"
start=$(date +%s.%N)
mpirun "${FLAGS[@]}" -np 2 "$PROBE" "$OUT/s.h5" --stages 501 --items 64 --bytes 65536 --checkpoint-items 64 \
  --checkpoint-seconds 0 --report-stages 10 100 500 -v 2> "$OUT/s.log"
end=$(date +%s.%N)
echo "| stage | checkpoint file bytes | bytes written by the last checkpoint | block journal bytes | rank-0 peak RSS MiB |"
echo "|---|---|---|---|---|"
awk '/checkpoint written/ {for (i = 1; i <= NF; ++i) if ($i == "written,") last = $(i - 2)}
     /^report: stage/ {printf "| %s | %s | %s | %s | %.1f |\n", $3, $7, last, $9, $5 / 1024}' "$OUT/s.log"
awk -v a="$start" -v b="$end" 'BEGIN {printf "wall time %.1f s\n", b - a}'
echo
echo "1 stage x 1,048,576 single-value items (2 ranks, checkpoint every 0.5 s)"
start=$(date +%s.%N)
mpirun "${FLAGS[@]}" -np 2 "$PROBE" "$OUT/m.h5" --stages 1 --items 1048576 --bytes 16 --no-log \
  --checkpoint-seconds 0.5 --report-stages 0 -v 2> "$OUT/m.log"
end=$(date +%s.%N)
echo "| checkpoint | items done | bytes written | checkpoint file bytes | block journal bytes |"
echo "|---|---|---|---|---|"
awk '/checkpoint written/ {n++; for (i = 1; i <= NF; ++i) { if ($i == "written:") done = $(i + 1);
       if ($i == "written,") w = $(i - 2); if ($i == "checkpoint" && $(i + 2) == "bytes,") c = $(i + 1);
       if ($i == "journal") j = $(i + 1) }
     printf "| %d | %s | %s | %s | %s |\n", n, done, w, c, j}' "$OUT/m.log"
awk '/^report: stage 0/ {printf "rank-0 peak RSS at start %.1f MiB\n", $5 / 1024}
     /^report: end/ {printf "rank-0 peak RSS at the end %.1f MiB\n", $4 / 1024}' "$OUT/m.log"
echo "result file $(stat -c %s "$OUT/m.h5") bytes"
awk -v a="$start" -v b="$end" 'BEGIN {printf "wall time %.1f s\n", b - a}'
