#!/usr/bin/env bash
# A sweep stopped by SIGTERM (exit 75) and killed by SIGKILL mid-level, resumed each time (once on another
# rank count), ends bitwise identical to an uninterrupted run: warm starts come from kept results, and
# nothing is refitted differently after a resume.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-sweep.yaml" job.yaml
note "uninterrupted reference on 2 ranks"
run_ranks 2 run job.yaml --output reference.h5 -q
expect_status 0

note "SIGTERM during level 0"
interrupt_after 120 TERM 2 run job.yaml
[[ -f result.h5.checkpoint ]] || fail "no checkpoint after SIGTERM"

note "resume on 1 rank, SIGKILL during level 1"
interrupt_after $(($(items_done result.h5) + 400)) KILL 1 run job.yaml --resume

note "resume to completion on 2 ranks"
run_ranks 2 run job.yaml --resume -q
expect_status 0
expect_identical reference.h5 result.h5 /ltc
echo "PASS"
