#!/usr/bin/env bash
# metricmap occupancy: outputs of a real run, then bad input (one line, exit 1, no file left).
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
kitti=$DATA/kitti_odometry_00
out=$tmp/o
mkdir -p "$out"

"$MM" occupancy "$kitti" --frames 0-1 --resolution 0.2 --max-range 50 --out "$out/m.bt" \
  --out-ot "$out/m.ot" --out-cloud "$out/occ.pcd" --out-map "$out/m.pgm" --band -1.5,0.5 \
  --format json >"$out/run.json" 2>"$out/run.err"
check "run succeeds quietly" test ! -s "$out/run.err"
for f in m.bt m.ot occ.pcd m.pgm m.yaml; do check "$f written" test -s "$out/$f"; done
check "json frames" grep -q '"frames": 2' "$out/run.json"
check "json beams" grep -q '"beams": 249273' "$out/run.json"
check "yaml trinary" grep -q 'mode: trinary' "$out/m.yaml"
check "pgm header" grep -qa '^P5' "$out/m.pgm"
# the .bt read back: the same occupied voxels as the scans gave
occ=$(grep -o '"occupied": [0-9]*' "$out/run.json" | tail -1)
"$MM" occupancy "$out/m.bt" --format json >"$out/back.json" 2>"$out/back.err"
check "bt read back: $occ" grep -q "$occ" "$out/back.json"
check "bt read quietly" test ! -s "$out/back.err"
# Beams cast on three threads: the same files, byte for byte.
"$MM" occupancy "$kitti" --frames 0-1 --resolution 0.2 --max-range 50 --threads 3 \
  --out "$out/m3.bt" --out-cloud "$out/occ3.pcd" >/dev/null
check "--threads 3: the same .bt" cmp "$out/m.bt" "$out/m3.bt"
check "--threads 3: the same voxel centres, in the same order" cmp "$out/occ.pcd" "$out/occ3.pcd"
expect 2 "--threads: '$out/m.bt' is a map" -- "$MM" occupancy "$out/m.bt" --threads 2 \
  --out-cloud "$out/never.pcd"

# The mapping pipeline (metricmap kitti, ScanMapper) builds the same 3D map and trinary map as
# metricmap occupancy from the same frames in the velodyne world: byte for byte.
mkdir -p "$out/k"
"$MM" kitti "$kitti" --frames 0-1 --world velodyne --occupancy-resolution 0.2 \
  --occupancy-max-range 50 --out-octomap "$out/k/m.bt" --out-trinary "$out/k/m.pgm" \
  --band -1.5,0.5 --format json >"$out/k/run.json"
check "kitti .bt = occupancy .bt" cmp "$out/k/m.bt" "$out/m.bt"
check "kitti trinary = occupancy trinary" cmp "$out/k/m.pgm" "$out/m.pgm"
check "kitti yaml = occupancy yaml" cmp "$out/k/m.yaml" "$out/m.yaml"
check "kitti json occupancy" grep -q '"occupied_voxels"' "$out/k/run.json"
expect 2 "needs --world velodyne" -- "$MM" kitti "$kitti" --frames 0 --occupancy-resolution 0.2 \
  --out-trinary "$out/bad.pgm" --band 0,1
expect 2 "need the 3D occupancy map" -- "$MM" kitti "$kitti" --frames 0 --out-octomap "$out/bad.bt"
expect 2 "go together" -- "$MM" kitti "$kitti" --frames 0 --world velodyne \
  --occupancy-resolution 0.2 --out-trinary "$out/bad.pgm"

# bad option values: usage errors (exit 2); bad input: exit 1; one line, nothing written
for r in 0 -0.2 nan; do
  expect 2 "--resolution" -- "$MM" occupancy "$kitti" --frames 0 --resolution "$r" \
    --max-range 50 --out "$out/bad.bt"
done
for m in 0 -1 nan; do
  expect 2 "--max-range" -- "$MM" occupancy "$kitti" --frames 0 --resolution 0.2 \
    --max-range "$m" --out "$out/bad.bt"
done
head -c 60000 "$out/m.bt" >"$out/trunc.bt"
expect 1 "trunc.bt: truncated" -- "$MM" occupancy "$out/trunc.bt" --out "$out/bad.bt"
head -c 90 "$out/m.ot" >"$out/trunc.ot"
expect 1 "trunc.ot" -- "$MM" occupancy "$out/trunc.ot" --out "$out/bad.bt"
printf 'hello\n' >"$out/junk.bt"
expect 1 "not an OctoMap file" -- "$MM" occupancy "$out/junk.bt" --out "$out/bad.bt"
sed '/^VIEWPOINT/d' "$DATA/ua_mapas_metricos_pcd/museo000.pcd" >"$out/noview.pcd"
expect 1 "noview.pcd: no VIEWPOINT" -- "$MM" occupancy "$out/noview.pcd" --resolution 0.2 \
  --max-range 10 --out "$out/bad.bt"
expect 1 "000000.bin: scans must be PCD" -- "$MM" occupancy "$kitti/sequences/00/velodyne/000000.bin" \
  --resolution 0.2 --max-range 10 --out "$out/bad.bt"
expect 1 "height band" -- "$MM" occupancy "$kitti" --frames 0 --resolution 0.2 --max-range 50 \
  --out "$out/bad.bt" --out-map "$out/bad.pgm" --band 100,200
expect 2 "--band must be" -- "$MM" occupancy "$kitti" --frames 0 --resolution 0.2 --max-range 50 \
  --out-map "$out/bad.pgm" --band 1
expect 2 "--resolution and --max-range" -- "$MM" occupancy "$kitti" --frames 0 --resolution 0.2
check "no partial or stray file" test -z "$(ls "$out" | grep -E 'bad|tmp-')"
finish
