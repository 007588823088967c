#!/usr/bin/env bash
# Determinism under interruption: a job stopped by SIGTERM (exit 75), killed by SIGKILL, and resumed
# each time, ends with numeric datasets bitwise identical to an uninterrupted run; and the same for a table
# with the cloth channel, killed once.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" job.yaml
note "uninterrupted reference on 2 ranks"
run_ranks 2 run job.yaml --output reference.h5 -q
expect_status 0

note "SIGTERM to every rank after some items: checkpoint and exit 75"
interrupt_after 60 TERM 2 run job.yaml
[[ -f result.h5.checkpoint ]] || fail "no checkpoint after SIGTERM"
wait_for_state result.h5 "interrupted$"

note "resume, then SIGKILL the whole job"
interrupt_after $(($(items_done result.h5) + 120)) KILL 2 run job.yaml --resume
[[ -f result.h5.checkpoint ]] || fail "no checkpoint survived SIGKILL"
wait_for_state result.h5 "interrupted (the job stopped without saying so; its checkpoint can be resumed)"

note "resume on 1 rank, then SIGINT"
interrupt_after $(($(items_done result.h5) + 30)) INT 1 run job.yaml --resume

note "resume to completion on 2 ranks"
run_ranks 2 run job.yaml --resume
expect_status 0
[[ ! -f result.h5.checkpoint ]] || fail "the checkpoint outlived the completed job"
expect_identical reference.h5 result.h5 /dfg

note "resume of a complete job does nothing"
run_ranks 2 run job.yaml --resume
expect_status 0
expect_identical reference.h5 result.h5 /dfg

note "the cloth channel: SIGKILL, resume on 1 rank, identical to an uninterrupted run"
job_from tests/jobs/resume-dfg.yaml cloth.yaml "s/multiple_scattering: true/multiple_scattering: true\n  cloth: true/" \
  "s/resolution: .*/resolution: [64, 256]/" "s|^output: .*|output: cloth.h5|"
grep -q "cloth: true" cloth.yaml || fail "the cloth job was not made"
run_ranks 2 run cloth.yaml --output cloth-reference.h5 -q
expect_status 0
interrupt_after 40 KILL 2 run cloth.yaml
[[ -f cloth.h5.checkpoint ]] || fail "no checkpoint of the cloth job survived SIGKILL"
run_ranks 1 run cloth.yaml --resume -q
expect_status 0
expect_identical cloth-reference.h5 cloth.h5 /dfg
echo "PASS"
