#!/usr/bin/env bash
# Benchmarks of eBRDF prefiltering (figures in docs/BENCHMARKS.md, issue 11):
#  1. jobs/ebrdf-{stone,glitter,scratches}.yaml (128 x 128, 8 x 16 specular and 2 x 4 diffuse views, 128
#     samples) on 2 ranks x 1 thread: wall time, peak resident memory of the largest process, the tables'
#     size and the mean fit error;
#  2. their renders (jobs/ebrdf-*-renders.yaml): MSE of naive and ours against the ground truth per scene
#     and distance, and whether ours is lower wherever a pixel covers at least 2 texels;
#  3. bench_ebrdf_fit: the default fitter against the thesis' SGD baseline on sampled fits of every level;
#  4. scale: a 512 x 512 map on 2 ranks for SCALE_SECONDS (default 300), stopped by SIGTERM and resumed for
#     as long again: peak memory, checkpoint and journal sizes, and that the resumed run only appends to the
#     journal (tiles already written are not rewritten); SCALE_SECONDS=0 leaves it out.
# Usage: tests/benchmarks/ebrdf_benchmark.sh [build directory = build]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
PBRFIT=$BUILD/pbrfit
FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader --bind-to none)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
SCALE_SECONDS=${SCALE_SECONDS:-300}

# Runs pbrfit ARGS on 2 ranks under GNU time; prints "WALL_SECONDS PEAK_KIB".
timed_run() {
  /usr/bin/time -f "%e %M" -o "$OUT/time.txt" mpirun "${FLAGS[@]}" -np 2 "$PBRFIT" "$@" -q
  tail -1 "$OUT/time.txt"
}

echo "pbrfit eBRDF benchmarks: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo
echo "## 1. Prefiltering 128 x 128 maps on 2 ranks"
echo "| map | wall s | peak RSS MiB | matrices MB | all tables MB | fits | mean error |"
echo "|---|---|---|---|---|---|---|"
for map in stone glitter scratches; do
  read -r wall peak < <(timed_run run "jobs/ebrdf-$map.yaml" --output "$OUT/$map.h5" --threads 1 --force)
  /usr/bin/python3 - "$OUT/$map.h5" "$map" "$wall" "$peak" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
matrices = tables = fits = 0
errors = []
def visit(name, node):
    global matrices, tables, fits
    if isinstance(node, h5py.Dataset) and name.split("/")[-1] in ("matrix", "amplitude", "error"):
        tables += node.size * 4
        if name.endswith("matrix"): matrices += node.size * 4
        if name.endswith("error"): fits += node.size; errors.append(node[...].ravel())
f.visititems(visit)
print(f"| {sys.argv[2]} | {float(sys.argv[3]):.0f} | {int(sys.argv[4]) / 1024:.0f} | {matrices / 1e6:.1f} | "
      f"{tables / 1e6:.1f} | {fits} | {np.concatenate(errors).mean():.4f} |")
PY
done

echo
echo "## 2. Renders against the ground truth (128 x 128 pixels)"
echo "| map | scene | distance | texels per pixel | naive MSE | ours MSE | ours lower |"
echo "|---|---|---|---|---|---|---|"
for map in stone glitter scratches; do
  sed "s|tables: results/ebrdf-$map.h5|tables: $OUT/$map.h5|" "jobs/ebrdf-$map-renders.yaml" >"$OUT/render-$map.yaml"
  timed_run run "$OUT/render-$map.yaml" --output "$OUT/render-$map.h5" --force >"$OUT/render-time-$map.txt"
  /usr/bin/python3 - "$OUT/render-$map.h5" "$map" <<'PY'
import sys, h5py
g = h5py.File(sys.argv[1], "r")["ebrdf_render"]
scenes = g.attrs["scenes"].split(", ")
mse, texels, distances = g["mse"][...], g["texels_per_pixel"][...], g["distance"][...]
for s, scene in enumerate(scenes):
    for d, h in enumerate(distances):
        lower = "yes" if mse[s, d, 1] < mse[s, d, 0] else "no"
        print(f"| {sys.argv[2]} | {scene} | {h:g} | {texels[s, d]:.2f} | {mse[s, d, 0]:.5f} | {mse[s, d, 1]:.5f} | {lower} |")
PY
  echo "| $map | render wall s: $(cut -d' ' -f1 "$OUT/render-time-$map.txt") | | | | | |"
done

echo
echo "## 3. Fits against the SGD baseline ($BUILD/tests/bench_ebrdf_fit)"
"$BUILD/tests/bench_ebrdf_fit" 64

[[ $SCALE_SECONDS -gt 0 ]] || exit 0
echo
echo "## 4. Scale: a 512 x 512 stone map, ${SCALE_SECONDS} s, stopped, resumed for as long"
sed -e 's/size: 128/size: 512/' -e "s|output: results/ebrdf-stone.h5|output: $OUT/big.h5|" jobs/ebrdf-stone.yaml >"$OUT/big.yaml"
run_for() {  # runs the big job (ARGS) for SCALE_SECONDS, then SIGTERM; prints "PEAK_KIB"
  /usr/bin/time -f "%M" -o "$OUT/time.txt" setsid mpirun "${FLAGS[@]}" -np 2 "$PBRFIT" run "$OUT/big.yaml" --threads 1 -q "$@" &
  local pid=$!
  sleep "$SCALE_SECONDS"
  pkill -TERM -f "^$PBRFIT run $OUT/big.yaml" || true
  wait "$pid" || true
  tail -1 "$OUT/time.txt"  # GNU time writes "Command exited with non-zero status 75" first
}
peak1=$(run_for --force)
journal1=$(stat -c %s "$OUT/big.h5.journal"); checkpoint1=$(stat -c %s "$OUT/big.h5.checkpoint")
cp "$OUT/big.h5.journal" "$OUT/journal-before"
done1=$("$PBRFIT" status "$OUT/big.h5" | sed -n 's/^progress: *//p')
peak2=$(run_for --resume)
journal2=$(stat -c %s "$OUT/big.h5.journal"); checkpoint2=$(stat -c %s "$OUT/big.h5.checkpoint")
done2=$("$PBRFIT" status "$OUT/big.h5" | sed -n 's/^progress: *//p')
if cmp -s -n "$journal1" "$OUT/journal-before" "$OUT/big.h5.journal"; then appended=yes; else appended=no; fi
echo "| run | progress | peak RSS MiB | journal MB | checkpoint KB |"
echo "|---|---|---|---|---|"
echo "| first | $done1 | $((peak1 / 1024)) | $((journal1 / 1000000)) | $((checkpoint1 / 1000)) |"
echo "| resumed | $done2 | $((peak2 / 1024)) | $((journal2 / 1000000)) | $((checkpoint2 / 1000)) |"
echo "resumed run kept the first run's journal bytes unchanged (append only): $appended"
/usr/bin/python3 - <<'PY'
levels = sum((512 >> l) ** 2 for l in range(1, 10))
print(f"512 x 512 tables: {levels * 136 * 9 * 4 / 1e6:.0f} MB of matrices, {levels * 136 * 11 * 4 / 1e6:.0f} MB in all")
PY
