#!/usr/bin/env bash
# Builds pbrfit with clang and the given sanitizers in a build folder of its own, runs a part of the suite
# there and fails on any sanitizer report, whether or not the test that met it failed.
#   tests/sanitizers/run.sh SANITIZERS BUILD_DIR unit|all
#     SANITIZERS: address,undefined (ASan + UBSan) or thread (TSan)
#     unit: the unit tests (the in-process runtime tests among them); all: every test but the layer checks
#     (compile checks, nothing to sanitize) and, under TSan, the MPI tests (docs/RELIABILITY.md says why).
#   TESTS=regex runs only the tests of that part whose names match (to check a fix again).
# Reports go to BUILD_DIR/sanitizer-reports/ (one file per reporting process); the options and the
# suppressions of libraries that are not pbrfit's are in this folder.
set -euo pipefail
sanitizers=$1 build=$2 part=$3
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)

case $sanitizers in
  address,undefined|thread) ;;
  *) echo "run.sh: sanitizers must be address,undefined or thread, not '$sanitizers'" >&2; exit 2 ;;
esac
case $part in
  unit) select=(-L unit -E '^layers:') ;;
  all) select=(-E '^layers:') ;;
  *) echo "run.sh: part must be unit or all, not '$part'" >&2; exit 2 ;;
esac
[[ $sanitizers == thread && $part == all ]] && select=(-L unit -E '^layers:')
[[ -n ${TESTS:-} ]] && select+=(-R "$TESTS")

start=$SECONDS
cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DPBRFIT_SANITIZE="$sanitizers" >/dev/null
if [[ $part == unit ]]; then
  targets=(test_core test_engines test_spec test_store test_texture test_runtime test_jobs test_submit)
  for format in job_file expression csv merl image radiance_hdr checkpoint journal result_file; do
    targets+=("fuzz_replay_$format")
  done
else
  targets=(all)
fi
cmake --build "$build" -j "${JOBS:-2}" --target "${targets[@]}"
built=$SECONDS

reports=$(cd "$build" && pwd)/sanitizer-reports
crashes=$(cd "$build" && pwd)/tracer-crashes
rm -rf "$reports" "$crashes" && mkdir -p "$reports"
common="log_path=$reports/report:print_suppressions=0"
# The slow unwinder at malloc: OpenMPI unloads its components in MPI_Finalize, and the fast one stops in
# them (no frame pointers), leaving leaks without a module lsan.supp could name; the slow one reaches the
# OpenMPI library that called them.
export ASAN_OPTIONS="$common:detect_leaks=1:fast_unwind_on_malloc=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="$common:print_stacktrace=1:halt_on_error=1"
export TSAN_OPTIONS="$common:halt_on_error=1:second_deadlock_stack=1:suppressions=$here/tsan.supp"
status=0
log=$(cd "$build" && pwd)/sanitized-tests.log
(cd "$build" && ctest --output-on-failure "${select[@]}" -j 1) 2>&1 | tee "$log" || status=${PIPESTATUS[0]}

# LeakSanitizer's own tracer sometimes crashes at a process's exit ("Tracer caught signal 11 ... LeakSanitizer
# has encountered a fatal error", google/sanitizers#1353, open): a failure of the tool, not a report about
# the program. When every report is such a crash, the failed tests run once more, and only their second
# run counts; the crashes are kept in tracer-crashes/ and named here. Any other report fails the run.
tracer_crash_only() {
  grep -q 'LeakSanitizer has encountered a fatal error' "$1" &&
    ! grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer: detected)|runtime error|WARNING: ThreadSanitizer' "$1"
}
found=$(find "$reports" -type f | sort)
if [[ $status -ne 0 ]] && grep -qs 'LeakSanitizer has encountered a fatal error' "$log" $found; then
  crashes_only=1
  for f in $found; do tracer_crash_only "$f" || crashes_only=0; done
  if ((crashes_only)); then
    mkdir -p "$crashes" && cp "$log" "$crashes/" && { [[ -z $found ]] || mv $found "$crashes/"; }
    echo "run.sh: LeakSanitizer's tracer crashed (google/sanitizers#1353); the failed tests run once more" \
      "(the first run's log and reports: $crashes/)" >&2
    status=0
    (cd "$build" && ctest --output-on-failure --rerun-failed -j 1) || status=$?
    found=$(find "$reports" -type f | sort)
  fi
fi
if [[ -n $found ]]; then
  for f in $found; do echo "== $f"; cat "$f"; done
  echo "run.sh: $(wc -l <<<"$found") sanitizer report(s) under $sanitizers" >&2
  status=1
fi
echo "run.sh: $sanitizers $part: built in $((built - start)) s, tests in $((SECONDS - built)) s, status $status"
exit $status
