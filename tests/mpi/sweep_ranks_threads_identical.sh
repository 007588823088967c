#!/usr/bin/env bash
# Sweeps are bitwise identical over ranks and threads (1x1, 1x2, 2x1, 2x2): a marching, hierarchical LTC
# sweep, a multi-model sphere-light sweep whose cells all run the global search, and the Disney diffuse table.
source "$(dirname "$0")/lib/common.bash"
source "$(dirname "$0")/lib/layouts.bash"
source "$(dirname "$0")/lib/report_checks.bash"

MPI_FLAGS+=(--bind-to none)  # 1 rank x 2 threads needs both cores

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-sweep.yaml" ltc.yaml
GROUPS_TO_COMPARE=(/ltc/level0 /ltc/level1 /ltc/render)
compare_layouts ltc.yaml
"$PBRFIT" status ltc-ref.h5 | grep -q "^progress: *130 of 130 work items" ||
  fail "the sweep did not fit 25 + 81 cells and render 3 images of 8 bands"
/usr/bin/python3 - <<'PY' || fail "the LTC sweep's fits or warm starts are wrong"
import h5py, numpy as np
f = h5py.File("ltc-ref.h5", "r")
fine = f["ltc/level1"]
start = fine["start"][...]
assert np.isin(start[0], [0, 3]).all(), "the first marching step of level 1 starts from its parents (or DE)"
assert np.isin(start[1:], [0, 2, 3]).all() and (start[1:] == 2).any(), "later steps start from a neighbour"
assert np.isin(f["ltc/level0"]["start"][0], [0, 1]).all(), "level 0 starts cold at normal view"
assert np.isfinite(fine["error"][...]).all()
assert fine["ltc_1"].dtype == np.float32 and fine["ltc_1"].shape == (9, 9, 4)
assert (fine["m11"][0] == fine["m00"][0]).all(), "normal view: m11 follows m00"
assert fine["m00"].attrs["role"] == b"parameter" or fine["m00"].attrs["role"] == "parameter"
PY

note "report of the LTC sweep: maps of both levels, histograms, the published table beside ours"
"$PBRFIT" report ltc-ref.h5 --out ltc-report >/dev/null
expect_valid_images ltc-report 20
expect_tables_mentioned ltc-ref.h5 ltc-report
grep -q "Heitz et al. 2016 (published table)" ltc-report/index.html || fail "the report does not compare with the published table"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-sphere-light.yaml" light.yaml
GROUPS_TO_COMPARE=(/roughness_modification /capped_roughness /representative_point /smoothed_representative_point)
compare_layouts light.yaml

/usr/bin/python3 -c "
import h5py, numpy as np
f = h5py.File('light-ref.h5', 'r')
fine, mean = f['capped_roughness/level0'], f['capped_roughness/level0_mean_over_incidence']
assert mean['cap'].shape == (2, 2)
assert np.allclose(mean['cap'][...], fine['cap'][...].mean(axis=2)), 'projection is the mean over incidence'
assert np.allclose(mean['error_std'][...], fine['error'][...].std(axis=2, ddof=1))
" || fail "the projection over incidence is not the mean of the fits"

for problem in multi_lobe_sg parallax_distance parallax_angle; do
  cat > "$problem.yaml" <<YAML
name: $problem
kind: sweep
output: result.h5
sweep:
  problem: $problem
  axes: [{name: roughness, from: 0.4, to: 0.8, count: 2}]
  fit: {global_search: always, max_evaluations: 120, warm_evaluations: 30}
YAML
done
sed -i 's/  axes: \[{name: roughness, from: 0.4, to: 0.8, count: 2}\]/  axes: [{name: roughness, from: 0.4, to: 0.8, count: 2}, {name: view_angle, count: 2}]\n  objective: {samples: 256, lobes: 3}/' multi_lobe_sg.yaml
sed -i 's/  axes: \[{name: roughness, from: 0.4, to: 0.8, count: 2}\]/  axes: [{name: roughness, from: 0.4, to: 0.8, count: 2}, {name: distance, count: 2}]\n  objective: {tolerance: 1.0e-4}/' parallax_distance.yaml
sed -i 's/  axes: \[{name: roughness, from: 0.4, to: 0.8, count: 2}\]/  axes: [{name: roughness, from: 0.4, to: 0.8, count: 2}, {name: angle, count: 2}]\n  objective: {tolerance: 1.0e-4}/' parallax_angle.yaml
GROUPS_TO_COMPARE=(/free_amplitude /normalized)
compare_layouts multi_lobe_sg.yaml
GROUPS_TO_COMPARE=(/perpendicular_lobe)
compare_layouts parallax_distance.yaml
compare_layouts parallax_angle.yaml

cp "$PBRFIT_SOURCE_DIR/jobs/schlick-fresnel.yaml" fresnel.yaml
GROUPS_TO_COMPARE=(/model)
compare_layouts fresnel.yaml

cat > lobe.yaml <<'YAML'
name: lobe
kind: sweep
output: result.h5
sweep:
  problem: expression
  axes: [{name: n, from: 2, to: 40, count: 4}]
  expression: {domain: hemisphere, target: "(n + 2) / 6.2831853 * pow(wz, n)", model: "a * exp(b * (wz - 1))"}
  parameters: [{name: a, lower: 0.01, upper: 100, transform: log}, {name: b, lower: 0.1, upper: 200, transform: log}]
  fit: {global_search: always, max_evaluations: 800}
  objective: {norm: Linf, integrator: qmc, samples: 512}
YAML
GROUPS_TO_COMPARE=(/model)
compare_layouts lobe.yaml
/usr/bin/python3 -c "
import h5py, numpy as np
g = h5py.File('lobe-ref.h5', 'r')['model/level0']
assert np.all(np.isfinite(g['error'][...])) and np.all(g['relative_error'][...] < 0.5), g['relative_error'][...]
" || fail "the QMC expression sweep did not fit the Phong lobes with Gaussians"

cat > disney.yaml <<'YAML'
name: disney
kind: lut
output: result.h5
lut: {function: disney_diffuse, resolution: [8, 6], tolerance: 1.0e-6}
YAML
GROUPS_TO_COMPARE=(/disney_diffuse)
compare_layouts disney.yaml
echo "PASS"
