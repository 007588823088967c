#!/usr/bin/env bash
# A fuzz campaign (make fuzz): builds the libFuzzer targets with clang, ASan and UBSan in build-fuzz/, then
# runs each for SECONDS (default 600), two at a time, from its seeds (tests/fuzz/corpus/<target>/, plus
# the shipped and test job files for job_file) and its dictionary (tests/fuzz/dict/<target>.dict).
#   tests/fuzz/run.sh [SECONDS] [TARGET...]
# Each target's new corpus grows in build-fuzz/corpus/<target>/; a crash, leak, hang (25 s per input, 120 s
# for job_file) or allocation beyond 2 GiB leaves its input in build-fuzz/findings/<target>/ (emptied when
# its campaign starts: keep what matters in tests/fuzz/regressions/) and fails the campaign. The summary
# (executions, coverage, slowest input, findings per target) is build-fuzz/summary.txt.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
build=${BUILD_FUZZ:-$source_dir/build-fuzz}
seconds=${1:-600}; shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(job_file expression csv merl image radiance_hdr checkpoint journal result_file)
[[ $seconds =~ ^[0-9]+$ && $seconds -gt 0 ]] || { echo "run.sh: SECONDS must be a positive whole number, not '$seconds'" >&2; exit 2; }

cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DPBRFIT_SANITIZE=address,undefined -DPBRFIT_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build "$build" -j 2 --target "${targets[@]/#/fuzz_}"

# The MERL format has one size (34,992,012 bytes): a valid file, made here, seeds its target.
merl_seed=$build/seeds/merl
if [[ ! -f $merl_seed/valid.binary ]]; then
  mkdir -p "$merl_seed"
  /usr/bin/python3 -c "
import struct, sys
n = 90 * 90 * 180 * 3
with open(sys.argv[1], 'wb') as f:
    f.write(struct.pack('<3i', 90, 90, 180))
    f.write(struct.pack('<%dd' % n, *((i % 97) / 97.0 for i in range(n))))" "$merl_seed/valid.binary"
fi

# Job files naming a measured material tabulate its neural stand-in on the MERL grid (1.1 s in a release
# build, about 30 s under ASan at -O1); the campaign runs in $build, whose results/merl-cache keeps those
# tables as jobs' own default cache does. The release program (make program) fills it for the seeds'
# materials first, so that seeds are not mistaken for hangs; a material first met while fuzzing is
# tabulated once within the job_file target's longer limit, then read from the cache.
release=${PBRFIT_RELEASE:-$source_dir/build/pbrfit}
if [[ " ${targets[*]} " == *" job_file "* && -x $release ]]; then
  for job in $(grep -l -E '^ *(brdf: *\{ *)?material:|^ *materials:' "$source_dir"/jobs/*.yaml "$source_dir"/tests/jobs/*.yaml); do
    (cd "$build" && "$release" validate "$job" >/dev/null 2>&1) || true
  done
fi

export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0"
export LSAN_OPTIONS="suppressions=$source_dir/tests/sanitizers/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
summary=$build/summary.txt
: >"$summary"

campaign() {
  local target=$1 corpus=$build/corpus/$1 findings=$build/findings/$1 seeds=() extra=() timeout=25 asan=$ASAN_OPTIONS
  rm -rf "$findings" && mkdir -p "$corpus" "$findings"
  [[ -d $here/corpus/$1 ]] && seeds+=("$here/corpus/$1")
  case $target in
    job_file) seeds+=("$source_dir/jobs" "$source_dir/tests/jobs" "$source_dir/tests/bad_jobs"); timeout=120 ;;
    merl) seeds+=("$merl_seed"); extra+=(-max_len=34992012 -rss_limit_mb=4096) ;;
    checkpoint|journal) extra+=(-max_len=200000) ;;
    # The slow unwinder reaches H5O_protect inside HDF5 (built without frame pointers) for lsan.supp.
    result_file) extra+=(-max_len=200000); asan="$asan:fast_unwind_on_malloc=0" ;;
  esac
  [[ -f $here/dict/$target.dict ]] && extra+=(-dict="$here/dict/$target.dict")
  local log=$build/fuzz-$target.log
  # A bound on the whole campaign: libFuzzer's handler of the memory limit can hang here (its heap profile
  # never finishes on a 2 GiB heap), leaving the input unwritten; the log still names the limit.
  set +e
  (cd "$build" && ASAN_OPTIONS=$asan TMPDIR=$build timeout -k 10 $((seconds + 600)) "$build/tests/fuzz/fuzz_$target" "$corpus" "${seeds[@]}" -max_total_time="$seconds" \
     -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" "${extra[@]}") >"$log" 2>&1
  local status=$?
  set -e
  local runs cov found
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | tr -dc 0-9 || true)
  # libFuzzer also keeps inputs slower than 10 s as slow-unit-*: reported, not findings.
  found=$(find "$findings" -type f ! -name 'slow-unit-*' | wc -l)
  slowest=$(sed -n 's/^stat::slowest_unit_time_sec: *//p' "$log" | tail -1)
  printf '%-13s exit %3s  executions %10s  coverage (edges) %6s  slowest input %4s s  findings %s\n' "$target" \
    "$status" "${runs:-?}" "${cov:-?}" "${slowest:-?}" "$found" >>"$summary"
}

running=0
for target in "${targets[@]}"; do
  campaign "$target" &
  running=$((running + 1))
  if (( running == 2 )); then wait -n || true; running=$((running - 1)); fi
done
wait || true
sort "$summary" -o "$summary"
cat "$summary"
if (( $(wc -l <"$summary") != ${#targets[@]} )); then
  echo "run.sh: $(( ${#targets[@]} - $(wc -l <"$summary") )) campaign(s) did not report; logs: $build/fuzz-<target>.log" >&2
  exit 1
fi
if grep -qv "findings 0$" "$summary" || grep -q "exit  *[1-9]" "$summary"; then
  echo "run.sh: findings (inputs under $build/findings/); logs: $build/fuzz-<target>.log" >&2
  exit 1
fi
