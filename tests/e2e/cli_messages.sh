#!/usr/bin/env bash
# Issue 24, class 12 (in part): messages. A value is quoted as given or as the shortest text
# of the same number (`1e308` never reported as `inf`, a depth scale never as 309 digits, a
# cell edge never as `0.000010`); a size in a message is the real one (no wrap to "0 MiB" near
# 2^64); a NUL byte in quoted file text is shown as \x00 instead of ending the message; an error
# about a scan names the scan's file.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
tum=$D/open3d_tum_depth
o=$tmp/o
mkdir -p "$o"

printf '0.5,1\n0.6,a\0X\n' >"$tmp/nul.csv"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2\0X 3\n' >"$tmp/nul_body.pcd"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0\0X 0 0\nPOINTS 1\nDATA ascii\n1 2 3\n' >"$tmp/nul_vp.pcd"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 0 0 0 0\nPOINTS 1\nDATA ascii\n1 2 3\n' >"$tmp/zero_vp.pcd"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n1e12 0 0\n' >"$tmp/far.pcd"
# (2^32-1)^2 cells x 34 bytes, in MiB rounded up
need=$(python3 -c 'print(-(-(2**32 - 1)**2 * 34 // 2**20))')

cases=(
  # values as given, not as the float they became
  "2|--voxel: '1e308' is outside the single-precision range|kitti $k --frames 0 --voxel 1e308"
  "2|--voxel: '1e-300' is outside the single-precision range|kitti $k --frames 0 --voxel 1e-300"
  "2|--target-voxel: '1e308' is outside the single-precision range|kitti $k --frames 0 --refine icp --target-voxel 1e308"
  "1|depth scale 1e+308 times raw depth|depth-to-cloud $tum/TUM_depth.png --camera $tum/camera_primesense.json --depth-scale 1e308 --out $o/d.pcd"
  "1|at 0.0001 m|kitti $k --frames 0 --map-resolution 0.0001 --out-map $o/m.pgm"
  # sizes that do not wrap
  "1|--map-size 4294967295 with 3 height bins needs $need MiB|heightmap $tum/TUM_depth.png --camera $tum/camera_primesense.json --auto-floor --resolution 0.05 --map-size 4294967295 --z-bins 0.1,1 --out-prefix $o/hm"
  # a NUL byte shown, not ending the message
  "1|nul.csv: line 2: expected 'angle,range', got '0.6,a\\x00X'|lines $tmp/nul.csv"
  "1|nul_body.pcd: body line 1: '2\\x00X'|info $tmp/nul_body.pcd"
  "1|nul_vp.pcd: VIEWPOINT: '0\\x00X' is not a finite number|info $tmp/nul_vp.pcd"
  # errors about a scan or its VIEWPOINT name the file
  "1|zero_vp.pcd: VIEWPOINT quaternion is zero|occupancy $tmp/zero_vp.pcd --resolution 0.5 --max-range 20 --out $o/a.bt"
  "1|far.pcd: |occupancy $tmp/far.pcd --resolution 0.0001 --max-range 1e13 --out $o/a.bt"
  "1|velodyne/000000.bin: |occupancy $k --frames 0 --resolution 0.0001 --max-range 20 --out $o/a.bt"
)
expect_cases "${cases[@]}"
check "nothing written" test -z "$(ls -A "$o")"
check "no message holds a 20-digit run" bash -c \
  "'$MM' depth-to-cloud '$tum/TUM_depth.png' --camera '$tum/camera_primesense.json' --depth-scale 1e308 --out '$o/d.pcd' 2>&1 | grep -vqE '[0-9]{20}'"
finish
