#!/usr/bin/env bash
# Install metricmap into a scratch prefix and build a consumer of the core component only; its
# configure must not look for VTK, yaml-cpp or nlohmann-json.
set -euo pipefail
build_dir=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release >/dev/null
for pkg in VTK yaml-cpp nlohmann_json octomap PNG TIFF; do
  if grep -qE "^${pkg}_DIR:PATH=/" "$work/build/CMakeCache.txt"; then
    echo "core consumer's configure found $pkg" >&2
    exit 1
  fi
done
cmake --build "$work/build" -j 2 >/dev/null
"$work/build/core_consumer"
