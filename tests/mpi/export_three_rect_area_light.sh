#!/usr/bin/env bash
# pbrfit's LTC exports are drop-in replacements of three.js's RectAreaLight tables, proven in three.js itself
# (from npm) in headless Chromium with its software WebGL 2 (tests/web/rect_area_light_test.mjs): a floor and
# spheres of roughness 0.1 to 0.9 under a rectangular light, at a normal and a grazing view, rendered with
# three.js's tables, with pbrfit's export of the published table (the same image: mean difference at most
# 0.01 levels of 255, none more than 1), with pbrfit's own GGX fit (mean at most 2 levels, 99.9 % of the
# channels within 32: the fits differ only at grazing silhouettes), and with that fit exported transposed
# (--u-axis sqrt_one_minus_cos), which must fail the fit's comparison. A sphere shows Charlie sheen through
# pbrfit's Charlie tables in a patched shader chunk. The tables come from jobs/ltc-ggx.yaml (without its
# polygon-light judging) and a 32 x 32 jobs/ltc-charlie.yaml, exported as JavaScript modules in three.js's
# layout, float and half. The screenshots and results.json stay in $PBRFIT_ARTIFACTS (default: the build's
# Testing/three-rect-area-light) for a reader to look at.
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_WEB_MODULES:?PBRFIT_WEB_MODULES must name the web test packages (make web-deps)}"
for package in three playwright-core; do
  [[ -d $PBRFIT_WEB_MODULES/$package ]] || fail "$package is missing from $PBRFIT_WEB_MODULES (make web-deps installs it)"
done
command -v node >/dev/null || fail "node is missing (.ci/install-deps --web installs it)"
[[ -x /usr/bin/chromium ]] || fail "Debian's chromium is missing (.ci/install-deps --web installs it)"
ARTIFACTS=${PBRFIT_ARTIFACTS:-$(dirname "$PBRFIT")/Testing/three-rect-area-light}
MPI_FLAGS+=(--bind-to none)

note "the GGX and Charlie tables"
job_from jobs/ltc-ggx.yaml ggx.yaml "s|^output: .*|output: ggx.h5|" "s/judge_samples: 4096 .*/judge_samples: 4096\n    polygon_quads: 0/"
job_from jobs/ltc-charlie.yaml charlie.yaml "s|^output: .*|output: charlie.h5|" \
  '/^  models:/a\  axes: [{name: sqrt_one_minus_cos, count: 32}, {name: roughness, count: 32}]' \
  '$a\  objective: {samples: 256, judge_samples: 512, polygon_quads: 0}'
for job in ggx charlie; do
  run_ranks 2 run $job.yaml -q
  expect_status 0 "the job $job.yaml"
done

note "exported as three.js modules"
mkdir exported
table() {  # RESULT TABLE FILE PREFIX [options]
  local result=$1 table=$2 file=$3 prefix=$4; shift 4
  "$PBRFIT" export "$result" --table "$table" --format js -o "exported/$file" --prefix "$prefix" "$@" >out.txt 2>err.txt ||
    { cat err.txt; fail "export of $table to $file failed"; }
}
for n in 1 2; do
  table ggx.h5 ltc_$n ltc_$n.js LTC_${n}_
  table ggx.h5 ltc_$n ltc_${n}_half.js LTC_${n}_ --precision half
  table ggx.h5 published_ltc_$n published_$n.js LTC_${n}_
  table ggx.h5 published_ltc_$n published_${n}_half.js LTC_${n}_ --precision half
  table ggx.h5 ltc_$n transposed_$n.js LTC_${n}_ --u-axis sqrt_one_minus_cos
  table ggx.h5 ltc_$n transposed_${n}_half.js LTC_${n}_ --u-axis sqrt_one_minus_cos --precision half
  table charlie.h5 ltc_$n charlie_$n.js CHARLIE_${n}_
done
grep -q "^export const LTC_1_DATA = new Float32Array(\[" exported/ltc_1.js || fail "not three.js's float layout"
grep -q "^export const LTC_1_DATA = new Uint16Array(\[" exported/ltc_1_half.js || fail "not three.js's half layout"

note "three.js in headless Chromium"
rm -rf "$ARTIFACTS"
set +e
timeout 300 node "$PBRFIT_SOURCE_DIR/tests/web/rect_area_light_test.mjs" "$PBRFIT_WEB_MODULES" exported "$ARTIFACTS" \
  >render.txt 2>render-err.txt
STATUS=$?
set -e
cat render.txt
[[ $STATUS -ne 124 ]] || fail "the browser test hung"
[[ $STATUS -eq 0 ]] || { cat render-err.txt; fail "the renders disagree (screenshots in $ARTIFACTS)"; }
for image in three published pbrfit transposed; do
  [[ -s $ARTIFACTS/$image.png ]] || fail "no screenshot $image.png"
done
echo "PASS (screenshots in $ARTIFACTS)"
