#!/usr/bin/env bash
# LTC tables of any BRDF (problem `ltc`) are bitwise identical over ranks and threads (1x1, 1x2, 2x1, 2x2) and
# after a SIGTERM and a SIGKILL with resumes: two built-in families in one job, a BRDF expression with an axis
# of its own, a measured material (view axis only), and a GGX table refined on lights. The GGX model of `ltc`
# computes exactly the numbers of problem `ltc_ggx`, and every table carries its polygon-lighting errors.
source "$(dirname "$0")/lib/common.bash"
source "$(dirname "$0")/lib/layouts.bash"
source "$(dirname "$0")/lib/report_checks.bash"

MPI_FLAGS+=(--bind-to none)  # 1 rank x 2 threads needs both cores

cat > families.yaml <<'YAML'
name: families
kind: sweep
output: result.h5
sweep:
  problem: ltc
  models: [ggx, charlie, oren_nayar]
  axes: [{name: sqrt_one_minus_cos, count: 5}, {name: roughness, from: 0.2, to: 1, count: 5}]
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never, warm_evaluations: 120}
  objective: {samples: 128, judge_samples: 256, polygon_quads: 16}
YAML
GROUPS_TO_COMPARE=(/ggx /charlie /oren_nayar)
compare_layouts families.yaml

note "the GGX model of problem ltc is problem ltc_ggx, number for number"
sed -e 's/problem: ltc$/problem: ltc_ggx/' -e '/models:/d' families.yaml > ggx.yaml
run_ranks 2 run ggx.yaml --output ggx.h5 -q
expect_status 0
/usr/bin/python3 - <<'PY' || fail "problem ltc's GGX table differs from problem ltc_ggx's"
import h5py, numpy as np
a, b = h5py.File("families-ref.h5", "r")["ggx/level0"], h5py.File("ggx.h5", "r")["ltc/level0"]
for name in ["m00", "m11", "m02", "m20", "error", "error_l2", "norm", "ltc_1", "ltc_2", "polygon_error_median",
             "polygon_error_p95", "polygon_error_weighted", "polygon_lights", "published_polygon_error_p95"]:
    assert a[name][...].tobytes() == b[name][...].tobytes(), name
f = h5py.File("families-ref.h5", "r")
for model in ["ggx", "charlie", "oren_nayar"]:
    g = f[model + "/level0"]
    assert np.isfinite(g["polygon_error_weighted"][...]).all(), model
    assert (g["polygon_lights"][...] <= 16).all()
    assert g["ltc_1"].shape == (5, 5, 4) and g["ltc_1"].dtype == np.float32
    assert (g["m11"][0] == g["m00"][0]).all(), "normal view: m11 follows m00"
    assert np.isfinite(g["norm"][...]).all() and (g["norm"][...] > 0).all()
assert "published_polygon_error_p95" in f["ggx/level0"] and "published_polygon_error_p95" not in f["charlie/level0"]
PY

cat > retro.yaml <<'YAML'
name: retro
kind: sweep
output: result.h5
checkpoint: {interval_seconds: 0.5, interval_items: 4}
sweep:
  problem: ltc
  brdf:
    name: retro
    expression: |
      e = 2 / max(roughness * roughness, 1e-4) - 1
      (1 - retro) / pi + retro * (e + 2) / (2 * pi) * pow(max(lv, 0), e)
  axes:
    - {name: retro, from: 0.2, to: 0.6, count: 2}
    - {name: sqrt_one_minus_cos, count: 6}
    - {name: roughness, from: 0.3, to: 1, count: 5}
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never, warm_evaluations: 120}
  objective: {samples: 128, judge_samples: 256, polygon_quads: 16}
YAML
GROUPS_TO_COMPARE=(/retro)
compare_layouts retro.yaml
/usr/bin/python3 -c "
import h5py
g = h5py.File('retro-ref.h5', 'r')['retro/level0']
assert g['ltc_1'].shape == (2, 6, 5, 4), g['ltc_1'].shape
assert list(g['retro'][...]) == [0.2, 0.6]
" || fail "the expression's own axis is not the table's outer axis"

note "the expression table, stopped by SIGTERM and SIGKILL and resumed, ends identical"
cp retro.yaml job.yaml
interrupt_after 12 TERM 2 run job.yaml
[[ -f result.h5.checkpoint ]] || fail "no checkpoint after SIGTERM"
interrupt_after $(($(items_done result.h5) + 12)) KILL 1 run job.yaml --resume
run_ranks 2 run job.yaml --resume -q
expect_status 0
expect_identical retro-ref.h5 result.h5 /retro

cat > merl.yaml <<'YAML'
name: merl
kind: sweep
output: result.h5
sweep:
  problem: ltc
  brdf: {material: blue-acrylic}
  axes: [{name: sqrt_one_minus_cos, count: 6}]
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never, warm_evaluations: 120}
  objective: {samples: 128, judge_samples: 256, polygon_quads: 16}
YAML
GROUPS_TO_COMPARE=(/blue-acrylic)
compare_layouts merl.yaml
/usr/bin/python3 -c "
import h5py, numpy as np
g = h5py.File('merl-ref.h5', 'r')['blue-acrylic/level0']
rgb, norm = g['norm_rgb'][...], g['norm'][...]
assert rgb.shape == (6, 3) and g['ltc_1'].shape == (6, 4)
assert np.allclose(rgb @ [0.2126, 0.7152, 0.0722], norm, rtol=2e-3), (rgb @ [0.2126, 0.7152, 0.0722], norm)
assert rgb[0, 2] > rgb[0, 0], 'blue acrylic reflects more blue than red'
" || fail "the measured table's RGB albedo does not match its luminance norm"

cat > lights.yaml <<'YAML'
name: lights
kind: sweep
output: result.h5
sweep:
  problem: ltc_ggx
  axes: [{name: sqrt_one_minus_cos, count: 4}, {name: roughness, from: 0.3, to: 1, count: 4}]
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never, warm_evaluations: 120}
  objective: {samples: 128, judge_samples: 256, polygon_quads: 16, fit_to: lights, training_quads: 24}
YAML
GROUPS_TO_COMPARE=(/ltc)
compare_layouts lights.yaml
/usr/bin/python3 -c "
import h5py
text = h5py.File('lights-ref.h5', 'r')['ltc/level0'].attrs['fit_to']
text = text.decode() if isinstance(text, bytes) else text
assert 'refined on 24 training quad lights' in text, text
" || fail "the table fitted to lights does not name the 24 training lights it was refined on"

note "report of the families' tables"
"$PBRFIT" report families-ref.h5 --out families-report >/dev/null
expect_valid_images families-report 6
grep -q "polygon_error_median" families-report/index.html || fail "the report does not show the polygon-lighting errors"
echo "PASS"
