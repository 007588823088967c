#!/usr/bin/env bash
# Against a real single-node Slurm cluster (cluster/local-slurm): `pbrfit submit` a 2-rank job, requeue it
# mid-run with `scontrol requeue`, wait for it to finish, and check that the result is bitwise identical
# to a plain `mpirun -np 2` run. Skipped (exit 77, with the reason) where Slurm is not installed.
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
until [[ "$(items_done)" -ge 48 ]] 2>/dev/null; do
  (( SECONDS < deadline )) || { cat "$log" 2>/dev/null; squeue; fail "the Slurm job made no progress"; }
  sleep 0.2
done
[[ "$(job_state)" == RUNNING ]] || fail "the job is not running when it should be requeued"
before=$(items_done)

note "scontrol requeue $id after $before items"
scontrol requeue "$id"
saw_interrupted=no
deadline=$((SECONDS + 240))
while :; do
  if "$PBRFIT" status result.h5 > status.txt 2>/dev/null; then
    grep -q "^state: *interrupted" status.txt && saw_interrupted=yes
    grep -q "^state: *complete" status.txt && [[ -z "$(job_state)" || "$(job_state)" == COMPLETED ]] && break
  fi
  (( SECONDS < deadline )) || { cat status.txt "$log"; squeue; fail "the requeued job did not complete"; }
  sleep 0.2
done
cat "$log"
[[ $saw_interrupted == yes ]] || fail "status never showed the job interrupted between requeues"
grep -q "restart 0" "$log" || fail "the log lacks the first run"
grep -q "restart 1" "$log" || fail "the job did not run again after the requeue"
# On requeue Slurm ends the batch shell with the job, so the ranks' exit code is srun's to report.
grep -q "interrupted: checkpoint saved to $WORK/result.h5.checkpoint" "$log" || fail "the first run saved no checkpoint"
grep -q "Exited with exit code 75" "$log" || fail "the first run's ranks did not exit 75"
grep -q "resuming: [1-9][0-9]* of 512 work items already done" "$log" || fail "the second run did not resume"
expect_identical reference.h5 result.h5 /dfg
echo "PASS"
