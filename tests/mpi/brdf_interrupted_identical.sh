#!/usr/bin/env bash
# A genBRDF search stopped by SIGTERM (exit 75) and killed by SIGKILL, in the search and in the evaluation,
# resumed each time (once on another rank count), ends bitwise identical to an uninterrupted run.
source "$(dirname "$0")/lib/common.bash"

job_from tests/jobs/small-brdf.yaml job.yaml 's/^  generations: 4/  generations: 30/' 's/^  population: 8/  population: 64/' \
  's/^output: result.h5/output: result.h5\ncheckpoint: {interval_seconds: 0.2, interval_items: 2}/' \
  's/starts: 2, evaluations_per_start: 60/starts: 96, evaluations_per_start: 2000/'  # materials of ~5 s: room to stop among them
note "uninterrupted reference on 2 ranks"
run_ranks 2 run job.yaml --output reference.h5 -q
expect_status 0
total=$("$PBRFIT" status reference.h5 | sed -n 's/^progress: *[0-9]* of \([0-9]*\).*/\1/p')

note "SIGTERM during the search"
interrupt_after 150 TERM 2 run job.yaml
note "resume on 1 rank, then SIGKILL"
interrupt_after $(($(items_done result.h5) + 300)) KILL 1 run job.yaml --resume
note "resume on 2 ranks, SIGTERM in the evaluation of the materials"
interrupt_after $((total - 4)) TERM 2 run job.yaml --resume

note "resume to completion on 2 ranks"
run_ranks 2 run job.yaml --resume -q
expect_status 0
expect_identical reference.h5 result.h5 /brdf
echo "PASS"
