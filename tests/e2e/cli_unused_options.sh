#!/usr/bin/env bash
# Issue 24, class 6, the rest of the class: an option that would have no effect in the run given
# is refused (exit 2, one line "OPTION has no effect ..."), never dropped silently. Every command
# was gone through: kitti (--seed without a perturbation, --refine-target/--target-voxel without
# --refine or with another target, --pcd-format without --out-cloud, --occupancy-max-range without
# --occupancy-resolution, --occupancy-resolution shown nowhere, --count with --frames), grid/octree/occupancy --pcd-format without a PCD
# output, view (octree options without --octree, --cell-size without --grid, --free without a
# map, --scan without a log or --segments, --camera with --segments, --color-by height on scan
# logs alone), lines (--purge with nothing to purge, the noise model without --chi2 or JSON),
# heightmap (--pitch-deg/--yaw-deg without --camera-height), evaluate (--per-frame where it adds
# nothing, --max-time-diff when the poses pair by index).
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
bun=$D/pcl_test_pcd/milk.pcd
csv=$D/pythonrobotics_lidar01/lidar01.csv
tumd=$D/open3d_tum_depth/TUM_depth.png
tumc=$D/open3d_tum_depth/camera_primesense.json
o=$tmp/o
mkdir -p "$o"
"$MM" lines "$csv" --format json >"$tmp/seg.json" || { echo "FAIL: cannot make segments"; exit 1; }
hm="--resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix $o/hm"
eye="1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1"
# a TUM trajectory with stamps and one relation between two of them (the relation metric)
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n' >"$tmp/est_tum.txt"
printf '0 1 1 0 0 0 0 0\n' >"$tmp/rel.txt"
P=$k/poses/00.txt  # KITTI form: no stamps, pairs by index

cases=(
  # kitti
  "2|--seed has no effect without --perturb|kitti $k --frames 0-1 --seed 3"
  "2|--seed has no effect without --perturb|kitti $k --frames 0-1 --perturb 0,0 --seed 3"
  "2|--refine-target has no effect without --refine|kitti $k --frames 0-1 --refine-target first"
  "2|--target-voxel has no effect without --refine|kitti $k --frames 0-1 --target-voxel 0.5"
  "2|--target-voxel has no effect|kitti $k --frames 0-1 --refine icp --refine-target previous --target-voxel 0.5"
  "2|--pcd-format has no effect without --out-cloud|kitti $k --frames 0 --pcd-format ascii --out-map $o/m.pgm"
  "2|--occupancy-max-range has no effect|kitti $k --frames 0 --occupancy-max-range 30"
  "2|--count has no effect with --frames|kitti $k --frames 0-1 --count 5"
  "2|--occupancy-resolution has no effect without --out-octomap|kitti $k --frames 0 --occupancy-resolution 0.5"
  # a PCD encoding with no PCD written
  "2|--pcd-format has no effect without --out|grid $bun --cell-size 0.01 --pcd-format ascii --cells $o/c.csv"
  "2|--pcd-format has no effect without --out|octree $bun --max-points 100 --min-cell-size 0.01 --pcd-format ascii"
  "2|--pcd-format has no effect without --out-cloud|occupancy $k --frames 0 --resolution 0.5 --max-range 20 --out $o/a.bt --pcd-format ascii"
  # lines
  "2|--purge has no effect with --min-points 0 and --min-length 0|lines $csv --min-points 0 --min-length 0 --purge after-merge"
  "2|--range-sigma has no effect without --chi2 or --format json|lines $csv --range-sigma 0.02"
  "2|--bearing-sigma-deg has no effect|lines $csv --bearing-sigma-deg 0.2 --format csv"
  # heightmap: pitch and yaw turn the camera of --camera-height only
  "2|--pitch-deg has no effect without --camera-height|heightmap $tumd --camera $tumc --auto-floor --pitch-deg 10 $hm"
  "2|--yaw-deg has no effect without --camera-height|heightmap $tumd --camera $tumc --pose-matrix $eye --yaw-deg 5 $hm"
  # evaluate
  "2|--max-time-diff has no effect here: the poses pair by index|evaluate $P --reference $P --max-time-diff 0.5"
  "2|--per-frame has no effect with --format json|evaluate $P --reference $P --per-frame --format json"
  "2|--per-frame has no effect with --relations|evaluate $tmp/est_tum.txt --relations $tmp/rel.txt --per-frame"
)
expect_cases "${cases[@]}"
# view: refused before any window is opened (DISPLAY names no server: a view that went on would
# fail on it, exit 1)
export DISPLAY=:424242
view_cases=(
  "2|--max-points has no effect without --octree|view $bun --max-points 50"
  "2|--min-cell-size has no effect without --octree|view $bun --min-cell-size 0.5"
  "2|--show-empty has no effect without --octree|view $bun --show-empty"
  "2|--cell-size has no effect without --grid|view $bun --octree --cell-size 0.5"
  "2|--free has no effect without an OctoMap file|view $bun --free"
  "2|--scan has no effect without a scan log or --segments|view $bun --scan 0"
  "2|--camera has no effect with --segments|view $csv --segments $tmp/seg.json --camera iso"
  "2|--color-by height has no effect on scan logs alone|view $csv --color-by height"
)
expect_cases "${view_cases[@]}"
unset DISPLAY
check "nothing written by a refused option" test -z "$(ls -A "$o")"

# What applies is still accepted.
check "kitti: --seed with --perturb, --target-voxel with --refine (target map)" bash -c \
  "'$MM' kitti '$k' --frames 0-1 --perturb 0.1,1 --seed 3 --refine icp --target-voxel 0.5 >/dev/null"
check "grid: --pcd-format with --out" bash -c \
  "'$MM' grid '$bun' --cell-size 0.01 --out '$o/g.pcd' --pcd-format ascii >/dev/null && head -c 200 '$o/g.pcd' | grep -q 'DATA ascii'"
check "lines: the noise model with --chi2, and with --format json" bash -c \
  "'$MM' lines '$csv' --chi2 6.63 --range-sigma 0.02 >/dev/null && '$MM' lines '$csv' --bearing-sigma-deg 0.2 --format json >/dev/null"
check "lines: --purge when something is purged" bash -c "'$MM' lines '$csv' --purge after-merge >/dev/null"
check "heightmap: --pitch-deg and --yaw-deg with --camera-height" bash -c \
  "'$MM' heightmap '$tumd' --camera '$tumc' --camera-height 1 --pitch-deg 10 --yaw-deg 5 $hm >/dev/null"
check "evaluate: --per-frame in a table, --max-time-diff with stamps" bash -c \
  "'$MM' evaluate '$P' --reference '$P' --per-frame >/dev/null &&
   '$MM' evaluate '$tmp/est_tum.txt' --reference '$tmp/est_tum.txt' --align none --max-time-diff 0.5 >/dev/null"
finish
