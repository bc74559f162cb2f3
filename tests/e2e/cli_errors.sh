#!/usr/bin/env bash
# Bad input and bad usage: a clear one-line message, exit 1 (2 for usage), no crash, no hang,
# no output file left behind.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
scan=$DATA/ua_mapas_metricos_pcd/museo000.pcd

# Usage errors: exit 2.
for v in 0 -1 nan inf -inf abc ""; do
  expect 2 "--cell-size" -- "$MM" grid "$scan" --cell-size "$v"
done
for v in 0 -0.5 nan abc; do
  expect 2 "--min-cell-size" -- "$MM" octree "$scan" --max-points 100 --min-cell-size "$v"
done
expect 2 "--max-points" -- "$MM" octree "$scan" --max-points -5 --min-cell-size 1
expect 2 "--max-points" -- "$MM" octree "$scan" --max-points 1.5 --min-cell-size 1
expect 2 "--bogus" -- "$MM" grid "$scan" --cell-size 1 --bogus
expect 2 "--cell-size is required" -- "$MM" grid "$scan"
for v in -1 1025 1.5 two ""; do
  expect 2 "--threads" -- "$MM" grid "$scan" --cell-size 1 --threads "$v"
done
expect 2 "cell_size must be" -- "$MM" compare "$scan" --config cell_size=0,min_cell_size=1,max_points=3
expect 2 "unknown key" -- "$MM" compare "$scan" --config cell=1,min_cell_size=1,max_points=3
expect 2 "max_points must be" -- "$MM" compare "$scan" --config cell_size=1,min_cell_size=1,max_points=-3
expect 2 "needs cell_size" -- "$MM" compare "$scan" --config cell_size=1
expect 2 "--format" -- "$MM" compare "$scan" --format xml
expect 2 "--pcd-format" -- "$MM" grid "$scan" --cell-size 1 --pcd-format text
expect 2 "subcommand" -- "$MM"
expect 2 "frobnicate" -- "$MM" frobnicate
# The list of commands comes from the registered ones (view and occupancy included).
expect 2 "view, occupancy, evaluate, posegraph, slam2d, slam3d, localize, distance; see --help" -- "$MM" frobnicate

# Input errors: exit 1, the message names the file.
milk=$DATA/pcl_test_pcd/milk.pcd
hdr='VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\nPOINTS 3\n'
: >"$tmp/empty.pcd"
tail -c 4096 "$DATA/pcl_test_pcd/milk.pcd" >"$tmp/garbage.pcd"
printf "${hdr}DATA ascii\n1 2 3\n4 5 6\n" >"$tmp/trunc.pcd"
printf "${hdr}DATA ascii\n1 2 3\n4 5\n6 7 8\n" >"$tmp/ragged.pcd"
printf "${hdr}DATA binary\n0123456789" >"$tmp/truncbin.pcd"
printf "${hdr}DATA ascii\nnan nan nan\nnan 0 0\n0 nan 1\n" >"$tmp/allnan.pcd"
printf "${hdr/WIDTH 3/WIDTH 4294967295}" | sed 's/POINTS 3/POINTS 4294967295/' >"$tmp/absurd.pcd"
printf "DATA binary\n0123456789" >>"$tmp/absurd.pcd"
head -c 40000 "$milk" >"$tmp/cutcompressed.pcd"
cp "$milk" "$tmp/corrupt.pcd"
printf '\xff%.0s' $(seq 1 3000) | dd of="$tmp/corrupt.pcd" bs=1 seek=400 conv=notrunc status=none
head -c 17 /dev/zero >"$tmp/scan.bin"
echo "1 2 3" >"$tmp/cloud.txt"
for f in empty garbage trunc ragged truncbin allnan absurd cutcompressed corrupt; do
  expect 1 "$tmp/$f.pcd" -- "$MM" grid "$tmp/$f.pcd" --cell-size 1 --out "$tmp/out_$f.pcd"
  check "no output left for $f" test ! -e "$tmp/out_$f.pcd"
  expect 1 "$tmp/$f.pcd" -- "$MM" octree "$tmp/$f.pcd" --max-points 10 --min-cell-size 1
done
expect 1 "$tmp/scan.bin" -- "$MM" info "$tmp/scan.bin"
expect 1 "$tmp/cloud.txt" -- "$MM" info "$tmp/cloud.txt"
expect 1 "$tmp/missing.pcd" -- "$MM" compare "$tmp/missing.pcd"
expect 1 "$tmp/missing.pcd" -- "$MM" compare "$scan" "$tmp/missing.pcd" --format markdown --out "$tmp/study.md"
check "no table left when one input is bad" test ! -e "$tmp/study.md"

