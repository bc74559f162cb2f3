#!/usr/bin/env bash
# metricmap slam2d on the raw Intel Research Lab log (13631 scans): the trajectory agrees with the
# corrected Intel log (910 scans, an independent SLAM run; scans matched by their ranges) far
# better than the raw odometry does; outputs are consistent with the log and with each other;
# bad input and bad options are refused with nothing written.
MM=$1
SHARED=$3
source "$(dirname "$0")/lib.sh"
raw=$SHARED/radish_clf_raw/intel.clf.bz2
cor=$SHARED/radish_carmen_corrected/intel-corrected.log.gz
need_shared_data "$raw" "$cor"
"$MM" slam2d "$raw" --out-poses "$tmp/p.tum" --out-map "$tmp/m.pgm" --out-graph "$tmp/g.g2o" \
  --out-png "$tmp/m.png" --format json >"$tmp/r.json"
check "all outputs written" test -s "$tmp/p.tum" -a -s "$tmp/m.pgm" -a -s "$tmp/m.yaml" \
  -a -s "$tmp/g.g2o" -a -s "$tmp/m.png"
# ATE after a rigid 2D alignment (Umeyama, no scale), mean over the corrected log's scans.
ate() {  # ate TRAJECTORY|odom
  /usr/bin/python3 - "$raw" "$cor" "$1" <<'PY'
import sys, bz2, gzip, numpy as np
raw = [l.split() for l in bz2.open(sys.argv[1], 'rt') if l.startswith('FLASER')]
key = {}
for i, t in enumerate(raw):
    n = int(t[1]); key.setdefault(tuple(round(float(x) * 100) for x in t[2:2 + n]), i)
pairs = []
for l in gzip.open(sys.argv[2], 'rt'):
    if not l.startswith('FLASER'): continue
    t = l.split(); n = int(t[1]); k = tuple(round(float(x) * 100) for x in t[2:2 + n])
    if k in key: pairs.append((key[k], float(t[2 + n]), float(t[3 + n])))
assert len(pairs) == 910, len(pairs)
if sys.argv[3] == 'odom':
    est = np.array([[float(t[5 + int(t[1])]), float(t[6 + int(t[1])])] for t in raw])
else:  # rows in stamp order: each scan's row found by its stamp
    rows = np.loadtxt(sys.argv[3]); where = {round(s, 6): k for k, s in enumerate(rows[:, 0])}
    est = np.array([rows[where[round(float(t[-3]), 6)], 1:3] for t in raw])
idx = np.array([p[0] for p in pairs]); ref = np.array([p[1:] for p in pairs]); e = est[idx]
H = (e - e.mean(0)).T @ (ref - ref.mean(0)); U, S, Vt = np.linalg.svd(H)
D = np.diag([1, np.sign(np.linalg.det(Vt.T @ U.T))]); R = Vt.T @ D @ U.T
d = np.linalg.norm((R @ (e - e.mean(0)).T).T + ref.mean(0) - ref, axis=1)
print(d.mean())
PY
}
slam=$(ate "$tmp/p.tum")
odom=$(ate odom)
echo "ATE against the corrected log: slam2d $slam m, raw odometry $odom m"
check "slam2d within 0.15 m of the corrected log on average (ten runs: 0.05-0.07 m; local SLAM alone: 0.18 m)" \
  /usr/bin/python3 -c "assert $slam < 0.15, $slam"
check "the raw odometry is far worse (> 5 m), as published" \
  /usr/bin/python3 -c "assert $odom > 5 and $odom > 10 * $slam, ($odom, $slam)"
