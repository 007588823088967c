#!/usr/bin/env bash
# `pbrfit report` of a lut result: a finished small DFG table (2 ranks) gives RESULT.report/index.html
# whose every image is a valid PNG and which names every table, with scale and bias as curves beside the
# convention's published fit and that fit's differences from the table (checked here on the file's own axes); a report of a job still running works
# too and shows the cells not yet computed; with --watch it is remade while the job runs (the page
# reloading itself) and a last time, without reloading, once the job has stopped.
source "$(dirname "$0")/lib/common.bash"
source "$PBRFIT_SOURCE_DIR/tests/mpi/lib/report_checks.bash"

note "a finished small DFG table"
report_of_test_job small-dfg.yaml
expect_tables_mentioned result.h5 result.report
expect_valid_images result.report "$TABLES"   # every lut table is a map or a curve
grep -q "small-dfg" result.report/index.html || fail "the page does not name the job"
"$H5PY_PYTHON" -c 'import html, sys; sys.exit(("<pre>" + html.escape(open("job.yaml").read()) + "</pre>") not in open(sys.argv[1]).read())' \
  result.report/index.html || fail "the job text is not on the page, whole, in a <pre>"
grep -q "visibility" result.report/index.html || fail "the group's attributes are not on the page"
note "$IMAGES images for $TABLES tables"

note "scale and bias beside the convention's published fit (UE4's: Karis 2014), over every cell"
grep -q 'id="dfg-curves"' result.report/index.html || fail "no 'Scale and bias' section"
grep -q 'alt="dfg scale and bias curves"' result.report/index.html || fail "no curves of scale and bias"
PYTHONPATH=$(dirname "$PBRFIT")/share/pbrfit/report "$H5PY_PYTHON" - result.h5 result.report/index.html <<'PY' ||
import re, sys, h5py, numpy as np
from pbrfit_report.kinds.lut import karis_2014
page = open(sys.argv[2]).read()
assert "Beside Karis 2014 (UE4 mobile)" in page
with h5py.File(sys.argv[1], "r") as f:
    scale = f["dfg/scale"]
    outer, inner = (scale.dims[d][0] for d in (0, 1))  # the table's own axes, read from its dimension scales
    assert (outer.name.split("/")[-1], inner.name.split("/")[-1]) == ("roughness", "n_dot_v")
    r, v = np.meshgrid(outer[()], inner[()], indexing="ij")
    fitted = karis_2014(v, r)
    for name, k in (("scale", 0), ("bias", 1)):
        rms = float(np.sqrt(np.mean((f["dfg/" + name][()] - fitted[k]) ** 2)))
        shown = re.search(rf"<td>{name}</td><td class=\"number\">([^<]*)</td>", page).group(1)
        assert f"{rms:.4g}" == shown, (name, rms, shown)
        print(f"{name}: RMS difference from Karis 2014 {shown}")
PY
  fail "the published fit's differences on the page are not the table's"

note "again into an existing directory: the same page, no figure left over from before"
touch result.report/fig-9999.png
"$PBRFIT" report result.h5 --out result.report >/dev/null
[[ ! -e result.report/fig-9999.png ]] || fail "a stale figure was left in the report directory"
expect_valid_images result.report "$TABLES"

note "a job still running"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/long-dfg.yaml" long.yaml
sed -i 's/^output: .*/output: long.h5/' long.yaml
start_ranks 1 run long.yaml -q
wait_for_items long.h5 8
set +e
"$PBRFIT" report long.h5 --out live >out.txt 2>err.txt; STATUS=$?
set -e
expect_status 0 "$(cat err.txt)"
expect_valid_images live 1
grep -q "not yet computed" live/index.html || fail "the report of a running job shows no cell as not yet computed"
grep -q "running" live/index.html || fail "the report of a running job does not say it runs"
if grep -q 'http-equiv="refresh"' live/index.html; then fail "a report made once reloads itself"; fi
background_running || fail "the job finished before the report was made; make the test job longer"

note "--watch: remade while the job runs (the page reloads itself), a last time when it stops"
"$PBRFIT" report long.h5 --out watched --watch 1 >watch.txt 2>watch-err.txt &
watcher=$!
for _ in $(seq 600); do
  [[ $(grep -c "the job is running, again in 1 s" watch.txt) -ge 2 ]] && break
  sleep 0.1
done
[[ $(grep -c "the job is running, again in 1 s" watch.txt) -ge 2 ]] || { cat watch.txt watch-err.txt; fail "the report was not remade while the job ran"; }
grep -q '<meta http-equiv="refresh" content="1">' watched/index.html || fail "the watched page does not reload itself"
kill -TERM $(rank_pids)
wait_background
expect_status 75
set +e
timeout 60 tail --pid=$watcher -f /dev/null; wait $watcher; STATUS=$?
set -e
expect_status 0 "$(cat watch-err.txt)"
tail -1 watch.txt | grep -q "^report: watched/index.html ([0-9]* figures)$" || { cat watch.txt; fail "no last line once the job stopped"; }
if grep -q 'http-equiv="refresh"' watched/index.html; then fail "the last page still reloads itself"; fi
grep -q "interrupted" watched/index.html || fail "the last page does not show the job stopped"
echo "PASS"
