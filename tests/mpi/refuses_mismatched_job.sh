#!/usr/bin/env bash
# A checkpoint or result of a different job text is never resumed or overwritten without --force;
# a damaged checkpoint is rejected with a one-line error and exit code 2.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" job.yaml
start_ranks 2 run job.yaml -q
wait_for_items result.h5 8
kill -USR1 "$BACKGROUND_PID"   # mpirun forwards SIGUSR1 to the ranks
wait_background
expect_status 75 "SIGUSR1 forwarded by mpirun"
cp result.h5.checkpoint saved.checkpoint

note "same output, different job text: --resume refuses"
job_from tests/jobs/resume-dfg.yaml other.yaml 's/tolerance: 1.0e-6/tolerance: 2.0e-6/'
run_ranks 2 run other.yaml --resume 2>err.txt
expect_status 2
grep -q "result.h5.checkpoint: error: this checkpoint was written by a different job text" err.txt ||
  { cat err.txt; fail "wrong message for a mismatched checkpoint"; }
[[ $(grep -c "error:" err.txt) -eq 1 ]] || { cat err.txt; fail "the error is not reported exactly once"; }
cmp -s saved.checkpoint result.h5.checkpoint || fail "the refused run touched the checkpoint"

note "damaged checkpoint"
head -c 1000 saved.checkpoint > result.h5.checkpoint
"$PBRFIT" run job.yaml --resume 2>err.txt && fail "a truncated checkpoint was accepted" || STATUS=$?
expect_status 2
grep -q "result.h5.checkpoint: error: corrupt checkpoint at byte" err.txt || { cat err.txt; fail "wrong message for a truncated checkpoint"; }
printf 'not a checkpoint at all, just some text padding it out' > result.h5.checkpoint
"$PBRFIT" run job.yaml --resume 2>err.txt && fail "a foreign checkpoint was accepted" || STATUS=$?
expect_status 2
grep -q "result.h5.checkpoint: error: corrupt checkpoint" err.txt || { cat err.txt; fail "wrong message for a foreign checkpoint"; }
cp saved.checkpoint result.h5.checkpoint

note "complete the job, then a different job text may not overwrite its result"
run_ranks 2 run job.yaml --resume -q
expect_status 0
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