check "one TUM row per scan, with the log's own stamps, in stamp order" /usr/bin/python3 -c "
import bz2, numpy as np
st = sorted(float(l.split()[-3]) for l in bz2.open('$raw', 'rt') if l.startswith('FLASER'))
p = np.loadtxt('$tmp/p.tum'); assert p.shape == (len(st), 8), p.shape
assert np.all(np.abs(p[:, 0] - st) < 1e-5) and np.all(p[:, 3] == 0), 'stamps or z'"
check "report: loops kept, scans = nodes' scans, the graph has a vertex per node" /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/r.json'))
assert j['scans'] == 13631 and j['loop_closures']['kept'] > 100, j
v = sum(1 for l in open('$tmp/g.g2o') if l.startswith('VERTEX_SE2'))
e = sum(1 for l in open('$tmp/g.g2o') if l.startswith('EDGE_SE2'))
assert v == j['nodes'] and e == j['nodes'] - 1 + j['loop_closures']['kept'], (v, e, j)"
# The benchmark's relation metric through `metricmap evaluate`: relations between corrected
# scans 100 apart (their true relative pose from the corrected log, their stamps the raw log's).
/usr/bin/python3 - "$raw" "$cor" "$tmp" <<'PY'
import sys, bz2, gzip, numpy as np
raw = [l.split() for l in bz2.open(sys.argv[1], 'rt') if l.startswith('FLASER')]
key = {}
for t in raw:
    n = int(t[1]); key.setdefault(tuple(round(float(x) * 100) for x in t[2:2 + n]), t)
m = []
for l in gzip.open(sys.argv[2], 'rt'):
    if not l.startswith('FLASER'): continue
    t = l.split(); n = int(t[1]); r = key[tuple(round(float(x) * 100) for x in t[2:2 + n])]
    m.append((float(r[-3]), float(t[2 + n]), float(t[3 + n]), float(t[4 + n])))
with open(sys.argv[3] + '/rel.txt', 'w') as f:
    for a, b in zip(m, m[100:]):
        c, s = np.cos(a[3]), np.sin(a[3]); dx, dy = b[1] - a[1], b[2] - a[2]
        f.write('%.6f %.6f %.6f %.6f 0 0 0 %.9f\n' % (a[0], b[0], c * dx + s * dy, -s * dx + c * dy,
                (b[3] - a[3] + np.pi) % (2 * np.pi) - np.pi))
rows = sorted((float(t[-3]), float(t[5 + int(t[1])]), float(t[6 + int(t[1])]), float(t[7 + int(t[1])])) for t in raw)
with open(sys.argv[3] + '/odom.tum', 'w') as f:
    for st, x, y, th in rows:
        f.write('%.6f %.6f %.6f 0 0 0 %.9f %.9f\n' % (st, x, y, np.sin(th / 2), np.cos(th / 2)))
PY
"$MM" evaluate "$tmp/p.tum" --relations "$tmp/rel.txt" --max-time-diff 0.0001 --format json >"$tmp/rs.json"
"$MM" evaluate "$tmp/odom.tum" --relations "$tmp/rel.txt" --max-time-diff 0.0001 --format json >"$tmp/ro.json"
check "relations (scans 100 apart): slam2d's error far below the raw odometry's" /usr/bin/python3 -c "
import json; s = json.load(open('$tmp/rs.json')); o = json.load(open('$tmp/ro.json'))
print('slam2d', s['abs_translation_m'], s['abs_rotation_deg']); print('odometry', o['abs_translation_m'], o['abs_rotation_deg'])
assert s['relations']['used'] == 810 and o['relations']['used'] == 810, (s['relations'], o['relations'])
assert 5 * s['abs_translation_m']['mean'] < o['abs_translation_m']['mean'], (s, o)
assert 5 * s['abs_rotation_deg']['mean'] < o['abs_rotation_deg']['mean'], (s, o)"
# A trajectory of every seventh scan: the relation stamps it lacks are placed by the log's raw
# odometry from the nearest pose (the benchmark's rule); without --odometry they are skipped.
/usr/bin/python3 -c "
import numpy as np; np.savetxt('$tmp/sparse.tum', np.loadtxt('$tmp/p.tum')[::7], fmt='%.6f')"
"$MM" evaluate "$tmp/sparse.tum" --relations "$tmp/rel.txt" --max-time-diff 0.0001 \
  --odometry "$raw" --format json >"$tmp/rsp.json"
