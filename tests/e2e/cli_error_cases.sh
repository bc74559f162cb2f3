# Damaged and hostile inputs, odd option values, outputs that cannot be written. Sourced by
# cli_errors.sh (MM, DATA, tmp, expect, check set there). Files under tests/fuzz_regressions are
# small reproductions (also the fuzzers' starting corpus).
R=$(cd "$(dirname "${BASH_SOURCE[0]}")/../fuzz_regressions" && pwd)
tumd=$DATA/open3d_tum_depth/TUM_depth.png
in4=(--intrinsics 525,525,1.5,0)
tin=(--intrinsics 525,525,319.5,239.5)

# Images: damaged, truncated, absurd sizes, signed or short TIFFs.
for f in png_truncated_60000 png_8_bytes png_zero_size png_declares_30000x30000; do
  expect 1 "$R/$f.png" -- "$MM" depth-to-cloud "$R/$f.png" "${tin[@]}" --out "$tmp/o.pcd"
  expect 1 "$R/$f.png" -- "$MM" depth-to-cloud "$tumd" --rgb "$R/$f.png" "${tin[@]}" --out "$tmp/o.pcd"
  expect 1 "$R/$f.png" -- "$MM" heightmap "$R/$f.png" "${tin[@]}" --auto-floor --resolution 0.05 \
    --map-size 100 --z-bins 0.1,1 --out-prefix "$tmp/hm"
done
expect 1 "memory budget" -- "$MM" --max-memory 100K depth-to-cloud "$tumd" "${tin[@]}" --out "$tmp/o.pcd"
expect 1 "must not be negative" -- "$MM" depth-to-cloud "$R/tiff_signed_negative.tiff" "${in4[@]}" --out "$tmp/o.pcd"
head -c 142 "$R/tiff_signed_negative.tiff" >"$tmp/cut.tiff"
expect 1 "runs past the end" -- "$MM" depth-to-cloud "$tmp/cut.tiff" "${in4[@]}" --out "$tmp/o.pcd"
head -c 300000 "$DATA/pcl_grabber_kinect_depth/tiff/frame_20121214T142255.814212_depth.tiff" >"$tmp/cut2.tiff"
expect 1 "$tmp/cut2.tiff" -- "$MM" depth-to-cloud "$tmp/cut2.tiff" "${in4[@]}" --out "$tmp/o.pcd"
check "no cloud from a damaged image" test ! -e "$tmp/o.pcd"
rm -f "$tmp/o.pcd"
# A strip longer than the file: libtiff sizes it from the image, the 8 values are read exactly.
"$MM" depth-to-cloud "$R/tiff_strip_beyond_file.tiff" "${in4[@]}" --out "$tmp/s.pcd" >"$tmp/s.json" 2>&1
check "TIFF with an overlong strip: all 8 pixels valid" grep -q '"valid_points":8' "$tmp/s.json"
# A one-row depth image is a valid organized image.
"$MM" depth-to-cloud "$R/depth_one_row.png" "${in4[@]}" --depth-scale 0.001 --out "$tmp/row.pcd" --pcd-format ascii >"$tmp/row.json" 2>"$tmp/row.err"
check "one-row depth image: 3 valid points" grep -q '"valid_points":3' "$tmp/row.json"
check "one-row depth image: point 0 at z = 1 m" grep -q '^-0.0028571428 0 1$' "$tmp/row.pcd"
expect 1 "beyond float range" -- "$MM" depth-to-cloud "$R/depth_one_row.png" "${in4[@]}" --depth-scale 1e300 --out "$tmp/o.pcd"
check "no cloud with infinite coordinates" test ! -e "$tmp/o.pcd"

# Camera files: every number checked, nesting bounded.
expect 1 "z_multiplication_factor" -- "$MM" depth-to-cloud "$R/depth_one_row.png" --camera "$R/camera_z_factor_abc.xml" --out "$tmp/o.pcd"
for v in nan -0.001 0x10 1e999; do
  sed "s/>abc</>$v</" "$R/camera_z_factor_abc.xml" >"$tmp/cam.xml"
  expect 1 "$tmp/cam.xml" -- "$MM" depth-to-cloud "$R/depth_one_row.png" --camera "$tmp/cam.xml" --out "$tmp/o.pcd"
done
expect 1 "nested deeper" -- "$MM" depth-to-cloud "$R/depth_one_row.png" --camera "$R/camera_deep.json" --out "$tmp/o.pcd"

# Option values: usage errors exit 2.
for v in 525,525,319.5 525,525,319.5,239.5,1 0,525,319.5,239.5 525,,319.5,239.5 525,525,319.5,nan 0x20,525,1,1 ""; do
  expect 2 "--intrinsics" -- "$MM" depth-to-cloud "$tumd" --intrinsics "$v" --out "$tmp/o.pcd"
