#!/usr/bin/env bash
# A checkpoint or result of a different job text is never resumed or overwritten without --force;
# a damaged checkpoint is rejected with a one-line error and exit code 2.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" job.yaml
start_logged_ranks 2 run job.yaml --verbose
wait_for_checkpoint 8   # rank 0's own log: the published file may lag until the job is nearly done
kill -USR1 "$BACKGROUND_PID"   # mpirun forwards SIGUSR1 to the ranks
wait_background
[[ $STATUS -eq 75 ]] || { log_around_trigger 8; trigger_timing 8; fail "expected exit code 75, got $STATUS (SIGUSR1 forwarded by mpirun)"; }
cp result.h5.checkpoint saved.checkpoint

note "same output, different job text: --resume refuses"
job_from tests/jobs/resume-dfg.yaml other.yaml 's/tolerance: 1.0e-6/tolerance: 2.0e-6/'
run_ranks 2 run other.yaml --resume 2>err.txt
expect_status 2
grep -q "result.h5.checkpoint: error: this checkpoint was written by a different job text" err.txt ||
  { cat err.txt; fail "wrong message for a mismatched checkpoint"; }
[[ $(grep -c "error:" err.txt) -eq 1 ]] || { cat err.txt; fail "the error is not reported exactly once"; }
cmp -s saved.checkpoint result.h5.checkpoint || fail "the refused run touched the checkpoint"

note "damaged checkpoint: altered, foreign, or cut short in its last record"
cp saved.checkpoint result.h5.checkpoint
printf 'X' | dd of=result.h5.checkpoint bs=1 seek=30 conv=notrunc status=none   # inside the snapshot
"$PBRFIT" run job.yaml --resume 2>err.txt && fail "an altered checkpoint was accepted" || STATUS=$?
expect_status 2
grep -q "result.h5.checkpoint: error: damaged checkpoint at byte 12: record checksum mismatch" err.txt ||
  { cat err.txt; fail "wrong message for an altered checkpoint"; }
printf 'not a checkpoint at all, just some text padding it out' > result.h5.checkpoint
"$PBRFIT" run job.yaml --resume 2>err.txt && fail "a foreign checkpoint was accepted" || STATUS=$?
expect_status 2
grep -q "result.h5.checkpoint: error: damaged checkpoint at byte 0: not a pbrfit checkpoint" err.txt ||
  { cat err.txt; fail "wrong message for a foreign checkpoint"; }
head -c $(( $(stat -c %s saved.checkpoint) - 5 )) saved.checkpoint > result.h5.checkpoint
run_ranks 1 run job.yaml --resume 2>err.txt
expect_status 0
grep -q "the last checkpoint was cut short; continuing from the one before it" err.txt ||
  { cat err.txt; fail "a checkpoint cut short in its last record was not resumed from the one before"; }
note "a different job text may not overwrite the complete result"
cp result.h5 complete.h5
run_ranks 1 run other.yaml 2>err.txt
expect_status 2
grep -q "result.h5: error: holds the result of a different job text (job 'resume-dfg')" err.txt ||
  { cat err.txt; fail "wrong message for overwriting another job's result"; }
expect_identical complete.h5 result.h5 /dfg

note "--force overwrites"
job_from tests/jobs/small-dfg.yaml small.yaml
run_ranks 1 run small.yaml --force -q
expect_status 0
h5dump -a /job_name result.h5 | grep -q small-dfg || fail "--force did not overwrite"

note "a damaged result file without a checkpoint is not overwritten without --force"
echo "not HDF5" > result.h5
run_ranks 1 run small.yaml 2>err.txt
expect_status 2
grep -q "result.h5: error: exists but is not a readable pbrfit result; use --force to overwrite it" err.txt ||
  { cat err.txt; fail "wrong message for a damaged result file"; }
grep -q "not HDF5" result.h5 || fail "the refused run touched the damaged file"
run_ranks 1 run small.yaml --force -q
expect_status 0
echo "PASS"
