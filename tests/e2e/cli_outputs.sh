#!/usr/bin/env bash
# The subcommands' outputs: formats parse, written files read back, figures agree across commands.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
scan=$DATA/ua_mapas_metricos_pcd/museo000.pcd

check "--help works" "$MM" --help >/dev/null
check "grid --help works" "$MM" grid --help >/dev/null
check "info json" bash -c "'$MM' info '$scan' --format json >'$tmp/info.json'"
check "info reports 79149 points" grep -q '"points": 79149' "$tmp/info.json"

for fmt in ascii binary binary_compressed; do
  check "grid --out ($fmt)" "$MM" grid "$scan" --cell-size 0.5 --out "$tmp/g_$fmt.pcd" \
    --pcd-format "$fmt" --cells "$tmp/cells.csv" --format json >"$tmp/grid.json"
  check "means file is $fmt" grep -aq "^DATA $fmt" "$tmp/g_$fmt.pcd"
  check "means file has one point per occupied cell" bash -c \
    "'$MM' info '$tmp/g_$fmt.pcd' --format json | grep -q '\"points\": 1192'"
done
check "grid json has the occupied count" grep -q '"occupied_cells": 1192' "$tmp/grid.json"
for t in 1 3; do
  check "grid --threads $t: the same cells" "$MM" grid "$scan" --cell-size 0.5 --threads "$t" \
    --cells "$tmp/cells_t$t.csv" --format json
  check "grid --threads $t: cells.csv identical" cmp -s "$tmp/cells.csv" "$tmp/cells_t$t.csv"
done
check "cells.csv has a header and 1192 rows" test "$(wc -l <"$tmp/cells.csv")" = 1193
check "cells.csv counts add up to every point" \
  test "$(awk -F, 'NR>1{s+=$4} END{print s}' "$tmp/cells.csv")" = 79149

check "octree --leaves" "$MM" octree "$scan" --max-points 100 --min-cell-size 0.5 \
  --leaves "$tmp/leaves.csv" --out "$tmp/o.pcd" --format csv >"$tmp/octree.csv"
check "octree csv row" grep -q ",4033,3529,504,1735,1794," "$tmp/octree.csv"
check "leaves.csv has every leaf" test "$(wc -l <"$tmp/leaves.csv")" = 3530
check "leaf counts add up to every point" \
  test "$(awk -F, 'NR>1{s+=$9} END{print s}' "$tmp/leaves.csv")" = 79149

check "compare markdown" "$MM" compare "$scan" --format markdown --out "$tmp/study.md"
check "markdown has 3 default configs" test "$(grep -c museo000 "$tmp/study.md")" = 3
check "compare --pcl-octree json" bash -c \
  "'$MM' compare '$scan' --pcl-octree --format json | grep -q pcl_octree"
check "kitti bin accepted" "$MM" grid "$DATA/kitti_odometry_00/sequences/00/velodyne/000000.bin" \
  --cell-size 0.1 --origin world >/dev/null
check "poli001 warns once" bash -c \
  "'$MM' info '$DATA/ua_mapas_metricos_pcd/poli001.pcd' 2>&1 >/dev/null | grep -c 'skipped 6 malformed' | grep -qx 1"
mines=$DATA/breezyslam_mines_urg04lx/exp2.dat
check "lines on all 641 URG scans" bash -c \
  "'$MM' lines '$mines' --preset urg04lx-mines --all --format json >'$tmp/lines.json'"
check "641 scans in the JSON" test "$(grep -c '"scan":' "$tmp/lines.json")" = 641
check "scans_per_second reported" grep -q '"scans_per_second"' "$tmp/lines.json"
check "lines on lidar01.csv with a drawing and steps" "$MM" lines \
  "$DATA/pythonrobotics_lidar01/lidar01.csv" --svg "$tmp/l.svg" --steps "$tmp/steps" --format csv
check "the drawing is an SVG with segments" grep -q "<line" "$tmp/l.svg"
check "lines --png writes a PNG" "$MM" lines "$mines" --preset urg04lx-mines --scan 100 \
  --png "$tmp/l.png" --format csv
check "the PNG has the PNG signature" bash -c "head -c 8 '$tmp/l.png' | od -An -c | grep -q 'P   N   G'"
check "one picture per step" test "$(ls "$tmp/steps" | grep -c 'split.svg$')" -ge 3
check "generic flags read the URG log like the preset" bash -c \
  "diff <('$MM' lines '$mines' --preset urg04lx-mines --scan 7) <('$MM' lines '$mines' --scan 7 \
   --skip-tokens 24 --count 682 --angle-min-deg -120 --angle-increment-deg 0.35242290748898675 \
   --range-scale 0.001 --min-range 0.02)"
