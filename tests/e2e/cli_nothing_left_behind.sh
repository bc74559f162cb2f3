#!/usr/bin/env bash
# Issue 15 leftovers, each as a class: FIFOs and devices as inputs, full disks under every
# writer, occupancy's outputs/budget/options/header, KITTI poses and calib, heightmap's pose
# and bins, float sizes and their printing. One line, exit 1 (2 for usage), nothing left behind.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
tum=$D/open3d_tum_depth
bun=$D/pcl_test_pcd/bunny.pcd
o=$tmp/o
mkdir -p "$o"

# --- 1. a FIFO (or a device) as any input: refused at once, never opened -------------------
for ext in pcd ply bin log csv png tiff xml json bt ot txt; do mkfifo "$tmp/f.$ext"; done
for ext in pcd ply bin; do expect 1 "f.$ext: cannot open (not a regular file" -- "$MM" info "$tmp/f.$ext"; done
expect 1 "f.log" -- "$MM" lines "$tmp/f.log"
expect 1 "f.png" -- "$MM" depth-to-cloud "$tmp/f.png" --intrinsics 525,525,319.5,239.5 --out "$o/x.pcd"
expect 1 "f.tiff" -- "$MM" depth-to-cloud "$tmp/f.tiff" --intrinsics 525,525,319.5,239.5 --out "$o/x.pcd"
for ext in xml json; do
  expect 1 "f.$ext" -- "$MM" depth-to-cloud "$tum/TUM_depth.png" --camera "$tmp/f.$ext" --out "$o/x.pcd"
done
expect 1 "f.txt" -- "$MM" heightmap "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" \
  --trajectory "$tmp/f.txt" --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$o/hm"
for ext in bt ot; do expect 1 "f.$ext: cannot open (not a regular file" -- "$MM" occupancy "$tmp/f.$ext"; done
expect 1 "f.pcd: cannot open (not a regular file" -- "$MM" occupancy "$tmp/f.pcd" --resolution 0.2 --max-range 10
ln -s /dev/zero "$tmp/zero.bt"
expect 1 "zero.bt: cannot open (not a regular file: a device" -- "$MM" occupancy "$tmp/zero.bt"
expect 1 "f.pcd" -- "$MM" compare "$tmp/f.pcd"
# a KITTI root whose calib, poses or scan is a FIFO
fk=$tmp/fifo_kitti
mkdir -p "$fk/sequences/00/velodyne" "$fk/poses"
ln -s "$k/sequences/00/velodyne/000000.bin" "$fk/sequences/00/velodyne/000000.bin"
mkfifo "$fk/sequences/00/calib.txt" "$fk/poses/00.txt" "$fk/sequences/00/velodyne/000001.bin"
expect 1 "calib.txt: cannot open (not a regular file" -- "$MM" kitti "$fk" --frames 0
expect 1 "calib.txt: cannot open (not a regular file" -- "$MM" odometry "$fk" --frames 0
expect 1 "calib.txt: cannot open (not a regular file" -- "$MM" occupancy "$fk" --frames 0 --resolution 0.2 --max-range 10
rm "$fk/sequences/00/calib.txt"
cp "$k/sequences/00/calib.txt" "$fk/sequences/00/calib.txt"
expect 1 "00.txt: cannot open (not a regular file" -- "$MM" kitti "$fk" --frames 0
expect 1 "000001.bin: cannot open (not a regular file" -- "$MM" kitti "$fk" --frames 0-1 --poses odometry

