#!/usr/bin/env bash
# metricmap localize: a map made by slam2d of the Intel log's first scans, the same log localised
# in it without an initial pose: a fix within 20 scans, poses at slam2d's (an independent
# estimate of the same scans); hostile map files and bad options refused, nothing written.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
log=$DATA/radish_clf_raw/intel.clf.bz2
if [ ! -f "$log" ]; then echo "skip: $log missing"; exit 77; fi
"$MM" slam2d "$log" --frames 0-599 --out-map "$tmp/m.pgm" --out-poses "$tmp/slam.tum" >/dev/null
"$MM" localize "$log" --map "$tmp/m.yaml" --frames 300-499 --out-poses "$tmp/p.tum" \
  --out-png "$tmp/p.png" --format json >"$tmp/r.json"
check "poses and picture written" test -s "$tmp/p.tum" -a -s "$tmp/p.png"
check "fixed within 20 scans, 95 % localised, at slam2d's poses" /usr/bin/python3 - "$tmp" <<'PY'
import json, math, sys
d = sys.argv[1]
r = json.load(open(f'{d}/r.json'))
assert r['first_fix'] is not None and r['first_fix']['scan'] < 20, r['first_fix']
assert r['localised'] >= 0.95 * (r['scans'] - r['first_fix']['scan']), r['localised']
assert len(r['per_scan']['status']) == r['scans'] == 200
slam = {l.split()[0]: [float(x) for x in l.split()[1:3]] for l in open(f'{d}/slam.tum')}
rows = [l.split() for l in open(f'{d}/p.tum')]
assert len(rows) == r['localised'], (len(rows), r['localised'])
err = sorted(math.dist([float(x) for x in row[1:3]], slam[row[0]]) for row in rows)
print('median error', err[len(err) // 2], 'max', err[-1])
assert err[len(err) // 2] <= 0.05 and err[int(len(err) * 0.95)] <= 0.15
PY
"$MM" localize "$log" --map "$tmp/m.yaml" --frames 300-349 --out-poses "$tmp/k.txt" \
  --pose-format kitti >/dev/null
check "kitti rows: 12 numbers" /usr/bin/python3 -c "
import sys; rows = [l.split() for l in open('$tmp/k.txt')]
assert rows and all(len(r) == 12 for r in rows)"

# Hostile map files: one line naming the file, exit 1, no pose file.
y() {  # y NAME IMAGE: a map_server YAML naming IMAGE
  printf 'image: %s\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' "$2" >"$tmp/$1.yaml"
}
y missing nowhere.pgm
printf 'P5 100000 100000 255 \000\000' >"$tmp/huge.pgm"; y huge huge.pgm
printf 'not an image' >"$tmp/odd.pgm"; y odd odd.pgm
printf 'P5 2 2 65535 \000\000\000\000\000\000\000\000' >"$tmp/deep.pgm"; y deep deep.pgm
printf 'image: [m.pgm\n' >"$tmp/broken.yaml"
printf 'image: m.pgm\nresolution: -1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' >"$tmp/neg.yaml"
for case in "missing|nowhere.pgm" "huge|100000 x 100000" "odd|not a PGM" "deep|16-bit" \
            "broken|broken.yaml" "neg|resolution"; do
  IFS='|' read -r name needle <<<"$case"
  expect 1 "$needle" -- "$MM" localize "$log" --map "$tmp/$name.yaml" --out-poses "$tmp/x.tum"
  check "$name: nothing written" test ! -e "$tmp/x.tum"
done
expect_cases \
  "2|--initial-pose|localize $log --map $tmp/m.yaml --initial-pose 1,2" \
  "2|--initial-pose|localize $log --map $tmp/m.yaml --initial-pose=" \
  "2|outside the map|localize $log --map $tmp/m.yaml --initial-pose 1e300,0,0" \
  "2|outside the map|localize $log --map $tmp/m.yaml --initial-pose 1000,-1000,0" \
  "2|yaw 1e+30 rad|localize $log --map $tmp/m.yaml --initial-pose 0,0,1e30" \
  "2|--map|localize $log --map $tmp/m.pgm" \
  "2|--pose-format|localize $log --map $tmp/m.yaml --pose-format kitti" \
  "2|global_min_score|localize $log --map $tmp/m.yaml --set global_min_score=2" \
  "2|unknown localisation parameter|localize $log --map $tmp/m.yaml --set nope=1" \
  "2|--set max_range and --max-range set the same parameter|localize $log --map $tmp/m.yaml --max-range 5 --set max_range=30" \
  "2|--set lost_after_weak_scans and --lost-after|localize $log --map $tmp/m.yaml --lost-after 1 --set lost_after_weak_scans=50" \
  "2|no effect without --initial-pose|localize $log --map $tmp/m.yaml --set initial_linear_window=2" \
  "2|voxel_filter must be in|localize $log --map $tmp/m.yaml --set voxel_filter=1e-30" \
  "2|max_range must be in|localize $log --map $tmp/m.yaml --set max_range=1e-25"

# Maps of cells finer than a map file holds, a yaw no double resolves, a search beyond the
# budget: refused before anything is allocated (a 1e-9 m map crashed, a 1e-5 m one grew to 24 GB).
for v in "tiny|resolution: 1e-9|resolution 1e-9 must be in" "yaw|origin: [0, 0, 1e30]|origin yaw 1e30"; do
  IFS='|' read -r name line needle <<<"$v"
  sed "s/^resolution:.*/resolution: 0.05/" "$tmp/m.yaml" >"$tmp/$name.yaml"
  key=${line%%:*}
  sed -i "s/^$key:.*/$line/" "$tmp/$name.yaml"
  expect 1 "$needle" -- "$MM" localize "$log" --map "$tmp/$name.yaml" --frames 300 --out-poses "$tmp/x.tum"
done
sed "s/^resolution:.*/resolution: 0.001/" "$tmp/m.yaml" >"$tmp/fine.yaml"
expect 1 "a branch-and-bound search needs" -- "$MM" --max-memory 256M localize "$log" \
  --map "$tmp/fine.yaml" --frames 300 --out-poses "$tmp/x.tum"
# Nothing localised: no pose file, said so.
expect 1 "no scan was localised" -- "$MM" localize "$log" --map "$tmp/m.yaml" --frames 300-310 \
  --min-score 0.99 --out-poses "$tmp/x.txt" --pose-format kitti
check "nothing written" test ! -e "$tmp/x.tum" -a ! -e "$tmp/x.txt"
# An output that is (a link to) the map's image is never replaced.
ln "$tmp/m.pgm" "$tmp/link.txt"
expect 2 "--map's image" -- "$MM" localize "$log" --map "$tmp/m.yaml" --frames 300 --out-poses "$tmp/link.txt"
check "the map's image intact" cmp -s "$tmp/m.pgm" "$tmp/link.txt"
# 3D maps (.pcd, .ply, .bt, .ot): hostile files get one line and exit 1, nothing written.
mkdir -p "$tmp/scans"
pcd() {  # pcd FILE N ROWS...: an ascii PCD of N points
  local f=$1 n=$2; shift 2
  printf 'VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %s\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %s\nDATA ascii\n' "$n" "$n" >"$f"
  printf '%s\n' "$@" >>"$f"
}
pcd "$tmp/scans/000000.pcd" 3 "1 0 0" "0 1 0" "0 0 1"
pcd "$tmp/nan.pcd" 2 "nan nan nan" "nan 0 1"
pcd "$tmp/far.pcd" 2 "0 0 0" "3e7 0 0"
: >"$tmp/empty.ply"
printf '# Octomap OcTree binary file\nres x\n' >"$tmp/junk.bt"
for v in "nan.pcd|no finite points" "far.pcd|beyond" "empty.ply|empty.ply" "junk.bt|junk.bt"; do
  IFS='|' read -r map needle <<<"$v"
  expect 1 "$needle" -- "$MM" localize "$tmp/scans" --map "$tmp/$map" --out-poses "$tmp/x.tum"
  check "nothing written for $map" test ! -e "$tmp/x.tum"
done
expect 1 "2D laser scans" -- "$MM" localize "$log" --map "$tmp/scans/000000.pcd" --frames 300
expect 2 "x,y,z,roll,pitch,yaw" -- "$MM" localize "$tmp/scans" --map "$tmp/scans/000000.pcd" \
  --initial-pose 1,2,3
expect 2 "--set" -- "$MM" localize "$tmp/scans" --map "$tmp/scans/000000.pcd" --set max_range=5
finish
