#!/usr/bin/env bash
# Benchmarks of LTC tables for any BRDF (figures in docs/BENCHMARKS.md, section "LTC tables of any BRDF"):
#  1. each built-in family's 64 x 64 table (jobs/ltc-<family>.yaml, and jobs/ltc-ggx.yaml) on 2 ranks: wall
#     time, and the table's polygon-lighting errors where r >= 0.1 (the median over the table of the cells'
#     median, 95th-percentile and weighted errors);
#  2. GGX beside the published table on the same quad lights: the share of cells whose 95th-percentile
#     polygon error is at or below the published one, for the lobe fit (jobs/ltc-ggx.yaml) and the table fitted
#     to lights (jobs/ltc-ggx-lights.yaml), with the lobe errors beside;
#  3. Beckmann and Disney diffuse beside the LTC paper's fitting procedure on the same grid
#     (build/tests/bench_ltc_reference);
#  4. all nine in one job (jobs/ltc-families.yaml), the expression BRDF (jobs/ltc-retro.yaml) and the measured
#     material (jobs/ltc-merl.yaml).
# Usage: tests/benchmarks/ltc_families_benchmark.sh [build directory]   (about 20 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
PBRFIT=$BUILD/pbrfit
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

timed_run() {
  local job=$1 name=$2 start end
  start=$(date +%s.%N)
  mpirun "${FLAGS[@]}" -np 2 "$PBRFIT" run "$job" --output "$OUT/$name.h5" --threads 1 --force -q
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}'
}

polygon_summary() {  # FILE GROUP WALL
  /usr/bin/python3 - "$@" <<'PY'
import sys, h5py, numpy as np
path, group, wall = sys.argv[1], sys.argv[2], sys.argv[3]
g = h5py.File(path, "r")[group]
r = g["roughness"][...] if "roughness" in g else None
pick = (lambda a: a[:, r >= 0.1]) if r is not None else (lambda a: a)
med, p95, w = (pick(g[k][...]) for k in ("polygon_error_median", "polygon_error_p95", "polygon_error_weighted"))
print(f"| {group.split('/')[0]} | {wall} | {100 * np.nanmedian(med):.2f} % | {100 * np.nanmedian(p95):.1f} % | "
      f"{100 * np.nanmedian(w):.2f} % | {np.isnan(med).sum()} |")
PY
}

echo "pbrfit LTC benchmarks: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo
echo "## 1. Each family's table on 2 ranks (polygon errors where r >= 0.1: median over cells)"
echo "| family | wall s | median | p95 | weighted | cells without a light inside the lobe |"
echo "|---|---|---|---|---|---|"
wall=$(timed_run jobs/ltc-ggx.yaml ggx)
polygon_summary "$OUT/ggx.h5" ltc/level0 "$wall"
for family in beckmann cook-torrance ward disney-diffuse oren-nayar fabric-lambert charlie ashikhmin; do
  wall=$(timed_run "jobs/ltc-$family.yaml" "$family")
  polygon_summary "$OUT/$family.h5" "${family//-/_}/level0" "$wall"
done

echo
echo "## 2. GGX beside the published table, same 64 / 128 quad lights"
wall=$(timed_run jobs/ltc-ggx-lights.yaml lights)
/usr/bin/python3 - "$OUT/ggx.h5" "$OUT/lights.h5" "$wall" <<'PY'
import sys, h5py, numpy as np
print("| table | wall s | p95 <= published | median <= published | weighted <= published | cubed <= published | L2 <= published |")
print("|---|---|---|---|---|---|---|")
for path, label, wall in [(sys.argv[1], "lobe fit (jobs/ltc-ggx.yaml, 64 lights)", "see 1."),
                          (sys.argv[2], "fitted to lights (jobs/ltc-ggx-lights.yaml, 128 lights)", sys.argv[3])]:
    g = h5py.File(path, "r")["ltc/level0"]
    def share(ours, theirs):
        a, b = g[ours][...], g[theirs][...]
        return 100 * np.mean((a <= b) | (np.isnan(a) & np.isnan(b)))
    print(f"| {label} | {wall} | {share('polygon_error_p95', 'published_polygon_error_p95'):.1f} % | "
          f"{share('polygon_error_median', 'published_polygon_error_median'):.1f} % | "
          f"{share('polygon_error_weighted', 'published_polygon_error_weighted'):.1f} % | "
          f"{share('error_cubed', 'published_error_cubed'):.1f} % | {share('error_l2', 'published_error_l2'):.1f} % |")
PY

echo
echo "## 3. Beside the LTC paper's fitting procedure (one core)"
for family in beckmann disney_diffuse ggx; do
  file=$OUT/${family//_/-}.h5; group=$family/level0
  [[ $family == ggx ]] && group=ltc/level0
  /usr/bin/python3 - "$file" "$group" > "$OUT/$family.csv" <<'PY'
import sys, h5py
g = h5py.File(sys.argv[1], "r")[sys.argv[2]]
m = [g[k][...] for k in ("m00", "m11", "m02", "m20")]
for t in range(64):
    for a in range(64):
        print(t, a, *(f"{x[t, a]:.17g}" for x in m))
PY
  "$BUILD/tests/bench_ltc_reference" "$family" "$OUT/$family.csv"
done

echo
echo "## 4. One job for all nine, an expression BRDF, a measured material"
echo "| job | wall s |"
echo "|---|---|"
for job in ltc-families ltc-retro ltc-merl; do echo "| jobs/$job.yaml | $(timed_run "jobs/$job.yaml" "$job") |"; done
polygon_summary "$OUT/ltc-retro.h5" retro/level0 "-"
polygon_summary "$OUT/ltc-merl.h5" gold-metallic-paint/level0 "-"