"$MM" evaluate "$tmp/sparse.tum" --relations "$tmp/rel.txt" --max-time-diff 0.0001 \
  --format json >"$tmp/rsn.json"
check "--odometry places the stamps a sparse estimate lacks; the metric stays close (odometry adds < 0.15 m)" /usr/bin/python3 -c "
import json; s = json.load(open('$tmp/rs.json')); p = json.load(open('$tmp/rsp.json'))
n = json.load(open('$tmp/rsn.json'))
print('sparse + odometry', p['abs_translation_m'], p['relations']['stamps_placed_by_odometry'])
assert p['relations']['used'] == 810 and p['relations']['stamps_placed_by_odometry'] > 1000, p
assert n['relations']['used'] < 100, n['relations']
a, b = p['abs_translation_m']['mean'], s['abs_translation_m']['mean']
assert a != b and 0.5 * b < a < b + 0.15, (a, b)"
expect 2 "--odometry has no effect without --relations" -- \
  "$MM" evaluate "$tmp/p.tum" --reference "$tmp/p.tum" --odometry "$raw"
check "the map's YAML matches its PGM" /usr/bin/python3 -c "
d = open('$tmp/m.yaml').read(); assert 'resolution: 0.05' in d and 'image: m.pgm' in d, d"

# Bad input: one line naming the file, exit 1, nothing written.
bzcat "$raw" | head -c 200000 >"$tmp/cut.clf"
printf 'FLASER 3 1 2\n' >>"$tmp/cut.clf"
head -c 5000 /dev/urandom >"$tmp/garbage.clf"
printf 'FLASER 180 nan\n' >"$tmp/nan.clf"
expect 1 "garbage.clf" -- "$MM" slam2d "$tmp/garbage.clf" --out-poses "$tmp/x.tum"
expect 1 "nan.clf" -- "$MM" slam2d "$tmp/nan.clf" --out-poses "$tmp/x.tum"
expect 1 "slam2d needs 2D laser scans" -- "$MM" slam2d "$DATA_DIR/kitti_odometry_00" --out-poses "$tmp/x.tum"
expect 2 "--out-map" -- "$MM" slam2d "$tmp/cut.clf" --out-map "$tmp/x.png"
expect 2 "--out-poses" -- "$MM" slam2d "$tmp/cut.clf" --out-poses "$tmp/cut.clf"
expect 2 "--loop-window" -- "$MM" slam2d "$tmp/cut.clf" --no-loop-closure --loop-window 3
expect 2 "--map-resolution" -- "$MM" slam2d "$tmp/cut.clf" --map-resolution 0
expect 2 "--max-range" -- "$MM" slam2d "$tmp/cut.clf" --max-range nan
bzcat "$raw" | grep -m 40 '^FLASER' >"$tmp/s40.clf"
awk '{for(i=3;i<=182;i++)$i="0"}1' "$tmp/s40.clf" >"$tmp/zero.clf"
awk 'NR==10{$186="1e300"}1' "$tmp/s40.clf" >"$tmp/odohuge.clf"
expect 1 "zero.clf: no beam within --max-range" -- "$MM" slam2d "$tmp/zero.clf" --out-map "$tmp/x.pgm"
expect 1 "odohuge.clf: line 10" -- "$MM" slam2d "$tmp/odohuge.clf" --out-poses "$tmp/x.tum"
expect 2 "--frames" -- "$MM" slam2d "$tmp/s40.clf" --frames "" --out-poses "$tmp/x.tum"
expect 2 "--out-poses" -- "$MM" slam2d "$tmp/s40.clf" --out-poses "$tmp/x.pcd"
expect 2 "unknown SLAM parameter 'loop_min_scor' (did you mean loop_min_score?)" -- \
  "$MM" slam2d "$tmp/s40.clf" --set loop_min_scor=0.5 --out-poses "$tmp/x.tum"
expect 2 "--set: prob_hit must be in (0.5, 1)" -- \
  "$MM" slam2d "$tmp/s40.clf" --set prob_hit=2 --out-poses "$tmp/x.tum"
