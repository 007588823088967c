#!/usr/bin/env bash
# Ranks with different kernel sets (as on nodes of two CPU generations; here PBRFIT_KERNELS per rank) agree
# on the best set all of them have (core/kernel_set.hpp): the result is bitwise the one of a run with that
# set on every rank, and the log names the set. A symbolic-regression job, whose transcendental values
# differ between sets, so that a rank keeping its own set would show in the result.
source "$(dirname "$0")/lib/common.bash"

best=$("$PBRFIT" --version | sed -n 's/^kernels: \([a-z0-9]*\) .*/\1/p')
[[ -n $best ]] || fail "pbrfit --version names no kernel set"
cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-symreg.yaml" job.yaml

note "every rank on the generic set, then every rank on this machine's best ($best)"
PBRFIT_KERNELS=generic run_ranks 2 run job.yaml -o generic.h5 -q
expect_status 0
run_ranks 2 run job.yaml -o best.h5 >best.log 2>&1
cat best.log
expect_status 0
grep -q "2 ranks x 1 thread, $best kernels" best.log || fail "the log does not name the $best kernels"
if [[ $best != generic ]]; then
  h5diff -r generic.h5 best.h5 /y /y >/dev/null 2>&1 && fail "generic and $best gave the same front: this job cannot tell the sets apart"
fi

note "rank 0 on $best, rank 1 on generic: both use generic"
set +e
"$MPIEXEC" "${MPI_FLAGS[@]}" -np 1 -x PBRFIT_KERNELS="$best" "$PBRFIT" run job.yaml -o mixed.h5 : \
  -np 1 -x PBRFIT_KERNELS=generic "$PBRFIT" run job.yaml -o mixed.h5 >mixed.log 2>&1
STATUS=$?
set -e
cat mixed.log
expect_status 0
grep -q "2 ranks x 1 thread, generic kernels" mixed.log || fail "the log does not name the agreed generic kernels"
expect_identical generic.h5 mixed.h5 /y
expect_identical generic.h5 mixed.h5 /subexpressions

note "a kernel set this machine lacks, or no such set, is refused on one line"
PBRFIT_KERNELS=avx1024 run_pbrfit validate job.yaml
expect_status 2
[[ $(wc -l <err.txt) -eq 1 ]] && grep -q "^PBRFIT_KERNELS: error: must be generic, avx2 or avx512" err.txt ||
  { cat err.txt; fail "a bad PBRFIT_KERNELS is not refused on one line"; }
echo PASS
