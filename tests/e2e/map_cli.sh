#!/usr/bin/env bash
# metricmap map: the KITTI layout with its reference poses gives `kitti`'s map byte for byte; a
# hand-carried scanner's folder maps with reference poses and with odometry; options that would
# be ignored are refused; nothing is written on a refusal.
MM=$1
DATA=$2
SHARED=$3
source "$(dirname "$0")/lib.sh"
k=$DATA/kitti_odometry_00
"$MM" map "$k" --frames 0-5 --out-map "$tmp/a.pgm" >/dev/null
"$MM" kitti "$k" --frames 0-5 --out-map "$tmp/b.pgm" >/dev/null
check "map on KITTI with poses/00.txt = kitti's map (PGM)" cmp -s "$tmp/a.pgm" "$tmp/b.pgm"
check "and its YAML (but for the image name)" cmp -s <(grep -v '^image:' "$tmp/a.yaml") <(grep -v '^image:' "$tmp/b.yaml")
balm=$SHARED/balm_realworld_dev
# The reference in the frame of the first scan (the odometry's world), written with numpy.
/usr/bin/python3 -c "
import numpy as np
P = np.loadtxt('$balm/poses.txt').reshape(-1, 3, 4)
T = np.tile(np.eye(4), (len(P), 1, 1)); T[:, :3, :] = P
R = np.linalg.inv(T[0]) @ T
np.savetxt('$tmp/rel.txt', R[:, :3, :].reshape(-1, 12), fmt='%.9e')"
"$MM" map "$balm" --frames 0-9 --reference "$tmp/rel.txt" --out-map "$tmp/r.pgm" --out-cloud "$tmp/r.pcd" --format json >"$tmp/r.json"
check "balm with reference poses" test -s "$tmp/r.pgm" -a -s "$tmp/r.pcd"
"$MM" map "$balm" --frames 0-9 --poses odometry --world-frame first-scan --out-map "$tmp/o.pgm" \
  --format json >"$tmp/o.json"
check "balm with odometry poses" test -s "$tmp/o.pgm"
check "both maps have occupied cells of similar count" /usr/bin/python3 -c "
import json
r = json.load(open('$tmp/r.json'))['map']['occupied_cells']
o = json.load(open('$tmp/o.json'))['map']['occupied_cells']
assert r > 1000 and abs(r - o) < 0.05 * r, (r, o)"
# The 2D log-odds occupancy grid: the PGM agrees with its YAML and with the report's counts.
grid_check() {  # grid_check PGM JSON MODE
  /usr/bin/python3 -c "
import json, re, sys
data = open('$1', 'rb').read()
m = re.match(rb'P5\s+(?:#[^\n]*\n)?(\d+)\s+(\d+)\s+255\s', data)
w, h = int(m.group(1)), int(m.group(2))
px = data[m.end():]
assert len(px) == w * h, (len(px), w, h)
g = json.load(open('$2'))['occupancy_2d']
yaml = open('$1'[:-4] + '.yaml').read()
assert (g['width'], g['height']) == (w, h), g
assert 'mode: $3' in yaml, yaml
if '$3' == 'trinary':
    assert set(px) <= {0, 205, 254}, set(px)
    assert px.count(0) == g['occupied_cells'] > 100, (px.count(0), g)
    assert px.count(254) == g['free_cells'] > 1000, (px.count(254), g)
else:  # probability: 255 (1 - p); occupied cells p >= 0.5, the unknown prior 127
    assert sum(v < 127 for v in px) == g['occupied_cells'] > 100, g
    assert px.count(127) == w * h - g['known_cells'], g
"
}
"$MM" map "$balm" --frames 0-9 --reference "$tmp/rel.txt" --out-occupancy-2d "$tmp/g.pgm" --format json >"$tmp/g.json"
check "balm: 2D occupancy grid (trinary) agrees with its YAML and the report" grid_check "$tmp/g.pgm" "$tmp/g.json" trinary
"$MM" map "$k" --frames 0-5 --poses odometry --out-occupancy-2d "$tmp/kg.pgm" --occupancy-2d-image probability \
  --occupancy-2d-resolution 0.2 --occupancy-2d-max-range 40 --format json >"$tmp/kg.json"
check "KITTI with odometry: 2D occupancy grid (probability)" grid_check "$tmp/kg.pgm" "$tmp/kg.json" scale
expect 2 "--band-2d" -- "$MM" map "$balm" --out-occupancy-2d "$tmp/x.pgm" --band-2d 1,0
expect 2 "--occupancy-2d-image" -- "$MM" map "$balm" --out-map "$tmp/x.pgm" --occupancy-2d-image probability
expect 2 "--out-occupancy-2d" -- "$MM" map "$balm" --out-occupancy-2d "$tmp/x.png"
expect 2 "--out-occupancy-2d" -- "$MM" map "$balm" --out-occupancy-2d "$tmp/x.pgm" --out-map "$tmp/./x.pgm"
expect 2 "--occupancy-2d-resolution" -- "$MM" map "$balm" --out-occupancy-2d "$tmp/x.pgm" --occupancy-2d-resolution 0
expect 1 "--frames 0-20" -- "$MM" map "$k" --frames 0-20 --out-map "$tmp/x.pgm"
expect 2 "--poses odometry" -- "$MM" map "$balm" --max-range 20 --out-map "$tmp/x.pgm"
expect 2 "--out-map" -- "$MM" map "$balm"
expect 2 "--min-height" -- "$MM" map "$balm" --min-height 2 --max-height 1 --out-map "$tmp/x.pgm"
expect 2 "poses.txt" -- "$MM" map "$balm" --out-cloud "$balm/poses.txt"
mkdir -p "$tmp/noref"; cp "$balm/full60.pcd" "$balm/full61.pcd" "$tmp/noref/"
expect 1 "no reference poses" -- "$MM" map "$tmp/noref" --out-map "$tmp/x.pgm"
check "nothing written after a refusal" test ! -e "$tmp/x.pgm"
finish
