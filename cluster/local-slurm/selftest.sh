#!/usr/bin/env bash
# Prove the local Slurm cluster works: start it, run plain and MPI (PMIx) steps, requeue a
# running batch job, check --signal early warnings, stop it.
#
# Usage:  cluster/local-slurm/selftest.sh [--keep] [STATE_DIR]
#   --keep   keep STATE_DIR afterwards (it is always kept when a check fails).
# Exit 0 when every check passed, 77 when Slurm/munge are not installed, 1 otherwise.
# Takes about 1-1.5 minutes (the requeue cycle and the 30-s --signal tick dominate).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
keep=0
state=
for a in "$@"; do
  case "$a" in
    --keep) keep=1 ;;
    -h|--help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "selftest: unknown option $a" >&2; exit 1 ;;
    *) state=$a ;;
  esac
done
[[ -n $state ]] || state=$(mktemp -d "${TMPDIR:-/tmp}/local-slurm-selftest.XXXXXX")

passed=0
failed=0
ok()   { echo "ok   - $*"; passed=$((passed + 1)); }
fail() { echo "FAIL - $*"; failed=$((failed + 1)); }
info() { echo "       $*"; }
now()  { echo "$EPOCHREALTIME"; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

# wait_for SECONDS COMMAND...: poll COMMAND every 0.2 s until it succeeds; 1 on timeout.
wait_for() {
  local deadline=$((SECONDS + $1))
  shift
  until "$@"; do
    ((SECONDS < deadline)) || return 1
    sleep 0.2
  done
}
job_state() { scontrol show job "$1" 2>/dev/null | grep -o -m1 'JobState=[A-Z_]*' | cut -d= -f2; }
job_field() { scontrol show job "$1" 2>/dev/null | grep -o -m1 "$2=[^ ]*" | cut -d= -f2; }
job_is()    { [[ $(job_state "$1") == "$2" ]]; }
job_gone_or_done() { local s; s=$(job_state "$1"); [[ -z $s || $s =~ ^(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY)$ ]]; }
log_has()   { grep -q -- "$2" "$1" 2>/dev/null; }
log_count() { grep -c -- "$2" "$1" 2>/dev/null || true; }
# first_time LOG PATTERN: the [EPOCHREALTIME] stamp of the first line matching PATTERN.
first_time() { grep -m1 -- "$2" "$1" 2>/dev/null | sed -n 's/^\[\([0-9.]*\)\].*/\1/p'; }

# --- start -----------------------------------------------------------------------------------
echo "local Slurm selftest, STATE_DIR=$state"
started_pids=
finish() {
  local rc=$?
  if [[ -n $started_pids ]]; then
    "$here/stop.sh" "$state" 2>&1 | sed 's/^/       /' || true
    local p left=()
    for p in $started_pids; do
      [[ -d /proc/$p ]] && ! grep -q '^State:.*Z' "/proc/$p/status" 2>/dev/null && left+=("$p")
    done
    if [[ ${#left[@]} -eq 0 ]]; then ok "stop.sh stopped every daemon start.sh had started"
    else fail "daemons still running after stop.sh: ${left[*]}"; fi
  fi
  if [[ $rc -eq 77 ]]; then exit 77; fi
  echo "$passed passed, $failed failed"
  if [[ $failed -gt 0 || $rc -ne 0 ]]; then
    echo "selftest FAILED; logs kept in $state/log and $state/selftest"
    exit 1
  fi
  if [[ $keep -eq 0 ]]; then rm -rf -- "$state"; fi
  echo "selftest passed"
}
trap finish EXIT

rc=0
env_lines=$("$here/start.sh" "$state") || rc=$?
if [[ $rc -eq 77 ]]; then echo "SKIP - local Slurm unavailable (see above)"; exit 77; fi
started_pids=$(awk '{ print $2 }' "$state/pids" 2>/dev/null | tr '\n' ' ')
if [[ $rc -ne 0 ]]; then fail "start.sh exited with $rc"; exit 1; fi
eval "$env_lines"
ok "start.sh: node idle; it printed: $(echo "$env_lines" | tr '\n' ';')"
[[ $SLURM_CONF == "$state/slurm.conf" ]] || fail "SLURM_CONF is $SLURM_CONF"

work=$state/selftest
mkdir -p "$work"
cd "$work"

# --- 1. plain step ---------------------------------------------------------------------------
if out=$(timeout 60 srun -n 2 hostname 2>&1) && [[ $(wc -l <<<"$out") -eq 2 ]]; then
  ok "srun -n 2 hostname -> $(echo "$out" | tr '\n' ' ')"
else
  fail "srun -n 2 hostname: $out"
fi

# --- 2. MPI over PMIx ------------------------------------------------------------------------
cat >mpi_hello.c <<'EOF'
#include <mpi.h>
#include <stdio.h>
int main(int argc, char **argv) {
  int rank, size, sum = 0;
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Allreduce(&rank, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  printf("rank %d of %d (sum of ranks %d)\n", rank, size, sum);
  MPI_Finalize();
  return (size == 2 && sum == 1) ? 0 : 3;
}
EOF
if ! command -v mpicc >/dev/null 2>&1; then
  fail "mpicc not found (install openmpi-bin libopenmpi-dev)"
elif ! mpicc -o mpi_hello mpi_hello.c 2>mpicc.err; then
  fail "mpicc failed: $(cat mpicc.err)"
elif out=$(timeout 60 srun --mpi=pmix -n 2 ./mpi_hello 2>&1) &&
     grep -q "rank 0 of 2" <<<"$out" && grep -q "rank 1 of 2" <<<"$out"; then
  ok "srun --mpi=pmix -n 2 mpi_hello: $(echo "$out" | sort | tr '\n' ' ')"
else
  fail "srun --mpi=pmix -n 2 mpi_hello: $out"
fi

# --- 3. requeue of a running batch job ---------------------------------------------------------
# Task: ~20 s of short sleeps (no child processes, so traps run at once), TERM -> exit 75,
# USR1 -> exit 0 when EXIT_ON_USR1 is set.
cat >task.sh <<'EOF'
#!/bin/bash
me="task $SLURM_PROCID restart=${SLURM_RESTART_COUNT:-0}"
trap 'echo "[$EPOCHREALTIME] $me got TERM"; exit 75' TERM
trap 'echo "[$EPOCHREALTIME] $me got USR1"; [ -n "${EXIT_ON_USR1:-}" ] && exit 0' USR1
exec 3<> <(:)   # a pipe nobody writes to: read -t sleeps without forking
echo "[$EPOCHREALTIME] $me start"
for ((i = 0; i < ${STEPS:-200}; i++)); do read -r -t 0.1 -u 3 || true; done
echo "[$EPOCHREALTIME] $me done"
[ -z "${EXIT_ON_USR1:-}" ]   # waiting for USR1 but none came: fail
EOF
cat >job.sh <<'EOF'
#!/bin/bash
echo "[$EPOCHREALTIME] batch start job=$SLURM_JOB_ID restart=${SLURM_RESTART_COUNT:-0}"
srun --mpi=pmix -n 2 ./task.sh &
srun_pid=$!
trap 'echo "[$EPOCHREALTIME] batch got TERM"' TERM
exec 3<> <(:)
# With FORWARD_USR1 the script passes USR1 on to srun (which forwards it to the tasks) after 2 s,
# so a task that got it directly from Slurm would show it 2 s earlier.
trap 'echo "[$EPOCHREALTIME] batch got USR1"; [ -n "${FORWARD_USR1:-}" ] && { read -r -t 2 -u 3; kill -USR1 $srun_pid; }' USR1
while :; do   # wait returns early when a trapped signal arrives
  wait $srun_pid; rc=$?
  [ $rc -gt 128 ] && kill -0 $srun_pid 2>/dev/null || break
done
echo "[$EPOCHREALTIME] batch: srun rc=$rc"
exit $rc
EOF
chmod +x task.sh job.sh

rq_log=$work/requeue.log
jid=$(sbatch --parsable -J requeue -n 2 --requeue --open-mode=append -o "$rq_log" job.sh)
both_started() { log_has "$rq_log" "task 0 restart=0 start" && log_has "$rq_log" "task 1 restart=0 start"; }
if ! wait_for 30 both_started; then
  fail "requeue job $jid: tasks did not start within 30 s (state $(job_state "$jid"))"
else
  sleep 2
  t_rq=$(now)
  if scontrol requeue "$jid"; then ok "scontrol requeue $jid accepted while RUNNING"; else fail "scontrol requeue $jid"; fi
  sleep 1
  info "right after requeue: JobState=$(job_state "$jid") Reason=$(job_field "$jid" Reason) Restarts=$(job_field "$jid" Restarts) EligibleTime=$(job_field "$jid" EligibleTime)"
  wait_for 90 log_has "$rq_log" "batch start job=$jid restart=1" || true
  t_restart=$(first_time "$rq_log" "batch start job=$jid restart=1")
  wait_for 60 job_gone_or_done "$jid" || true
  final=$(job_state "$jid")
  t_term0=$(first_time "$rq_log" "task 0 restart=0 got TERM")
  t_term1=$(first_time "$rq_log" "task 1 restart=0 got TERM")
  if [[ -n $t_term0 && -n $t_term1 ]]; then
    ok "first run: both tasks got SIGTERM $(secs "$t_rq" "$t_term0") s after scontrol requeue"
  else
    fail "first run: SIGTERM not seen by both tasks"
  fi
  if log_has "$rq_log" "batch: srun rc=75"; then ok "first run: srun returned the tasks' exit code 75"; else fail "first run: no 'srun rc=75'"; fi
  if [[ -n $t_restart ]]; then
    ok "job ran again (SLURM_RESTART_COUNT=1) $(secs "$t_rq" "$t_restart") s after scontrol requeue"
  else
    fail "job $jid did not start again within 90 s"
  fi
  if [[ $(log_count "$rq_log" "batch start job=$jid") -eq 2 ]]; then
    ok "--open-mode=append log keeps both runs"
  else
    fail "expected 2 'batch start' lines in $rq_log, got $(log_count "$rq_log" "batch start")"
  fi
  if [[ $final == COMPLETED ]] && log_has "$rq_log" "task 0 restart=1 done" && log_has "$rq_log" "batch: srun rc=0"; then
    ok "second run completed: JobState=COMPLETED Restarts=$(job_field "$jid" Restarts) ExitCode=$(job_field "$jid" ExitCode)"
  else
    fail "second run: JobState=${final:-gone}; log: $(tail -n 3 "$rq_log" | tr '\n' ' ')"
  fi
fi

# --- 4. --signal early warning -----------------------------------------------------------------
# slurmctld checks warning signals every 30 s and sends them at the first check at which
# (time left - 30 s) <= N, so with --time=1 and @50 they arrive 0-30 s after start.
signal_job() {  # signal_job NAME SIGNAL_SPEC [ENV...]: run, wait, print the log path
  local name=$1 spec=$2 log=$work/$1.log j
  shift 2
  rm -f "$log"
  j=$(env "$@" STEPS=450 EXIT_ON_USR1=1 sbatch --parsable -J "$name" -n 2 --time=1 \
      --signal="$spec" -o "$log" job.sh)
  wait_for 70 job_gone_or_done "$j" || true
  echo "$log $j"
}

read -r log j < <(signal_job sig-steps USR1@50)
t0=$(first_time "$log" "task 0 restart=0 start")
u0=$(first_time "$log" "task 0 restart=0 got USR1")
u1=$(first_time "$log" "task 1 restart=0 got USR1")
if [[ -n $u0 && -n $u1 ]] && ! log_has "$log" "batch got USR1"; then
  ok "--signal=USR1@50: both tasks of the step got USR1 $(secs "$t0" "$u0") s after start; the batch shell did not"
  [[ $(secs "$t0" "$u0" | cut -d. -f1) -le 32 ]] || fail "USR1 later than the 30 s check period"
else
  fail "--signal=USR1@50 (job $j, $(job_state "$j")): $(tr '\n' ' ' <"$log")"
fi

read -r log j < <(signal_job sig-batch B:USR1@50 FORWARD_USR1=1)
t0=$(first_time "$log" "batch start")
b=$(first_time "$log" "batch got USR1")
u0=$(first_time "$log" "task 0 restart=0 got USR1")
u1=$(first_time "$log" "task 1 restart=0 got USR1")
if [[ -n $b && -n $u0 && -n $u1 ]] && awk -v b="$b" -v u="$u0" -v v="$u1" 'BEGIN { exit !(u >= b + 1.9 && v >= b + 1.9) }'; then
  ok "--signal=B:USR1@50: batch shell got USR1 $(secs "$t0" "$b") s after start; the tasks only when the script forwarded it to srun ($(secs "$b" "$u0") s later)"
else
  fail "--signal=B:USR1@50 (job $j, $(job_state "$j")): $(tr '\n' ' ' <"$log")"
fi
# finish (EXIT trap) stops the cluster and prints the summary.