tum=$DATA/open3d_tum_depth
check "heightmap runs end to end on the TUM frame" bash -c "'$MM' heightmap '$tum/TUM_depth.png' \
  --camera '$tum/camera_primesense.json' --auto-floor --resolution 0.05 --map-size 200 \
  --z-bins 0.1,1.0 --out-prefix '$tmp/tum' >'$tmp/tum.json'"
for f in obstacles explored layers; do
  check "heightmap wrote $f.png" bash -c "head -c 8 '$tmp/tum_$f.png' | od -An -c | grep -q 'P   N   G'"
done
check "counts.npy is a NumPy file with the map's shape" bash -c \
  "head -c 128 '$tmp/tum_counts.npy' | grep -aq \"'shape': (200, 200, 3)\""
check "the npy holds 200*200*3 uint32 after its 128-byte header" \
  test "$(stat -c %s "$tmp/tum_counts.npy")" = $((128 + 200 * 200 * 3 * 4))
check "heightmap accounts for every valid pixel" bash -c "python3 -c 1 2>/dev/null; \
  awk '/bin_counts/{f=1;next} f&&/]/{f=0} f{gsub(/,/,\"\");s+=\$1} /points_outside_map/{gsub(/,/,\"\");o=\$2} /\"points\"/{gsub(/,/,\"\");v=\$2} END{exit !(s+o==v && v>0)}' '$tmp/tum.json'"
check "explicit pose works" "$MM" heightmap "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" \
  --camera-height 1.2 --pitch-deg 20 --resolution 0.05 --map-size 200 --z-bins 0.1,1.0 \
  --out-prefix "$tmp/tum2" --format table
kitti=$DATA/kitti_odometry_00
check "kitti frames 0-5 to a map_server map and a global cloud" bash -c "'$MM' kitti '$kitti' \
  --frames 0-5 --min-range 2.5 --out-map '$tmp/k.pgm' --out-cloud '$tmp/k.pcd' \
  --map-resolution 0.2 --min-hits 2 --format json >'$tmp/k.json'"
check "PGM is binary P5" bash -c "head -c 2 '$tmp/k.pgm' | grep -q P5"
check "YAML names the image and the thresholds" bash -c "grep -q '^image: k.pgm' '$tmp/k.yaml' && \
  grep -q '^negate: 0' '$tmp/k.yaml' && grep -q '^occupied_thresh: 0.65' '$tmp/k.yaml' && \
  grep -q '^free_thresh: 0.196' '$tmp/k.yaml' && grep -q '^origin: \[' '$tmp/k.yaml'"
check "preview and heat map PNGs" test -s "$tmp/k_preview.png" -a -s "$tmp/k_heat.png"
check "every point of the six scans read" grep -q '"points_read": 745811' "$tmp/k.json"
check "the global cloud holds the kept points" bash -c "'$MM' info '$tmp/k.pcd' --format json | \
  grep -q \"\\\"points\\\": \$(grep -o '\"points_kept\": [0-9]*' '$tmp/k.json' | grep -o '[0-9]*$')\""
check "velodyne world and xy plane" "$MM" kitti "$kitti" --first 0 --count 2 --world velodyne \
  --map-plane xy --out-map "$tmp/kv.pgm"
check "kitti --refine icp --perturb reports per-frame errors and the ATE" bash -c "'$MM' kitti \
  '$kitti' --frames 0-2 --min-range 2.5 --refine icp --perturb 0.5,2 --seed 3 --format json \
  >'$tmp/reg.json' && grep -q '\"ate_after\"' '$tmp/reg.json' && grep -q '\"correction\"' '$tmp/reg.json'"
check "--perturb moves each later pose by exactly 0.5 m" bash -c \
  "grep -A3 error_before '$tmp/reg.json' | grep -c '\"translation\": 0.5' | grep -qx 2"
check "--out-poses without --refine writes the ground-truth poses back" bash -c "'$MM' kitti \
  '$kitti' --frames 0-5 --out-poses '$tmp/poses.txt' >/dev/null && head -n 6 '$kitti/poses/00.txt' | \
  paste -d' ' - '$tmp/poses.txt' | awk '{for(i=1;i<=12;i++){d=\$i-\$(i+12); if(d<0)d=-d; if(d>1e-6) exit 1}}\
  END{exit NR!=6}'"
check "--refine-target first aligns to frame 0 and says so" bash -c "'$MM' kitti '$kitti' \
  --frames 0-2 --refine icp --refine-target first --out-poses '$tmp/rp.txt' --format json \
  >'$tmp/rf.json' && grep -q '\"target\": \"first\"' '$tmp/rf.json' && test \$(wc -l <'$tmp/rp.txt') -eq 3"
finish
