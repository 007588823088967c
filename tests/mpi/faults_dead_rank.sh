#!/usr/bin/env bash
# A rank that dies (SIGKILL) or stops answering (SIGSTOP) does not hang the job or lose its work:
# rank 0 saves a checkpoint and exits 75 in bounded time, naming the silent rank, and --resume
# continues to the same numbers.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" job.yaml
run_ranks 1 run job.yaml --output reference.h5 -q
expect_status 0

# Waits for the background job to end within `limit` seconds.
wait_bounded() {
  local limit=$1 start=$SECONDS
  while background_running; do
    (( SECONDS - start < limit )) || fail "the job did not end within $limit s"
    sleep 0.2
  done
  wait_background
}

note "SIGKILL rank 1: the job ends with a checkpoint"
start_logged_ranks 2 run job.yaml --rank-timeout 5 --verbose
wait_for_checkpoint 40
# A fresh run publishes its file at its first flush, about a second in; on a loaded machine the checkpoint
# can come first, and a run killed before that leaves only its checkpoint (status points to it), not a
# file that says 'interrupted'. Kill once the file is there.
for _ in $(seq 1 200); do [[ -f result.h5 ]] && break; nap 0.05; done
[[ -f result.h5 ]] || fail "the running job did not publish result.h5 within 10 s"
kill -KILL "$(pid_of_rank 1)"
wait_bounded 40
[[ $STATUS -ne 0 ]] || fail "the job reported success with a dead rank"
[[ -f result.h5.checkpoint ]] || fail "no checkpoint after rank 1 died"
wait_for_state result.h5 "interrupted"

note "SIGSTOP rank 1: lost after --rank-timeout, checkpoint, exit 75"
done_before=$(items_done result.h5)
start_logged_ranks 2 run job.yaml --resume --rank-timeout 3 --verbose
wait_for_checkpoint $((done_before + 40))
kill -STOP "$(pid_of_rank 1)"
wait_bounded 40
expect_status 75 "rank 0 after losing rank 1"
grep -q "rank 1 has sent nothing" run.log || { tail -n 8 run.log; fail "the message does not name rank 1"; }
[[ -f result.h5.checkpoint ]] || fail "no checkpoint after rank 1 was lost"

note "resume to the same numbers"
run_ranks 2 run job.yaml --resume -q
expect_status 0
expect_identical reference.h5 result.h5 /dfg
echo "PASS"
