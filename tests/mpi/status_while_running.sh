#!/usr/bin/env bash
# While a job runs, `pbrfit status`, h5dump and h5py read its result file.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/long-dfg.yaml" job.yaml
start_ranks 2 run job.yaml -q
wait_for_items result.h5 8

# Each reader may land in the instant of a flush: a few retries are allowed, a failure is not.
retry() { local i; for i in 1 2 3 4 5 6 7 8 9 10; do "$@" && return 0; sleep 0.2; done; return 1; }

"$PBRFIT" status result.h5 | tee status.txt
grep -q "^state: *running" status.txt || fail "status does not say running"
grep -q "^job: *long-dfg (lut)" status.txt || fail "status does not name the job"
grep -Eq "^progress: *[0-9]+ of 8192 work items" status.txt || fail "status progress is missing"
grep -Eq "^headline: .*max error estimate" status.txt || fail "status has no headline"

retry bash -c 'h5dump -d /dfg/scale -s "0,0" -c "2,4" result.h5 > dump.txt' || fail "h5dump cannot read the running job's file"
grep -q 'DATASET "/dfg/scale"' dump.txt || fail "h5dump output lacks /dfg/scale"

cat > read.py <<'PY'
import sys, h5py, math
with h5py.File("result.h5", "r") as f:
    scale = f["dfg/scale"]
    rows = scale.shape[0]
    assert scale.shape[1] == 128, scale.shape
    assert f.attrs["state"] == "running", f.attrs["state"]
    assert not math.isnan(scale[0, 0])
    print("h5py read", rows, "rows while running")
PY
retry "$H5PY_PYTHON" read.py || fail "h5py cannot read the running job's file"

background_running || fail "the job finished before the readers were done; make the test job longer"
pids=$(rank_pids)
kill -TERM $pids
wait_background
expect_status 75
echo "PASS"
