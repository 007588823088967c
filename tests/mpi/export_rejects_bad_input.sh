#!/usr/bin/env bash
# `pbrfit export` refusals, each exit 2 with exactly one line on stderr and nothing on stdout: what is not
# a readable pbrfit result (the lines of `pbrfit status`), a table result without a format (export_tables.sh
# has the table refusals), an unknown output or
# none chosen among several, a member out of range, a front not there yet (a job still running), bad
# option values. Any other failure (a damaged symreg result, stdout that cannot be written) is exit 3 with
# one "pbrfit: error:" line. Never a stack trace.
source "$(dirname "$0")/lib/common.bash"

export_() { run_pbrfit export "$@"; }

# expect_one_line, and nothing on stdout.
expect_refusal() {
  expect_one_line "$@"
  [[ ! -s out.txt ]] || { cat out.txt; fail "a refusal printed on stdout"; }
}

note "what is not a readable pbrfit result"
export_ missing.h5
expect_refusal 2 "missing.h5: error: cannot read file: No such file or directory"
mkdir folder.h5
export_ folder.h5
expect_refusal 2 "folder.h5: error: is a directory, not a file"
mkfifo fifo.h5
export_ fifo.h5
expect_refusal 2 "fifo.h5: error: is not a regular file"
echo "just text" > fake.h5
export_ fake.h5
expect_refusal 2 "fake.h5: error: not a readable HDF5 file (damaged, or not a pbrfit result)"
"$H5PY_PYTHON" -c 'import h5py, numpy; h5py.File("other.h5", "w")["x"] = numpy.arange(3.0)'
export_ other.h5
expect_refusal 2 "other.h5: error: not a pbrfit result file (no pbrfit_version or job_yaml attribute)"

note "a table result: the format is needed, and options of a front member do not apply"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" dfg.yaml
"$PBRFIT" run dfg.yaml -q --output dfg.h5
export_ dfg.h5
expect_refusal 2 "--format: error: is needed to export a table: one of dds, ktx2, exr, hdr, png, npy, cpp, glsl, hlsl, js"
export_ dfg.h5 --format glsl --double
expect_refusal 2 "--double: error: applies to a front member's function, not to a table"

note "an unknown output, a member out of range, bad option values"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-symreg.yaml" symreg.yaml
"$PBRFIT" run symreg.yaml -q --output symreg.h5
members=$("$H5PY_PYTHON" -c 'import h5py; print(len(h5py.File("symreg.h5", "r")["y/front"]))')
export_ symreg.h5 --output z
expect_refusal 2 "symreg.h5: error: no output 'z' in the result; its outputs: 'y'"
export_ symreg.h5 --member "$members"
expect_refusal 2 "symreg.h5: error: member $members is out of range: the front of 'y' has $members members (0 to $((members - 1)))"
export_ symreg.h5 --member -1
expect_refusal 2 "--member: error: '-1' is not a row of the front (0, 1, 2, ...) or 'test'"
export_ symreg.h5 --name 'my model'
expect_refusal 2 "--name: error: 'my model' is not a name every export language accepts (a letter, then letters, digits and single '_'; no keyword or built-in function)"
export_ symreg.h5 --double --format glsl
expect_refusal 2 "--double: error: only C++ exports can use double (--format cpp)"
export_ symreg.h5 --format java
expect_status 2
! grep -qi "terminate\|abort\|stack" err.txt || fail "a bad --format crashes"
export_ symreg.h5 --member 0
expect_status 0 "$(cat err.txt)"

note "several outputs: one must be chosen"
job_from tests/jobs/small-symreg.yaml tables.yaml "s|^  dataset: .*|  dataset: {result: dfg.h5, tables: [dfg/scale, dfg/bias]}|" \
  "s/generations: 100/generations: 10/"
"$PBRFIT" run tables.yaml -q --output tables.h5
export_ tables.h5
expect_refusal 2 "tables.h5: error: the result has several outputs ('bias', 'scale'); choose one with --output"
export_ tables.h5 --output scale
expect_status 0 "$(cat err.txt)"
grep -q "^float scale(float roughness, float n_dot_v) {$" out.txt || { cat out.txt; fail "the inputs are not the parameters"; }

note "a job that has not finished its last stage"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/endless-symreg.yaml" long.yaml
start_ranks 1 run long.yaml -q
wait_for_items long.h5 8
export_ long.h5
expect_status 2
[[ $(wc -l <err.txt) -eq 1 && ! -s out.txt ]] || { cat err.txt out.txt; fail "not one line on stderr alone"; }
grep -qE "^long.h5: error: no front of 'y' yet: the job has not finished its last stage \(running, [0-9]+ of [0-9]+ work items done\)$" err.txt ||
  { cat err.txt; fail "wrong message while the job runs"; }
kill -TERM $(rank_pids)
wait_background
expect_status 75

note "other failures: a damaged symreg result, stdout that cannot be written"
cp symreg.h5 damaged.h5
"$H5PY_PYTHON" -c 'import h5py; del h5py.File("damaged.h5", "r+")["y/front"]'
export_ damaged.h5
expect_status 3
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q "^pbrfit: error: " err.txt || { cat err.txt; fail "a damaged result is not one 'pbrfit: error:' line"; }
set +e
"$PBRFIT" export symreg.h5 >/dev/full 2>err.txt; STATUS=$?
set -e
expect_one_line 3 "pbrfit: error: cannot write to stdout"
echo "PASS"
