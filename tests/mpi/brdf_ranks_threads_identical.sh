#!/usr/bin/env bash
# The genBRDF search and its evaluation are bitwise identical over ranks and threads (1x1, 1x2, 2x1, 2x2),
# with and without the stand-in cache; the result holds the front, the evaluation tables and the renders;
# every front member exports as GLSL that compiles; the report shows tables, renders and front; a directory of real MERL files is read, and a malformed
# file in it is refused naming it.
source "$(dirname "$0")/lib/common.bash"
MPI_FLAGS+=(--bind-to none)

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-brdf.yaml" job.yaml
note "reference on 1 rank x 1 thread (the stand-ins evaluated, then cached)"
run_ranks 1 run job.yaml --output ref.h5 --threads 1 -q
expect_status 0
[[ -f results/merl-cache/steel.binary ]] || fail "the stand-in was not cached"
for layout in "1 2" "2 1" "2 2"; do
  set -- $layout
  note "$1 rank(s) x $2 thread(s), from the cache"
  run_ranks "$1" run job.yaml --output "r-$1x$2.h5" --threads "$2" -q
  expect_status 0
  expect_identical ref.h5 "r-$1x$2.h5" /brdf
done

"$H5PY_PYTHON" - <<'PY' || fail "the search's or the evaluation's tables are wrong"
import h5py, numpy as np
f = h5py.File("ref.h5", "r")
front, log = f["brdf/front"][...], f["brdf/log"][...]
assert len(front) >= 1 and (front["knee"] == 1).sum() == 1
assert np.all(np.diff(front["cost"]) > 0) and np.all(np.diff(front["rmse"]) < 0), "a front: size rises, error falls"
assert len(log) == 2 * 4, len(log)                          # 2 islands x 4 generations
assert np.all(log["abandoned"][log["generation"] == 0] == 0), "generation 0 has no median to abandon at"
assert log["abandoned"][log["generation"] > 0].sum() > 0, "no fit was abandoned"
e = f["brdf/evaluation"]
models = [m.decode() for m in e["models"]["model"]]
assert models[:2] == ["cook_torrance", "ggx_smith"], models      # the seed, then the reference
assert np.all(np.isnan(e["models"]["training_error"][:2])), "the seed and the reference were not searched"
assert np.all(np.isfinite(e["models"]["training_error"][2:]))
rows = e["materials"][...]
assert len(rows) == 4 * len(models), len(rows)             # 2 training + 2 testing materials
assert set(r.decode() for r in rows["set"]) == {"training", "testing"}
assert np.all(np.isfinite(rows["image_l2"])) and np.all(rows["image_l2"] > 0)
assert np.all((rows["one_minus_ssim"] >= 0) & (rows["one_minus_ssim"] <= 2))
averages = e["averages"][...]
assert len(averages) == 2 * len(models)
ct = averages[averages["model"] == b"cook_torrance"]
assert np.all(ct["l2_reduction"] == 0) and np.all(ct["ssim_reduction"] == 0), "the baseline's own reduction is 0"
renders = e["renders"]
assert renders.shape == (4, len(models) + 1, 24, 24, 3), renders.shape
assert renders[:, 0].max() > 50, "the measured renders are black"
assert e["parameters"].shape == (4, len(models), 3, 4)
assert "of" in f["brdf"].attrs["metric_cells"]
PY

note "every front member exports as GLSL that compiles; its arguments are the inputs, then p0..p3"
if command -v glslangValidator >/dev/null; then
  members=$("$H5PY_PYTHON" -c 'import h5py; print(len(h5py.File("ref.h5")["brdf/front"]))')
  arguments="0.5, 0.6, 0.9, 0.8, 0.1, 0.2, 0.3, 0.4, 0.05, 1.0, 0.3, 0.5"
  {
    echo "#version 450"
    echo "layout(local_size_x = 64) in;"
    echo "layout(std430, binding = 0) buffer Values { float values[]; };"
    for ((k = 0; k < members; ++k)); do
      "$PBRFIT" export ref.h5 --format glsl --member "$k" --name "m$k" 2>err.txt || { cat err.txt; fail "export of member $k failed"; }
    done
    echo "void main() {"
    echo "  uint i = gl_GlobalInvocationID.x;"
    for ((k = 0; k < members; ++k)); do echo "  values[i] += m$k($arguments);"; done
    echo "}"
  } >members.comp
  head -5 members.comp | grep -q "^// small-brdf, output brdf, member 0 of $members" || fail "no leading comment in the export"
  glslangValidator -V -o members.spv members.comp >glsl.txt 2>&1 || { cat glsl.txt; fail "the GLSL export does not compile"; }
