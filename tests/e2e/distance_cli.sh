#!/usr/bin/env bash
# metricmap distance: a hand-made 2D map_server map against scipy's exact EDT (the .npy layout,
# clamp, signs), its costmap against nav2's formula, queries against the field's values at
# voxel centres; a real OctoMap file's report against its .npy; bad input refused with one line
# and nothing written.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
py=/usr/bin/python3
if ! $py -c "import numpy, scipy.ndimage" 2>/dev/null; then echo "skip: numpy/scipy missing"; exit 77; fi

# A 60 x 45 map at 5 cm: walls, a pillar, an unknown patch.
$py - "$tmp" <<'PY'
import sys, numpy as np
d = sys.argv[1]
h, w = 45, 60
img = np.full((h, w), 254, np.uint8)
img[5:40, 12] = 0; img[20, 12:50] = 0; img[30:33, 40:43] = 0
img[0:10, 30:45] = 205
with open(d + "/m.pgm", "wb") as f:
    f.write(b"P5\n%d %d\n255\n" % (w, h)); f.write(img.tobytes())
open(d + "/m.yaml", "w").write("image: m.pgm\nresolution: 0.05\norigin: [-1.0, 2.0, 0.0]\n"
                               "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
np.savetxt(d + "/q.csv", [[-1.0 + 0.025 + 0.05 * i, 2.0 + 0.025 + 0.05 * j] for i, j in
                          [(3, 4), (20, 30), (59, 44), (0, 0)]], delimiter=",", header="x,y")
PY
"$MM" distance "$tmp/m.yaml" --max-distance 0.6 --out "$tmp/f.npy" --out-costmap "$tmp/c.pgm" \
  --inscribed-radius 0.1 --inflation-radius 0.3 --cost-scaling-factor 8 \
  --query "$tmp/q.csv" --out-query "$tmp/a.csv" --format json >"$tmp/r.json"
check "2D outputs written" test -s "$tmp/f.npy" -a -s "$tmp/c.pgm" -a -s "$tmp/c.yaml" -a -s "$tmp/a.csv"
check "2D field equals scipy's EDT; costmap equals nav2's formula; queries equal voxel values" \
  $py - "$tmp" <<'PY'
import sys, json, numpy as np
from scipy.ndimage import distance_transform_edt
d = sys.argv[1]
r = json.load(open(d + "/r.json"))
raw = open(d + "/m.pgm", "rb").read(); img = np.frombuffer(raw[-45 * 60:], np.uint8).reshape(45, 60)
occ = (img == 0)[::-1].T                       # (nx, ny): cell (i, j) = column i, row from the bottom
f = np.load(d + "/f.npy")
assert f.dtype == np.float32 and f.shape == (60, 45) and f.flags.c_contiguous, (f.dtype, f.shape)
assert r["shape"] == [60, 45] and r["resolution"] == 0.05 and r["max_distance"] == 0.6, r
assert abs(r["origin"][0] - (-0.975)) < 1e-12 and abs(r["origin"][1] - 2.025) < 1e-12, r["origin"]
assert r["counts"]["occupied"] == occ.sum() and "field" in r["seconds"], r
ref = np.minimum(distance_transform_edt(~occ) * 0.05, 0.6)
assert np.abs(f - ref).max() < 1e-5, np.abs(f - ref).max()
# costmap: nav2 computeCost over the cells' distances in cells, unknown 255 below 253
cells = distance_transform_edt(~occ)
cost = np.where(cells == 0, 254, np.where(cells * 0.05 <= 0.1, 253,
        (252 * np.exp(-8 * (cells * 0.05 - 0.1))).astype(np.uint8)))
cost = np.where(cells > np.ceil(0.3 / 0.05), 0, cost)
unknown = (img == 205)[::-1].T
cost = np.where(unknown & (cost < 253), 255, cost)
craw = open(d + "/c.pgm", "rb").read(); c = np.frombuffer(craw[-45 * 60:], np.uint8).reshape(45, 60)
assert (c[::-1].T == cost).all(), np.argwhere(c[::-1].T != cost)[:5]
assert "mode: raw" in open(d + "/c.yaml").read()
q = np.genfromtxt(d + "/a.csv", delimiter=",", names=True)
for row, (i, j) in zip(q, [(3, 4), (20, 30), (59, 44), (0, 0)]):
    assert abs(row["distance"] - f[i, j]) < 1e-6 and row["inside"] == 1, (row, f[i, j])
PY

# Signed, unknown as occupied: negative inside obstacles, scipy's EDT of the complement.
"$MM" distance "$tmp/m.yaml" --signed --unknown occupied --max-distance 10 --out "$tmp/s.npy" \
  --format json >"$tmp/s.json"
check "signed field equals scipy's EDT(obstacles) - EDT(free), walls beyond the box as obstacles" \
  $py - "$tmp" <<'PY'
import sys, numpy as np
from scipy.ndimage import distance_transform_edt
d = sys.argv[1]
raw = open(d + "/m.pgm", "rb").read(); img = np.frombuffer(raw[-45 * 60:], np.uint8).reshape(45, 60)
obst = np.pad(((img == 0) | (img == 205))[::-1].T, 1, constant_values=True)
ref = (distance_transform_edt(~obst) - distance_transform_edt(obst))[1:-1, 1:-1] * 0.05
s = np.load(d + "/s.npy")
assert np.abs(s - ref).max() < 1e-5, np.abs(s - ref).max()
assert (s < 0).sum() == obst[1:-1, 1:-1].sum()
PY

# A real OctoMap file: the report's shape and counts agree with the .npy.
"$MM" distance "$DATA/octomap_geb079/geb079.bt" --max-distance 0.5 --out "$tmp/g.npy" \
  --out-vdb "$tmp/g.vdb" --format json >"$tmp/g.json"
# OpenVDB's magic number (0x56444220, little-endian) opens the file
check "--out-vdb writes an OpenVDB file" test "$(head -c 4 "$tmp/g.vdb" | od -An -tx1 | tr -d ' ')" = 20424456
check "3D report agrees with its .npy" $py - "$tmp" <<'PY'
import sys, json, numpy as np
d = sys.argv[1]
r = json.load(open(d + "/g.json")); f = np.load(d + "/g.npy")
assert list(f.shape) == r["shape"] and len(r["origin"]) == 3, (f.shape, r)
assert (f == 0).sum() == r["counts"]["occupied"] and r["counts"]["occupied"] > 1000, r["counts"]
assert abs(f[f > 0].min() - r["resolution"]) < 1e-6 and f.max() <= 0.5 + 1e-6
assert (f >= np.float32(0.5)).sum() == r["counts"]["clamped"]
PY

# Bad input: one line, exit 1 (2 for usage), nothing written.
printf 'x,y,z\n1,2,3\nnan,1,2\n' >"$tmp/nan.csv"
printf 'x,y\ninf,0\n' >"$tmp/inf.csv"       # only the first line may be a header
printf 'x,y\nabc,1\n' >"$tmp/word.csv"
$py -c "
import numpy as np
p = np.array([[0, 0, 0], [1e30, 0, 0]], np.float32)
h = 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\nDATA binary\n'
open('$tmp/far.pcd', 'wb').write(h.encode() + p.tobytes())"
printf 'P5\n4 3\n255\n' >"$tmp/e.pgm"; head -c 12 /dev/zero | tr '\0' '\376' >>"$tmp/e.pgm"
printf 'image: e.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' >"$tmp/e.yaml"
expect_cases \
  "2|--max-distance|distance $tmp/m.yaml --max-distance nan --out $tmp/bad.npy" \
  "2|--max-distance|distance $tmp/m.yaml --max-distance -1 --out $tmp/bad.npy" \
  "1|nan.csv:3|distance $tmp/m.yaml --query $tmp/nan.csv --out-query $tmp/bad.csv --out $tmp/bad.npy" \
  "2|--resolution|distance $tmp/m.yaml --resolution 0.1" \
  "1|inf.csv:2|distance $tmp/m.yaml --query $tmp/inf.csv --out-query $tmp/bad.csv --out $tmp/bad.npy" \
  "1|word.csv:2|distance $tmp/m.yaml --query $tmp/word.csv --out-query $tmp/bad.csv --out $tmp/bad.npy" \
  "1|smallest float32|distance $tmp/m.yaml --max-distance 1e-300 --out $tmp/bad.npy" \
  "1|far.pcd: point (1e+30, 0, 0)|distance $tmp/far.pcd --resolution 0.1 --out $tmp/bad.npy" \
  "2|--out-costmap|distance $DATA/octomap_geb079/geb079.bt --out-costmap $tmp/bad.pgm" \
  "1|budget|--max-memory 1M distance $DATA/octomap_geb079/geb079.bt --out $tmp/bad.npy" \
  "2|--out-vdb|distance $tmp/m.yaml --out-vdb $tmp/bad.npy" \
  "1|nodir/bad.vdb|distance $tmp/m.yaml --out-vdb $tmp/nodir/bad.vdb"
ln "$tmp/m.pgm" "$tmp/img.pgm"
expect 2 "map's image" -- "$MM" distance "$tmp/m.yaml" --out-costmap "$tmp/img.pgm"
check "the map's image intact" cmp -s "$tmp/m.pgm" "$tmp/img.pgm"
expect 2 "drop --signed" -- "$MM" distance "$tmp/m.yaml" --signed --out-costmap "$tmp/bad.pgm"
check "nothing written by the refused runs" test ! -e "$tmp/bad.npy" -a ! -e "$tmp/bad.csv" -a ! -e "$tmp/bad.pgm" -a ! -e "$tmp/bad.vdb"
# A map with no occupied cell: written, and said once on stderr and in the report.
"$MM" distance "$tmp/e.yaml" --out "$tmp/e.npy" --format json >"$tmp/e.json" 2>"$tmp/e.err"
check "empty map reported" grep -q '"no_obstacle": true' "$tmp/e.json"
check "empty map warned in one line" test "$(grep -c 'no occupied' "$tmp/e.err")" = 1
finish
