#!/usr/bin/env bash
# Stopped by SIGTERM or killed by SIGKILL at every stage boundary and in the middle of every stage, then
# resumed on another number of ranks: the synthetic multi-stage workload ends bitwise identical to an
# uninterrupted run. (The signal is raised by rank 0 itself at the exact point, so every case is hit.)
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_PROBE:?PBRFIT_PROBE must name pbrfit_runtime_probe}"

chain=(--stages 3 --items 16 --spin 400 --bytes 128 --checkpoint-items 3 -q)
probe() { local ranks=$1 out=$2; shift 2; set +e; "$MPIEXEC" "${MPI_FLAGS[@]}" -np "$ranks" "$PBRFIT_PROBE" "$out" "${chain[@]}" "$@" 2>probe.err; STATUS=$?; set -e; }

probe 2 reference.h5
expect_status 0

for signal in 15 9; do
  for point in "1 0" "2 0" "0 5" "1 5" "2 11"; do
    read -r stage after <<< "$point"
    note "signal $signal at stage $stage after $after results of it"
    rm -f result.h5 result.h5.checkpoint result.h5.journal
    probe 2 result.h5 --signal "$signal" --at-stage "$stage" --after "$after"
    if [[ $signal -eq 15 ]]; then
      expect_status 75 "SIGTERM on rank 0"
      [[ -f result.h5.checkpoint ]] || fail "no checkpoint after SIGTERM"
    else
      [[ $STATUS -ne 0 ]] || fail "a SIGKILLed rank 0 reported success"
    fi
    probe 3 result.h5 --resume
    expect_status 0 "resumed on 3 ranks"
    expect_identical reference.h5 result.h5 /chain
  done
done
echo "PASS"
