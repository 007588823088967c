#!/usr/bin/env bash
# `pbrfit export` of symbolic-regression fronts (tests/jobs/small-symreg.yaml, and the same job with random
# and fitted constants): every member exported as C++ (double), compiled without FMA contraction, gives
# on 1000 random rows in the training box what the engine's tree walker gives for its expression (within
# 1e-12 relative); the knee exported as C++ in double and in float reproduces the knee_prediction the
# result stored (1e-12, and 1e-5 in float); every member exported as GLSL and as HLSL compiles with
# glslangValidator (GLSL 450 and HLSL compute shaders, to SPIR-V). A perturbed constant or output fails
# the comparisons, a broken shader the validator: the checks can fail.
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_EXPRESSION_VALUES:?PBRFIT_EXPRESSION_VALUES must name the expression evaluator (tests/support)}"
VALUES=("$H5PY_PYTHON" "$PBRFIT_SOURCE_DIR/tests/mpi/lib/export_values.py")
CXX=${CXX:-g++}
command -v "$CXX" >/dev/null || { echo "SKIP: no C++ compiler ($CXX)"; exit 77; }
command -v glslangValidator >/dev/null || { echo "SKIP: glslangValidator is missing (Debian: glslang-tools)"; exit 77; }

# Exports member K of the front in DIR's result as FORMAT with function name mK; extra arguments go to export.
export_member() {
  local dir=$1 k=$2 format=$3; shift 3
  "$PBRFIT" export "$dir/result.h5" --format "$format" --member "$k" --name "m$k" "$@" >"$dir/m$k.$format" 2>err.txt ||
    { cat err.txt; fail "export of member $k as $format failed"; }
  [[ ! -s err.txt ]] || { cat err.txt; fail "export wrote to stderr"; }
  head -1 "$dir/m$k.$format" | grep -q "^// small-symreg, output y, member $k of " || fail "no leading comment in m$k.$format"
}

# A C++ program reading rows of INPUTS numbers from stdin and printing per row each function's value
# (%.17g); the functions m<K> of the given headers take TYPE (double or float).
compile_driver() {
  local program=$1 type=$2 inputs=$3; shift 3
  {
    local header k arguments=""
    for header in "$@"; do echo "#include \"$header\""; done
    echo "#include <cstdio>"
    echo "int main() {"
    echo "  double in[$inputs];"
    echo "  for (;;) {"
    for ((k = 0; k < inputs; ++k)); do
      echo "    if (std::scanf(\"%lf\", &in[$k]) != 1) return 0;"
      arguments+="${arguments:+, }$type(in[$k])"
    done
    for header in "$@"; do
      k=$(basename "$header"); k=${k%%.*}
      echo "    std::printf(\"%.17g \", double($k($arguments)));"
    done
    echo "    std::printf(\"\\n\");"
    echo "  }"
    echo "}"
  } >"$program-driver.cpp"
  "$CXX" -std=c++20 -O2 -ffp-contract=off -Wall -o "$program" "$program-driver.cpp" 2>compile.txt ||
    { cat compile.txt "$program-driver.cpp"; fail "the exported C++ does not compile"; }
}

# Every member of DIR's front in double C++ against the tree walker on the random rows.
check_members_cpp() {
  local dir=$1 members inputs headers=() k
  members=$(cat "$dir/members.txt"); inputs=$(cat "$dir/inputs.txt")
  for ((k = 0; k < members; ++k)); do
    export_member "$dir" "$k" cpp --double
    headers+=("$dir/m$k.cpp")
  done
  compile_driver "$dir/all" double "$(tr ',' '\n' <<<"$inputs" | wc -l)" "${headers[@]}"
  "$dir/all" <"$dir/random_rows.txt" >"$dir/ours.txt"
  mapfile -t expressions <"$dir/expressions.txt"
  "$PBRFIT_EXPRESSION_VALUES" "$inputs" "${expressions[@]}" <"$dir/random_rows.txt" >"$dir/walker.txt"
  "${VALUES[@]}" compare "$dir/ours.txt" "$dir/walker.txt" 1e-12 || fail "$dir: an exported member differs from the tree walker"
}

# The knee (the default member) in double and in float C++ against the stored knee_prediction.
check_knee_cpp() {
  local dir=$1 inputs
  inputs=$(tr ',' '\n' <"$dir/inputs.txt" | wc -l)
  "$PBRFIT" export "$dir/result.h5" --format cpp --double --name knee_double >"$dir/knee_double.cpp"
  "$PBRFIT" export "$dir/result.h5" --format cpp --name knee_float >"$dir/knee_float.cpp"
  grep -q "(the knee)" "$dir/knee_double.cpp" || fail "the default member is not the knee"
  compile_driver "$dir/knee" double "$inputs" "$dir/knee_double.cpp"
  "$dir/knee" <"$dir/knee_rows.txt" >"$dir/knee_double.txt"
  "${VALUES[@]}" compare "$dir/knee_double.txt" "$dir/knee_prediction.txt" 1e-12 || fail "$dir: the knee in double differs"
  compile_driver "$dir/knee_f" float "$inputs" "$dir/knee_float.cpp"
  "$dir/knee_f" <"$dir/knee_rows.txt" >"$dir/knee_float.txt"
  "${VALUES[@]}" compare "$dir/knee_float.txt" "$dir/knee_prediction.txt" 1e-5 || fail "$dir: the knee in float differs"
}

