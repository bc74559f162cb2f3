#!/usr/bin/env bash
# Install metricmap into a scratch prefix and build a consumer of one component; its configure
# must not look for the packages named after the source directory (default: those the core
# component must not need), and the consumer must run and pass its own checks.
# run_core_consumer.sh BUILD_DIR CONSUMER_SOURCE_DIR [PACKAGE...]
set -euo pipefail
build_dir=$1 source_dir=$2
shift 2
forbidden=("$@")
[ ${#forbidden[@]} -gt 0 ] || forbidden=(VTK yaml-cpp nlohmann_json octomap PNG TIFF)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release >/dev/null
for pkg in "${forbidden[@]}"; do
  if grep -qE "^${pkg}_DIR:PATH=/" "$work/build/CMakeCache.txt"; then
    echo "$(basename "$source_dir")'s configure found $pkg" >&2
    exit 1
  fi
done
cmake --build "$work/build" -j 2 >/dev/null
"$work/build/$(basename "$source_dir")"
