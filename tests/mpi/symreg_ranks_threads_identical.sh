#!/usr/bin/env bash
# Symbolic regression is bitwise identical over ranks and threads (1x1, 1x2, 2x1, 2x2) for a built-in
# generator, a table of a pbrfit result (two outputs, each reading the other) and a CSV file; bad data files
# are refused with their own position.
source "$(dirname "$0")/lib/common.bash"
source "$(dirname "$0")/lib/layouts.bash"
MPI_FLAGS+=(--bind-to none)

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-symreg.yaml" nguyen.yaml
GROUPS_TO_COMPARE=(/y /subexpressions)
compare_layouts nguyen.yaml
"$H5PY_PYTHON" - <<'PY' || fail "the front, archive or log is wrong"
import h5py, numpy as np
f = h5py.File("nguyen-ref.h5", "r")
front, log = f["y/front"][...], f["y/log"][...]
assert len(front) >= 3 and (front["knee"] == 1).sum() == 1
assert np.all(np.diff(front["cost"]) > 0) and np.all(np.diff(front["rmse"]) < 0), "a front: cost rises, error falls"
assert np.all(np.isfinite(front["test_rmse"]))
assert len(log) == 4 * 20, len(log)                       # 4 islands x 20 epochs
assert log["generation"].max() == 100
assert len(f["y/archive"]) >= len(front)
assert len(f["y/knee_prediction"]) == 20
PY

note "jobs/nguyen7.yaml: recovered exactly, then the remaining epochs are skipped"
sed 's|^output: .*|output: result.h5|' "$PBRFIT_SOURCE_DIR/jobs/nguyen7.yaml" > nguyen7.yaml
GROUPS_TO_COMPARE=(/y)
compare_layouts nguyen7.yaml
"$PBRFIT" status nguyen7-2x2.h5 | grep -q "^progress: *1201 of 1201 work items" || fail "skipped epochs are not counted as done"
"$H5PY_PYTHON" - <<'PY' || fail "Nguyen-7 was not recovered, or the search did not stop early"
import h5py
f = h5py.File("nguyen7-ref.h5", "r")
assert any(m["test_rmse"] < 1e-9 for m in f["y/front"][...]), "no exact member"
assert f["y/log"][...]["generation"].max() < 3000, "the search ran to its last generation"
PY

note "a table of a pbrfit result as data: two outputs of a DFG table, each reading the other"
cat > lut.yaml <<'YAML'
name: lut
kind: lut
output: lut.h5
lut: {function: dfg, resolution: [12, 10], tolerance: 1.0e-6}
YAML
run_ranks 2 run lut.yaml -q
expect_status 0
cat > dfg.yaml <<'YAML'
name: dfg
kind: symreg
symreg:
  dataset: {result: lut.h5, tables: [dfg/scale, dfg/bias], cross_inputs: true}
  operators: [add, sub, mul, div, exp2]
  population: 100
  generations: 20
  islands: 2
  migration_interval: 5
  anchors: [{name: zero, output: bias, expression: "0 * n_dot_v"}]
YAML
GROUPS_TO_COMPARE=(/scale /bias /subexpressions)
compare_layouts dfg.yaml
"$H5PY_PYTHON" - <<'PY' || fail "the DFG regression's inputs or anchors are wrong"
import h5py
f = h5py.File("dfg-ref.h5", "r")
assert f["scale"].attrs["inputs"] == "roughness, n_dot_v, bias", f["scale"].attrs["inputs"]
assert len(f["scale/knee_prediction"]) == 120
anchors = f["bias/anchors"][...]
assert anchors["name"][0] == b"zero" and anchors["cost"][0] == 1.0
PY

note "a CSV file as data, and bad CSV files refused at their own line and column"
printf 'x,y\n' > data.csv
for i in $(seq 0 30); do echo "$i,$((i * i + 3))" >> data.csv; done
cat > csv.yaml <<'YAML'
name: csv
kind: symreg
symreg:
  dataset: {csv: data.csv, inputs: [x], targets: [y]}
  population: 100
  generations: 10
YAML
GROUPS_TO_COMPARE=(/y)
compare_layouts csv.yaml
note "a quarter of the CSV rows held out: test errors in the front, the same on any ranks and threads"
sed 's/targets: \[y\]}/targets: [y], test_fraction: 0.25}/' csv.yaml > held.yaml
compare_layouts held.yaml
"$H5PY_PYTHON" - <<'PY' || fail "the held-out rows are not measured"
import h5py, numpy as np
with h5py.File("held-ref.h5", "r") as f:
    y = f["y"]
    assert int(y.attrs["test_rows"]) == 8 and int(y.attrs["rows"]) == 23, dict(y.attrs)
    assert np.all(np.isfinite(y["front"]["test_rmse"]))
PY
printf 'x,y\n1,2\n3,four\n' > bad.csv
sed 's/data.csv/bad.csv/' csv.yaml > bad.yaml
run_ranks 1 run bad.yaml --output bad.h5 -q 2> err.txt
expect_status 2
grep -qx "bad.csv:3:3: error: expected a finite number, got 'four'" err.txt || fail "bad CSV: $(cat err.txt)"
printf 'x,y\n1,2\n3\n' > short.csv
sed 's/data.csv/short.csv/' csv.yaml > short.yaml
run_ranks 1 run short.yaml --output short.h5 -q 2> err.txt
expect_status 2
grep -qx "short.csv:3:1: error: a row of 1 fields; the header has 2" err.txt || fail "short CSV row: $(cat err.txt)"
sed 's/targets: \[y\]/targets: [z]/' csv.yaml > nocolumn.yaml
run_ranks 1 run nocolumn.yaml --output nc.h5 -q 2> err.txt
expect_status 2
grep -q "'z' is not a column of data.csv (columns: x, y)" err.txt || fail "unknown column: $(cat err.txt)"
echo "PASS"
