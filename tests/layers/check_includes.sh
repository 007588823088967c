#!/usr/bin/env bash
# Fails when a source or header includes a third-party library that its layer may not use
# (docs/ARCHITECTURE.md). Include paths cannot enforce this for libraries installed in /usr/include
# (spdlog, yaml-cpp, CLI11), and engines must not touch files at all.
# Usage: check_includes.sh SOURCE_DIR
set -euo pipefail
cd "$1"

mpi='<mpi\.h>'; hdf5='<(hdf5|H5)[^>]*>'; spdlog='<spdlog/'; yaml='<yaml-cpp/'; cli='<CLI/'
files='<(fstream|filesystem|fcntl\.h|unistd\.h|sys/[^>]*)>'
eigen='<Eigen/'

forbidden_for() {
  case $1 in
    core) echo "$mpi|$hdf5|$spdlog|$yaml|$cli|$files|$eigen" ;;
    geometry|integrate|brdf|optimize|ltc|gp|sweep|render|ebrdf) echo "$mpi|$hdf5|$spdlog|$yaml|$cli|$files" ;;
    spec) echo "$mpi|$hdf5|$spdlog|$cli" ;;
    store) echo "$mpi|$spdlog|$yaml|$cli" ;;
    texture) echo "$mpi|$hdf5|$spdlog|$yaml|$cli|$files|$eigen" ;;  # bytes in memory: OpenEXR, Imath, libpng only
    runtime) echo "$hdf5|$yaml|$cli" ;;
    submit) echo "$mpi|$hdf5|$spdlog|$cli" ;;
    jobs) echo "$mpi|$hdf5|$spdlog|$yaml|$cli" ;;
    cli) echo "$mpi|$hdf5|$yaml" ;;
    report) echo "$mpi|$hdf5|$spdlog|$yaml|$cli|$files|$eigen" ;;  # the cli's Python report: no C++ at all
    *) echo "unknown-layer" ;;
  esac
}

status=0
for dir in src/*/ include/pbrfit/*/; do
  module=$(basename "$dir")
  pattern=$(forbidden_for "$module")
  if [[ $pattern == unknown-layer ]]; then
    echo "FAIL: $dir belongs to no layer: add it to tests/layers/check_includes.sh and docs/ARCHITECTURE.md"
    status=1
    continue
  fi
  if hits=$(grep -rnE "^[[:space:]]*#[[:space:]]*include[[:space:]]*($pattern)" "$dir"); then
    echo "FAIL: the $module layer includes what it may not use:"
    echo "$hits"
    status=1
  fi
done
# Within the engines: ltc fits the lobes brdf provides, so brdf (and geometry below it) never reaches ltc.
for dir in src/brdf include/pbrfit/brdf src/geometry include/pbrfit/geometry; do
  if hits=$(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"pbrfit/ltc/' "$dir"); then
    echo "FAIL: $dir includes the ltc engine, which sits above it:"
    echo "$hits"
    status=1
  fi
done
[[ $status -eq 0 ]] && echo "PASS: every layer includes only the libraries it may use"
exit $status
