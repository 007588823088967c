#!/usr/bin/env bash
# Fault injection, many rounds (make soak; not part of make test). Each round runs the resume DFG job on
# 2 ranks and injects one fault at a random moment, resumes until complete, and checks the result
# against an undisturbed run. Counts crashes (exit by a signal pbrfit should have handled or a core
# dump message), hangs (no end within 120 s), unreadable results after resume and numeric mismatches.
# Usage: PBRFIT=build/pbrfit PBRFIT_SOURCE_DIR=. tests/soak/fault_soak.sh [ROUNDS]
source "$(dirname "$0")/../mpi/lib/common.bash"
ROUNDS=${1:-20}

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" job.yaml
run_ranks 2 run job.yaml --output reference.h5 -q
expect_status 0

crashes=0 hangs=0 unreadable=0 mismatches=0
count_crash() { grep -qE "Segmentation|Aborted|terminate called|\*\*\* Process received" err.txt && crashes=$((crashes + 1)) || true; }

random_delay() { printf '%d.%03d' $((RANDOM % 3)) $((RANDOM % 1000)); }

wait_bounded() {
  local start=$SECONDS
  while background_running; do
    (( SECONDS - start < 120 )) || { hangs=$((hangs + 1)); kill_session KILL; break; }
    sleep 0.1
  done
  wait_background
}

# Resumes until the job completes (at most 5 tries), then compares with the reference.
finish_and_compare() {
  local tries
  for tries in 1 2 3 4 5; do
    [[ -f result.h5.checkpoint || ! -f result.h5 ]] || break
    set +e; timeout 300 "$MPIEXEC" "${MPI_FLAGS[@]}" -np 2 "$PBRFIT" run job.yaml --resume -q 2>>err.txt; STATUS=$?; set -e
    [[ $STATUS -eq 124 ]] && hangs=$((hangs + 1))
    [[ $STATUS -eq 0 ]] && break
  done
  "$PBRFIT" status result.h5 >/dev/null 2>&1 || { unreadable=$((unreadable + 1)); return; }
  h5diff -r reference.h5 result.h5 /dfg /dfg >/dev/null 2>&1 || mismatches=$((mismatches + 1))
}

fault_kill_random_rank() {
  start_ranks 2 run job.yaml -q --rank-timeout 5 2>err.txt
  sleep "$(random_delay)"
  local pids=($(started_rank_pids))
  (( ${#pids[@]} )) && kill -KILL "${pids[RANDOM % ${#pids[@]}]}" 2>/dev/null || true
  wait_bounded
}
fault_kill_every_rank() {
  start_ranks 2 run job.yaml -q 2>err.txt
  sleep "$(random_delay)"
  kill_session KILL
  wait_bounded
}
fault_stop_signal() {
  start_ranks 2 run job.yaml -q 2>err.txt
  sleep "$(printf '0.%03d' $((20 + RANDOM % 980)))"
  kill -"$(shuf -n1 -e TERM USR1 INT)" $(started_rank_pids) 2>/dev/null || true
  wait_bounded
}
fault_two_runs_one_output() {
  start_ranks 2 run job.yaml -q 2>err.txt
  sleep "$(random_delay)"
  set +e; timeout 120 "$PBRFIT" run job.yaml -q --resume 2>>err.txt; set -e
  wait_bounded
}
fault_full_disk() {
  rm -rf disk && mkdir disk
  mount -t tmpfs -o size=$((100 + RANDOM % 400))k tmpfs disk || { echo "SKIP full disk: cannot mount"; return; }
  set +e; timeout 120 "$MPIEXEC" "${MPI_FLAGS[@]}" -np 2 "$PBRFIT" run job.yaml --output disk/result.h5 -q 2>err.txt; STATUS=$?; set -e
  [[ $STATUS -eq 124 ]] && hangs=$((hangs + 1))
  count_crash
  mount -o remount,size=50m disk
  set +e; timeout 300 "$MPIEXEC" "${MPI_FLAGS[@]}" -np 2 "$PBRFIT" run job.yaml --output disk/result.h5 --resume -q 2>>err.txt; set -e
  "$PBRFIT" status disk/result.h5 >/dev/null 2>&1 || unreadable=$((unreadable + 1))
  h5diff -r reference.h5 disk/result.h5 /dfg /dfg >/dev/null 2>&1 || mismatches=$((mismatches + 1))
  umount disk
}

for fault in kill_random_rank kill_every_rank stop_signal two_runs_one_output full_disk; do
  crashes=0 hangs=0 unreadable=0 mismatches=0
  start=$SECONDS
  for round in $(seq 1 "$ROUNDS"); do
    rm -f result.h5 result.h5.*
    "fault_$fault"
    count_crash
    [[ $fault == full_disk ]] || finish_and_compare
  done
  printf '%-22s rounds %3d  crashes %d  hangs %d  unreadable %d  mismatches %d  (%d s)\n' \
    "$fault" "$ROUNDS" "$crashes" "$hangs" "$unreadable" "$mismatches" $((SECONDS - start))
done
