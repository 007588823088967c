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

note "the cloth channel, on 1 and 2 ranks and interrupted"
cat > cloth.yaml <<'YAML'
name: cloth
kind: lut
output: result.h5
checkpoint: {interval_items: 3}
lut: {function: dfg, cloth: true, multiple_scattering: true, resolution: [24, 16], samples: edges}
YAML
run_ranks 1 run cloth.yaml --output cloth-one.h5 -q
expect_status 0
run_ranks 2 run cloth.yaml --output cloth-two.h5 -q
expect_status 0
expect_identical cloth-one.h5 cloth-two.h5 /dfg
/usr/bin/python3 -c "
import h5py, numpy as np
g = h5py.File('cloth-two.h5', 'r')['dfg']
c = g['cloth'][...]
assert c.shape == (16, 24) and np.isfinite(c).all() and (c >= 0).all(), c
assert (g['cloth_error_estimate'][...] <= 1e-6).all()
assert c[0].max() == 0.0, 'roughness 0 (alpha 0) has no sheen albedo'
assert 0.1 < c[-1, -1] < 1.0, c[-1, -1]
" || fail "the cloth channel is wrong"
echo "PASS"
