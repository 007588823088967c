#!/usr/bin/env bash
# `pbrfit report` refusals: what is not a readable pbrfit result is exit 2 with exactly one line on stderr
# naming the file (the lines of `pbrfit status`) and no report written; a report that cannot be written,
# or a Python that cannot run it, is exit 3 with one "pbrfit: error:" line. Never a traceback.
source "$(dirname "$0")/lib/common.bash"

report() { run_pbrfit report "$@"; }

note "a missing file"
report missing.h5
expect_one_line 2 "missing.h5: error: cannot read file: No such file or directory"
[[ ! -e missing.report ]] || fail "a report directory was made for a missing file"

note "a directory"
mkdir folder.h5
report folder.h5
expect_one_line 2 "folder.h5: error: is a directory, not a file"

note "a FIFO"
mkfifo fifo.h5
report fifo.h5
expect_one_line 2 "fifo.h5: error: is not a regular file"

note "a text file renamed .h5"
echo "just text" > fake.h5
report fake.h5
expect_one_line 2 "fake.h5: error: not a readable HDF5 file (damaged, or not a pbrfit result)"
[[ ! -e fake.report ]] || fail "a report directory was made for a text file"

note "an HDF5 file that is not a pbrfit result"
"$H5PY_PYTHON" -c 'import h5py, numpy; h5py.File("other.h5", "w")["x"] = numpy.arange(3.0)'
report other.h5
expect_one_line 2 "other.h5: error: not a pbrfit result file (no pbrfit_version or job_yaml attribute)"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" job.yaml
"$PBRFIT" run job.yaml -q

note "a report directory that cannot be made: below a regular file"
touch blocker
report result.h5 --out blocker/report
expect_one_line 3 "pbrfit: error: cannot create report directory blocker/report: Not a directory"

note "a report directory that cannot be written"
mkdir readonly
if [[ $(id -u) -eq 0 ]]; then
  if mount -t tmpfs -o ro,size=100k tmpfs readonly 2>/dev/null; then
    trap 'umount readonly 2>/dev/null || true; kill_group_if_running; rm -rf "$WORK"' EXIT
    report result.h5 --out readonly
    umount readonly
    expect_one_line 3 "pbrfit: error: cannot write readonly/fig-0001.png: Read-only file system"
  else
    note "skipped: root, and no read-only tmpfs can be mounted here"
  fi
else
  chmod 555 readonly
  report result.h5 --out readonly/sub
  expect_one_line 3 "pbrfit: error: cannot create report directory readonly/sub: Permission denied"
fi

note "no Python, no report package, a Python that fails"
PBRFIT_PYTHON=/nonexistent/python3 report result.h5
expect_one_line 3 "pbrfit: error: cannot run '/nonexistent/python3': No such file or directory"
PBRFIT_REPORT_DIR=/nonexistent report result.h5
expect_one_line 3 "pbrfit: error: the report package is missing: no '/nonexistent/__main__.py'"
PBRFIT_PYTHON=false report result.h5
expect_one_line 3 "pbrfit: error: the report script ('false') ended with exit code 1"

note "a Python without matplotlib: one line, exit 3"
mkdir -p nomatplotlib/matplotlib
echo 'raise ImportError("No module named matplotlib (test)")' > nomatplotlib/matplotlib/__init__.py
cp -r "$PBRFIT_SOURCE_DIR/src/report/." nomatplotlib/
PBRFIT_REPORT_DIR=$WORK/nomatplotlib report result.h5 --out nomatplotlib.report
expect_status 3
[[ $(wc -l <err.txt) -eq 1 ]] || { cat err.txt; fail "not exactly one line on stderr"; }
grep -q "^pbrfit: error: the report needs h5py, numpy and matplotlib" err.txt || { cat err.txt; fail "wrong message"; }

note "the valid result still gives a report"
report result.h5
expect_status 0 "$(cat err.txt)"
[[ -f result.report/index.html ]] || fail "no report"
echo "PASS"