# --- 2. a full disk under every writer: exit 1 naming the target, nothing left -------------
full=$tmp/full
mkdir -p "$full"
if mount -t tmpfs -o size=64k tmpfs "$full" 2>/dev/null; then
  trap 'umount "$full" 2>/dev/null; rm -rf "$tmp"' EXIT
  fill() { rm -f "$full"/*; head -c 60000 /dev/zero >"$full/filler"; }
  for f in ascii binary binary_compressed; do
    fill
    expect 1 "$full/g_$f.pcd: cannot write" -- "$MM" grid "$bun" --cell-size 0.001 --out "$full/g_$f.pcd" --pcd-format $f
    check "full disk, grid $f: nothing left" test "$(ls "$full")" = filler
    fill
    expect 1 "$full/t_$f.pcd: cannot write" -- "$MM" octree "$bun" --max-points 1 --min-cell-size 0.0001 --out "$full/t_$f.pcd" --pcd-format $f
    check "full disk, octree $f: nothing left" test "$(ls "$full")" = filler
    fill
    expect 1 "$full/d_$f.pcd: cannot write" -- "$MM" depth-to-cloud "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" --out "$full/d_$f.pcd" --pcd-format $f
    check "full disk, depth-to-cloud $f: nothing left" test "$(ls "$full")" = filler
  done
  fill
  expect 1 "$full/cells.csv: cannot write" -- "$MM" grid "$bun" --cell-size 0.001 --cells "$full/cells.csv"
  fill
  expect 1 "$full/g.pcd: cannot write" -- "$MM" kitti "$k" --frames 0 --out-cloud "$full/g.pcd" --pcd-format ascii
  fill
  expect 1 "$full/m.bt: cannot write" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out "$full/m.bt"
  fill
  expect 1 "$full/c.pcd: cannot write" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out-cloud "$full/c.pcd" --pcd-format ascii
  fill
  expect 1 "$full/m.pgm: cannot write image" -- "$MM" kitti "$k" --frames 0 --out-map "$full/m.pgm" --map-resolution 0.1
  fill
  expect 1 "$full/o.pgm: cannot write image" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out-map "$full/o.pgm" --band -1,1
  fill
  expect 1 "$full/hm_" -- "$MM" heightmap "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" --auto-floor --resolution 0.05 --map-size 200 --z-bins 0.1,1 --out-prefix "$full/hm"
  check "full disk: nothing left" test "$(ls "$full")" = filler
  umount "$full"
else
  skip_part "full-disk cases need root (mount -t tmpfs)"
fi

# --- 3. occupancy ----------------------------------------------------------------------------
# the map checks the budget as it grows and names the options that asked
expect 1 "--max-memory" -- "$MM" --max-memory 300M occupancy "$k" --frames 0 --resolution 0.002 --max-range 50 --out "$o/fine.bt"
expect 1 "--resolution" -- "$MM" --max-memory 300M occupancy "$k" --frames 0 --resolution 0.002 --max-range 50 --out "$o/fine.bt"
# two outputs naming one file, empty names, bad values, hex: usage errors
expect 2 "both write" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out "$o/a.bt" --out-ot "$o/a.bt"
expect 2 "both write" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out "$o/a.bt" --out-ot "$o/./a.bt"
expect 2 "both write" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out-map "$o/m.pgm" --band -1,1 --map-preview "$o/m.yaml"
expect 2 "--out" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out ''
expect 2 "--cells and --out both write" -- "$MM" grid "$bun" --cell-size 0.05 --out "$o/x.csv" --cells "$o/./x.csv"
expect 2 "--leaves and --out both write" -- "$MM" octree "$bun" --max-points 100 --min-cell-size 0.01 --out "$o/x.csv" --leaves "$o/x.csv"
expect 2 "--plot and --out both write" -- "$MM" compare "$bun" --out "$o/x.svg" --plot "$o/x.svg"
for opt in --out --cells; do expect 2 "$opt" -- "$MM" grid "$bun" --cell-size 0.05 "$opt" ''; done
expect 2 "--out-map" -- "$MM" kitti "$k" --frames 0 --out-map ''
expect 2 "--out-cloud" -- "$MM" kitti "$k" --frames 0 --out-cloud ''
for r in 0 -0.2 nan 0x10 1e999; do
  expect 2 "--resolution" -- "$MM" occupancy "$k" --frames 0 --resolution "$r" --max-range 50 --out "$o/bad.bt"
done
expect 2 "--max-range" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 0x10 --out "$o/bad.bt"
for b in 1 0x1,2 2,1 1,2,3; do
  expect 2 "--band" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out-map "$o/bad.pgm" --band "$b"
done
expect 2 "--frames" -- "$MM" occupancy "$k" --frames 0-1, --resolution 0.2 --max-range 50 --out "$o/bad.bt"
expect 2 "--out" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out "$o/bad.txt"
for c in cell_size=0x10,min_cell_size=1,max_points=100 cell_size=1,min_cell_size=1,max_points=0x10; do
  expect 2 "0x10" -- "$MM" compare "$bun" --config "$c"
done
# .bt/.ot headers: every number checked, every key once
"$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out "$o/good.bt" --out-ot "$o/good.ot" >/dev/null
check "a good .bt and .ot" test -s "$o/good.bt" -a -s "$o/good.ot"
for bad in "res 0.08abc" "res 1e-300" "res 0x1p-3" "res nan"; do
  sed "s/^res .*/$bad/" "$o/good.bt" >"$o/hdr.bt"
  expect 1 "hdr.bt: bad res line" -- "$MM" occupancy "$o/hdr.bt" --out "$o/bad.bt"
done
sed 's/^res .*/res 0.2 0.2/' "$o/good.bt" >"$o/hdr.bt"
expect 1 "hdr.bt: header line 'res 0.2 0.2' is not 'KEY VALUE'" -- "$MM" occupancy "$o/hdr.bt" --out "$o/bad.bt"
sed 's/^res .*/res 0.2\nres 0.4/' "$o/good.bt" >"$o/twice.bt"
expect 1 "twice.bt: header has two 'res' lines" -- "$MM" occupancy "$o/twice.bt" --out "$o/bad.bt"
sed 's/^size .*/size 12abc/' "$o/good.ot" >"$o/size.ot"
expect 1 "size.ot: bad size line" -- "$MM" occupancy "$o/size.ot" --out "$o/bad.bt"
rm -f "$o/hdr.bt" "$o/twice.bt" "$o/size.ot" "$o/good.bt" "$o/good.ot"
check "occupancy: nothing written by the refused runs" test -z "$(ls -A "$o")"
# all outputs together: a map that cannot be written leaves no .bt
expect 1 "$o/nodir/m.pgm" -- "$MM" occupancy "$k" --frames 0 --resolution 0.2 --max-range 50 --out "$o/m.bt" --out-map "$o/nodir/m.pgm" --band -1,1
check "occupancy: no .bt when the map fails" test -z "$(ls -A "$o")"

# --- 4. KITTI poses, calib, perturbation, frame lists, odometry frames -----------------------
bk=$tmp/bad_kitti
mkdir -p "$bk/sequences/00/velodyne" "$bk/poses"
for f in 000000 000001; do ln -s "$k/sequences/00/velodyne/$f.bin" "$bk/sequences/00/velodyne/$f.bin"; done
cp "$k/sequences/00/calib.txt" "$bk/sequences/00/calib.txt"
head -1 "$k/poses/00.txt" >"$bk/poses/00.txt"
echo "1 0 0 1e308 0 1 0 0 0 0 1 0" >>"$bk/poses/00.txt"
expect 1 "00.txt: line 2: translation" -- "$MM" kitti "$bk" --frames 0-1
head -1 "$k/poses/00.txt" >"$bk/poses/00.txt"
echo "0 0 0 0 0 0 0 0 0 0 0 0" >>"$bk/poses/00.txt"
expect 1 "00.txt: line 2: the 3x3 part is not a rotation" -- "$MM" kitti "$bk" --frames 0-1
expect 1 "00.txt: line 2: the 3x3 part is not a rotation" -- "$MM" occupancy "$bk" --frames 0-1 --resolution 0.2 --max-range 50
head -1 "$k/poses/00.txt" >"$bk/poses/00.txt"
echo "-1 0 0 0 0 1 0 0 0 0 1 0" >>"$bk/poses/00.txt"  # a reflection: det -1
expect 1 "00.txt: line 2: the 3x3 part is not a rotation" -- "$MM" kitti "$bk" --frames 0-1
head -2 "$k/poses/00.txt" >"$bk/poses/00.txt"
(cat "$k/sequences/00/calib.txt"; grep '^Tr:' "$k/sequences/00/calib.txt") >"$bk/sequences/00/calib.txt"
expect 1 "calib.txt: a second 'Tr:' line" -- "$MM" kitti "$bk" --frames 0-1
sed 's/^Tr: .*/Tr: 0 0 0 0 0 0 0 0 0 0 0 0/' "$k/sequences/00/calib.txt" >"$bk/sequences/00/calib.txt"
expect 1 "calib.txt: Tr (line" -- "$MM" kitti "$bk" --frames 0-1
cp "$k/sequences/00/calib.txt" "$bk/sequences/00/calib.txt"
for v in 1e308,0 101,0 0,181 1e20,1e20; do
  expect 2 "--perturb" -- "$MM" kitti "$k" --frames 0-1 --perturb "$v"
done
for f in 0-1, ,0 0,,1; do expect 2 "--frames" -- "$MM" kitti "$k" --frames "$f"; done
expect 2 "--frames" -- "$MM" odometry "$k" --frames 0-1,
# a 30-point frame constrains no pose: refused naming it
rm "$bk/sequences/00/velodyne/000001.bin"
head -c 480 "$k/sequences/00/velodyne/000001.bin" >"$bk/sequences/00/velodyne/000001.bin"
expect 1 "000001.bin: 30 point(s)" -- "$MM" odometry "$bk" --frames 0-1 --min-range 0
expect 1 "000001.bin" -- "$MM" kitti "$bk" --frames 0-1 --poses odometry
check "kitti/odometry: nothing written" test -z "$(ls -A "$o")"

# --- 5. heightmap: a rigid --pose-matrix, at least two bin edges, usage errors -------------
hm=("$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" --resolution 0.05 --map-size 100 --out-prefix "$o/hm")
expect 2 "--pose-matrix: the 3x3 part is not a rotation" -- "$MM" heightmap "${hm[@]}" --z-bins 0.1,1 --pose-matrix 0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0
expect 2 "--pose-matrix: the last row" -- "$MM" heightmap "${hm[@]}" --z-bins 0.1,1 --pose-matrix 1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1
expect 2 "--pose-matrix: translation" -- "$MM" heightmap "${hm[@]}" --z-bins 0.1,1 --pose-matrix 1,0,0,1e300,0,1,0,0,0,0,1,0,0,0,0,1
expect 2 "at least two edges" -- "$MM" heightmap "${hm[@]}" --z-bins 0.5 --auto-floor
expect 2 "--z-bins" -- "$MM" heightmap "${hm[@]}" --z-bins 1,0 --auto-floor
"$MM" heightmap "${hm[@]}" --z-bins 0.1,1 --pose-matrix 1,0,0,0,0,0,1,0,0,-1,0,1.2,0,0,0,1 >"$tmp/hm.json"
check "a rigid --pose-matrix is used" grep -q '"points": ' "$tmp/hm.json"
check "heightmap's JSON has no valid_pixels key" bash -c "! grep -q valid_pixels '$tmp/hm.json'"
rm -f "$o"/hm_*

# --- 6. float sizes: the value given in the message, usage exit; tiny sizes printed ---------
expect 2 "1e308" -- "$MM" grid "$bun" --cell-size 1e308
expect 2 "1e-300" -- "$MM" grid "$bun" --cell-size 1e-300
expect 2 "1e-300" -- "$MM" octree "$bun" --max-points 10 --min-cell-size 1e-300
"$MM" octree "$bun" --max-points 100 --min-cell-size 0.0015 >"$tmp/oct.txt"
check "octree prints --min-cell-size 0.0015 as given" grep -q ' 0.0015 ' "$tmp/oct.txt"
"$MM" grid "$bun" --cell-size 0.05 >"$tmp/grid.txt"
check "grid prints --cell-size 0.05 as 0.050" grep -q ' 0.050 ' "$tmp/grid.txt"
check "nothing left behind" test -z "$(ls -A "$o")"
finish