done
for v in "" ,1 1, 0.1,,1 0.1,nan; do
  expect 2 "--z-bins" -- "$MM" heightmap "$tumd" "${tin[@]}" --auto-floor --resolution 0.05 --map-size 100 --z-bins "$v" --out-prefix "$tmp/hm"
done
expect 2 "--pitch-deg" -- "$MM" heightmap "$tumd" "${tin[@]}" --camera-height 1 --pitch-deg nan --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$tmp/hm"
expect 2 "--max-memory" -- "$MM" --max-memory lots info "$scan"
expect 1 "--map-size 16000" -- "$MM" --max-memory 1G heightmap "$tumd" "${tin[@]}" --auto-floor --resolution 0.05 --map-size 16000 --z-bins 0.1,1 --out-prefix "$tmp/hm"
expect 1 "--window-size 16384x16384" -- "$MM" --max-memory 1G view "$scan" --window-size 16384x16384 --screenshot "$tmp/v.png"
expect 2 "--angle-min-deg" -- "$MM" lines "$DATA/breezyslam_mines_urg04lx/exp2.dat" --count 10 --angle-min-deg nan
check "no map after refused options" test ! -e "$tmp/hm_obstacles.png"

# Point clouds: PLY layouts PCL asserts on, zero points, absurd compressed sizes, directories.
expect 1 "list property" -- "$MM" info "$R/ply_list_before_xyz.ply"
expect 1 "num_cols" -- "$MM" info "$R/ply_obj_info_negative_cols.ply"
expect 1 "no points" -- "$MM" info "$R/ply_zero_vertices.ply"
expect 1 "no points" -- "$MM" grid "$R/pcd_width_0.pcd" --cell-size 1
expect 1 "cannot unpack" -- "$MM" info "$R/pcd_compressed_declares_357913941.pcd"
: >"$tmp/empty.bin"
expect 1 "no points" -- "$MM" info "$tmp/empty.bin"
mkdir -p "$tmp/x.bin"
expect 1 "not a regular file" -- "$MM" info "$tmp/x.bin"

# Scan logs: a beam count that is not a small integer makes the line malformed.
expect 1 "no scan found (2 malformed" -- "$MM" lines "$R/carmen_flaser_1e20.log"

# Outputs: all-or-nothing, special files never replaced, full disks reported.
mkdir -p "$tmp/hmx_layers.png"
expect 1 "hmx_layers.png" -- "$MM" heightmap "$tumd" "${tin[@]}" --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$tmp/hmx"
check "heightmap: no obstacles map when the layers map cannot be written" test ! -e "$tmp/hmx_obstacles.png"
expect 1 "$tmp/nodir/c.csv" -- "$MM" grid "$scan" --cell-size 1 --out "$tmp/g.pcd" --cells "$tmp/nodir/c.csv"
check "grid: no means cloud when --cells fails" test ! -e "$tmp/g.pcd"
expect 1 "$tmp/nodir/s.svg" -- "$MM" lines "$DATA/pythonrobotics_lidar01/lidar01.csv" --steps "$tmp/steps" --svg "$tmp/nodir/s.svg"
check "lines: no step drawings when --svg fails" test ! -e "$tmp/steps"
expect 1 "$tmp/nodir/p.svg" -- "$MM" compare "$scan" --format markdown --out "$tmp/s.md" --plot "$tmp/nodir/p.svg"
check "compare: no table when --plot fails" test ! -e "$tmp/s.md"
mkfifo "$tmp/fifo.pcd"
expect 1 "not a regular file" -- "$MM" grid "$scan" --cell-size 1 --out "$tmp/fifo.pcd"
check "a FIFO is not replaced by a regular file" test -p "$tmp/fifo.pcd"
if [ -w /dev/full ]; then
  rc=0
  "$MM" info "$scan" >/dev/full 2>"$tmp/full.err" || rc=$?
  check "stdout on a full disk: exit 1 with a message" test "$rc" = 1 -a "$(grep -c 'standard output' "$tmp/full.err")" = 1
fi
check "no temporary files left" test -z "$(find "$tmp" -name '*.tmp-*')"

# Inputs that are not regular files: never opened (a FIFO would block), one clear line.
mkfifo "$tmp/in.pcd" "$tmp/in.png" "$tmp/in.csv"
expect 1 "a FIFO" -- "$MM" info "$tmp/in.pcd"
expect 1 "a FIFO" -- "$MM" depth-to-cloud "$tmp/in.png" "${tin[@]}" --out "$tmp/o.pcd"
expect 1 "a FIFO" -- "$MM" lines "$tmp/in.csv"
expect 1 "a directory" -- "$MM" lines "$tmp"

# compare --config: values beyond float range or in other notations are usage errors.
for v in 1e300 0x1 inf; do
  expect 2 "cell_size" -- "$MM" compare "$scan" --config cell_size=$v,min_cell_size=1,max_points=3
done
