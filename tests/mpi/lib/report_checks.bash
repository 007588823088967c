# Checks of a `pbrfit report` directory, shared by the report tests (source after common.bash).

# "WIDTH HEIGHT" of a PNG file from its IHDR chunk; fails unless the file starts with the 8-byte PNG
# signature followed by the IHDR chunk.
png_dimensions() {
  local bytes
  bytes=$(head -c 24 "$1" | od -An -v -tx1 | tr -d ' \n')
  [[ ${bytes:0:16} == 89504e470d0a1a0a && ${bytes:24:8} == 49484452 ]] || return 1
  echo "$((16#${bytes:32:8})) $((16#${bytes:40:8}))"
}

# Every <img src=...> of DIR/index.html names a file in DIR that is a PNG of positive size; at least
# MIN images. Sets IMAGES to their count.
expect_valid_images() {
  local dir=$1 min=${2:-1} src size width height
  [[ -f $dir/index.html ]] || fail "no $dir/index.html"
  IMAGES=0
  while IFS= read -r src; do
    [[ $src =~ ^[A-Za-z0-9._-]+$ ]] || fail "image path '$src' is not a plain relative name"
    [[ -f $dir/$src ]] || fail "index.html references $src, which is not in $dir"
    size=$(png_dimensions "$dir/$src") || fail "$src is not a PNG (signature or IHDR missing)"
    read -r width height <<<"$size"
    (( width > 0 && height > 0 )) || fail "$src is $width x $height pixels"
    IMAGES=$((IMAGES + 1))
  done < <(grep -o '<img src="[^"]*"' "$dir/index.html" | sed 's/^<img src="//; s/"$//')
  (( IMAGES >= min )) || fail "$IMAGES images in $dir/index.html, expected at least $min"
}

# Every dataset of RESULT that is not an axis (dimension scale) is named by its path in DIR/index.html.
# Sets TABLES to their count.
expect_tables_mentioned() {
  local result=$1 dir=$2 path
  TABLES=0
  while IFS= read -r path; do
    grep -qF -- "$path" "$dir/index.html" || fail "index.html does not mention table $path"
    TABLES=$((TABLES + 1))
  done < <("$H5PY_PYTHON" - "$result" <<'PY'
import sys, h5py
def show(name, obj):
    if isinstance(obj, h5py.Dataset) and not h5py.h5ds.is_scale(obj.id):
        print("/" + name)
with h5py.File(sys.argv[1], "r") as f:
    f.visititems(show)
PY
)
  (( TABLES > 0 )) || fail "$result has no tables"
}

# Runs tests/jobs/JOB (whose output is result.h5) on 2 ranks and reports it: result.report/index.html,
# nothing on stderr, and the page's path said on stdout.
report_of_test_job() {
  cp "$PBRFIT_SOURCE_DIR/tests/jobs/$1" job.yaml
  run_ranks 2 run job.yaml -q
  expect_status 0
  set +e
  "$PBRFIT" report result.h5 >out.txt 2>err.txt; STATUS=$?
  set -e
  expect_status 0 "$(cat err.txt)"
  [[ ! -s err.txt ]] || { cat err.txt; fail "report wrote to stderr"; }
  grep -q "result.report/index.html" out.txt || { cat out.txt; fail "report does not say where the page is"; }
}