# The shader of every member: a GLSL 450 compute shader and an HLSL one, each calling every member.
check_members_shaders() {
  local dir=$1 members arguments k
  members=$(cat "$dir/members.txt")
  arguments=$(tr ',' '\n' <"$dir/inputs.txt" | sed 's/.*/v/' | paste -sd, | sed 's/,/, /g')
  {
    echo "#version 450"
    for ((k = 0; k < members; ++k)); do export_member "$dir" "$k" glsl; cat "$dir/m$k.glsl"; done
    echo "layout(local_size_x = 64) in;"
    echo "layout(std430, binding = 0) buffer Values { float values[]; };"
    echo "void main() {"
    echo "  uint i = gl_GlobalInvocationID.x;"
    echo "  float v = values[i];"
    for ((k = 0; k < members; ++k)); do echo "  values[i] += m$k($arguments);"; done
    echo "}"
  } >"$dir/members.comp"
  glslangValidator -V -o "$dir/members.spv" "$dir/members.comp" >glsl.txt 2>&1 ||
    { cat glsl.txt; fail "$dir: the GLSL export does not compile"; }
  {
    for ((k = 0; k < members; ++k)); do export_member "$dir" "$k" hlsl; cat "$dir/m$k.hlsl"; done
    echo "RWStructuredBuffer<float> values : register(u0);"
    echo "[numthreads(64, 1, 1)]"
    echo "void main(uint3 id : SV_DispatchThreadID) {"
    echo "  float v = values[id.x];"
    for ((k = 0; k < members; ++k)); do echo "  values[id.x] += m$k($arguments);"; done
    echo "}"
  } >"$dir/members.hlsl"
  glslangValidator -D -V -S comp -e main -o "$dir/members_hlsl.spv" "$dir/members.hlsl" >hlsl.txt 2>&1 ||
    { cat hlsl.txt; fail "$dir: the HLSL export does not compile"; }
}

check_result() {
  local dir=$1
  "${VALUES[@]}" rows "$dir/result.h5" y "$dir"
  note "$dir: $(cat "$dir/members.txt") members, knee $(cat "$dir/knee.txt")"
  check_members_cpp "$dir"
  check_knee_cpp "$dir"
  check_members_shaders "$dir"
}

note "tests/jobs/small-symreg.yaml (no constants), on 2 ranks"
mkdir plain
job_from tests/jobs/small-symreg.yaml plain/job.yaml "s|^output: .*|output: $WORK/plain/result.h5|"
run_ranks 2 run plain/job.yaml -q
expect_status 0
check_result "$WORK/plain"

note "the same job with random and fitted constants"
mkdir constants
job_from tests/jobs/small-symreg.yaml constants/job.yaml "s|^output: .*|output: $WORK/constants/result.h5|" \
  "s|constant_probability: 0|constant_probability: 0.3|"
"$PBRFIT" run constants/job.yaml -q
check_result "$WORK/constants"
literals=$(grep -hE "^  double " constants/m*.cpp | grep -oE "[0-9]+\.[0-9]{6,}(e-?[0-9]+)?" | wc -l)
(( literals > 0 )) || fail "no member of the second job has a fitted constant to check"
note "$literals constants with 6 or more digits in the exported members"

note "the checks can fail: a perturbed constant, a perturbed output, a broken shader"
cp constants/all-driver.cpp perturbed.cpp
file=$(grep -lE "^  double .*[0-9]+\.[0-9]{6,}" "$WORK"/constants/m*.cpp | head -1)
"$H5PY_PYTHON" - "$file" >perturbed-member.cpp <<'PY'
import re, sys
comment, body = open(sys.argv[1]).read().split("\n", 1)   # the comment line has numbers too
print(comment + "\n" + re.sub(r"([0-9]+\.[0-9]{6,}(e-?[0-9]+)?)", r"(\1 * 1.000000001)", body, count=1), end="")
PY
cmp -s "$file" perturbed-member.cpp && fail "no constant was perturbed"
sed -i "s|#include \"$file\"|#include \"$WORK/perturbed-member.cpp\"|" perturbed.cpp
"$CXX" -std=c++20 -O2 -ffp-contract=off -o perturbed perturbed.cpp
./perturbed <constants/random_rows.txt >perturbed.txt
! "${VALUES[@]}" compare perturbed.txt constants/walker.txt 1e-12 >compare.txt || fail "a constant off by 1e-9 went unnoticed"
sed -E 's/^  return (.*);$/  return \1 * (1.0f + 1e-4f);/; s/knee_float/knee_perturbed/' plain/knee_float.cpp >knee_perturbed.cpp
compile_driver knee_perturbed float 1 "$WORK/knee_perturbed.cpp"
./knee_perturbed <plain/knee_rows.txt >knee_perturbed.txt
! "${VALUES[@]}" compare knee_perturbed.txt plain/knee_prediction.txt 1e-5 >compare.txt || fail "a float output off by 1e-4 went unnoticed"
sed 's/m0(v)/undefined_function(v)/' plain/members.comp >broken.comp
! glslangValidator -V -o broken.spv broken.comp >/dev/null 2>&1 || fail "glslangValidator accepts a broken GLSL shader"
sed 's/m0(v)/undefined_function(v)/' plain/members.hlsl >broken.hlsl
! glslangValidator -D -V -S comp -e main -o broken.spv broken.hlsl >/dev/null 2>&1 || fail "glslangValidator accepts a broken HLSL shader"
echo "PASS"
