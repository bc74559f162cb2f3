#!/usr/bin/env bash
# Issue 24, class 5: values the tool cannot read back. Every option whose value ends up in a
# file has the range that file's format and metricmap's own reader accept: an OctoMap `res`
# line holds a voxel edge from 0.0001 to 1000 m (src/metricmap/occupancy/octomap_file_check.cpp),
# and the map_server YAML (`resolution`, `origin`) gets the same range. Beyond it the option is
# a usage error at parse time (exit 2 naming it), before any file is written; the bounds
# themselves write files that read back.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
o=$tmp/o
mkdir -p "$o"
occ="occupancy $k --frames 0 --max-range 20"
kit="kitti $k --frames 0"

cases=(
  # occupancy --resolution: the .bt/.ot `res` line, the .pcd voxel centres, the YAML
  "2|--resolution|$occ --resolution 1001 --out $o/m.bt"
  "2|--resolution|$occ --resolution 1e308 --out-cloud $o/c.pcd"
  "2|--resolution|$occ --resolution 1e308 --out-ot $o/m.ot"
  "2|--resolution|$occ --resolution 0.00009 --out $o/m.bt"
  "2|--resolution|$occ --resolution 1e-300 --out $o/m.bt"
  "2|--resolution|$occ --resolution 5000 --out-map $o/m.pgm --band -1,1"
  # kitti: the 3D map's voxel edge, the 2D map's cell edge (YAML resolution and origin)
  "2|--occupancy-resolution|$kit --occupancy-resolution 1001 --out-octomap $o/m.bt"
  "2|--occupancy-resolution|$kit --occupancy-resolution 1e308 --out-octomap $o/m.ot"
  "2|--occupancy-resolution|$kit --occupancy-resolution 0.00001 --out-octomap $o/m.bt"
  "2|--map-resolution|$kit --map-resolution 1e308 --out-map $o/m.pgm"
  "2|--map-resolution|$kit --map-resolution 1001 --out-map $o/m.pgm"
  "2|--map-resolution|$kit --map-resolution 0.00001 --out-map $o/m.pgm"
  # heights that select the mapped points: decimal numbers only
  "2|--min-height|$kit --min-height 0x10 --out-map $o/m.pgm"
  "2|--max-height|$kit --max-height inf --out-map $o/m.pgm"
  "2|--max-height|$kit --max-height 1e999 --out-map $o/m.pgm"
)
expect_cases "${cases[@]}"
check "nothing written by a refused option" test -z "$(ls -A "$o")"

# The largest voxel edge writes maps that metricmap reads back.
check "occupancy --resolution 1000 writes a .bt that reads back" bash -c \
  "'$MM' $occ --resolution 1000 --out '$o/big.bt' >/dev/null &&
   '$MM' occupancy '$o/big.bt' --out-cloud '$o/big.pcd' >/dev/null && '$MM' info '$o/big.pcd' >/dev/null"
check "occupancy --resolution 1000 writes a .ot that reads back" bash -c \
  "'$MM' $occ --resolution 1000 --out-ot '$o/big.ot' >/dev/null &&
   '$MM' occupancy '$o/big.ot' --out '$o/big2.bt' >/dev/null"
check "kitti --map-resolution 1000 writes a finite YAML" bash -c \
  "'$MM' $kit --map-resolution 1000 --out-map '$o/km.pgm' >/dev/null &&
   grep -q '^resolution: 1000$' '$o/km.yaml' && ! grep -qi 'inf\|nan\|e+' '$o/km.yaml'"
check "kitti --occupancy-resolution 1000 writes a .bt that reads back" bash -c \
  "'$MM' $kit --occupancy-resolution 1000 --out-octomap '$o/k.bt' >/dev/null &&
   '$MM' occupancy '$o/k.bt' --out-cloud '$o/k.pcd' >/dev/null"
finish
