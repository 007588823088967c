#!/usr/bin/env bash
# Benchmarks of the sweep kind (figures in docs/BENCHMARKS.md):
#  1. jobs/ltc-ggx.yaml (the 64 x 64 LTC table) on 1 rank x 1 thread and 2 ranks x 1 thread: wall time,
#     job time, the 2-rank speedup, and the share of texels whose judged errors (cubed and L2) are at most
#     the published table's;
#  2. warm starts against cold starts: the same sweep fitted hierarchically (3 levels, marching, global search
#     only where the warm start fits poorly) and flat (every cell from the default start, global search
#     always), comparing the objective evaluations spent and the final level's errors.
# Usage: tests/benchmarks/sweep_benchmark.sh [path/to/pbrfit]
set -euo pipefail
cd "$(dirname "$0")/../.."
PBRFIT=${1:-build/pbrfit}
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# Runs JOB on RANKS ranks x 1 thread into OUT/NAME.h5 and prints the whole command's wall seconds.
timed_run() {
  local job=$1 ranks=$2 name=$3 start end
  start=$(date +%s.%N)
  mpirun "${FLAGS[@]}" -np "$ranks" "$PBRFIT" run "$job" --output "$OUT/$name.h5" --threads 1 --force -q
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.2f", b - a}'
}

echo "pbrfit sweep benchmarks: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo
echo "## LTC table of GGX, 64 x 64 (jobs/ltc-ggx.yaml)"
one=$(timed_run jobs/ltc-ggx.yaml 1 ltc1)
two=$(timed_run jobs/ltc-ggx.yaml 2 ltc2)
/usr/bin/python3 - "$OUT/ltc1.h5" "$OUT/ltc2.h5" "$one" "$two" <<'PY'
import sys, h5py, numpy as np
one, two = (h5py.File(p, "r") for p in sys.argv[1:3])
wall1, wall2 = float(sys.argv[3]), float(sys.argv[4])
t1, t2 = one.attrs["elapsed_seconds"], two.attrs["elapsed_seconds"]
print("| ranks | wall s | job s |\n|---|---|---|")
print(f"| 1 | {wall1:.2f} | {t1:.2f} |\n| 2 | {wall2:.2f} | {t2:.2f} |")
print(f"| speedup | {wall1 / wall2:.2f}x | {t1 / t2:.2f}x |")
g = two["ltc/level0"]
for ours, theirs in (("error_cubed", "published_error_cubed"), ("error_l2", "published_error_l2")):
    a, b = g[ours][...], g[theirs][...]
    ok = np.isfinite(a) & np.isfinite(b)
    print(f"{ours}: ours <= published in {100 * np.mean(a[ok] <= b[ok]):.2f} % of {ok.sum()} texels "
          f"(within 1 %: {100 * np.mean(a[ok] <= 1.01 * b[ok]):.2f} %); median ratio {np.median(a[ok] / b[ok]):.3f}")
print(f"evaluations per texel: mean {g['evaluations'][...].mean():.0f}; 1 vs 2 ranks identical: "
      f"{all(np.array_equal(one['ltc/level0'][k][...], g[k][...], equal_nan=True) for k in ('m00', 'm02', 'ltc_1'))}")
PY

warm_cold() {
  local problem=$1 axes=$2 levels=$3 march=$4 extra=$5
  cat > "$OUT/warm.yaml" <<YAML
name: warm
kind: sweep
sweep:
  problem: $problem
  axes: $axes
  levels: $levels
  march: {axis: $march}
  fit: {global_search: when_poor, poor_ratio: 3, poor_absolute: $extra, warm_evaluations: 200, max_evaluations: 3000}
YAML
  cat > "$OUT/cold.yaml" <<YAML
name: cold
kind: sweep
sweep:
  problem: $problem
  axes: $axes
  fit: {global_search: always, max_evaluations: 3000}
YAML
  local warm cold
  warm=$(timed_run "$OUT/warm.yaml" 2 warm)
  cold=$(timed_run "$OUT/cold.yaml" 2 cold)
  /usr/bin/python3 - "$OUT/warm.h5" "$OUT/cold.h5" "$warm" "$cold" <<'PY'
import sys, h5py, numpy as np
warm, cold = (h5py.File(p, "r") for p in sys.argv[1:3])
def totals(f):
    evaluations, finals = 0, {}
    for model in f:
        levels = sorted(f[model], key=lambda l: int(l[5:]))
        for level in levels:
            evaluations += int(f[model][level]["evaluations"][...].sum())
        finals[model] = f[model][levels[-1]]["error"][...].ravel()
    return evaluations, finals
we, wf = totals(warm)
ce, cf = totals(cold)
print("| sweep | wall s | objective evaluations | " + " | ".join(f"{m} median / mean / max error" for m in wf) + " |")
print("|---|---|---|" + "---|" * len(wf))
for name, wall, e, f in (("hierarchical, warm-started", sys.argv[3], we, wf), ("flat, cold (DE everywhere)", sys.argv[4], ce, cf)):
    cells = " | ".join(f"{np.median(v):.4g} / {np.mean(v):.4g} / {np.max(v):.4g}" for v in f.values())
    print(f"| {name} | {float(wall):.1f} | {e} | {cells} |")
print(f"evaluations: cold / warm = {ce / we:.2f}x; final cells where warm <= cold * 1.01: " +
      ", ".join(f"{m} {100 * np.mean(wf[m] <= cf[m] * 1.01):.0f} %" for m in wf))
PY
}

echo
echo "## Warm starts against cold starts: sphere lights (4 models), 10 x 6 x 5 cells"
warm_cold sphere_light "[{name: roughness, from: 0.1, to: 1.0, count: 10}, {name: half_angle, from: 0.05, to: 0.8, count: 6}, {name: incidence, from: 0.0, to: 1.2, count: 5}]" 2 incidence 0.01
echo
echo "## Warm starts against cold starts: parallax distance study, 7 x 7 cells"
warm_cold parallax_distance "[{name: roughness, count: 7}, {name: distance, count: 7}]" 2 distance 0.01
