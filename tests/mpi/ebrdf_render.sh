#!/usr/bin/env bash
# The reference renders of prefiltered tables are bitwise identical on 1 and 2 ranks (and threads), and after
# a SIGTERM and a SIGKILL with resumes; every scene view has
# its three renders, MSEs, SSIMs, energies (plane and highlight) and texels per pixel; the report shows the renders and the error plot beside the
# ebrdf report's levels; tables that are not a finished ebrdf result are refused naming the file.
source "$(dirname "$0")/lib/common.bash"
MPI_FLAGS+=(--bind-to none)

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-ebrdf.yaml" job.yaml
run_ranks 2 run job.yaml --output tables.h5 -q
expect_status 0
cat >render.yaml <<'YAML'
name: small-render
kind: ebrdf_render
output: render.h5
ebrdf_render:
  tables: tables.h5
  distances: [1, 4, 16]
  resolution: 24
YAML
note "1 rank, then 2 ranks"
run_ranks 1 run render.yaml --output r1.h5 -q
expect_status 0
run_ranks 2 run render.yaml --output r2.h5 --threads 2 -q
expect_status 0
expect_identical r1.h5 r2.h5 /ebrdf_render

note "filtering: matrices changes ours alone"
sed 's|^  resolution: 24|  resolution: 24\n  filtering: matrices|' render.yaml >matrices.yaml
run_ranks 1 run matrices.yaml --output matrices.h5 -q
expect_status 0
"$H5PY_PYTHON" - <<'PY' || fail "filtering: matrices changed more than ours, or nothing"
import h5py, numpy as np
a = h5py.File("r2.h5", "r")["ebrdf_render/renders"][...]
b = h5py.File("matrices.h5", "r")["ebrdf_render/renders"][...]
assert np.array_equal(a[:, :, :2], b[:, :, :2]), "the ground truth or naive changed"
assert not np.array_equal(a[:, :, 2], b[:, :, 2]), "ours is the same"
PY

note "SIGTERM, resume, SIGKILL, resume: the same renders"
sed -e 's|distances: \[1, 4, 16\]|distances: [1, 2, 4, 8, 16, 32]|' -e 's|resolution: 24|resolution: 96|' \
  -e 's|^output: render.h5|output: result.h5\ncheckpoint: {interval_seconds: 0.2, interval_items: 1}|' render.yaml >long.yaml
run_ranks 2 run long.yaml --output long-ref.h5 -q
expect_status 0
interrupt_after 2 TERM 2 run long.yaml
interrupt_after $(($(items_done result.h5) + 2)) KILL 1 run long.yaml --resume
run_ranks 2 run long.yaml --resume -q
expect_status 0
expect_identical long-ref.h5 result.h5 /ebrdf_render

"$H5PY_PYTHON" - <<'PY' || fail "the render tables are wrong"
import h5py, numpy as np
g = h5py.File("r2.h5", "r")["ebrdf_render"]
r, mse, texels = g["renders"][...], g["mse"][...], g["texels_per_pixel"][...]
assert r.shape == (2, 3, 3, 24, 24, 3) and r.dtype == np.uint8, r.shape
assert mse.shape == (2, 3, 2) and np.all(np.isfinite(mse)) and np.all(mse >= 0)
assert np.all(np.diff(texels, axis=1) > 0), texels          # further away: more texels per pixel
assert r[:, :, 0].max() > 100, "the ground truth is black"
assert np.any(r[:, 2, 0] != r[:, 2, 1]), "far away the naive render equals the ground truth"
assert g.attrs["scenes"] == "top, grazing" and g.attrs["tables"] == "tables.h5"
ssim, energy, highlight = g["ssim"][...], g["energy"][...], g["highlight_energy"][...]
assert ssim.shape == (2, 3, 2) and np.all(ssim > 0.5) and np.all(ssim <= 1.0), ssim
assert energy.shape == highlight.shape == (2, 3, 3) and np.all(energy > 0), energy
assert np.all(highlight > 2 * energy), "the highlight is not brighter than the plane"
# The energies are the renders' own: the ground truth's display image, linearized, has about its energy.
linear = (r[:, :, 0, :, :, 0] / 255.0) ** 2.2
plane = r[:, :, 0, :, :, 0] > 0
for s in range(2):
    for d in range(3):
        mean = linear[s, d][plane[s, d]].mean()
        assert abs(mean - energy[s, d, 0]) < 0.02 + 0.05 * energy[s, d, 0], (s, d, mean, energy[s, d, 0])
PY

note "reports of the tables and of the renders"
"$PBRFIT" report tables.h5 --out tables-page >out.txt 2>err.txt || { cat err.txt; fail "the ebrdf report failed"; }
grep -q "eBRDF prefiltering" tables-page/index.html || fail "the ebrdf report lacks its section"
grep -q "MB of float32" tables-page/index.html || fail "the ebrdf report lacks the tables' size"
"$PBRFIT" report r2.h5 --out render-page >out.txt 2>err.txt || { cat err.txt; fail "the render report failed"; }
[[ ! -s err.txt ]] || { cat err.txt; fail "report wrote to stderr"; }
grep -q "ebrdf_render/renders, scene grazing" render-page/index.html || fail "the report lacks the renders"
grep -q "ebrdf_render/mse over texels per pixel" render-page/index.html || fail "the report lacks the MSE plot"
grep -q "ebrdf_render/energy and highlight_energy" render-page/index.html || fail "the report lacks the energy plot"
grep -q "ours energy / truth" render-page/index.html || fail "the report lacks the energy table"
! grep -q "cannot be shown" render-page/index.html tables-page/index.html || fail "a report part failed"

note "tables that are not a finished ebrdf result are refused"
sed -i 's|tables: tables.h5|tables: r1.h5|' render.yaml
run_ranks 1 run render.yaml --output bad.h5 -q 2>err.txt
expect_status 2
grep -q "render.yaml:5:11: error: 'tables' names r1.h5: is a result of kind 'ebrdf_render', not of an ebrdf job" err.txt ||
  { cat err.txt; fail "wrong message for a result of another kind"; }
echo "PASS"
