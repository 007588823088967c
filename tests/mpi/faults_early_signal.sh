#!/usr/bin/env bash
# A stop signal at any moment of start-up (before MPI, the job file or the result file exist) ends the
# run with exit 75, or 0 when it came after the end, never by the signal itself; whatever it left is
# resumed to the same numbers. The time the dynamic loader takes to map the libraries, before any of
# pbrfit's code runs, is out of reach (about 10 ms, far longer on a loaded machine): each delay counts from
# the moment the process catches the signal (its SigCgt mask in /proc).
source "$(dirname "$0")/lib/common.bash"

# Waits (up to 5 s) until process PID catches signal number N, or is gone.
wait_for_handler() {
  local pid=$1 number=$2 mask i
  for i in $(seq 1 500); do
    mask=$(sed -n 's/^SigCgt:[[:space:]]*//p' "/proc/$pid/status" 2>/dev/null) || return 0
    [[ -n $mask ]] || return 0
    (( (16#$mask >> (number - 1)) & 1 )) && return 0
    sleep 0.01
  done
  fail "process $pid did not catch signal $number within 5 s"
}

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" job.yaml
run_ranks 1 run job.yaml --output reference.h5 -q
expect_status 0

for round in $(seq 1 8); do
  for signal in TERM USR1 INT; do
    delay=$(printf '0.%03d' $((RANDOM % 480)))
    rm -f result.h5*
    "$PBRFIT" run job.yaml -q 2>err.txt &
    pid=$!
    wait_for_handler $pid "$(kill -l $signal)"
    sleep "$delay"
    kill -$signal $pid 2>/dev/null || true
    set +e
    wait $pid
    STATUS=$?
    set -e
    [[ $STATUS -eq 75 || $STATUS -eq 0 ]] ||
      { cat err.txt; fail "SIG$signal ${delay}s after the handlers were installed: exit $STATUS (expected 75 or 0)"; }
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
