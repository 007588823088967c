#!/usr/bin/env bash
# Outside readers never fail while a job runs: h5py opening and reading the result in a tight loop for
# the whole run sees only complete (published) files, with the job's progress never going backwards.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/long-dfg.yaml" job.yaml
start_ranks 2 run job.yaml -q
wait_for_items result.h5 8

cat >reader.py <<'PY'
import sys, time, h5py
path, seconds = sys.argv[1], float(sys.argv[2])
reads = failures = 0
last_done = 0
end = time.monotonic() + seconds
while time.monotonic() < end:
    try:
        with h5py.File(path, "r") as f:
            done = int(f.attrs["items_done"])
            f["dfg/scale"][0:4, 0:4]
        if done < last_done:
            print(f"progress went back from {last_done} to {done}", file=sys.stderr); sys.exit(1)
        last_done = done
        reads += 1
    except Exception as e:
        failures += 1
        print(f"read failed: {type(e).__name__}: {e}", file=sys.stderr)
print(f"{reads} reads, {failures} failures, last progress {last_done}")
sys.exit(1 if failures or reads < 20 else 0)
PY
"$H5PY_PYTHON" reader.py result.h5 6 || fail "h5py failed to read the running job's result"
kill_session TERM
wait_background
echo "PASS"
