#!/usr/bin/env bash
# `pbrfit export` of every table kind in every format, each file read back by a reader pbrfit did not write
# and every value compared with the HDF5 table (lib/check_export.py: bitwise as float32, to nearest as
# float16): numpy (.npy), pypng (16-bit PNG and its ranges), three.js's EXRLoader, HDRLoader and KTX2Loader
# in node and ktx-parse for arrays (tests/web/read_textures.mjs), the DDS headers field by field against the
# specification; C++ headers compiled into one program that prints their values, JavaScript modules
# imported by node, GLSL includes compiled by glslangValidator as GLSL ES 3.00 and 4.50, HLSL as HLSL.
# Tables: a DFG LUT with the multiple-scattering and cloth channels (also swapped, flipped, repacked), a
# Disney-diffuse LUT, LTC tables of GGX and Charlie (the 2-layer pair, ltc_1, ltc_2; and a BRDF expression
# with an axis of its own, whose pairs are further layers), sphere-light tables (a volume; the fitted
# parameters) and eBRDF mip hierarchies (texture arrays with mips). What a format cannot hold, an unknown
# table, model or channel, and an unfinished result are exit 2 with one line.
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_WEB_MODULES:?PBRFIT_WEB_MODULES must name the web test packages (make web-deps)}"
[[ -d $PBRFIT_WEB_MODULES/three && -d $PBRFIT_WEB_MODULES/ktx-parse ]] ||
  fail "three.js and ktx-parse are missing from $PBRFIT_WEB_MODULES (make web-deps installs them)"
for tool in node glslangValidator "${CXX:-g++}"; do
  command -v "$tool" >/dev/null || fail "$tool is missing (.ci/install-deps --web installs what the tests need)"
done
CHECKS=checks.txt READS=reads.txt
: >"$CHECKS"; : >"$READS"

note "results: small versions of shipped jobs"
job_from jobs/dfg-filament.yaml dfg.yaml "s/resolution: .*/resolution: [16, 8]/" "s|^output: .*|output: dfg.h5|"
job_from jobs/disney-diffuse.yaml diffuse.yaml "s/resolution: .*/resolution: [8, 4]/" "s|^output: .*|output: diffuse.h5|"
cat > ltc.yaml <<'YAML'
name: ltc-small
kind: sweep
output: ltc.h5
sweep:
  problem: ltc
  models: [ggx, charlie]
  axes: [{name: sqrt_one_minus_cos, count: 6}, {name: roughness, from: 0.2, to: 1, count: 5}]
  march: {axis: sqrt_one_minus_cos}
  fit: {global_search: never, warm_evaluations: 100}
  objective: {samples: 64, judge_samples: 128, polygon_quads: 0}
YAML
job_from jobs/ltc-retro.yaml retro.yaml "s|^output: .*|output: retro.h5|" "s/count: 32}/count: 4}/" \
  "s/{name: retro, from: 0.5, to: 0.5, count: 1}/{name: retro, from: 0.25, to: 0.75, count: 2}/" \
  "s/warm_evaluations: 300/warm_evaluations: 60/" '/^  fit:/a\  objective: {samples: 64, judge_samples: 128, polygon_quads: 0}'
job_from tests/jobs/small-sphere-light.yaml sphere.yaml "s|^output: .*|output: sphere.h5|"
job_from tests/jobs/small-ebrdf.yaml ebrdf.yaml "s|^output: .*|output: ebrdf.h5|"
for job in dfg diffuse ltc retro sphere ebrdf; do
  run_ranks 2 run $job.yaml -q
  expect_status 0 "the job $job.yaml"
done

# Exports RESULT with OPTIONS as FORMAT (float and, where the format has a choice, half) to NAME.*, and
# queues the read-backs and checks.
N=0
export_as() {
  local name=$1 result=$2 format=$3 precision=$4; shift 4
  local file="$name.$precision.$format" extra=()
  [[ $format == cpp ]] && file="$name.$precision.hpp"
  N=$((N + 1))
  [[ $format == cpp || $format == js ]] && extra=(--prefix "T${N}_")
  "$PBRFIT" export "$result" --format "$format" --precision "$precision" -o "$file" "${extra[@]}" "$@" >out.txt 2>err.txt ||
    { cat err.txt; fail "export of $result $* as $format ($precision) failed"; }
  grep -q "^wrote $file: " out.txt || { cat out.txt; fail "export does not say what it wrote"; }
  local check=("$result" "$file" --format "$format" --precision "$precision" "$@")
  # three.js's EXRLoader reads Y, RGB and RGBA files only; OpenEXR reads RG files back in test_texture.
  [[ $format == exr ]] && grep -q ", 2 channels " out.txt && return
  case $format in
    exr | hdr | ktx2) echo "$format $file $file.json" >>"$READS"; check+=(--readback "$file.json") ;;
    cpp | js) echo "$file T${N}_ $precision" >>"$format-modules.txt"; check+=(--values "T${N}_.values") ;;
    glsl | hlsl) compile_shader "$file" "$format" ;;
  esac
  [[ $format == glsl || $format == hlsl ]] || printf '%q ' "${check[@]}" >>"$CHECKS"
  echo >>"$CHECKS"
}

