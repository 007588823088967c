#!/usr/bin/env bash
# Against a real single-node Slurm cluster (cluster/local-slurm): `pbrfit submit` a 2-rank job, requeue it
# mid-run with `scontrol requeue` (SIGTERM), then signal it as Slurm's time-limit warning does (SIGUSR1: the
# job requeues itself), wait for it to finish, and check that the result is bitwise identical to a plain
# `mpirun -np 2` run. Skipped (exit 77, with the reason) where Slurm is not installed.
source "$(dirname "$0")/lib/common.bash"

cluster="$PBRFIT_SOURCE_DIR/cluster/local-slurm"
state="$WORK/slurm"
set +e
"$cluster/start.sh" "$state" > slurm-env.sh 2> start.err
started=$?
set -e
if [[ $started -eq 77 ]]; then
  echo "SKIP: $(tail -n 1 start.err)"
  exit 77
fi
trap '"$cluster/stop.sh" "$state" >/dev/null 2>&1 || true; kill_group_if_running; rm -rf "$WORK"' EXIT
[[ $started -eq 0 ]] || { cat start.err; fail "the local Slurm cluster did not start"; }
source slurm-env.sh

cp "$PBRFIT_SOURCE_DIR/tests/jobs/slurm-dfg.yaml" job.yaml
note "reference: plain mpirun -np 2"
run_ranks 2 run job.yaml --output reference.h5 -q
expect_status 0

note "submit"
"$PBRFIT" submit job.yaml --ranks 2 --time 10:00 | tee submit.txt
id=$(sed -n 's/.* as Slurm job \([0-9][0-9]*\) .*/\1/p' submit.txt)
[[ -n "$id" ]] || fail "submit printed no Slurm job id"
grep -q "log: *$WORK/result.slurm-$id.log" submit.txt || fail "submit does not say where the log is"
log="$WORK/result.slurm-$id.log"

job_state() { squeue -h -j "$id" -o %T 2>/dev/null || true; }
items_done() { "$PBRFIT" status result.h5 2>/dev/null | sed -n 's/^progress: *\([0-9]*\) of.*/\1/p'; }

note "wait until it has done some work"
deadline=$((SECONDS + 120))
until [[ "$(items_done)" -ge 64 ]] 2>/dev/null; do
  (( SECONDS < deadline )) || { cat "$log" 2>/dev/null; squeue; fail "the Slurm job made no progress"; }
  sleep 0.2
done
[[ "$(job_state)" == RUNNING ]] || fail "the job is not running when it should be requeued"
before=$(items_done)

# Waits until the result file reports STATE (and, optionally, at least N items), failing after a while.
wait_for() {
  local state=$1 items=${2:-0} deadline=$((SECONDS + 240))
  while :; do
    if "$PBRFIT" status result.h5 > status.txt 2>/dev/null && grep -q "^state: *$state" status.txt &&
       [[ "$(sed -n 's/^progress: *\([0-9]*\) of.*/\1/p' status.txt)" -ge $items ]]; then
      return 0
    fi
    (( SECONDS < deadline )) || { cat status.txt "$log"; squeue; fail "the job never reached '$state' with $items items"; }
    sleep 0.2
  done
}

note "scontrol requeue $id after $before items: SIGTERM, checkpoint, Slurm requeues"
scontrol requeue "$id"
wait_for interrupted
grep -q "^scheduler: *slurm job $id, restart 0" status.txt || fail "status does not name the Slurm job"

note "the time-limit warning path: SIGUSR1 to the ranks, checkpoint, the script requeues the job"
wait_for running 250
grep -q "^scheduler: *slurm job $id, restart 1" status.txt || fail "the requeued run does not say it is restart 1"
scancel --signal=USR1 "$id"
wait_for interrupted
wait_for complete 1536
while [[ -n "$(job_state)" && "$(job_state)" != COMPLETED ]]; do sleep 0.2; done
cat "$log"
grep -q "restart 2" "$log" || fail "the job did not requeue itself after exit 75"
# On `scontrol requeue` Slurm ends the batch shell with the job, so srun reports the ranks' exit code;
# after SIGUSR1 the script itself sees 75 and requeues.
grep -q "Exited with exit code 75" "$log" || fail "the requeued run's ranks did not exit 75"
grep -q "^pbrfit: exit code 75" "$log" || fail "the batch script did not see exit code 75 after SIGUSR1"
[[ $(grep -c "interrupted: checkpoint saved to $WORK/result.h5.checkpoint" "$log") -eq 2 ]] ||
  fail "the two interrupted runs did not both save a checkpoint"
[[ $(grep -c "resuming: [1-9][0-9]* of 1536 work items already done" "$log") -eq 2 ]] || fail "the runs did not resume"
"$PBRFIT" status result.h5 | grep -q "^scheduler: *slurm job $id, restart 2" || fail "the final run is not restart 2"
expect_identical reference.h5 result.h5 /dfg
echo "PASS"
