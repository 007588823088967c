#!/usr/bin/env bash
# An error on any rank ends the whole job: exit 3, the reason logged once, the result marked failed.
source "$(dirname "$0")/lib/common.bash"

job_from tests/jobs/small-dfg.yaml job.yaml 's/  samples: edges/  samples: edges\n  tolerance: 1.0e-12\n  max_evaluations: 1000/'
run_ranks 2 run job.yaml 2>err.txt
cat err.txt
expect_status 3
[[ $(grep -c "job failed:" err.txt) -eq 1 ]] || fail "the failure is not logged exactly once"
grep -q "did not reach the tolerance" err.txt || fail "the failure does not say why"
"$PBRFIT" status result.h5 | grep -q "^state: *failed" || fail "status does not say failed"
[[ -f result.h5.checkpoint ]] || fail "no checkpoint after the failure"

note "an output directory that cannot be created"
touch blocker
job_from tests/jobs/small-dfg.yaml job2.yaml 's#output: result.h5#output: blocker/result.h5#'
run_ranks 2 run job2.yaml 2>err.txt
cat err.txt
expect_status 3
grep -q "cannot start the job" err.txt || fail "no clear message for an unwritable output"
echo "PASS"
