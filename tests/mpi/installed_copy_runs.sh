#!/usr/bin/env bash
# pbrfit installs like HPC software (docs/install.md): `cmake --install` to a prefix and the Debian package
# built by CPack each give a program that runs from outside the source and build trees, finding its data,
# report package and templates beside itself; `--version` names the version and the commit.
#  - the prefix: the quickstart (lut), a sweep over a measured material (its stand-in from the installed
#    data) and `pbrfit report`, all from the installed files and jobs, in a folder of their own;
#  - the package: its files under /usr, its dependencies (shared libraries, MPI, the report's Python), and
#    the quickstart from its unpacked copy (unpacked, not installed: a test does not change the system).
source "$(dirname "$0")/lib/common.bash"

build=$(dirname "$PBRFIT")
[[ -f $build/cmake_install.cmake ]] || fail "no build tree beside $PBRFIT"

# Runs the program at $1 with the remaining arguments under 2 ranks, from the current folder.
run_installed() {
  local program=$1; shift
  set +e
  env -u PBRFIT_SHARE_DIR -u PBRFIT_DATA_DIR "$MPIEXEC" "${MPI_FLAGS[@]}" -np 2 "$program" "$@" >out.txt 2>err.txt
  STATUS=$?
  set -e
  [[ $STATUS -eq 0 ]] || { cat out.txt err.txt; fail "$program $* failed ($STATUS)"; }
}

note "cmake --install to a prefix"
cmake --install "$build" --prefix "$WORK/prefix" >install.log || { cat install.log; fail "installation failed"; }
installed=$WORK/prefix/bin/pbrfit
for file in share/pbrfit/data/reference/ltc_ggx_heitz2016_64.csv share/pbrfit/report/pbrfit_report/__init__.py \
  share/pbrfit/sbatch.template share/pbrfit/cluster/local-slurm/start.sh share/doc/pbrfit/README.md \
  share/doc/pbrfit/job-files.md share/doc/pbrfit/jobs/quickstart.yaml; do
  [[ -f prefix/$file ]] || fail "the installation has no $file"
done
[[ -z $(find prefix -name __pycache__) ]] || fail "compiled Python caches were installed"

note "--version names the version and the commit"
"$installed" --version >version.txt
grep -Eq '^pbrfit [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{12}|unknown)\)$' version.txt ||
  { cat version.txt; fail "--version does not say 'pbrfit X.Y.Z (commit C)'"; }
grep -Eq '^kernels: (generic|avx2|avx512) \(this machine has generic' version.txt ||
  { cat version.txt; fail "--version does not name the kernel set in use"; }
if git -C "$PBRFIT_SOURCE_DIR" rev-parse HEAD >/dev/null 2>&1; then
  grep -q "$(git -C "$PBRFIT_SOURCE_DIR" rev-parse --short=12 HEAD)" version.txt ||
    note "(the build was configured at another commit: $(cat version.txt))"
fi

note "the installed program runs the installed jobs from a folder of its own"
mkdir run && cd run
cp "$WORK/prefix/share/doc/pbrfit/jobs/quickstart.yaml" "$WORK/prefix/share/doc/pbrfit/jobs/ltc-merl.yaml" .
run_installed "$installed" run quickstart.yaml -q -o quickstart.h5
run_installed "$installed" run ltc-merl.yaml -q -o ltc-merl.h5   # a sweep; the material's stand-in is data
"$installed" status ltc-merl.h5 >status.txt
grep -q "complete" status.txt || { cat status.txt; fail "the sweep did not complete"; }
"$H5PY_PYTHON" - ltc-merl.h5 "$WORK/prefix/share/pbrfit/data" <<'EOF' || fail "the material did not come from the installed data"
import sys, h5py
found = []
with h5py.File(sys.argv[1], "r") as f:
    f.visititems(lambda name, obj: found.extend(str(v) for v in obj.attrs.values()))
sys.exit(0 if any(sys.argv[2] in v for v in found) else 1)
EOF
set +e
env -u PBRFIT_SHARE_DIR "$installed" report ltc-merl.h5 >out.txt 2>err.txt; STATUS=$?
set -e
[[ $STATUS -eq 0 ]] || { cat out.txt err.txt; fail "pbrfit report from the installation failed ($STATUS)"; }
[[ -s ltc-merl.report/index.html ]] || fail "no report page"
if grep -rq "$PBRFIT_SOURCE_DIR" ltc-merl.report/index.html; then fail "the report refers to the source tree"; fi
cd "$WORK"

note "the Debian package"
command -v dpkg-shlibdeps >/dev/null || fail "dpkg-shlibdeps is missing (Debian: dpkg-dev, which .ci/install-deps installs)"
cpack --config "$build/CPackConfig.cmake" -B "$WORK/package" >cpack.log 2>&1 || { cat cpack.log; fail "cpack failed"; }
deb=$(ls package/pbrfit_*.deb 2>/dev/null | head -1)
[[ -n $deb ]] || { cat cpack.log; fail "cpack made no .deb"; }
dpkg-deb -f "$deb" Package Version Depends >control.txt
for needed in 'Package: pbrfit' 'libhdf5' 'libopenmpi' 'libyaml-cpp' 'openmpi-bin' 'python3-h5py' 'python3-matplotlib'; do
  grep -q "$needed" control.txt || { cat control.txt; fail "the package's control fields lack $needed"; }
done
dpkg-deb -c "$deb" >contents.txt
for file in ./usr/bin/pbrfit ./usr/share/pbrfit/sbatch.template ./usr/share/pbrfit/data/reference/ltc_ggx_heitz2016_64.csv \
  ./usr/share/doc/pbrfit/jobs/quickstart.yaml; do
  grep -q " $file\$" contents.txt || fail "the package does not hold $file"
done
dpkg-deb -x "$deb" root
mkdir packaged && cd packaged
cp ../root/usr/share/doc/pbrfit/jobs/quickstart.yaml .
run_installed "$WORK/root/usr/bin/pbrfit" run quickstart.yaml -q -o quickstart.h5
"$H5PY_PYTHON" "$PBRFIT_SOURCE_DIR/tests/support/compare_numeric_datasets.py" quickstart.h5 ../run/quickstart.h5 ||
  fail "the packaged program's quickstart differs from the installed one's"
echo "PASS"
