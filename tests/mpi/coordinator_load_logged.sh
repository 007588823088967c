#!/usr/bin/env bash
# The verbose log states what coordinating cost rank 0 and what items cost (runtime/coordinator_load.hpp):
# a line per finished stage with its items, wall time and mean and longest item time, and a line for the
# run with every item counted once, those from other ranks, message sizes and rank 0's main-thread time.
# The cluster model (tests/benchmarks/cluster_model.py) reads these lines: a change of their wording
# fails here, not silently in the benchmark.
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_PROBE:?PBRFIT_PROBE must name pbrfit_runtime_probe}"

note "3 stages x 16 items, each item spinning 2 ms on average (spin 1000 us x (i * 7 % 5)), 2 ranks"
set +e
"$MPIEXEC" "${MPI_FLAGS[@]}" -np 2 "$PBRFIT_PROBE" run.h5 --stages 3 --items 16 --spin 1000 --threads 1 -v 2> run.log
STATUS=$?
set -e
expect_status 0
grep -E 'r0\] debug: (stage [0-9]+|coordinator):' run.log || fail "no load lines in the verbose log"

stages=$(grep -cE 'r0\] debug: stage [0-9]+: 16 items in [0-9.]+ s; computing [0-9.e+-]+ ms an item on average, longest [0-9.e+-]+ ms$' run.log)
[[ $stages == 3 ]] || fail "expected 3 stage lines of 16 items, found $stages"
# Item i spins (i * 7 % 5) ms: the mean over 16 items is 1.875 ms, the longest 4 ms (more on a loaded machine,
# never less).
awk '/r0\] debug: stage [0-9]+: / {
       for (i = 1; i <= NF; ++i) { if ($i == "average,") mean = $(i - 5); if ($i == "longest") longest = $(i + 1) }
       if (mean < 1.875 || mean > 20 || longest < 4 || longest > 100) { print "bad item times: " $0; bad = 1 } }
     END { exit bad }' run.log || fail "item times do not match the items' spin"

line=$(grep -E 'r0\] debug: coordinator: ' run.log) || fail "no coordinator line"
number='[0-9]+(\.[0-9]+)?'
pattern="coordinator: 48 items \(([0-9]+) from other ranks; ([0-9]+) work messages of ($number) bytes and ($number) items on average, ([0-9]+) result messages of ($number) bytes and ($number) items\), main thread $number s of processor time, $number us per item$"
[[ $line =~ $pattern ]] || fail "coordinator line not as expected: $line"
remote=${BASH_REMATCH[1]} work_messages=${BASH_REMATCH[2]} result_messages=${BASH_REMATCH[7]}
(( remote > 0 && remote < 48 )) || fail "items from the other rank: $remote of 48 (both ranks compute)"
# Work and results travel in batches: never more messages than items, and a message holds at least one.
(( work_messages >= 1 && work_messages <= remote && result_messages >= 1 && result_messages <= remote )) ||
  fail "$work_messages work and $result_messages result messages for $remote items"

note "the cluster model reads the log"
cat > rate.md <<'MD'
| ranks | empty items per second | rank 0 main thread, us per item | work message bytes | result message bytes | stage boundary, ms |
|---|---|---|---|---|---|
| 2 | 100000 | 10.0 | 20 | 44 | 3.5 |
| 4 | 100000 | 10.0 | 20 | 44 | 3.5 |
MD
/usr/bin/python3 "$PBRFIT_SOURCE_DIR/tests/benchmarks/cluster_model.py" --rate rate.md run.log | tee model.md
grep -qE '^\| run \| 3 \| 48 \| [0-9.]+ \|' model.md || fail "the model did not read 3 stages of 48 items"

note "many short items travel in batches: 100,000 empty items on 2 ranks"
set +e
"$MPIEXEC" "${MPI_FLAGS[@]}" -np 2 "$PBRFIT_PROBE" short.h5 --stages 1 --items 100000 --no-log --threads 1 -v 2> short.log
STATUS=$?
set -e
expect_status 0
line=$(grep -E 'r0\] debug: coordinator: ' short.log) || fail "no coordinator line"
pattern="coordinator: 100000 items \(([0-9]+) from other ranks; ([0-9]+) work messages of $number bytes and ($number) items on average, ([0-9]+) result messages of $number bytes and ($number) items\)"
[[ $line =~ $pattern ]] || fail "coordinator line not as expected: $line"
remote=${BASH_REMATCH[1]} per_work=${BASH_REMATCH[4]} per_result=${BASH_REMATCH[8]}
echo "$remote items from rank 1: $per_work items a work message, $per_result a result message"
# One item a message was the protocol before batching. How many share one depends on how fast rank 0 is
# against the worker (6-10 in the Release build, 3 under AddressSanitizer, where rank 0 is 50 times slower
# and computes most items itself); more than 1.5 on average only comes from batches.
awk -v w="$per_work" -v r="$per_result" 'BEGIN { exit !(w >= 1.5 && r >= 1.5) }' ||
  fail "work and results do not travel in batches: $line"
echo "PASS"
