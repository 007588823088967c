#!/usr/bin/env bash
# Every job kind's `pbrfit report` page, opened in headless Chromium (Debian's, driven by playwright-core from
# npm: tests/web/report_pages_test.mjs) as a reader would: a small job of each kind (lut, sweep, symreg,
# brdf_search, ebrdf, and ebrdf_render from the ebrdf tables) on 2 ranks, its report, and the page served from
# a loopback HTTP server must load without a console error, page error, failed request or HTTP error; show
# every figure the report wrote, loaded and at its natural size; have only links that resolve (anchors on the
# page, files in the report directory) and none that leave the report. A full-page screenshot of each kind
# and results.json stay in $PBRFIT_ARTIFACTS (default: the build's Testing/report-pages).
source "$(dirname "$0")/lib/common.bash"
: "${PBRFIT_WEB_MODULES:?PBRFIT_WEB_MODULES must name the web test packages (make web-deps)}"
[[ -d $PBRFIT_WEB_MODULES/playwright-core ]] ||
  fail "playwright-core is missing from $PBRFIT_WEB_MODULES (make web-deps installs it)"
command -v node >/dev/null || fail "node is missing (.ci/install-deps --web installs it)"
[[ -x /usr/bin/chromium ]] || fail "Debian's chromium is missing (.ci/install-deps --web installs it)"
[[ -x $H5PY_PYTHON ]] || fail "$H5PY_PYTHON is missing (it serves the pages)"
ARTIFACTS=${PBRFIT_ARTIFACTS:-$(dirname "$PBRFIT")/Testing/report-pages}
MPI_FLAGS+=(--bind-to none)

SERVER_PID=""
stop_server() {
  if [[ -n $SERVER_PID ]]; then kill "$SERVER_PID" 2>/dev/null || true; wait "$SERVER_PID" 2>/dev/null || true; fi
  SERVER_PID=""
}
trap 'stop_server; kill_group_if_running; rm -rf "$WORK"' EXIT

# KIND SOURCE_JOB: the job copied here, writing KIND.h5 here.
job() {
  job_from "$2" "$1.yaml" "s|^output: .*|output: $1.h5|"
}
job lut tests/jobs/small-dfg.yaml
job sweep tests/jobs/small-sweep.yaml
job symreg tests/jobs/small-symreg.yaml
job brdf_search tests/jobs/small-brdf.yaml
job ebrdf tests/jobs/small-ebrdf.yaml
cat >ebrdf_render.yaml <<'YAML'
name: small-render
kind: ebrdf_render
output: ebrdf_render.h5
ebrdf_render:
  tables: ebrdf.h5
  distances: [1, 4, 16]
  resolution: 24
YAML
KINDS=(lut sweep symreg brdf_search ebrdf ebrdf_render)   # ebrdf before ebrdf_render: its tables

declare -A FIGURES
for kind in "${KINDS[@]}"; do
  note "$kind: the job on 2 ranks and its report"
  run_ranks 2 run "$kind.yaml" -q
  expect_status 0 "the $kind job"
  set +e
  "$PBRFIT" report "$kind.h5" >out.txt 2>err.txt; STATUS=$?
  set -e
  expect_status 0 "the report of the $kind job: $(head -n 1 err.txt)"
  [[ ! -s err.txt ]] || { cat err.txt; fail "the report of the $kind job wrote to stderr"; }
  [[ -f $kind.report/index.html ]] || fail "the report of the $kind job wrote no $kind.report/index.html"
  FIGURES[$kind]=$(sed -n 's/^report: .* (\([0-9][0-9]*\) figures\?).*/\1/p' out.txt)
  [[ -n ${FIGURES[$kind]} ]] || { cat out.txt; fail "the report of the $kind job does not say how many figures it drew"; }
done

note "the pages from a loopback HTTP server, in headless Chromium"
"$H5PY_PYTHON" -u -m http.server --bind 127.0.0.1 --directory "$WORK" 0 >server.txt 2>server-log.txt &
SERVER_PID=$!
PORT=""
for _ in $(seq 1 100); do
  PORT=$(sed -n 's/^Serving HTTP on .* port \([0-9][0-9]*\) .*/\1/p' server.txt)
  [[ -n $PORT ]] && break
  kill -0 "$SERVER_PID" 2>/dev/null || { cat server-log.txt; fail "the HTTP server did not start"; }
  sleep 0.1
done
[[ -n $PORT ]] || fail "the HTTP server did not say its port within 10 s"
PAGES=()
for kind in "${KINDS[@]}"; do PAGES+=("$kind=http://127.0.0.1:$PORT/$kind.report/index.html"); done
rm -rf "$ARTIFACTS"
set +e
timeout 120 node "$PBRFIT_SOURCE_DIR/tests/web/report_pages_test.mjs" "$PBRFIT_WEB_MODULES" "$ARTIFACTS" "${PAGES[@]}" \
  >browser.txt 2>browser-err.txt
STATUS=$?
set -e
stop_server
[[ $STATUS -ne 124 ]] || fail "the browser test hung"
if [[ $STATUS -ne 0 ]]; then
  (( $(wc -l <browser-err.txt) <= 1 )) || head -n 20 browser-err.txt >&2   # more than the reason: node's own
  fail "$(tail -n 1 browser-err.txt) (screenshots in $ARTIFACTS)"
fi
cat browser.txt

# The browser saw every figure each report wrote, and kept a screenshot of each page.
"$H5PY_PYTHON" - browser.txt $(for kind in "${KINDS[@]}"; do echo "$kind=${FIGURES[$kind]}"; done) \
  2>count.txt <<'PY' || fail "$(tail -n 1 count.txt)"
import json, sys
pages = {p["name"]: p for p in json.load(open(sys.argv[1]))["pages"]}
for arg in sys.argv[2:]:
    kind, figures = arg.split("=")
    if kind not in pages:
        sys.exit(f"the browser did not report the {kind} page")
    if pages[kind]["images"] != int(figures):
        sys.exit(f"the {kind} page shows {pages[kind]['images']} images, its report drew {figures} figures")
PY
for kind in "${KINDS[@]}"; do
  [[ -s $ARTIFACTS/$kind.png ]] || fail "no screenshot of the $kind page ($ARTIFACTS/$kind.png)"
done
echo "PASS (screenshots in $ARTIFACTS)"
