#!/usr/bin/env bash
# Issue 24, class 2: outputs are compared by file identity (device + inode of an existing file,
# normalised absolute path of a new one) against every other output and every input of the
# command. An output that names an input, however spelled (the same name, ./x, $PWD/x,
# sub/../x, a symbolic link, a hard link, a symlinked directory), is a usage error: exit 2, one
# line naming both, before any work; the input is unchanged and no file appears.
MM=$1
DATA=$2
case $MM in /*) ;; */*) MM=$PWD/$MM ;; esac  # the cases run in another directory
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)

# A private copy of every input: a failing case must never damage the repository's data.
w=$tmp/w
mkdir -p "$w/sub" "$w/out"
cp "$D/pcl_test_pcd/bunny.pcd" "$w/m.pcd"
cp "$D/open3d_tum_depth/TUM_depth.png" "$w/depth.png"
cp "$D/open3d_tum_depth/TUM_depth.png" "$w/hm_obstacles.png"
cp "$D/open3d_tum_depth/camera_primesense.json" "$w/cam.json"
ln -s m.pcd "$w/link.pcd"
ln "$w/m.pcd" "$w/hard.pcd"
ln -s "$w" "$tmp/wl"  # a symlinked directory
k=$w/k
mkdir -p "$k/sequences/00/velodyne" "$k/poses"
cp "$D/kitti_odometry_00/sequences/00/calib.txt" "$k/sequences/00/"
cp "$D/kitti_odometry_00/sequences/00/velodyne/000000.bin" "$D/kitti_odometry_00/sequences/00/velodyne/000001.bin" "$k/sequences/00/velodyne/"
cp "$D/kitti_odometry_00/poses/00.txt" "$k/poses/"
"$MM" occupancy "$k" --frames 0 --resolution 0.5 --max-range 20 --out "$w/map.bt" >/dev/null ||
  { echo "FAIL: cannot make the .bt input"; exit 1; }
(cd "$w" && find . -type f ! -path './out/*' -print0 | sort -z | xargs -0 sha256sum) >"$tmp/before.sum"

cam=(--camera "$w/cam.json")
kit=(kitti "$k" --frames 0-1)
occ=(occupancy "$k" --frames 0 --resolution 0.5 --max-range 20)

# Each row: exit code, text the one stderr line must hold, then the command (run in $w, so that
# relative spellings are relative to the inputs' directory).
cases=(
  # --- an output naming an input ------------------------------------------------------------
  "2|same file|grid m.pcd --cell-size 0.05 --out m.pcd"
  "2|same file|grid m.pcd --cell-size 0.05 --out ./m.pcd"
  "2|same file|grid m.pcd --cell-size 0.05 --out $w/m.pcd"
  "2|same file|grid m.pcd --cell-size 0.05 --out sub/../m.pcd"
  "2|same file|grid m.pcd --cell-size 0.05 --out link.pcd"
  "2|same file|grid link.pcd --cell-size 0.05 --out m.pcd"
  "2|same file|grid m.pcd --cell-size 0.05 --out hard.pcd"
  "2|same file|grid m.pcd --cell-size 0.05 --out $tmp/wl/m.pcd"
  "2|same file|grid $D/pcl_test_pcd/milk.pcd m.pcd --cell-size 0.05 --cells m.pcd"
  "2|same file|octree m.pcd --max-points 100 --min-cell-size 0.01 --out ./m.pcd"
  "2|same file|octree m.pcd --max-points 100 --min-cell-size 0.01 --leaves hard.pcd"
  "2|same file|compare m.pcd --out sub/../m.pcd"
  "2|same file|depth-to-cloud depth.png ${cam[*]} --out ./depth.png"
  "2|same file|depth-to-cloud depth.png ${cam[*]} --out cam.json"
  "2|same file|heightmap hm_obstacles.png ${cam[*]} --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix ./hm"
  "2|same file|${kit[*]} --out-poses k/poses/00.txt"
  "2|same file|${kit[*]} --out-poses ./k/sequences/00/calib.txt"
  "2|same file|${kit[*]} --out-cloud $w/k/sequences/00/velodyne/000001.bin"
  "2|same file|${kit[*]} --out-cloud k/sequences/00/../00/velodyne/000000.bin"
  "2|same file|${occ[*]} --out-cloud k/poses/00.txt"
  "2|same file|${occ[*]} --out-cloud ./k/sequences/00/velodyne/000000.bin"
  "2|same file|${occ[*]} --out-cloud k/sequences/00/calib.txt"
  "2|same file|occupancy map.bt --out ./map.bt"
  "2|same file|occupancy map.bt --out-ot map.ot --out sub/../map.bt"
  "2|same file|occupancy m.pcd --resolution 0.01 --max-range 1 --out-cloud ./m.pcd"
  # --- two outputs naming one file -----------------------------------------------------------
  "2|both write|grid m.pcd --cell-size 0.05 --out out/a.pcd --cells $w/out/a.pcd"
  "2|both write|grid m.pcd --cell-size 0.05 --out out/a.pcd --cells sub/../out/a.pcd"
  "2|both write|grid m.pcd --cell-size 0.05 --out out/a.pcd --cells $tmp/wl/out/a.pcd"
  "2|both write|octree m.pcd --max-points 100 --min-cell-size 0.01 --out out/a.csv --leaves $w/out/a.csv"
  "2|both write|${occ[*]} --out out/a.bt --out-ot $w/out/./a.bt"
  "2|both write|${occ[*]} --out-map out/m.pgm --band -1,1 --map-preview $w/out/m.yaml"
  "2|both write|${kit[*]} --out-poses out/m.yaml --out-map $w/out/m.pgm"
  "2|both write|${kit[*]} --out-cloud out/c.pcd --out-poses sub/../out/c.pcd"
)
for row in "${cases[@]}"; do
  IFS='|' read -r code needle cmd <<<"$row"
  # shellcheck disable=SC2086  # the command is a word list
  (cd "$w" && expect "$code" "$needle" -- "$MM" $cmd)
done 2>&1 | tee "$tmp/log"
fails=$(grep -c '^FAIL' "$tmp/log")

# The existing output files that two outputs name are compared by inode too.
touch "$w/out/e.pcd"
ln "$w/out/e.pcd" "$w/out/e_hard.pcd"
ln -s e.pcd "$w/out/e_link.pcd"
for other in e_hard.pcd e_link.pcd; do
  (cd "$w" && expect 2 "both write" -- "$MM" grid m.pcd --cell-size 0.05 --out out/e.pcd --cells "out/$other")
done | tee -a "$tmp/log"
fails=$(grep -c '^FAIL' "$tmp/log")

# Nothing replaced, nothing written.
(cd "$w" && find . -type f ! -path './out/*' -print0 | sort -z | xargs -0 sha256sum) >"$tmp/after.sum"
check "every input unchanged" cmp -s "$tmp/before.sum" "$tmp/after.sum"
check "no output written" test "$(ls "$w/out" | sort | tr '\n' ' ')" = "e.pcd e_hard.pcd e_link.pcd "
check "no file appeared beside the inputs" test -z "$(find "$w" -newer "$tmp/before.sum" -type f ! -path "$w/out/*")"
# Distinct files still work: an output beside its input, a new file through a symlinked dir.
check "grid m.pcd --out out/m.pcd works" bash -c "cd '$w' && '$MM' grid m.pcd --cell-size 0.05 --out out/m.pcd >/dev/null"
check "occupancy map.bt --out out/map.bt works" bash -c "cd '$w' && '$MM' occupancy map.bt --out '$tmp/wl/out/map.bt' >/dev/null"
finish
