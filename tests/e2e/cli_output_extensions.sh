#!/usr/bin/env bash
# Issue 24, class 10: file type by extension. Every output option writes one format, and the
# name it is given must end in that format's extension (lowercase): otherwise the run is a
# usage error (exit 2, one line naming the option and the extension) and nothing is written.
# `--out-cloud c.bin` used to write PCD bytes that `info` then rejected, `--screenshot s.jpg` a
# PNG, `--out-ot x.bt` a maximum-likelihood .bt.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
bun=$D/pcl_test_pcd/bunny.pcd
tum=$D/open3d_tum_depth
mines=$D/breezyslam_mines_urg04lx/exp2.dat
o=$tmp/o
mkdir -p "$o"
cam="--camera $tum/camera_primesense.json"
occ="occupancy $k --frames 0 --resolution 0.5 --max-range 20"
kit="kitti $k --frames 0"

cases=(
  # PCD outputs
  "2|--out-cloud|$occ --out-cloud $o/c.bin"
  "2|--out-cloud|$occ --out-cloud $o/c.ply"
  "2|--out-cloud|$kit --out-cloud $o/c.bin"
  "2|--out-cloud|$kit --out-cloud $o/c"
  "2|--out|grid $bun --cell-size 0.01 --out $o/g.ply"
  "2|--out|grid $bun --cell-size 0.01 --out $o/g.PCD"
  "2|--out|octree $bun --max-points 100 --min-cell-size 0.01 --out $o/t.bin"
  "2|--out|depth-to-cloud $tum/TUM_depth.png $cam --out $o/d.ply"
  # CSV outputs
  "2|--cells|grid $bun --cell-size 0.01 --cells $o/c.json"
  "2|--leaves|octree $bun --max-points 100 --min-cell-size 0.01 --leaves $o/l.pcd"
  # OctoMap outputs: --out is .bt (maximum likelihood), --out-ot is .ot (log-odds)
  "2|--out-ot|$occ --out-ot $o/x.bt"
  "2|--out|$occ --out $o/x.ot"
  "2|--out|$occ --out $o/x.txt"
  "2|--out-octomap|$kit --occupancy-resolution 0.5 --out-octomap $o/x.pcd"
  # map_server maps (PGM + YAML) and their PNG previews
  "2|--out-map|$occ --out-map $o/m.png --band -1,1"
  "2|--out-map|$kit --out-map $o/m.png"
  "2|--out-map|$kit --out-map $o/m"
  "2|--out-trinary|$kit --occupancy-resolution 0.5 --out-trinary $o/t.png --band -1,1 --world velodyne"
  "2|--map-preview|$occ --out-map $o/m.pgm --band -1,1 --map-preview $o/p.jpg"
  # pictures
  "2|--screenshot|view $bun --screenshot $o/s.jpg"
  "2|--screenshot|view $bun --screenshot $o/s.svg"
  "2|--png|lines $mines --preset urg04lx-mines --png $o/l.svg"
  "2|--svg|lines $mines --preset urg04lx-mines --svg $o/l.png"
  "2|--plot|compare $bun --plot $o/p.jpg"
  # text: the poses file, the study table in the format --format names
  "2|--out-poses|$kit --out-poses $o/p.pcd"
  "2|--out-poses|odometry $k --frames 0,1 --out-poses $o/p.tum"
  "2|--out|compare $bun --format csv --out $o/s.json"
  "2|--out|compare $bun --format json --out $o/s.csv"
  "2|--out|compare $bun --format markdown --out $o/s.png"
)
expect_cases "${cases[@]}"
check "nothing written by a refused name" test -z "$(ls -A "$o")"

# The extensions each option names are accepted, and what they write reads back.
check "occupancy writes .bt, .ot, .pcd, .pgm, .png" bash -c \
  "'$MM' $occ --out '$o/a.bt' --out-ot '$o/a.ot' --out-cloud '$o/a.pcd' --out-map '$o/a.pgm' --band -1,1 --map-preview '$o/a.png' >/dev/null &&
   '$MM' info '$o/a.pcd' >/dev/null && '$MM' occupancy '$o/a.ot' --out-cloud '$o/b.pcd' >/dev/null"
check "kitti writes .pcd, .pgm, .txt, .ot" bash -c \
  "'$MM' $kit --out-cloud '$o/k.pcd' --out-map '$o/k.pgm' --out-poses '$o/k.txt' --occupancy-resolution 0.5 --out-octomap '$o/k.ot' >/dev/null &&
   '$MM' info '$o/k.pcd' >/dev/null"
check "odometry writes TUM rows to .tum as to .txt" bash -c \
  "'$MM' odometry $k --frames 0,1 --pose-format tum --out-poses '$o/p.tum' >/dev/null &&
   '$MM' odometry $k --frames 0,1 --pose-format tum --out-poses '$o/p.txt' >/dev/null &&
   cmp '$o/p.tum' '$o/p.txt'"
check "grid and compare write .pcd, .csv, .md" bash -c \
  "'$MM' grid '$bun' --cell-size 0.01 --out '$o/g.pcd' --cells '$o/g.csv' >/dev/null &&
   '$MM' compare '$bun' --format markdown --out '$o/s.md' && '$MM' compare '$bun' --out '$o/s.txt'"
finish
