#!/usr/bin/env bash
# Symbolic regression stopped by SIGTERM (exit 75) and killed by SIGKILL between and within epochs, resumed
# each time (once on another rank count), ends bitwise identical to an uninterrupted run: islands, their
# random streams and their migrants all come from the checkpointed state.
source "$(dirname "$0")/lib/common.bash"

cat > job.yaml <<'YAML'
name: resume-symreg
kind: symreg
seed: 11
output: result.h5
checkpoint: {interval_seconds: 0.3, interval_items: 4}
symreg:
  dataset: {generator: nguyen7, points: 30, test_points: 200}
  operators: [add, sub, mul, div, sin, cos, exp, log]
  precision: float64
  population: 400
  generations: 300
  migration_interval: 5
  migrants: 2
YAML
note "uninterrupted reference on 2 ranks"
run_ranks 2 run job.yaml --output reference.h5 -q
expect_status 0

note "SIGTERM after a few epochs"
interrupt_after 40 TERM 2 run job.yaml
note "resume on 1 rank, then SIGKILL"
interrupt_after $(($(items_done result.h5) + 40)) KILL 1 run job.yaml --resume

note "resume to completion on 2 ranks"
run_ranks 2 run job.yaml --resume -q
expect_status 0
expect_identical reference.h5 result.h5 /y
expect_identical reference.h5 result.h5 /subexpressions
echo "PASS"
