#!/usr/bin/env bash
# Bad input on the command line: one-line errors, exit code 2, no crash, also under mpirun.
source "$(dirname "$0")/lib/common.bash"

cat > bad.yaml <<'YAML'
name: bad
kind: lut
lut:
  function: dfg
  tolerence: 1e-6
YAML
expected="bad.yaml:5:3: error: unknown key 'tolerence' in 'lut'; did you mean 'tolerance'?"

set +e
"$PBRFIT" validate bad.yaml 2>err.txt; STATUS=$?
set -e
expect_status 2
[[ "$(cat err.txt)" == "$expected" ]] || { cat err.txt; fail "validate: wrong message"; }

run_ranks 2 run bad.yaml 2>err.txt
expect_status 2
[[ $(grep -c "error: unknown key 'tolerence'" err.txt) -eq 1 ]] || { cat err.txt; fail "run: not reported exactly once"; }

"$PBRFIT" validate "$PBRFIT_SOURCE_DIR/jobs/quickstart.yaml" | grep -q "ok: lut job 'dfg-quickstart', 128 work items" ||
  fail "validate does not accept the quickstart job"

set +e
"$PBRFIT" validate missing.yaml 2>err.txt; STATUS=$?
set -e
expect_status 2
grep -q "^missing.yaml: error: cannot read job file" err.txt || { cat err.txt; fail "missing job file"; }

echo "just text" > fake.h5
set +e
"$PBRFIT" status fake.h5 2>err.txt; STATUS=$?
set -e
expect_status 2
grep -q "^fake.h5: error: not a readable HDF5 file" err.txt || { cat err.txt; fail "status of a non-HDF5 file"; }

set +e
"$PBRFIT" run 2>err.txt; STATUS=$?
set -e
expect_status 2
set +e
"$PBRFIT" frobnicate 2>err.txt; STATUS=$?
set -e
expect_status 2
! grep -qi "terminate\|abort\|stack" err.txt || fail "usage errors crash"
note "submit: bad jobs are refused before Slurm is asked; --dry-run renders one script per job"
set +e
"$PBRFIT" submit bad.yaml --dry-run 2>err.txt; STATUS=$?
set -e
expect_status 2
[[ "$(cat err.txt)" == "$expected" ]] || { cat err.txt; fail "submit: wrong message"; }
cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" a.yaml
cp "$PBRFIT_SOURCE_DIR/tests/jobs/resume-dfg.yaml" b.yaml
"$PBRFIT" submit a.yaml b.yaml --dry-run --ranks 4 --threads 3 --time 30 > scripts.txt
[[ $(grep -c "^#SBATCH --requeue" scripts.txt) -eq 2 ]] || fail "submit --dry-run did not render two scripts"
[[ $(grep -c "^#SBATCH --ntasks=4" scripts.txt) -eq 2 ]] || fail "--ranks did not override the job's ranks"
[[ $(grep -c "^#SBATCH --cpus-per-task=3" scripts.txt) -eq 2 ]] || fail "--threads did not set the CPUs per task"
grep -q "^srun --mpi=pmix --cpus-per-task=3 '.*/pbrfit' run '$WORK/a.yaml' --output '$WORK/result.h5' --resume$" scripts.txt ||
  { cat scripts.txt; fail "the script does not run the job with --resume"; }
set +e
"$PBRFIT" submit a.yaml --dry-run --time "soon" 2>err.txt; STATUS=$?
set -e
expect_status 2
grep -q "^--time: error: 'soon' is not a Slurm time limit" err.txt || { cat err.txt; fail "submit accepted a bad --time"; }
echo "PASS"
