# Shared helpers of the end-to-end tests. Each test runs in its own temporary directory.
# Environment (set by ctest): PBRFIT (the binary), PBRFIT_SOURCE_DIR, MPIEXEC, and PBRFIT_TEST_SLOWDOWN: how
# many times slower the build runs than a Release build (5 under the sanitizers, tests/CMakeLists.txt),
# which stretches the waits for a job's progress below.
set -euo pipefail

: "${PBRFIT:?PBRFIT must name the pbrfit binary}"
: "${PBRFIT_SOURCE_DIR:?}"
MPIEXEC=${MPIEXEC:-mpirun}
MPI_FLAGS=(--oversubscribe --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && MPI_FLAGS+=(--allow-run-as-root)
H5PY_PYTHON=/usr/bin/python3   # Debian's h5py is installed for the system interpreter
PROGRESS_WAIT=$((120 * ${PBRFIT_TEST_SLOWDOWN:-1}))   # seconds a wait for a job's progress may take

WORK=$(mktemp -d "${TMPDIR:-/tmp}/pbrfit-test.XXXXXX")
trap 'kill_group_if_running; rm -rf "$WORK"' EXIT
cd "$WORK"

BACKGROUND_PID=""

fail() { echo "FAIL: $*" >&2; exit 1; }
note() { echo "--- $*"; }

# mpirun with N ranks in the foreground; prints the command's exit code as $STATUS.
run_ranks() {
  local ranks=$1; shift
  set +e
  "$MPIEXEC" "${MPI_FLAGS[@]}" -np "$ranks" "$PBRFIT" "$@"
  STATUS=$?
  set -e
}

# mpirun with N ranks in the background, in a session of its own; each rank notes its pid in $RANK_PIDS
# (lib/as_rank.bash) before it becomes pbrfit.
RANK_PIDS="$WORK/rank-pids.txt"
start_ranks() {
  local ranks=$1; shift
  : >"$RANK_PIDS"
  RANK_PIDS_FILE="$RANK_PIDS" setsid "$MPIEXEC" "${MPI_FLAGS[@]}" -np "$ranks" \
    bash "$PBRFIT_SOURCE_DIR/tests/mpi/lib/as_rank.bash" "$@" &
  BACKGROUND_PID=$!
}

# start_ranks with every rank's output (and mpirun's) appended to run.log as it is written, not forwarded
# by mpirun: the tests that act on what the log says must see it when the ranks say it.
start_logged_ranks() {
  : >run.log
  RANK_LOG="$WORK/run.log" start_ranks "$@" >>run.log 2>&1
}

wait_background() {
  set +e
  wait "$BACKGROUND_PID"
  STATUS=$?
  set -e
  BACKGROUND_PID=""
}

kill_group_if_running() {
  if [[ -n "$BACKGROUND_PID" ]] && kill -0 "$BACKGROUND_PID" 2>/dev/null; then
    kill_session KILL
    wait "$BACKGROUND_PID" 2>/dev/null || true
  fi
}

# The pids of the background job's ranks that have started, in rank order (possibly none).
started_rank_pids() {
  local rank pid pids=()
  while read -r rank pid; do pids[rank]=$pid; done <"$RANK_PIDS"
  echo "${pids[*]}"
}

# The same, failing the test when no rank has started.
rank_pids() {
  [[ -s "$RANK_PIDS" ]] || fail "no rank of the background job has started"
  started_rank_pids
}

# The pid of rank R of the background job.
pid_of_rank() {
  local pid
  pid=$(awk -v rank="$1" '$1 == rank { print $2 }' "$RANK_PIDS")
  [[ -n "$pid" ]] || fail "rank $1 of the background job has not started"
  echo "$pid"
}

# True while the background job runs (a finished job that is not yet waited for is a zombie).
background_running() {
  local state
  state=$(ps -o stat= -p "$BACKGROUND_PID" 2>/dev/null) || return 1
  [[ $state != Z* ]]
}

# Sends a signal to mpirun and every rank at once (and to anything else left in mpirun's session).
kill_session() {
  kill "-$1" "$BACKGROUND_PID" $(started_rank_pids) 2>/dev/null || true
  pkill "-$1" -s "$BACKGROUND_PID" 2>/dev/null || true
}

# Waits until the result file reports at least N finished items (while the job runs).
wait_for_items() {
  local file=$1 wanted=$2 deadline=$((SECONDS + PROGRESS_WAIT)) done
  while (( SECONDS < deadline )); do
    done=$("$PBRFIT" status "$file" 2>/dev/null | sed -n 's/^progress: *\([0-9]*\) of.*/\1/p' || true)
    if [[ -n "$done" ]] && (( done >= wanted )); then return 0; fi
    background_running || fail "the job ended before $wanted items were done"
    sleep 0.1
  done
  fail "timed out waiting for $wanted items in $file ($PROGRESS_WAIT s)"
}

# Sleeps without starting a process: a read that times out on a FIFO nobody writes to.
nap() {
  [[ -p "$WORK/.nap" ]] || mkfifo "$WORK/.nap"
  local fifo
  exec {fifo}<>"$WORK/.nap"
  read -r -t "$1" -u "$fifo" || true
  exec {fifo}>&-
}

# Waits until run.log (start_logged_ranks, --verbose) reports a checkpoint of at least N finished items,
# and fails unless the job still runs then. Rank 0 logs its own state there, while the published result
# file that `pbrfit status` reads may lag by many seconds on a slow disk (publication gives copying at
# most 5 % of the time): a short job can end before its published progress reaches N.
wait_for_checkpoint() {
  local wanted=$1 deadline=$((SECONDS + PROGRESS_WAIT)) saved=0 line partial="" log
  TRIGGER_STAMP="" NEWEST_STAMP=""
  exec {log}<run.log   # read as it grows, with builtins only: a loaded machine delays every fork
  while (( SECONDS < deadline )); do
    while IFS= read -r -u "$log" line; do
      line=$partial$line partial=""
      if [[ $line =~ ^\[\ *([0-9.]+)s\ r0\] ]]; then NEWEST_STAMP=${BASH_REMATCH[1]}; fi
      if (( saved < wanted )) && [[ $line =~ checkpoint\ written:\ ([0-9]+)\ of ]]; then
        saved=${BASH_REMATCH[1]} TRIGGER_STAMP=$NEWEST_STAMP
      fi
    done
    partial+=$line   # a line still being written
    if (( saved >= wanted )); then
      exec {log}<&-
      background_running || { trigger_timing "$wanted"; fail "the job had ended when its log showed a checkpoint of $wanted items"; }
      return 0
    fi
    kill -0 "$BACKGROUND_PID" 2>/dev/null || { tail -n 5 run.log; stop_senders; fail "the job ended before a checkpoint of $wanted items"; }
    nap 0.05
  done
  fail "timed out waiting for a checkpoint of $wanted items in run.log ($PROGRESS_WAIT s)"
}

# The stop signals the ranks logged (with the pid that sent each) and what those processes are, if alive.
stop_senders() {
  local line pid
  echo "this test is process $$; its mpirun ${BACKGROUND_PID:-(none)}; its ranks: $(started_rank_pids)"
  while IFS= read -r line; do
    echo "$line"
    [[ $line =~ from\ process\ ([0-9]+) ]] || continue
    pid=${BASH_REMATCH[1]}
    ps -o pid=,ppid=,etimes=,args= -p "$pid" 2>/dev/null || echo "process $pid has gone"
  done < <(grep -E "received: (stopping|asking)" run.log || true)
}

# When rank 0 logged the trigger, and its newest line the test had read by then (seconds since its start).
trigger_timing() {
  echo "rank 0 logged the checkpoint of $1 items at ${TRIGGER_STAMP:-?} s; the test saw it with the line of ${NEWEST_STAMP:-?} s"
}

# The lines of run.log that tell when a stop was due: resumption, signals received, the first checkpoint
# of at least N items.
log_around_trigger() {
  awk -v n="$1" '/resuming|received/ { print }
                 /checkpoint written:/ && !shown { split($0, a, "checkpoint written: ")
                                                   if (a[2] + 0 >= n) { print; shown = 1 } }' run.log
}

# Runs `pbrfit ARGS --verbose` on N ranks in the background (log in run.log) until rank 0 has checkpointed
# ITEMS finished items, then stops it: SIGNAL TERM or INT goes to the ranks (which must exit 75), KILL to
# the whole session. The job must checkpoint often (its checkpoint section), and ARGS must not hold -q.
interrupt_after() {
  local items=$1 signal=$2 ranks=$3; shift 3
  start_logged_ranks "$ranks" "$@" --verbose
  wait_for_checkpoint "$items"
  if [[ $signal == KILL ]]; then
    kill_session KILL
    wait_background
  else
    local pids; pids=$(rank_pids)
    kill "-$signal" $pids || { ps -o pid,ppid,stat,etimes,args -p "$BACKGROUND_PID,${pids// /,}" || true
                                trigger_timing "$items"; tail -n 12 run.log
                                fail "no rank left to signal (ranks: $pids), checkpointed at $items items"; }
    local signalled_at=$SECONDS
    wait_background
    [[ $STATUS -ne 0 ]] || { log_around_trigger "$items"; trigger_timing "$items"; tail -n 4 run.log
                             fail "the job completed $((SECONDS - signalled_at)) s after SIG$signal was sent to its ranks ($pids) at a checkpoint of $items items"; }
    expect_status 75 "ranks stopped by SIG$signal"
  fi
}

# The number of finished items `pbrfit status` reports for a result file.
items_done() { "$PBRFIT" status "$1" | sed -n 's/^progress: *\([0-9]*\) of.*/\1/p'; }

# Waits (up to 10 s) until `pbrfit status` shows a state line matching the pattern; a killed process can
# take a moment to disappear, longer on a loaded machine.
wait_for_state() {
  local file=$1 pattern=$2 i
  for i in $(seq 1 100); do
    "$PBRFIT" status "$file" > status.txt 2>&1 && grep -q "^state: *$pattern" status.txt && return 0
    sleep 0.1
  done
  cat status.txt
  fail "status never showed state '$pattern'"
}

# Runs `pbrfit ARGS` with a deadline (a FIFO must not hang it); STATUS, out.txt and err.txt.
run_pbrfit() {
  set +e
  timeout 60 "$PBRFIT" "$@" >out.txt 2>err.txt
  STATUS=$?
  set -e
  [[ $STATUS -ne 124 ]] || fail "pbrfit $* hung"
}

# The exit code and exactly one line on stderr, which is the expected one.
expect_one_line() {
  local code=$1 expected=$2
  expect_status "$code" "$expected"
  [[ $(wc -l <err.txt) -eq 1 ]] || { cat err.txt; fail "not exactly one line on stderr"; }
  [[ "$(cat err.txt)" == "$expected" ]] || { cat err.txt; fail "expected: $expected"; }
}

expect_status() {
  [[ "$STATUS" -eq "$1" ]] || fail "expected exit code $1, got $STATUS${2:+ ($2)}"
}

# Bitwise comparison of every dataset of a group (h5diff compares values exactly unless asked not to).
expect_identical() {
  local a=$1 b=$2 group=$3
  h5diff -r "$a" "$b" "$group" "$group" >diff.txt 2>&1 || { cat diff.txt; fail "$a and $b differ in $group"; }
}

# A job file derived from a source job: KEY=VALUE pairs replace top-level or lut keys by sed.
job_from() {
  local source=$1 target=$2; shift 2
  cp "$PBRFIT_SOURCE_DIR/$source" "$target"
  local edit
  for edit in "$@"; do sed -i "$edit" "$target"; done
}
