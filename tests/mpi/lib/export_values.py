# The numbers behind the export tests (Debian's h5py: run with /usr/bin/python3).
#
#   export_values.py rows RESULT OUTPUT DIR   writes into DIR, from RESULT's group OUTPUT:
#       inputs.txt (the input names, comma-separated), members.txt (the front's size), knee.txt (the knee's
#       row), expressions.txt (a member's expression a line), knee_rows.txt and knee_prediction.txt (the
#       training rows' inputs and the knee's stored outputs), random_rows.txt (1000 rows uniform in the
#       training rows' box, seed 1)
#   export_values.py compare OURS REFERENCE TOLERANCE [COLUMN]
#       compares two tables of numbers (a line a row) column by column, or OURS with column COLUMN of
#       REFERENCE: equal where both are NaN or the same infinity, else |ours - reference| <= TOLERANCE *
#       max(|reference|, 1). Prints the largest scaled difference per column; exit 1 on any mismatch.
# Every number is written with 17 significant digits, so doubles read back exactly.
import sys

import h5py
import numpy as np

RANDOM_ROWS = 1000


def write_table(path, values):
    np.savetxt(path, np.atleast_2d(values), fmt="%.17g")


def rows(result, output, directory):
    with h5py.File(result, "r") as f:
        group = f[output]
        inputs = [n.strip() for n in str(group.attrs["inputs"]).split(",")]
        front = group["front"][()]
        knee = group["knee_prediction"][()]
    expressions = [e.decode() if isinstance(e, bytes) else e for e in front["expression"]]
    training = np.column_stack([knee[name] for name in inputs])
    low, high = training.min(axis=0), training.max(axis=0)
    random = np.random.default_rng(1).uniform(low, high, size=(RANDOM_ROWS, len(inputs)))
    open(f"{directory}/inputs.txt", "w").write(",".join(inputs) + "\n")
    open(f"{directory}/members.txt", "w").write(f"{len(expressions)}\n")
    open(f"{directory}/knee.txt", "w").write(f"{int(np.flatnonzero(front['knee'] == 1)[0])}\n")
    open(f"{directory}/expressions.txt", "w").write("".join(e + "\n" for e in expressions))
    write_table(f"{directory}/knee_rows.txt", training)
    write_table(f"{directory}/knee_prediction.txt", knee["prediction"].reshape(-1, 1))
    write_table(f"{directory}/random_rows.txt", random)


def compare(ours_path, reference_path, tolerance, column=None):
    ours = np.loadtxt(ours_path, ndmin=2)
    reference = np.loadtxt(reference_path, ndmin=2)
    if column is not None:
        reference = reference[:, [int(column)]]
    if ours.shape != reference.shape:
        print(f"shapes differ: {ours.shape} and {reference.shape}")
        return 1
    same = (ours == reference) | (np.isnan(ours) & np.isnan(reference))
    scaled = np.where(same, 0.0, np.abs(ours - reference) / np.maximum(np.abs(reference), 1.0))
    scaled = np.where(np.isnan(scaled), np.inf, scaled)
    bad = scaled > float(tolerance)
    for c in range(ours.shape[1]):
        print(f"column {c}: largest scaled difference {scaled[:, c].max():.3g}, {int(bad[:, c].sum())} beyond {tolerance}")
    return 1 if bad.any() else 0


if __name__ == "__main__":
    if sys.argv[1] == "rows":
        rows(*sys.argv[2:5])
    else:
        sys.exit(compare(*sys.argv[2:]))
