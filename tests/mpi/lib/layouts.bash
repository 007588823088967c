# compare_layouts JOB: runs JOB on 1 rank x 1 thread into NAME-ref.h5, then on 1 x 2, 2 x 1 and 2 x 2 into
# NAME-RxT.h5, and requires every group of GROUPS_TO_COMPARE to be bitwise identical to the reference's.
# Sourced after common.bash; the caller adds --bind-to none to MPI_FLAGS (1 rank x 2 threads needs both cores).
compare_layouts() {
  local job=$1 name=${1%.yaml}
  run_ranks 1 run "$job" --output "$name-ref.h5" --threads 1 -q
  expect_status 0
  for layout in "1 2" "2 1" "2 2"; do
    set -- $layout
    note "$job on $1 rank(s) x $2 thread(s)"
    run_ranks "$1" run "$job" --output "$name-$1x$2.h5" --threads "$2" -q
    expect_status 0
    for group in "${GROUPS_TO_COMPARE[@]}"; do expect_identical "$name-ref.h5" "$name-$1x$2.h5" "$group"; done
  done
}