# lines: bad scans and thresholds.
mines=$DATA/breezyslam_mines_urg04lx/exp2.dat
printf '0.1,1.0\r\n0.2,abc\r\n' >"$tmp/bad.csv"
: >"$tmp/empty.csv"
printf '1 2 3\n' >"$tmp/unknown.dat"
expect 1 "$tmp/bad.csv" -- "$MM" lines "$tmp/bad.csv"
expect 1 "$tmp/empty.csv" -- "$MM" lines "$tmp/empty.csv"
expect 1 "$tmp/unknown.dat" -- "$MM" lines "$tmp/unknown.dat"
expect 1 "$tmp/missing.csv" -- "$MM" lines "$tmp/missing.csv"
expect 1 "out of range" -- "$MM" lines "$mines" --preset urg04lx-mines --scan 641
expect 1 "no scan" -- "$MM" lines "$tmp/unknown.dat" --count 5
for v in 0 -0.1 nan abc; do
  expect 2 "--distance-threshold" -- "$MM" lines "$mines" --preset urg04lx-mines --distance-threshold "$v"
done
expect 2 "--angle-threshold-deg" -- "$MM" lines "$mines" --preset urg04lx-mines --angle-threshold-deg -1
expect 2 "--angle-threshold-deg" -- "$MM" lines "$mines" --preset urg04lx-mines --angle-threshold-deg nan
expect 2 "--max-gap" -- "$MM" lines "$mines" --preset urg04lx-mines --max-gap inf
expect 2 "--chi2" -- "$MM" lines "$mines" --preset urg04lx-mines --chi2 0
expect 2 "--max-range" -- "$MM" lines "$mines" --count 10 --min-range 2 --max-range 1
expect 2 "--min-points" -- "$MM" lines "$mines" --preset urg04lx-mines --min-points -2
expect 2 "--svg" -- "$MM" lines "$mines" --preset urg04lx-mines --all --svg "$tmp/x.svg"
expect 2 "--preset" -- "$MM" lines "$mines" --preset sick

# depth-to-cloud and heightmap.
K=$DATA/pcl_grabber_kinect_depth
kd=$K/tiff/frame_20121214T142255.814212_depth.tiff
kx=$K/xml/frame_20121214T142255.814212.xml
tum=$DATA/open3d_tum_depth
expect 1 "must be 16-bit" -- "$MM" depth-to-cloud "$tum/TUM_color.png" --intrinsics 525,525,319.5,239.5 --out "$tmp/c.pcd"
expect 1 "must be 16-bit" -- "$MM" depth-to-cloud "$K/tiff/frame_20121214T142255.814212_rgb.tiff" --camera "$kx" --out "$tmp/c.pcd"
check "no cloud written for a colour image" test ! -e "$tmp/c.pcd"
expect 2 "intrinsics" -- "$MM" depth-to-cloud "$kd" --out "$tmp/c.pcd"
expect 2 "--depth-scale" -- "$MM" depth-to-cloud "$kd" --camera "$kx" --depth-scale 0 --out "$tmp/c.pcd"
expect 2 "--depth-scale" -- "$MM" depth-to-cloud "$kd" --camera "$kx" --depth-scale -1 --out "$tmp/c.pcd"
expect 1 "RGB image" -- "$MM" depth-to-cloud "$kd" --rgb "$tum/TUM_depth.png" --camera "$kx" --out "$tmp/c.pcd"
expect 1 "$tmp/missing.png" -- "$MM" depth-to-cloud "$tmp/missing.png" --camera "$kx" --out "$tmp/c.pcd"
hm=(--resolution 0.05 --map-size 100 --z-bins 0.1,1.0 --out-prefix "$tmp/hm")
expect 2 "--map-size" -- "$MM" heightmap "$kd" --camera "$kx" --auto-floor --resolution 0.05 --map-size 0 --z-bins 0.1,1 --out-prefix "$tmp/hm"
expect 1 "MiB" -- "$MM" heightmap "$kd" --camera "$kx" --auto-floor --resolution 0.05 --map-size 200000 --z-bins 0.1,1 --out-prefix "$tmp/hm"
expect 2 "strictly increasing" -- "$MM" heightmap "$kd" --camera "$kx" --auto-floor --resolution 0.05 --map-size 100 --z-bins 1,0.1 --out-prefix "$tmp/hm"
expect 2 "exactly one" -- "$MM" heightmap "$kd" --camera "$kx" "${hm[@]}"
expect 2 "exactly one" -- "$MM" heightmap "$kd" --camera "$kx" --auto-floor --camera-height 1 "${hm[@]}"
printf '1.0 0 0 0 0 0 0 1\n' >"$tmp/traj.txt"
cp "$kd" "$tmp/kd2.tiff"  # a second frame: one file named twice is refused
expect 1 "1 pose(s) for 2 frame(s)" -- "$MM" heightmap "$kd" "$tmp/kd2.tiff" --camera "$kx" --trajectory "$tmp/traj.txt" "${hm[@]}"
printf '1.0 0 0 nan 0 0 0 1\n' >"$tmp/nan_traj.txt"
expect 1 "$tmp/nan_traj.txt" -- "$MM" heightmap "$kd" --camera "$kx" --trajectory "$tmp/nan_traj.txt" "${hm[@]}"
check "no map written after bad input" test ! -e "$tmp/hm_obstacles.png"

