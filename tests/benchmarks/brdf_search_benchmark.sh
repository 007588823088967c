#!/usr/bin/env bash
# The genBRDF search benchmark of issue 10 (figures in docs/BENCHMARKS.md): a shipped search job (default
# jobs/merl-metals.yaml: 100 generations x 4 islands x 256 genomes on the 4 training metals, then the
# evaluation on the 4 + 16 metals) on 2 ranks x 1 thread; prints the wall time, the search's and the
# evaluation's share of it, and the paper's table: mean image L2 and 1 - SSIM of Cook-Torrance and of the
# found BRDFs on the training and held-out materials, with the reductions (paper, metals: 39 % and 58 %;
# dielectrics: 64 % and 71 %). Hours long: not part of `make bench`; `make bench-brdf` runs both classes.
# Usage: tests/benchmarks/brdf_search_benchmark.sh [path/to/pbrfit] [job.yaml] [result.h5]
set -euo pipefail
cd "$(dirname "$0")/../.."
PBRFIT=${1:-build/pbrfit}
JOB=${2:-jobs/merl-metals.yaml}
RESULT=${3:-results/bench-$(basename "$JOB" .yaml).h5}
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader --bind-to none)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)

echo "pbrfit genBRDF benchmark: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo "job: $JOB -> $RESULT (2 ranks x 1 thread; resumes an interrupted run of the same job)"
start=$(date +%s)
mpirun "${FLAGS[@]}" -np 2 "$PBRFIT" run "$JOB" --output "$RESULT" --threads 1 --resume -q
echo "wall time of this run: $(( $(date +%s) - start )) s"
"$PBRFIT" status "$RESULT" | sed -n 's/^\(elapsed\|progress\|headline\): */  \1: /p'
/usr/bin/python3 - "$RESULT" <<'PY'
import sys, h5py
f = h5py.File(sys.argv[1], "r")
b, e = f["brdf"], f["brdf/evaluation"]
print(f"metric: {b.attrs['metric_cells']} ({b.attrs['render']}); renders: {e.attrs['render']}")
print("| materials | model | size | mean image L2 | mean 1 - SSIM | L2 reduction | 1 - SSIM reduction |")
print("|---|---|---|---|---|---|---|")
sizes = {m["model"].decode(): m["cost"] for m in e["models"][...]}
for r in e["averages"][...]:
    model = r["model"].decode()
    print(f"| {r['set'].decode()} | {model} | {sizes[model]:.0f} | {r['image_l2']:.4f} | {r['one_minus_ssim']:.4f} | "
          f"{r['l2_reduction']:.1f} % | {r['ssim_reduction']:.1f} % |")
for m in e["models"][...]:
    print(f"{m['model'].decode()}: {m['expression'].decode()}")
PY
