#!/usr/bin/env bash
# `pbrfit report` of symreg results: Nguyen-5 (tests/jobs/small-symreg.yaml, seed 2: its front has a
# recurring sub-expression) with an anchor whose name holds HTML special characters, and a regression of
# two tables of a pbrfit result (two inputs on a grid, two outputs). Every image is a valid PNG (a front,
# the knee typeset, a residual and a log figure per output), the front table lists every member's expression
# with its constants rounded (the printed RMSE unchanged) and its exact text a click away, the
# anchor appears beside our best member at equal or lower cost (checked against the file), the recurring
# sub-expressions are listed, every text is escaped; a job still running shows no front yet, and its log.
source "$(dirname "$0")/lib/common.bash"
source "$PBRFIT_SOURCE_DIR/tests/mpi/lib/report_checks.bash"

# Runs `pbrfit report RESULT --out DIR` and expects success, silently.
report_ok() {
  set +e
  "$PBRFIT" report "$1" --out "$2" >out.txt 2>err.txt; STATUS=$?
  set -e
  expect_status 0 "$(cat err.txt)"
  [[ ! -s err.txt ]] || { cat err.txt; fail "report wrote to stderr"; }
}

# Exit 0 when every text the Python snippet prints (a line each) is in the page, escaped, as a whole cell
# or as the exact text behind a cell's readable form.
cells_in_page() {
  local page=$1 snippet=$2
  "$H5PY_PYTHON" - "$page" <<PY
import html, sys, h5py
page = open(sys.argv[1]).read()
texts = []
$snippet
missing = [t for t in texts if "<td>" + html.escape(t) + "</td>" not in page and
           "<code>" + html.escape(t) + "</code></details></td>" not in page]
print("\n".join("missing: " + t for t in missing))
sys.exit(1 if missing or not texts else 0)
PY
}

note "Nguyen-5 with an anchor"
job_from tests/jobs/small-symreg.yaml job.yaml "s/^seed: 3/seed: 2/"
echo '  anchors: [{name: "exact <&> \"formula\"", expression: "sin(x*x) * cos(x) - 1"}]' >>job.yaml
"$PBRFIT" run job.yaml -q
report_ok result.h5 page
html=page/index.html
expect_tables_mentioned result.h5 page
expect_valid_images page 4
[[ $IMAGES -eq 4 ]] || fail "$IMAGES images, expected 4 (knee formula, front, residuals, log)"
grep -qF 'alt="/y knee formula"' "$html" || fail "the knee is not typeset"
cells_in_page "$html" 'texts = [e.decode() for e in h5py.File("result.h5", "r")["y/front"]["expression"]]' ||
  fail "the front table does not list every member's expression"
cells_in_page "$html" 'texts = [s.decode() for s in h5py.File("result.h5", "r")["subexpressions/recurring"]["subexpression"]]' ||
  fail "the recurring sub-expressions are not listed"
grep -qF "<td>exact &lt;&amp;&gt; &quot;formula&quot;</td><td>sin(x*x) * cos(x) - 1</td>" "$html" ||
  fail "the anchor is not in the anchors table, escaped"
! grep -qF "exact <&>" "$html" || fail "the anchor's name is not escaped"
best=$("$H5PY_PYTHON" - <<'PY'
import h5py, numpy as np
with h5py.File("result.h5", "r") as f:
    front, anchor = f["y/front"][()], f["y/anchors"][0]
cheap = np.flatnonzero(front["cost"] <= anchor["cost"])
print(f"member {cheap[np.argmin(front['rmse'][cheap])]}")
PY
)
grep -qF "<td>$best</td>" "$html" || fail "the anchor is not compared with $best"
knee=$("$H5PY_PYTHON" -c 'import h5py, numpy; print(int(numpy.flatnonzero(h5py.File("result.h5", "r")["y/front"]["knee"] == 1)[0]))')
grep -q "the knee (the default of pbrfit export) is member $knee: " "$html" || fail "the knee is not named"
tested=$("$H5PY_PYTHON" -c 'import h5py, numpy; print(int(numpy.nanargmin(h5py.File("result.h5", "r")["y/front"]["test_rmse"])))')
grep -q "On the test rows the lowest RMSE is member ${tested}[^ ]* (.*); pbrfit export --member test exports it." "$html" ||
  fail "the member of the lowest test RMSE ($tested) is not named"
note "$IMAGES images; knee member $knee; the anchor compared with $best; member $tested best on the test rows"


note "two tables of a pbrfit result: two inputs on a grid, two outputs"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" dfg.yaml
"$PBRFIT" run dfg.yaml -q --output dfg.h5
job_from tests/jobs/small-symreg.yaml tables.yaml "s|^  dataset: .*|  dataset: {result: dfg.h5, tables: [dfg/scale, dfg/bias]}|" \
  "s/generations: 100/generations: 10/" "s/constant_probability: 0/constant_probability: 0.3/"
"$PBRFIT" run tables.yaml -q --output tables.h5
report_ok tables.h5 tables
expect_tables_mentioned tables.h5 tables
expect_valid_images tables 8
[[ $IMAGES -eq 8 ]] || fail "$IMAGES images, expected 8 (4 per output)"

note "readable expressions: fewer digits, the same printed RMSE on the training rows, the exact text a click away"
PYTHONPATH=$(dirname "$PBRFIT")/share/pbrfit/report "$H5PY_PYTHON" - tables.h5 tables/index.html <<'PY' || fail "a readable expression is wrong"
import html, sys, h5py, numpy as np
from pbrfit_report.readable_expressions import Expression, rmse
page = open(sys.argv[2]).read()
shorter = members = 0
with h5py.File(sys.argv[1], "r") as f:
    for output in ("scale", "bias"):
        g = f[output]
        inputs = [n.strip() for n in g.attrs["inputs"].decode().split(",")] if isinstance(g.attrs["inputs"], bytes) \
            else [n.strip() for n in g.attrs["inputs"].split(",")]
        front, rows = g["front"][()], g["knee_prediction"][()]
        columns, target = {n: rows[n] for n in inputs}, rows["target"]
        for member in front:
            members += 1
            exact = member["expression"].decode()
            marker = "<code>" + html.escape(exact) + "</code>"
            if marker not in page:
                assert "<td>" + html.escape(exact) + "</td>" in page, exact  # nothing to round: shown as found
                continue
            shown = html.unescape(page.split(marker)[0].rsplit("<td>", 1)[-1].split("<details>")[0])
            assert len(shown) < len(exact), (shown, exact)
            value = rmse(Expression(shown, inputs), columns, target)
            assert f"{value:.4g}" == f"{member['rmse']:.4g}", (shown, value, member["rmse"])
            shorter += 1
print(f"{shorter} of {members} members shown rounded, each with the file's RMSE to 4 digits")
assert shorter > members // 2
PY

note "a job still running: no front yet, the log so far"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/endless-symreg.yaml" long.yaml
start_ranks 1 run long.yaml -q
wait_for_items long.h5 8
report_ok long.h5 live
expect_valid_images live 1
grep -q "No front yet: the job has not finished its last stage" live/index.html || fail "the running job's page claims a front"
background_running || fail "the job finished before the report was made; make the test job longer"
kill -TERM $(rank_pids)
wait_background
expect_status 75
echo "PASS"