# GLSL includes as GLSL ES 3.00 (WebGL 2) and GLSL 4.50; HLSL includes in a compute shader.
compile_shader() {
  local file=$1 language=$2 symbol
  symbol=$(grep -o "^[a-z ]*float [A-Z0-9_]*DATA\[" "$file" | grep -o "[A-Z0-9_]*DATA" || true)
  [[ -n $symbol ]] || symbol=$(grep -o "uint [A-Z0-9_]*DATA\[" "$file" | grep -o "[A-Z0-9_]*DATA")
  if [[ $language == glsl ]]; then
    for version in "300 es" 450; do
      { echo "#version $version"; echo "precision highp float;"; cat "$file"
        echo "out vec4 colour; void main() { colour = vec4(float(${symbol}[0])); }"; } >"$file.frag"
      glslangValidator "$file.frag" >compile.txt 2>&1 || { cat compile.txt; fail "$file is not GLSL $version"; }
    done
  else
    { cat "$file"; echo "RWStructuredBuffer<float> o; [numthreads(1, 1, 1)] void main() { o[0] = float(${symbol}[0]); }"; } >"$file.comp.hlsl"
    glslangValidator -D -V -S comp -e main "$file.comp.hlsl" -o /dev/null >compile.txt 2>&1 ||
      { cat compile.txt; fail "$file is not HLSL"; }
  fi
}

ALL_FORMATS=(dds ktx2 exr hdr png npy cpp glsl hlsl js)
# Every format that holds TABLE, at both precisions where there is a choice; hdr only for non-negative values.
export_all() {
  local name=$1 result=$2; shift 2
  local format
  for format in dds ktx2 exr npy cpp glsl hlsl js; do
    export_as "$name" "$result" "$format" float "$@"
    export_as "$name" "$result" "$format" half "$@"
  done
  export_as "$name" "$result" png float "$@"
}

note "exports of 2D tables in every format"
export_all dfg dfg.h5
export_as dfg dfg.h5 hdr float
export_all dfg-energy dfg.h5 --channels energy,scale
export_all dfg-swapped dfg.h5 --u-axis roughness --flip-v
export_as dfg-swapped dfg.h5 hdr float --u-axis roughness --flip-v
export_all diffuse diffuse.h5
export_all ggx-1 ltc.h5 --model ggx --table ltc_1
export_all ggx-2 ltc.h5 --model ggx --table ltc_2
export_all charlie-1 ltc.h5 --model charlie --table ltc_1 --flip-v
export_all ggx-parameters ltc.h5 --model ggx --table parameters

note "arrays, volumes and mips: the formats that hold them"
for format in dds ktx2 cpp js glsl hlsl npy; do
  for precision in float half; do
    export_as ggx-pair ltc.h5 "$format" "$precision" --model ggx --table ltc
    export_as retro-pairs retro.h5 "$format" "$precision" --table ltc
    export_as sphere-cap sphere.h5 "$format" "$precision" --model capped_roughness --table cap
    export_as sphere-parameters sphere.h5 "$format" "$precision" --model capped_roughness --table parameters \
      --channels cap,smoothness
    [[ $format == npy ]] && continue
    export_as specular ebrdf.h5 "$format" "$precision" --table specular
    export_as diffuse-ebrdf ebrdf.h5 "$format" "$precision" --table diffuse
  done
done

note "the GLSL snippets of docs/export.md compile as GLSL ES 3.00 fragment shaders"
awk '/^```glsl$/ { n++; file = sprintf("snippet-%d.frag", n); next } /^```$/ { file = "" } file { print > file }' \
  "$PBRFIT_SOURCE_DIR/docs/export.md"
ls snippet-*.frag >/dev/null 2>&1 || fail "docs/export.md has no GLSL snippet"
for snippet in snippet-*.frag; do
  glslangValidator "$snippet" >compile.txt 2>&1 || { cat compile.txt "$snippet"; fail "a GLSL snippet of docs/export.md does not compile"; }
done

note "C++ headers compiled into one program; JavaScript modules imported by node"
{
  echo "#include <cstdio>"
  while read -r file prefix precision; do echo "#include \"$file\""; done <cpp-modules.txt
  echo "template <class T> void put(const char* path, const T* data, unsigned long n) {"
  echo "  std::FILE* f = std::fopen(path, \"w\");"
  echo "  for (unsigned long i = 0; i < n; ++i)"
  echo "    if constexpr (sizeof(T) == 2) std::fprintf(f, \"%u\\n\", unsigned(data[i])); else std::fprintf(f, \"%.9g\\n\", double(data[i]));"
  echo "  std::fclose(f);"
  echo "}"
  echo "int main() {"
  while read -r file prefix precision; do echo "  put(\"$prefix.values\", ${prefix}DATA, ${prefix}COUNT);"; done <cpp-modules.txt
  echo "}"
} >headers.cpp
"${CXX:-g++}" -std=c++17 -Wall -Wextra -Werror -o headers headers.cpp 2>compile.txt || { cat compile.txt; fail "the C++ headers do not compile"; }
./headers
{
  while read -r file prefix precision; do echo "import * as $prefix from './$file';"; done <js-modules.txt
  echo "import { writeFileSync } from 'node:fs';"
  while read -r file prefix precision; do
    echo "writeFileSync('$prefix.values', Array.from($prefix.${prefix}DATA).join('\\n') + '\\n');"
  done <js-modules.txt
} >modules.mjs
node modules.mjs 2>err.txt || { cat err.txt; fail "node cannot import the JavaScript modules"; }