# kitti: a scratch sequence with links to the real scans and crafted calib/poses.
kr=$tmp/kitti
mkdir -p "$kr/sequences/00/velodyne" "$kr/poses"
for f in 000000 000001; do ln -s "$DATA/kitti_odometry_00/sequences/00/velodyne/$f.bin" "$kr/sequences/00/velodyne/$f.bin"; done
head -c 1000 "$DATA/kitti_odometry_00/sequences/00/velodyne/000002.bin" | head -c 999 >"$kr/sequences/00/velodyne/000002.bin"
cp "$DATA/kitti_odometry_00/sequences/00/calib.txt" "$kr/sequences/00/calib.txt"
head -n 3 "$DATA/kitti_odometry_00/poses/00.txt" >"$kr/poses/00.txt"
expect 1 "000003.bin: missing frame" -- "$MM" kitti "$kr" --frames 0-1,3 --out-map "$tmp/km.pgm"
expect 1 "not a multiple of 16" -- "$MM" kitti "$kr" --frames 2 --out-map "$tmp/km.pgm"
head -n 1 "$DATA/kitti_odometry_00/poses/00.txt" >"$kr/poses/00.txt"
expect 1 "1 pose(s)" -- "$MM" kitti "$kr" --first 0 --count 2 --out-map "$tmp/km.pgm"
head -n 3 "$DATA/kitti_odometry_00/poses/00.txt" >"$kr/poses/00.txt"
check "no map after bad input" test ! -e "$tmp/km.pgm"
grep -v '^Tr:' "$DATA/kitti_odometry_00/sequences/00/calib.txt" >"$kr/sequences/00/calib.txt"
expect 1 "no 'Tr:' line" -- "$MM" kitti "$kr" --frames 0
cp "$DATA/kitti_odometry_00/sequences/00/calib.txt" "$kr/sequences/00/calib.txt"
sed -i '2s/^[^ ]*/nan/' "$kr/poses/00.txt"
expect 1 "line 2 is not 12 finite numbers" -- "$MM" kitti "$kr" --frames 0-1
expect 2 "--frames" -- "$MM" kitti "$kr" --frames 0 --first 0 --count 1
expect 2 "frames" -- "$MM" kitti "$kr"
expect 2 "frame list" -- "$MM" kitti "$kr" --frames 3-1
expect 2 "--map-resolution" -- "$MM" kitti "$kr" --frames 0 --map-resolution 0
expect 2 "--map-plane" -- "$MM" kitti "$kr" --frames 0 --map-plane ab
expect 2 "--perturb" -- "$MM" kitti "$kr" --frames 0 --perturb 0.5
expect 2 "--refine" -- "$MM" kitti "$kr" --frames 0 --refine ndt

# view without an X display: a clear message, not a crash.
expect 1 "no X display" -- env -u DISPLAY "$MM" view "$scan" --screenshot "$tmp/v.png"
expect 1 "no X display" -- env -u DISPLAY "$MM" view "$scan"
expect 1 "no X display" -- env -u DISPLAY "$MM" view "$DATA/pythonrobotics_lidar01/lidar01.csv" --segments "$tmp/none.json"
expect 2 "--window-size" -- env DISPLAY=:99 "$MM" view "$scan" --window-size 10by10 --screenshot "$tmp/v.png"
check "no screenshot without a display" test ! -e "$tmp/v.png"

# Output errors: exit 1, nothing half-written.
expect 1 "$tmp/nodir/means.pcd" -- "$MM" grid "$scan" --cell-size 1 --out "$tmp/nodir/means.pcd"
expect 1 "$tmp/nodir/cells.csv" -- "$MM" grid "$scan" --cell-size 1 --cells "$tmp/nodir/cells.csv"
check "no temporary files left" test -z "$(find "$tmp" -name '*.tmp-*')"

source "$(dirname "$0")/cli_error_cases.sh"
finish
