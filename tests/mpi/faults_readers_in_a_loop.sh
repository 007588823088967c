#!/usr/bin/env bash
# Outside readers never fail while a job runs: h5py opening and reading the result in a tight loop for
# the whole run sees only complete (published) files, with the job's progress never going backwards.
# The reader stops after 20 s, or sooner once it has 40 reads and has seen progress; it must have seen the job publish new progress meanwhile, so
# a loaded machine (slow reads) cannot fail it, and a test that saw no publication cannot pass.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/long-dfg.yaml" job.yaml
start_ranks 2 run job.yaml -q
wait_for_items result.h5 8

cat >reader.py <<'PY'
import sys, time, h5py
path, seconds = sys.argv[1], float(sys.argv[2])
reads = failures = 0
first_done = last_done = None
end = time.monotonic() + seconds
while time.monotonic() < end and not (reads >= 40 and last_done > first_done):
    try:
        with h5py.File(path, "r") as f:
            done = int(f.attrs["items_done"])
            f["dfg/scale"][0:4, 0:4]
        if last_done is not None and done < last_done:
            print(f"progress went back from {last_done} to {done}", file=sys.stderr); sys.exit(1)
        first_done = done if first_done is None else first_done
        last_done = done
        reads += 1
    except Exception as e:
        failures += 1
        print(f"read failed: {type(e).__name__}: {e}", file=sys.stderr)
print(f"{reads} reads, {failures} failures, progress {first_done} -> {last_done}")
published = first_done is not None and last_done > first_done
sys.exit(1 if failures or reads < 5 or not published else 0)
PY
"$H5PY_PYTHON" reader.py result.h5 20 || fail "h5py failed to read the running job's result"
kill_session TERM
wait_background
echo "PASS"