expect 2 "--set: map_resolution must be in [0.0001, 1e3], got -1" -- \
  "$MM" slam2d "$tmp/s40.clf" --set map_resolution=-1 --out-poses "$tmp/x.tum"
expect 2 "--set: weak_direction_min_gain: 'nan' is not a finite number" -- \
  "$MM" slam2d "$tmp/s40.clf" --set weak_direction_min_gain=nan --out-poses "$tmp/x.tum"
expect 2 "--set: weak_direction_min_gain must be in [0, 1]" -- \
  "$MM" slam2d "$tmp/s40.clf" --set weak_direction_min_gain=2 --out-poses "$tmp/x.tum"
expect 2 "--set: weak_direction_weight must be in [0, 1e6]" -- \
  "$MM" slam2d "$tmp/s40.clf" --set weak_direction_weight=-1 --out-poses "$tmp/x.tum"
expect 2 "--set: map_prob_hit must be in (0.5, 1), got 0.2" -- \
  "$MM" slam2d "$tmp/s40.clf" --set map_prob_hit=0.2 --out-poses "$tmp/x.tum"
expect 2 "--set: scans_per_submap: 'x'" -- \
  "$MM" slam2d "$tmp/s40.clf" --set scans_per_submap=x --out-poses "$tmp/x.tum"
expect 2 "--set resolution and --resolution set the same parameter" -- \
  "$MM" slam2d "$tmp/s40.clf" --set resolution=0.1 --resolution 0.1 --out-poses "$tmp/x.tum"
expect 2 "--set: node_min_distance is given twice" -- "$MM" slam2d "$tmp/s40.clf" \
  --set node_min_distance=0 --set node_min_distance=1 --out-poses "$tmp/x.tum"
expect 2 "--set loop_min_overlap has no effect with --no-loop-closure" -- \
  "$MM" slam2d "$tmp/s40.clf" --no-loop-closure --set loop_min_overlap=0.2 --out-poses "$tmp/x.tum"
check "nothing written after a refusal" test ! -e "$tmp/x.tum" -a ! -e "$tmp/x.png" -a ! -e "$tmp/x.pgm" -a ! -e "$tmp/x.pcd"
"$MM" slam2d "$tmp/s40.clf" --format json >"$tmp/s40a.json"
"$MM" slam2d "$tmp/s40.clf" --format json --set node_min_distance=0 --set node_min_angle_deg=0 \
  >"$tmp/s40b.json"
check "--set reaches the SLAM: a motion filter of zero makes every scan a node" /usr/bin/python3 -c "
import json; a = json.load(open('$tmp/s40a.json')); b = json.load(open('$tmp/s40b.json'))
assert b['nodes'] == 40 and a['nodes'] < 40, (a['nodes'], b['nodes'])"
awk 'NR%2==0{sub(/^FLASER 180 /,"FLASER 181 ")}1' "$tmp/s40.clf" >"$tmp/mixed.clf"
"$MM" slam2d "$tmp/mixed.clf" --out-poses "$tmp/mixed.tum" >/dev/null 2>"$tmp/mixed.err"
check "lines with the wrong beam count: skipped and warned about" grep -q "mixed.clf: skipped 20 malformed" "$tmp/mixed.err"
check "... and the trajectory holds the 20 whole scans" test "$(wc -l <"$tmp/mixed.tum")" = 20
awk 'NR==10{$189="1e300"}1' "$tmp/s40.clf" >"$tmp/stamp.clf"
"$MM" slam2d "$tmp/stamp.clf" --out-poses "$tmp/stamp.tum" >/dev/null
check "a huge stamp is written whole (8 fields on every row)" \
  test "$(awk 'NF != 8' "$tmp/stamp.tum" | wc -l)" = 0
"$MM" slam2d "$tmp/cut.clf" --out-poses "$tmp/cut.tum" >"$tmp/cut.txt" 2>&1
check "a log cut mid-line: its whole scans mapped, the cut line skipped" grep -q "scans" "$tmp/cut.txt"
finish
