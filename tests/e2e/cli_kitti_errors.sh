#!/usr/bin/env bash
# metricmap kitti with bad options and inputs that once crashed, ran out of memory or left
# files: a clear one-line message, exit 1 (2 for usage), nothing written.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
k=$(cd "$DATA" && pwd)/kitti_odometry_00
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
expect 2 "--min-height" -- "$MM" kitti "$k" --frames 0 --min-height nan
expect 1 "the map is empty" -- "$MM" kitti "$k" --frames 0 --min-height 100 \
  --out-map "$o/empty.pgm" --out-cloud "$o/empty.pcd" --out-poses "$o/empty.txt"
check "nothing written for the empty map" test -z "$(ls -A "$o")"
expect 2 "--target-voxel" -- "$MM" kitti "$k" --frames 0 --target-voxel 0
# Outputs are committed together: a map that cannot be written leaves no cloud and no poses.
expect 1 "$o/nodir/m.pgm" -- "$MM" kitti "$k" --frames 0-1 --out-cloud "$o/g.pcd" \
  --out-poses "$o/p.txt" --out-map "$o/nodir/m.pgm"
check "nothing written when one output fails" test -z "$(ls -A "$o")"
# A directory with a dot: the YAML and PNGs stay beside the map. A map name without an extension
# names no format and is refused.
mkdir -p "$o/run.1"
expect 2 "--out-map" -- "$MM" kitti "$k" --frames 0 --out-map "$o/run.1/m"
check "map in a dotted directory" "$MM" kitti "$k" --frames 0 \
  --out-map "$o/run.1/m.pgm" --format json
check "its YAML is m.yaml in run.1" test -s "$o/run.1/m.yaml" -a -s "$o/run.1/m_heat.png"
rm -rf "$o/run.1"

# Poses from the scans alone: a sequence folder with no poses/ at all.
np=$tmp/nopose
mkdir -p "$np/sequences/00/velodyne"
cp "$k/sequences/00/calib.txt" "$np/sequences/00/"
for f in 000000 000001 000002 000003 000004 000005; do
  ln -s "$k/sequences/00/velodyne/$f.bin" "$np/sequences/00/velodyne/$f.bin"
done
expect 1 "poses/00.txt: cannot open" -- "$MM" kitti "$np" --frames 0-5
check "kitti --poses odometry builds the map without a pose file" "$MM" kitti "$np" \
  --frames 0-5 --poses odometry --out-map "$o/odo.pgm" --out-poses "$o/odo.txt" --format json
check "six odometry poses, about 0.7 m apart along z (the scans' motion)" awk '
  NR > 1 { d = sqrt(($4 - x) ^ 2 + ($8 - y) ^ 2 + ($12 - z) ^ 2); if (d < 0.6 || d > 0.8) bad = 1 }
  { x = $4; y = $8; z = $12 } END { exit !(NR == 6 && !bad) }' "$o/odo.txt"
check "the map_server pair is there" test -s "$o/odo.pgm" -a -s "$o/odo.yaml"
expect 2 "--perturb" -- "$MM" kitti "$np" --frames 0-1 --poses odometry --perturb 0.5,1
finish
