#!/usr/bin/env bash
# metricmap occupancy and map on scan sources: a folder of scans with poses.txt is cast at its
# reference poses (the KITTI frames as such a folder give the voxels of `occupancy KITTI
# --world velodyne`); outputs may not replace a scan of the source, spelled any way.
MM=$1
DATA=$2
SHARED=$3
source "$(dirname "$0")/lib.sh"
k=$DATA/kitti_odometry_00
# The KITTI frames 0-2 as a plain folder, with the velodyne poses Tr^-1 P Tr (numpy).
mkdir -p "$tmp/kf"
cp "$k"/sequences/00/velodyne/00000[0-2].bin "$tmp/kf/"
/usr/bin/python3 -c "
import numpy as np
tr = [l for l in open('$k/sequences/00/calib.txt') if l.startswith('Tr:')][0].split()[1:]
Tr = np.eye(4); Tr[:3, :] = np.array(tr, float).reshape(3, 4)
P = np.loadtxt('$k/poses/00.txt')[:3].reshape(-1, 3, 4)
out = []
for p in P:
    T = np.eye(4); T[:3, :] = p
    out.append((np.linalg.inv(Tr) @ T @ Tr)[:3, :].reshape(12))
np.savetxt('$tmp/kf/poses.txt', np.array(out), fmt='%.17g')"
"$MM" occupancy "$tmp/kf" --resolution 0.2 --max-range 30 --out "$tmp/a.bt" --format json >"$tmp/a.json"
"$MM" occupancy "$k" --frames 0-2 --world velodyne --resolution 0.2 --max-range 30 \
  --out "$tmp/b.bt" --format json >"$tmp/b.json"
check "occupancy on a folder source = on the KITTI root (velodyne world)" /usr/bin/python3 -c "
import json
a = json.load(open('$tmp/a.json')); b = json.load(open('$tmp/b.json'))
assert a['frames'] == b['frames'] == 3 and a['points'] == b['points'], (a, b)
for key in ('known', 'occupied', 'free'):
    x, y = a['voxels'][key], b['voxels'][key]
    assert y > 1000 and abs(x - y) <= 1e-3 * y, (key, x, y)"
check "  and a .bt beside it" test -s "$tmp/a.bt"
expect 2 "--sequence" -- "$MM" occupancy "$tmp/kf" --resolution 0.2 --max-range 30 --sequence 01 --out "$tmp/x.bt"
expect 2 "--world" -- "$MM" occupancy "$tmp/kf" --resolution 0.2 --max-range 30 --world camera --out "$tmp/x.bt"
expect 1 "frame 7 is beyond" -- "$MM" occupancy "$tmp/kf" --resolution 0.2 --max-range 30 --frames 0,7 --out "$tmp/x.bt"
# outputs over a scan of the source (folder, list; any spelling) are refused, nothing replaced
cp "$tmp/kf/000001.bin" "$tmp/keep.bin"
expect 2 "000001.bin" -- "$MM" map "$tmp/kf" --out-cloud "$tmp/kf/000001.bin"
expect 2 "000001.bin" -- "$MM" map "$tmp/kf" --out-cloud "$tmp/kf/../kf/./000001.bin"
expect 2 "000001.bin" -- "$MM" occupancy "$tmp/kf" --resolution 0.2 --max-range 30 --out-cloud "$tmp/kf/000001.bin"
printf '%s\n' "$tmp/kf/000000.bin" "$tmp/kf/000001.bin" >"$tmp/list.txt"
expect 2 "000001.bin" -- "$MM" map "$tmp/list.txt" --reference "$tmp/kf/poses.txt" --out-cloud "$tmp/kf/000001.bin" 2>/dev/null
expect 2 "000001.bin" -- "$MM" odometry "$tmp/list.txt" --out-poses "$tmp/kf/000001.bin"
# options without effect, values a map file cannot hold
expect 2 "--pcd-format" -- "$MM" map "$tmp/kf" --out-map "$tmp/x.pgm" --pcd-format ascii
expect 2 "--pose-format" -- "$MM" odometry "$tmp/kf" --pose-format tum
expect 2 "--map-resolution" -- "$MM" map "$tmp/kf" --out-map "$tmp/x.pgm" --map-resolution 1001
expect 2 "--map-resolution" -- "$MM" map "$tmp/kf" --out-map "$tmp/x.pgm" --map-resolution 3e38
expect 2 "--voxel" -- "$MM" map "$tmp/kf" --out-cloud "$tmp/x.pcd" --voxel 1e39
check "the scan is unchanged" cmp -s "$tmp/keep.bin" "$tmp/kf/000001.bin"
check "nothing written after a refusal" test ! -e "$tmp/x.bt" -a ! -e "$tmp/x.pgm" -a ! -e "$tmp/x.pcd"
finish
