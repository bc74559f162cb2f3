#!/usr/bin/env bash
# metricmap kitti with bad options and inputs that once crashed, ran out of memory or left
# files: a clear one-line message, exit 1 (2 for usage), nothing written.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
k=$DATA/kitti_odometry_00
o=$tmp/outputs
mkdir -p "$o"

# Registration with too few points (PCL's ICP dereferenced null, GICP asserted): exit 1.
expect 1 "000001.bin: scan 1: registration needs at least 20 points" -- \
  "$MM" kitti "$k" --frames 0-1 --max-range 4 --refine icp
expect 1 "000001.bin: scan 1: registration needs at least 20 points" -- \
  "$MM" kitti "$k" --frames 0-1 --max-range 5 --refine gicp
# --perturb: every malformed pair is a usage error naming the option.
for v in ",1" "1," "1e-320,0" "1,2,3" "nan,1" "0x10,1" "-1,2" "1, 2" ""; do
  expect 2 "--perturb" -- "$MM" kitti "$k" --frames 0-1 --perturb "$v"
done
# Lists and counts that would allocate without bound: refused before any work.
expect 2 "names more than 1000000 frames" -- "$MM" kitti "$k" --frames 0-999999999
expect 2 "--count" -- "$MM" kitti "$k" --first 0 --count 999999999999999999
# A resolution so fine that the map image would take gigabytes: refused, nothing written.
expect 1 "use a coarser map resolution" -- "$MM" kitti "$k" --frames 0-1 \
  --map-resolution 0.0055 --out-map "$o/fine.pgm" --out-cloud "$o/fine.pcd"
check "nothing written for the refused map" test -z "$(ls -A "$o")"
# Bands that select nothing or make no sense.
expect 2 "min range" -- "$MM" kitti "$k" --frames 0 --min-range 10 --max-range 5
expect 2 "NaN" -- "$MM" kitti "$k" --frames 0 --min-height nan
expect 1 "the map is empty" -- "$MM" kitti "$k" --frames 0 --min-height 100 \
  --out-map "$o/empty.pgm" --out-cloud "$o/empty.pcd" --out-poses "$o/empty.txt"
check "nothing written for the empty map" test -z "$(ls -A "$o")"
expect 2 "--target-voxel" -- "$MM" kitti "$k" --frames 0 --target-voxel 0
finish
