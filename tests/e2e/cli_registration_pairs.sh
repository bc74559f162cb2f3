#!/usr/bin/env bash
# Issue 24, class 8: parameters that leave nothing to register. A registration resting on too
# few point pairs fails naming the frame (exit 1, one line) instead of reporting success with its
# starting pose or a pose fitted to a handful of points. The rules (docs/RELIABILITY.md):
#   odometry (odometry, kitti --poses odometry): at least 20 pairs with the local map
#     (`odometry --voxel-size 100` left 8 points and 1-6 pairs per KITTI scan, exit 0);
#   kitti --refine icp|gicp: at least max(20, a tenth of the scan's registration points) pairs
#     within the fine distance (0.25 m) at the pose found (`--perturb 100,0` started 100 m off:
#     PCL found no pair and returned the perturbed pose, exit 0).
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
o=$tmp/o
mkdir -p "$o"

cases=(
  "1|000001.bin: the registration paired|odometry $k --voxel-size 100 --out-poses $o/p.txt"
  "1|at least 20 needed|odometry $k --frames 0-2 --voxel-size 60 --out-poses $o/p.txt"
  "1|velodyne/000001.bin: registration paired 0 of the scan's|kitti $k --frames 0-2 --refine icp --perturb 100,0 --out-poses $o/p.txt"
  "1|velodyne/000001.bin: registration paired|kitti $k --frames 0-2 --refine gicp --perturb 100,0 --out-poses $o/p.txt"
  "1|the pose cannot be trusted|kitti $k --frames 0-2 --refine icp --refine-target first --perturb 60,90 --seed 2 --out-cloud $o/c.pcd"
)
expect_cases "${cases[@]}"
check "nothing written by a refused registration" test -z "$(ls -A "$o")"

# Registrations that rest on enough pairs are unchanged.
check "odometry with its defaults and with a 5 m voxel" bash -c \
  "'$MM' odometry '$k' --out-poses '$o/d.txt' >/dev/null && '$MM' odometry '$k' --voxel-size 5 >/dev/null"
check "kitti --refine icp and gicp from 0.5 m / 2 degrees off" bash -c \
  "'$MM' kitti '$k' --frames 0-5 --refine icp --perturb 0.5,2 --seed 1 >/dev/null &&
   '$MM' kitti '$k' --frames 0-5 --refine gicp --refine-target first --perturb 0.5,2 --seed 1 >/dev/null"
check "kitti --poses odometry" bash -c "'$MM' kitti '$k' --frames 0-5 --poses odometry >/dev/null"
finish
