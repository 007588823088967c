#!/usr/bin/env bash
# A full disk is a run failure, not a crash: exit 3 naming the reason, no temporary file left behind,
# the checkpoint intact, `status` saying how to get the result back, and once there is room again
# --resume ends with the same numbers. Needs a size-limited tmpfs (skipped where mounting is not allowed).
source "$(dirname "$0")/lib/common.bash"

mkdir small
mount -t tmpfs -o size=200k tmpfs small 2>/dev/null || { echo "SKIP: cannot mount a tmpfs here"; exit 77; }
trap 'umount small 2>/dev/null || true; kill_group_if_running; rm -rf "$WORK"' EXIT

cp "$PBRFIT_SOURCE_DIR/jobs/quickstart.yaml" job.yaml
run_ranks 1 run job.yaml --output reference.h5 -q
expect_status 0

for ranks in 1 2; do
  note "$ranks rank(s) on a 200 KiB disk"
  rm -f small/*
  run_ranks $ranks run job.yaml --output small/result.h5 -q 2>err.txt
  expect_status 3 "a full disk"
  grep -q "No space left on device" err.txt || { cat err.txt; fail "the reason is not named"; }
  ! grep -q "Segmentation\|Aborted\|terminate called" err.txt || { cat err.txt; fail "crashed"; }
  ! ls small/*.tmp >/dev/null 2>&1 || fail "temporary files left: $(ls small)"
  [[ -f small/result.h5.checkpoint ]] || fail "no checkpoint"
  set +e
  "$PBRFIT" status small/result.h5 2>status.txt
  set -e
  grep -q "checkpoint is intact: \`pbrfit run JOB --resume\` rebuilds it\|state: *failed" status.txt ||
    { cat status.txt; fail "status does not say how to get the result back"; }
done

note "a read-only output directory: exit 3 with the OS's reason"
mkdir readonly
mount -t tmpfs -o ro,size=100k tmpfs readonly
run_ranks 1 run job.yaml --output readonly/result.h5 -q 2>err.txt
umount readonly
expect_status 3 "a read-only directory"
grep -q "Read-only file system" err.txt || { cat err.txt; fail "the reason is not named"; }

note "room again: --resume completes to the same numbers"
mount -o remount,size=20m small
run_ranks 2 run job.yaml --output small/result.h5 --resume -q
expect_status 0
expect_identical reference.h5 small/result.h5 /dfg
echo "PASS"
