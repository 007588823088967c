#!/usr/bin/env bash
# A 2-rank run completes, and its numeric datasets are bitwise identical to a 1-rank run.
source "$(dirname "$0")/lib/common.bash"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" job.yaml
note "1 rank"
run_ranks 1 run job.yaml --output one.h5 -q
expect_status 0
note "2 ranks"
run_ranks 2 run job.yaml --output two.h5
expect_status 0
expect_identical one.h5 two.h5 /dfg

"$PBRFIT" status two.h5 | tee status.txt
grep -q "^state: *complete" status.txt || fail "status does not say complete"
grep -q "^progress: *24 of 24 work items" status.txt || fail "status progress is wrong"
grep -q "2 ranks" status.txt || fail "status does not report 2 ranks"

note "self-describing attributes"
for attribute in pbrfit_version job_name job_kind job_yaml seed ranks state started_utc finished_utc; do
  h5dump -a "/$attribute" two.h5 >/dev/null || fail "missing root attribute $attribute"
done
h5dump -a /job_yaml two.h5 | grep -q "separable_schlick" || fail "job_yaml does not hold the job text"
h5dump -a /dfg/scale/DIMENSION_LIST two.h5 >/dev/null || fail "scale has no dimension scales attached"
h5dump -d /dfg/n_dot_v two.h5 | grep -q "0, 0.0322581" || fail "n_dot_v axis is not at the edges"
echo "PASS"
