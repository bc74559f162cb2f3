#!/usr/bin/env bash
# metricmap odometry on sources other than KITTI: a hand-carried scanner's PCD folder at the
# defaults against its reference (the figures `evaluate` prints for the same files), the same
# scans as .npy files written by numpy and as a list file, TUM output, and the refusals of
# folders, stamps and pose files (one line, exit 1 or 2, no pose file written).
MM=$1
SHARED=$2
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
balm=$SHARED/balm_realworld_dev
out=$tmp/p.txt

"$MM" odometry "$balm" --out-poses "$out" --format json --threads 1 >"$tmp/run.json" 2>"$tmp/err"
check "the balm folder runs at the defaults" test $? -eq 0
check "40 KITTI rows" test "$(awk 'NF == 12' "$out" | wc -l)" -eq 40
check "median <= 1 cm, no frame above 5 cm or 1 deg, a coarse stage chosen" $PY -c "
import json; j = json.load(open('$tmp/run.json'))
r = j['rpe_per_frame']; s = j['settings']
assert r['translation_m']['median'] <= 0.010, r
assert r['translation_m']['max'] <= 0.05, r
assert r['rotation_deg']['max'] <= 1.0, r
assert s['profile'] == 'auto' and s['coarse_voxel_size'] > s['voxel_size'], s"
"$MM" evaluate "$out" --reference "$balm/poses.txt" --format json >"$tmp/eval.json"
check "evaluate prints the same per-frame figures" $PY -c "
import json
a = json.load(open('$tmp/run.json'))['rpe_per_frame']
e = json.load(open('$tmp/eval.json'))
def find(d):
    if isinstance(d, dict):
        if 'rpe' in d and isinstance(d['rpe'], dict): return d['rpe']
        for v in d.values():
            r = find(v)
            if r: return r
    return None
r = find(e); assert r, e.keys()
t = r.get('translation_m') or r.get('translation')
for k in ('rmse', 'median', 'max'):
    assert abs(a['translation_m'][k] - t[k]) < 1e-9, (k, a, t)"

# TUM rows with the folder's stamps.
"$MM" odometry "$balm" --frames 0-4 --out-poses "$tmp/tum.txt" --pose-format tum >/dev/null
check "TUM rows carry times.txt's stamps" $PY -c "
import numpy as np
t = np.loadtxt('$tmp/tum.txt'); s = np.loadtxt('$balm/times.txt')[:5]
assert t.shape == (5, 8) and np.allclose(t[:, 0], s, rtol=0, atol=1e-6), t[:, 0]
q = t[:, 4:8]; assert np.allclose(np.linalg.norm(q, axis=1), 1)"

# The same three scans as PCD, as numpy .npy (float32 x y z intensity) and as a list file.
mkdir -p "$tmp/pcd" "$tmp/npy"
for f in full60 full61 full62; do cp "$balm/$f.pcd" "$tmp/pcd/"; done
$PY -c "
import numpy as np, sys
for f in ('full60', 'full61', 'full62'):
    d = open('$balm/' + f + '.pcd', 'rb').read()
    i = d.index(b'DATA binary\n') + 12
    np.save('$tmp/npy/' + f + '.npy', np.frombuffer(d[i:], dtype=np.float32).reshape(-1, 4))"
printf '%s\n' pcd/full60.pcd pcd/full61.pcd pcd/full62.pcd >"$tmp/list.txt"
for src in pcd npy list.txt; do
  "$MM" odometry "$tmp/$src" --out-poses "$tmp/o_${src%.txt}.txt" >/dev/null 2>"$tmp/err"
  check "odometry on $src" test $? -eq 0
done
check "npy scans give the PCD scans' poses" cmp -s "$tmp/o_pcd.txt" "$tmp/o_npy.txt"
check "a list file gives the folder's poses" cmp -s "$tmp/o_pcd.txt" "$tmp/o_list.txt"

# Refusals: one line, nothing written.
mkdir -p "$tmp/empty" "$tmp/mixed" "$tmp/bad"
expect 1 "no .pcd, .ply, .bin or .npy scan" -- "$MM" odometry "$tmp/empty" --out-poses "$tmp/never.txt"
cp "$balm/full60.pcd" "$tmp/mixed/a.pcd"; cp "$tmp/npy/full61.npy" "$tmp/mixed/b.npy"
expect 1 "mixed scan formats" -- "$MM" odometry "$tmp/mixed" --out-poses "$tmp/never.txt"
for f in full60 full61 full62; do cp "$balm/$f.pcd" "$tmp/bad/"; done
printf '1\n2\n' >"$tmp/bad/times.txt"
expect 1 "2 stamp(s) for 3 scan(s)" -- "$MM" odometry "$tmp/bad" --out-poses "$tmp/never.txt"
printf '1\n3\n2\n' >"$tmp/bad/times.txt"
expect 1 "is not after the one before" -- "$MM" odometry "$tmp/bad" --out-poses "$tmp/never.txt"
printf '1\n2\n3\n' >"$tmp/bad/times.txt"
head -2 "$balm/poses.txt" >"$tmp/bad/poses.txt"
expect 1 "2 pose line(s) for 3 scan(s)" -- "$MM" odometry "$tmp/bad" --out-poses "$tmp/never.txt"
rm "$tmp/bad/poses.txt"
mkdir -p "$tmp/u8"
printf 'VERSION 0.7\nFIELDS x y z t\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n1 2 3 4\n' >"$tmp/u8/0.pcd"
expect 1 "time field 't'" -- "$MM" odometry "$tmp/u8" --out-poses "$tmp/never.txt"
expect 2 "--frames" -- "$MM" odometry "$tmp/bad" --frames 2,1 --out-poses "$tmp/never.txt"
expect 2 "--frames" -- "$MM" odometry "$tmp/bad" --frames 0,0 --out-poses "$tmp/never.txt"
expect 1 "frame 7 is beyond" -- "$MM" odometry "$tmp/bad" --frames 0,7 --out-poses "$tmp/never.txt"
expect 2 "--max-range" -- "$MM" odometry "$tmp/bad" --max-range 1e308
expect 2 "--voxel-size" -- "$MM" odometry "$tmp/bad" --voxel-size 1e-300
expect 2 "--voxel-size" -- "$MM" map "$tmp/bad" --poses odometry --voxel-size 1e5 --out-map "$tmp/never.pgm"
expect 2 "--profile" -- "$MM" odometry "$tmp/bad" --profile car
expect 2 "times.txt" -- "$MM" odometry "$tmp/bad" --out-poses "$tmp/bad/times.txt"
check "no pose file after any refusal" test ! -e "$tmp/never.txt"
check "the times file is intact" test "$(cat "$tmp/bad/times.txt" | wc -l)" -eq 3
finish
