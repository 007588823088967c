#!/usr/bin/env bash
# Benchmark: how fast rank 0 hands out work, the input of the cluster model (docs/BENCHMARKS.md, "Scale
# past one machine"). Runs the synthetic chain workload through the real runtime with items that compute
# nothing, so rank 0 is the bottleneck, at 2 to 16 ranks (one compute thread each, oversubscribed and
# unbound on this machine), and prints from rank 0's verbose log:
#  1. one stage of ITEMS empty items: items per second, rank 0's main-thread processor time per item, the
#     work and result message sizes;
#  2. STAGES stages of 2 empty items each: the cost of a stage boundary (context down the relay tree, every
#     result back, the next stage's context built).
# Usage: tests/benchmarks/coordinator_rate.sh [path/to/pbrfit_runtime_probe]   (RANKS="2 4 8 16" ITEMS=200000 STAGES=20000)
set -euo pipefail
cd "$(dirname "$0")/../.."
PROBE=${1:-build/tests/pbrfit_runtime_probe}
RANKS=${RANKS:-"2 4 8 16"}
ITEMS=${ITEMS:-200000}
STAGES=${STAGES:-20000}
FLAGS=(--oversubscribe --bind-to none --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

echo "pbrfit coordinator rate: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo
echo "| ranks | empty items per second | rank 0 main thread, us per item | work messages: bytes, items (mean) | result messages: bytes, items (mean) | stage boundary, ms (${STAGES} stages of 2 items) |"
echo "|---|---|---|---|---|---|"
for ranks in $RANKS; do
  rm -f "$OUT"/*
  mpirun "${FLAGS[@]}" -np "$ranks" "$PROBE" "$OUT/r.h5" --stages 1 --items "$ITEMS" --bytes 16 --no-log --threads 1 \
    --checkpoint-seconds 60 -v 2> "$OUT/items.log"
  rm -f "$OUT"/*.h5*
  mpirun "${FLAGS[@]}" -np "$ranks" "$PROBE" "$OUT/s.h5" --stages "$STAGES" --items 2 --bytes 16 --no-log --threads 1 \
    --checkpoint-seconds 60 -v 2> "$OUT/stages.log"
  # rank 0's log stamps: from the end of the first stage to the end of the last, over the stages between
  boundary=$(awk '/ r0\] debug: stage [0-9]+: / {t = $0; sub(/^\[ */, "", t); sub(/s r0\].*/, "", t); if (!n++) first = t; last = t}
                  END {printf "%.3f", (n > 1 ? 1e3 * (last - first) / (n - 1) : 0)}' "$OUT/stages.log")
  # "stage 1: N items in W s; ..." and "coordinator: N items (R from other ranks; W work messages of B bytes and
  # I items on average, M result messages of B' bytes and I' items), main thread T s of processor time, U us per item"
  awk -v r="$ranks" -v boundary="$boundary" '
    /\] debug: stage 1: / {for (i = 1; i <= NF; ++i) if ($i == "items" && $(i + 1) == "in") {n = $(i - 1); w = $(i + 2)}}
    /\] debug: coordinator: / {for (i = 1; i <= NF; ++i) {
        if ($i == "work" && $(i + 1) == "messages") {wb = $(i + 3); wi = $(i + 6)}
        if ($i == "result" && $(i + 1) == "messages") {rb = $(i + 3); ri = $(i + 6)}
        if ($i == "us" && $(i + 1) == "per") us = $(i - 1)}}
    END {printf "| %d | %.0f | %.2f | %s B, %s | %s B, %s | %s |\n", r, n / w, us, wb, wi, rb, ri, boundary}' "$OUT/items.log"
done