else
  echo "SKIP: glslangValidator is missing (Debian: glslang-tools); the export is not compiled"
fi

note "the report shows the tables and the renders side by side"
"$PBRFIT" report ref.h5 --out page >out.txt 2>err.txt || { cat err.txt; fail "the report failed"; }
[[ ! -s err.txt ]] || { cat err.txt; fail "report wrote to stderr"; }
grep -q "mean 1 - SSIM" page/index.html || fail "the report lacks the evaluation's averages"
grep -q "brdf/evaluation/renders: each material measured" page/index.html || fail "the report lacks the renders"
grep -q "brdf/front: " page/index.html || fail "the report lacks the front"

note "the models' BRDFs for people: simplified, equal to the exact texts, typeset, the exact text a click away"
PYTHONPATH=$(dirname "$PBRFIT")/share/pbrfit/report "$H5PY_PYTHON" - ref.h5 page/index.html <<'PY' ||
import sys, html, h5py, numpy as np, sympy
from pbrfit_report.readable_expressions import Expression, plain
page = open(sys.argv[2]).read()
with h5py.File(sys.argv[1], "r") as f:
    inputs = [n.strip() for n in f["brdf"].attrs["inputs"].split(",")]
    models = f["brdf/evaluation/models"][()]
rng = np.random.default_rng(1)
columns = {n: rng.uniform(0.05, 0.95, 2000) for n in inputs}
for record in models:
    name, text = record["model"].decode(), record["expression"].decode()
    shown = plain(text, inputs)
    if shown == text or html.escape(shown) not in page or html.escape(text) not in page:
        sys.exit(f"{name}: not simplified, or a form missing from the page")
    if f'alt="{name} formula"' not in page:
        sys.exit(f"{name}: not typeset")
    symbols = {n: sympy.Symbol(n, real=True) for n in inputs}
    simplified = sympy.lambdify([symbols[n] for n in inputs], sympy.sympify(shown, locals=symbols), "math")
    ours = np.array([simplified(*(float(columns[n][k]) for n in inputs)) for k in range(2000)], dtype=float)
    exact = Expression(text, inputs).values(columns)
    finite = np.isfinite(exact) & (np.abs(exact) < 1e12)
    if finite.sum() < 1000 or not np.allclose(ours[finite], exact[finite], rtol=1e-9, atol=1e-12):
        sys.exit(f"{name}: the simplified BRDF differs from the exact text")
    print(f"{name}: {shown}")
PY
  fail "a BRDF printed for people is wrong"
for png in page/*.png; do [[ $(head -c 4 "$png" | od -An -c | tr -d ' ') == 211PNG ]] || fail "$png is not a PNG"; done

note "a directory of MERL .binary files: the cached files read as real ones give the same numbers"
sed -i 's|^  materials: custom|  materials: custom\n  merl_directory: results/merl-cache|' job.yaml
run_ranks 2 run job.yaml --output merl.h5 -q
expect_status 0
expect_identical ref.h5 merl.h5 /brdf/evaluation/materials

note "a malformed MERL file is refused naming it"
head -c 1000 results/merl-cache/steel.binary > results/merl-cache/short.binary
mv results/merl-cache/short.binary results/merl-cache/steel.binary
run_ranks 1 run job.yaml --output bad.h5 -q 2>err.txt
expect_status 2
grep -q "results/merl-cache/steel.binary: error: is 1000 bytes long; a MERL file has" err.txt ||
  { cat err.txt; fail "wrong message for a short MERL file"; }
[[ $(grep -c "error:" err.txt) -eq 1 ]] || { cat err.txt; fail "the error is not reported exactly once"; }
echo "PASS"
