#!/usr/bin/env bash
# A stop signal at any moment of start-up (before MPI, the job file or the result file exist) ends the
# run with exit 75, or 0 when it came after the end, never by the signal itself; whatever it left is
# resumed to the same numbers. The first ~10 ms, while the dynamic loader maps the libraries and before
# any of pbrfit's code runs, are out of reach: the delays start at 20 ms.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" job.yaml
run_ranks 1 run job.yaml --output reference.h5 -q
expect_status 0

for round in $(seq 1 8); do
  for signal in TERM USR1 INT; do
    delay=$(printf '0.%03d' $((20 + RANDOM % 480)))
    rm -f result.h5*
    "$PBRFIT" run job.yaml -q 2>err.txt &
    pid=$!
    sleep "$delay"
    kill -$signal $pid 2>/dev/null || true
    set +e
    wait $pid
    STATUS=$?
    set -e
    [[ $STATUS -eq 75 || $STATUS -eq 0 ]] ||
      { cat err.txt; fail "SIG$signal after ${delay}s: exit $STATUS (expected 75 or 0)"; }
    if [[ $STATUS -eq 75 && -f result.h5.checkpoint ]]; then
      run_ranks 1 run job.yaml -q --resume
      expect_status 0 "resume after SIG$signal at ${delay}s"
    fi
    if [[ -f result.h5 ]]; then
      [[ $STATUS -eq 0 ]] || run_ranks 1 run job.yaml -q --resume
      expect_identical reference.h5 result.h5 /dfg
    fi
  done
done
echo "PASS"
