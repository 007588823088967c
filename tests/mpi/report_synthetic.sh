#!/usr/bin/env bash
# `pbrfit report` of a synthetic result with what later kinds will write (tests/mpi/lib/synthetic_result.py):
# a 3-D and a 4-D table, error and anchor_error roles, a start table, NaNs, a nested group, a growing
# record table and a text table with HTML special characters and a newline. Checks the images, the
# anchor comparison (its fraction computed here from the file), the row cap and the escaping.
source "$(dirname "$0")/lib/common.bash"
source "$PBRFIT_SOURCE_DIR/tests/mpi/lib/report_checks.bash"

"$H5PY_PYTHON" "$PBRFIT_SOURCE_DIR/tests/mpi/lib/synthetic_result.py" synthetic.h5
set +e
"$PBRFIT" report synthetic.h5 --out page >out.txt 2>err.txt; STATUS=$?
set -e
expect_status 0 "$(cat err.txt)"
[[ ! -s err.txt ]] || { cat err.txt; fail "report wrote to stderr"; }
html=page/index.html

note "images and tables"
expect_tables_mentioned synthetic.h5 page
# 7 numeric tables over axes (params, error, heitz_error, start, evaluations, curve, cube4), each a figure,
# and a histogram for each of the two error tables.
expect_valid_images page 9
[[ $IMAGES -eq 9 ]] || fail "$IMAGES images, expected 9"
grep -q "/fit/level2" "$html" || fail "the nested group is missing"
grep -q "250 rows, the first 200 shown" "$html" || fail "the growing record table does not say 200 of 250 rows"
[[ $(grep -o "x \* 199 &lt; y &amp; z" "$html" | wc -l) -eq 1 ]] || fail "row 199 of the record table is not shown once"
! grep -q "x \* 200 &lt;" "$html" || fail "more than 200 rows of the record table are shown"
grep -q "program length" "$html" || fail "the record fields' descriptions are missing"
grep -q "cells won: " "$html" || fail "the start table's counts are missing"
grep -q "neighbour" "$html" || fail "the start labels are missing"

note "the anchor comparison"
expected=$("$H5PY_PYTHON" - <<'PY'
import h5py, numpy as np
with h5py.File("synthetic.h5", "r") as f:
    ours, theirs = f["fit/error"][()], f["fit/heitz_error"][()]
both = np.isfinite(ours) & np.isfinite(theirs)
wins, cells = int(np.sum(ours[both] <= theirs[both])), int(both.sum())
assert 0 < wins < cells and np.sum(ours[both] == theirs[both]) > 0, (wins, cells)
print(f"{wins / cells:.4f} ({wins} of {cells} cells)")
PY
)
grep -qF "<td>$expected</td>" "$html" || { grep -o "fraction[^/]*" "$html"; fail "the fraction ours <= anchor is not $expected"; }
grep -q "Heitz et al. 2016" "$html" || fail "the anchor is not named"

note "everything from the file is escaped"
for raw in "<b>bold</b>" "<script>" "<fit>" "<in progress>" "<vs>" "<as text>" '"quoted"'; do
  ! grep -qF -- "$raw" "$html" || fail "unescaped text from the file: $raw"
done
grep -qF "&lt;b&gt;bold&lt;/b&gt; &amp; &quot;quoted&quot; &#x27;single&#x27;" "$html" || fail "the text table is not escaped"
grep -A1 -F "&lt;b&gt;bold" "$html" | grep -q "^second line</td>" || fail "the newline of the text table is lost"
grep -qF "&lt;script&gt;alert(1)&lt;/script&gt;" "$html" || fail "the job text is not escaped"
[[ $(grep -c "<script" "$html") -eq 0 ]] || fail "the page holds a script element"
! grep -qE '(src|href)="(https?:|//)' "$html" || fail "the page references an external resource"
echo "PASS"
