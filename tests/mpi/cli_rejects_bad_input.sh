#!/usr/bin/env bash
# Bad input on the command line: one-line errors, exit code 2, no crash, also under mpirun.
source "$(dirname "$0")/lib/common.bash"

cat > bad.yaml <<'YAML'
name: bad
kind: lut
lut:
  function: dfg
  tolerence: 1e-6
YAML
expected="bad.yaml:5:3: error: unknown key 'tolerence' in 'lut'; did you mean 'tolerance'?"

set +e
"$PBRFIT" validate bad.yaml 2>err.txt; STATUS=$?
set -e
expect_status 2
[[ "$(cat err.txt)" == "$expected" ]] || { cat err.txt; fail "validate: wrong message"; }

run_ranks 2 run bad.yaml 2>err.txt
expect_status 2
[[ $(grep -c "error: unknown key 'tolerence'" err.txt) -eq 1 ]] || { cat err.txt; fail "run: not reported exactly once"; }

"$PBRFIT" validate "$PBRFIT_SOURCE_DIR/jobs/quickstart.yaml" | grep -q "ok: lut job 'dfg-quickstart', 128 work items" ||
  fail "validate does not accept the quickstart job"

set +e
"$PBRFIT" validate missing.yaml 2>err.txt; STATUS=$?
set -e
expect_status 2
grep -q "^missing.yaml: error: cannot read job file" err.txt || { cat err.txt; fail "missing job file"; }

echo "just text" > fake.h5
set +e
"$PBRFIT" status fake.h5 2>err.txt; STATUS=$?
set -e
expect_status 2
grep -q "^fake.h5: error: not a readable HDF5 file" err.txt || { cat err.txt; fail "status of a non-HDF5 file"; }

set +e
"$PBRFIT" run 2>err.txt; STATUS=$?
set -e
expect_status 2
set +e
"$PBRFIT" frobnicate 2>err.txt; STATUS=$?
set -e
expect_status 2
! grep -qi "terminate\|abort\|stack" err.txt || fail "usage errors crash"
echo "PASS"