note "EXR, HDR and KTX2 read by three.js's loaders (and ktx-parse) in node"
node "$PBRFIT_SOURCE_DIR/tests/web/read_textures.mjs" "$PBRFIT_WEB_MODULES" "$READS" 2>err.txt ||
  { cat err.txt; fail "a reader cannot read an exported file"; }
grep -q "three.KTX2Loader" ggx-1.float.ktx2.json || fail "three.js's KTX2Loader did not read the 2D KTX2 files"

note "every value against the HDF5 tables ($(grep -c . "$CHECKS") files)"
"$H5PY_PYTHON" "$PBRFIT_SOURCE_DIR/tests/mpi/lib/check_export.py" "$CHECKS" >checked.txt 2>err.txt ||
  { cat err.txt; fail "exported values differ from the HDF5 tables"; }
[[ $(grep -c "^ok " checked.txt) -eq $(grep -c . "$CHECKS") ]] || fail "not every export was checked"

note "the checks can fail: one bit of one exported value"
"$H5PY_PYTHON" - <<'PY'
import numpy as np
a = np.load("dfg.float.npy"); v = a.view(np.uint32); v.flat[5] ^= 1; np.save("dfg.flipped.npy", a)
PY
echo "dfg.h5 dfg.flipped.npy --format npy" >bad-checks.txt
! "$H5PY_PYTHON" "$PBRFIT_SOURCE_DIR/tests/mpi/lib/check_export.py" bad-checks.txt >/dev/null 2>err.txt ||
  fail "a changed bit passes the check"
grep -q "value 5 is" err.txt || { cat err.txt; fail "the failed check does not name the value"; }

note "refusals: exit 2, one line"
refuse() {
  local expected=$1; shift
  run_pbrfit export "$@"
  expect_one_line 2 "$expected"
  [[ ! -s out.txt ]] || fail "a refusal printed on stdout"
}
refuse "--table: error: is 'ltc'; this result holds the table 'dfg'" dfg.h5 --format dds --table ltc
refuse "--model: error: is needed: this sweep holds the models charlie, ggx" ltc.h5 --format dds
refuse "--model: error: is 'beckmann', not a model of this sweep (charlie, ggx)" ltc.h5 --format dds --model beckmann
refuse "--channels: error: names 'gloss', which this table does not have (it has: scale, bias, energy, cloth)" \
  dfg.h5 --format exr --channels scale,gloss
refuse "--u-axis: error: is 'theta'; this table's axes are roughness, n_dot_v" dfg.h5 --format exr --u-axis theta
refuse "ltc.h5: error: cannot export ggx/level0/ltc: png: holds one 2D image, not 2 array layers" \
  ltc.h5 --format png --model ggx
refuse "ebrdf.h5: error: cannot export ebrdf/specular: exr: holds one 2D image, not 4 mip levels" ebrdf.h5 --format exr
refuse "ebrdf.h5: error: cannot export ebrdf/specular: npy: holds one mip level, not 4" ebrdf.h5 --format npy
refuse "sphere.h5: error: cannot export capped_roughness/level0/cap: hdr: holds one 2D image, not a volume of depth 2" \
  sphere.h5 --format hdr --model capped_roughness --table cap
run_pbrfit export diffuse.h5 --format hdr -o x.hdr --channels beta,zh0,zh1_ratio
expect_status 2
grep -qE "^diffuse.h5: error: cannot export disney_diffuse: hdr: value -[0-9.e-]+ at .* is negative; RGBE holds values >= 0$" err.txt ||
  { cat err.txt; fail "negative values in HDR are not refused on one line"; }
refuse "--member: error: applies to a front member's function, not to a table" dfg.h5 --format dds --member 0
refuse "--format: error: 'webp' is not a table format (dds, ktx2, exr, hdr, png, npy, cpp, glsl, hlsl, js)" dfg.h5 --format webp
refuse "--precision: error: 'double' is neither float nor half" dfg.h5 --format dds --precision double
[[ ! -e x.hdr && ! -e dfg.dfg.png ]] || fail "a refused export left a file"

note "an unfinished result"
job_from jobs/dfg-filament.yaml long.yaml "s|^output: .*|output: long.h5|" "s/resolution: .*/resolution: [256, 256]/"
start_ranks 1 run long.yaml -q
wait_for_items long.h5 8
refuse "long.h5: error: is 'running', not complete: export its tables once the job has finished" long.h5 --format dds
kill -TERM $(rank_pids)
wait_background
expect_status 75
echo "PASS"
