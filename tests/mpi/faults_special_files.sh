#!/usr/bin/env bash
# Special files and hostile paths are input errors (exit 2, one line), never a hang or a crash: FIFOs
# and devices as job files, results and checkpoints; a directory as checkpoint; control characters in
# the output path.
source "$(dirname "$0")/lib/common.bash"

# Runs pbrfit (no mpirun) with a deadline; a hang is a failure, not a stuck test.
run_bounded() { run_pbrfit "$@"; }

# Exit 2 with exactly one line on stderr containing the expected text.
expect_refusal() {
  local expected=$1
  expect_status 2 "$expected"
  [[ $(wc -l <err.txt) -eq 1 ]] || { cat err.txt; fail "the refusal is not one line"; }
  grep -qF -- "$expected" err.txt || { cat err.txt; fail "expected '$expected'"; }
}

mkfifo fifo.yaml
for command in validate run; do
  note "$command: a FIFO as job file"
  run_bounded $command fifo.yaml
  expect_refusal "fifo.yaml: error: is not a regular file"
done
note "a device as job file"
run_bounded validate /dev/zero
expect_refusal "/dev/zero: error: is not a regular file"
note "a directory as job file"
run_bounded validate .
expect_refusal ".: error: is a directory, not a job file"

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-dfg.yaml" job.yaml
note "a FIFO as result"
mkfifo result.h5
run_bounded status result.h5
expect_refusal "result.h5: error:"
run_bounded run job.yaml -q
expect_refusal "result.h5"
rm result.h5

note "a FIFO, then a directory, as checkpoint"
mkfifo result.h5.checkpoint
run_bounded run job.yaml -q --resume
expect_refusal "result.h5.checkpoint"
rm result.h5.checkpoint
mkdir result.h5.checkpoint
run_bounded run job.yaml -q --resume
expect_refusal "result.h5.checkpoint"
[[ -d result.h5.checkpoint ]] || fail "the directory was removed"
rmdir result.h5.checkpoint

note "control characters in output: refused with the position, nothing written"
mkdir out
for value in '"out/R\0x.h5"' '"out/R\nx.h5"' '"out/R\tx.h5"'; do
  printf 'name: bad\nkind: lut\noutput: %s\nlut: {function: dfg, resolution: [4, 4]}\n' "$value" >bad.yaml
  run_bounded validate bad.yaml
  expect_refusal "bad.yaml:3:9: error:"
  run_bounded run bad.yaml -q
  expect_refusal "bad.yaml:3:9: error:"
done
run_bounded run job.yaml -q --output $'out/R\nx.h5'
expect_refusal "--output"
[[ -z $(ls out) ]] || fail "files were written for a refused output: $(ls out)"

note "the regular job still runs"
run_bounded run job.yaml -q
expect_status 0
echo "PASS"
