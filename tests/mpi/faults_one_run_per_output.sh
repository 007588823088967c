#!/usr/bin/env bash
# One run per output: while a job writes result.h5, a second run, a second --resume, and a run on
# 2 ranks are refused with exit 2 naming the holder's host and pid; the first run is not disturbed and
# ends bitwise identical to an undisturbed run. The lock dies with its holder (SIGKILL), so a resume
# afterwards is not refused.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" job.yaml
note "reference"
run_ranks 1 run job.yaml --output reference.h5 -q
expect_status 0

note "a second run while the first writes"
start_ranks 1 run job.yaml
wait_for_items result.h5 10
holder=$(rank_pids)
for args in "run job.yaml -q" "run job.yaml -q --resume"; do
  set +e
  timeout 30 "$PBRFIT" $args 2>err.txt
  STATUS=$?
  set -e
  expect_status 2 "$args while another run holds the output"
  grep -q "result.h5: error: is in use by another pbrfit run (.*$(hostname).*$holder" err.txt ||
    { cat err.txt; fail "the refusal does not name the holder $(hostname) pid $holder"; }
  [[ $(wc -l <err.txt) -eq 1 ]] || fail "the refusal is not one line"
done
run_ranks 2 run job.yaml -q --resume 2>err.txt
expect_status 2 "2 ranks resuming while another run holds the output"
background_running || fail "the first run did not survive the refused ones"

note "SIGKILL the holder: its lock goes with it"
kill_session KILL
wait_background
run_ranks 2 run job.yaml -q --resume
expect_status 0
expect_identical reference.h5 result.h5 /dfg
echo "PASS"
