#!/usr/bin/env bash
# `pbrfit report` of a sweep (an LTC table of GGX on 2 levels) opens with what the fit achieved at the
# requested grid: each error's median, 95th percentile and worst cell, the comparison with the published
# table (share of cells where ours is at most theirs, ratio maps) and the fitted lobes beside GGX, whose
# formulas must agree with the fitter (the LTC of a cell close to its GGX lobe, the transposed matrix far
# from it). Vector outputs (matrices, textures) are listed but not drawn; a table whose cells all hold one
# value gets a line instead of a map. The check render is drawn once, in its own section, with the mean
# errors of the file's images on the page.
source "$(dirname "$0")/lib/common.bash"
source "$PBRFIT_SOURCE_DIR/tests/mpi/lib/report_checks.bash"

report_of_test_job small-sweep.yaml
expect_tables_mentioned result.h5 result.report
expect_valid_images result.report 10
page=result.report/index.html

note "the quality section comes first, for the last level only"
grep -q 'id="quality"' "$page" || fail "no 'How good the fit is' section"
quality=$(sed -n '/id="quality"/,/id="group-1"/p' "$page")
for wanted in '<td>error_l2</td>' '<td>polygon_error_median</td>' '95th percentile' 'ours &lt;= theirs' \
  'alt="error_l2 over published_error_l2"' 'alt="/ltc/level1 lobes"'; do
  grep -qF -- "$wanted" <<<"$quality" || fail "the quality section lacks $wanted"
done
if grep -qF '/ltc/level0' <<<"$quality"; then fail "the quality section shows the coarse level"; fi

note "vector outputs listed, not drawn; one-value tables get a line"
grep -qF '/ltc/level1/ltc_1: 4 values per cell' "$page" || fail "no note for the ltc_1 texture"
if grep -qF 'alt="/ltc/level1/ltc_1"' "$page"; then fail "ltc_1 is drawn as slices"; fi
"$H5PY_PYTHON" - result.h5 "$page" <<'PY' || fail "a one-value table is drawn, or its line is missing"
import sys, h5py, numpy as np
page = open(sys.argv[2]).read()
with h5py.File(sys.argv[1], "r") as f:
    for name, table in f["ltc/level1"].items():
        if h5py.h5ds.is_scale(table.id) or table.dtype.names or table.dtype.kind not in "fiu":
            continue
        finite = np.asarray(table[()], dtype=float)
        finite = finite[np.isfinite(finite)]
        constant = finite.size > 1 and finite.min() == finite.max() and table.attrs.get("role", b"") not in (b"start", "start")
        noted = f"/ltc/level1/{name}: every computed cell is" in page
        drawn = f'alt="/ltc/level1/{name}"' in page
        if constant != noted or (constant and drawn):
            sys.exit(f"{name}: constant {constant}, line {noted}, drawn {drawn}")
PY

note "the lobe figure's formulas agree with the fitter"
PYTHONPATH=$(dirname "$PBRFIT")/share/pbrfit/report "$H5PY_PYTHON" - result.h5 <<'PY' || fail "the report's LTC lobe disagrees with GGX"
import sys, h5py, numpy as np
from pbrfit_report.kinds.sweep.lobe_figure import ggx_target, ltc_lobe
with h5py.File(sys.argv[1], "r") as f:
    g = f["ltc/level1"]
    matrix, norm = g["matrix"][()], g["norm"][()]
    x, r = g["sqrt_one_minus_cos"][()], g["roughness"][()]
theta = np.linspace(-np.pi / 2, np.pi / 2, 2001)
for vi, ri in ((2, 4), (4, 6), (6, 3)):
    cos_view = np.cos(min(np.arccos(1 - x[vi] ** 2), 1.57))
    target = ggx_target(r[ri] ** 2, cos_view, theta)
    m = matrix[vi, ri].reshape(3, 3)
    ours = np.abs(ltc_lobe(m, norm[vi, ri], theta) - target).sum() / target.sum()
    transposed = np.abs(ltc_lobe(m.T, norm[vi, ri], theta) - target).sum() / target.sum()
    print(f"cell ({vi}, {ri}): relative L1 {ours:.3f}, transposed {transposed:.3f}")
    if not (ours < 0.15 and transposed > 2 * ours):
        sys.exit(1)
PY
note "the check render: its own section with the file's errors; not drawn again as slices"
grep -q 'id="check-render"' "$page" || fail "no 'How the table lights a plane' section"
grep -qF 'alt="/ltc/render images"' "$page" || fail "the check render's images are missing"
if grep -qF 'alt="/ltc/render/ltc"' "$page"; then fail "the render is drawn as slices"; fi
"$H5PY_PYTHON" - result.h5 "$page" <<'PY' || fail "the check render's errors on the page disagree with the file"
import sys, h5py, numpy as np
page = open(sys.argv[2]).read()
section = page[page.index('id="check-render"'):]
with h5py.File(sys.argv[1], "r") as f:
    g = f["ltc/render"]
    ours, truth, theirs, r = g["ltc"][()], g["reference"][()], g["published"][()], g["roughness"][()]
for i in range(len(r)):
    both = np.isfinite(ours[i]) & np.isfinite(truth[i])
    assert both.sum() > 0.9 * both.size, "most pixels are lit"
    mean = np.abs(ours[i] - truth[i])[both].mean() / truth[i][both].mean()
    row = f"<td>{r[i]:.3g}</td><td class=\"number\">{100 * mean:.2f} %</td>"
    print(row)
    if row not in section or not (0.0 < mean < 0.2):
        sys.exit(f"image {i}: {row} not on the page, or an implausible error")
PY
echo "PASS"
