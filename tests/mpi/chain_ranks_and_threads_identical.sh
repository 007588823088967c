#!/usr/bin/env bash
# The synthetic multi-stage workload (each stage built from every result of the one before, per-item
# inputs from a ring neighbour, uneven costs, a growing table of records) gives bitwise identical
# results on 1, 2 and 3 ranks and with 1 or 2 threads per rank; readers see the growing table in item
# order.
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_PROBE:?PBRFIT_PROBE must name pbrfit_runtime_probe}"

chain=(--stages 4 --items 24 --spin 300 --bytes 256 -q)
probe() { local ranks=$1 out=$2; shift 2; set +e; "$MPIEXEC" "${MPI_FLAGS[@]}" -np "$ranks" "$PBRFIT_PROBE" "$out" "${chain[@]}" "$@"; STATUS=$?; set -e; }

note "reference: 1 rank, 1 thread"
probe 1 reference.h5 --threads 1
expect_status 0
for case in "1 2" "2 1" "2 2" "3 1"; do
  read -r ranks threads <<< "$case"
  note "$ranks ranks x $threads threads"
  probe "$ranks" "r${ranks}t${threads}.h5" --threads "$threads"
  expect_status 0
  expect_identical reference.h5 "r${ranks}t${threads}.h5" /chain
  [[ ! -e "r${ranks}t${threads}.h5.checkpoint" && ! -e "r${ranks}t${threads}.h5.journal" ]] ||
    fail "a complete run left its checkpoint or journal behind"
done

note "the growing table: records in (stage, item) order, read by h5py"
cat > log.py <<'PY'
import h5py
with h5py.File("r3t1.h5", "r") as f:
    log = f["chain/log"][()]
    keys = [(int(r["stage"]), int(r["item"])) for r in log]
    assert keys == sorted(keys), "rows out of item order"
    assert len(log) == 4 * sum(i % 3 for i in range(24)), len(log)
    first = log[0]
    note = first["note"].decode() if isinstance(first["note"], bytes) else first["note"]
    assert note == "s0i1k0", note
    assert f["chain/log"].dtype["stage"] == "uint32" and f["chain/log"].dtype["value"] == "float64"
    print("h5py reads", len(log), "log records in item order")
PY
"$H5PY_PYTHON" log.py || fail "h5py cannot read the growing record table as expected"
echo "PASS"
