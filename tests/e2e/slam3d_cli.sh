#!/usr/bin/env bash
# metricmap slam3d: every output from the KITTI frames in data/ (consistent with the report and
# with each other); no loop where the drive has no revisit (the KITTI frames, and the NCLT drive
# cut at keyframe 440, before its reverse revisit); bad options refused with one line.
MM=$1
DATA=$2
SHARED=$3
source "$(dirname "$0")/lib.sh"
k=$DATA/kitti_odometry_00
"$MM" slam3d "$k" --out-poses "$tmp/p.txt" --pose-format kitti --out-cloud "$tmp/c.pcd" \
  --out-map "$tmp/m.pgm" --out-bt "$tmp/m.bt" --out-graph "$tmp/g.g2o" --out-png "$tmp/t.png" \
  --format json >"$tmp/r.json"
check "all outputs written" test -s "$tmp/p.txt" -a -s "$tmp/c.pcd" -a -s "$tmp/m.pgm" \
  -a -s "$tmp/m.yaml" -a -s "$tmp/m.bt" -a -s "$tmp/g.g2o" -a -s "$tmp/t.png"
check "report: 6 keyframes, no verified loop" /usr/bin/python3 - "$tmp" <<'PY'
import json, sys
r = json.load(open(sys.argv[1] + "/r.json"))
assert r["keyframes"] == 6 and r["loops"]["verified"] == 0, r
assert sum(1 for l in open(sys.argv[1] + "/p.txt")) == 6
assert sum(1 for l in open(sys.argv[1] + "/g.g2o") if l.startswith("VERTEX_SE3")) == 6
PY
# Without a loop the trajectory is the odometry's: `metricmap odometry` writes the same poses.
check "odometry" "$MM" odometry "$k" --out-poses "$tmp/o.txt"
check "poses equal the odometry's without a loop" /usr/bin/python3 -c "
import numpy as np
p = np.loadtxt('$tmp/p.txt'); o = np.loadtxt('$tmp/o.txt')
assert p.shape == o.shape == (6, 12) and np.max(np.abs(p - o)) < 1e-6, np.max(np.abs(p - o))"

expect_cases \
  "2|voxel must be|slam3d $k --set voxel=0" \
  "2|unknown slam3d parameter|slam3d $k --set nope=1" \
  "2|NAME=VALUE|slam3d $k --set voxel" \
  "2|--map-resolution|slam3d $k --map-resolution 0.2" \
  "2|--out-map|slam3d $k --out-map $tmp/x.txt" \
  "2|--octomap-resolution|slam3d $k --octomap-resolution 0" \
  "1|no-such|slam3d $tmp/no-such"

nclt=$SHARED/nclt_2013_01_10_keyframes
if has_shared_data "$nclt"; then
  "$MM" slam3d "$nclt" --frames 0-440 --format json >"$tmp/n.json"
  check "NCLT before the revisit: no verified loop" /usr/bin/python3 -c "
import json; r = json.load(open('$tmp/n.json')); assert r['keyframes'] == 441 and r['loops']['verified'] == 0, r"
fi
finish
