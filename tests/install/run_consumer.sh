#!/usr/bin/env bash
# Install metricmap into a scratch prefix, build the consumer project against it, run it.
set -euo pipefail
build_dir=$1 source_dir=$2 data=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/metricmap/metricmap.h"
cmake -S "$source_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" -j 2 >/dev/null
out=$("$work/build/consumer" "$data")
echo "$out"
echo "$out" | grep -q "^2 segments; .*79149 points, 338 occupied cells, 1212 occupied leaves"
# The installed command finds its drawing module in <libdir>/metricmap.
data_root=$(dirname "$(dirname "$data")")
"$work/prefix/bin/metricmap" lines "$data_root/pythonrobotics_lidar01/lidar01.csv" \
  --png "$work/scan.png" >/dev/null
test -s "$work/scan.png"
echo "installed metricmap drew $work/scan.png through its drawing module"
