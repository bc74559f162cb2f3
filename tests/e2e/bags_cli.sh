#!/usr/bin/env bash
# ROS bags as sources: `info` on the real nebula VLP-16 rosbag2 bag and on the
# fixtures (table and json), `odometry` refusing a packet topic (exit 2 naming the type) and
# choosing among several scan topics (exit 2 listing them), odometry on the KITTI-frames bag
# equal to the KITTI layout's (camera-0 convention: Tr P Tr^-1), map and slam2d on bags, and
# hostile bags: one line naming the file, exit 1. Without --topic odometry takes the only
# PointCloud2 topic, slam2d the only LaserScan topic.
MM=$1
DATA=$2
SHARED=$3
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
BAGS=$(cd "$(dirname "$0")/../fixtures/bags" && pwd)
vlp=$SHARED/nebula_driver_samples/vlp16_bag

if has_shared_data "$vlp"; then
  "$MM" info "$vlp" >"$tmp/info.txt"
  check "info lists /velodyne_packets velodyne_msgs/msg/VelodyneScan 4" \
    grep -q "/velodyne_packets velodyne_msgs/msg/VelodyneScan 4 1673400471.837873222 1673400472.138016708 0.300143486" \
    <(tr -s ' ' <"$tmp/info.txt")
  "$MM" info "$vlp/1673400471837873222_0.db3" --format json >"$tmp/info.json"
  check "info json" $PY -c "
import json; j = json.load(open('$tmp/info.json'))
t = j[0]['topics'][0]
assert j[0]['format'] == 'rosbag2-sqlite3'
assert (t['topic'], t['type'], t['messages']) == ('/velodyne_packets', 'velodyne_msgs/msg/VelodyneScan', 4), t
assert t['start_ns'] == 1673400471837873222 and abs(t['duration_s'] - 0.300143486) < 1e-12, t"
  expect 2 "velodyne_msgs/msg/VelodyneScan" -- "$MM" odometry "$vlp"
  expect 2 "topic /velodyne_packets is of type velodyne_msgs/msg/VelodyneScan" -- \
    "$MM" odometry "$vlp" --topic /velodyne_packets
fi

for b in mixed.db3 mixed_lz4.mcap mixed_zstd_nosummary.mcap mixed_unchunked.mcap mixed_ros1_bz2.bag \
  mixed_ros1_lz4.bag; do
  "$MM" info "$BAGS/$b" --format csv >"$tmp/i.csv"
  check "info $b: 4 topics, /scan 40 messages over 3.9 s" $PY -c "
import csv; r = list(csv.DictReader(open('$tmp/i.csv')))
assert len(r) == 4, r
s = [x for x in r if x['topic'] == '/scan'][0]
assert s['type'] in ('sensor_msgs/msg/LaserScan', 'sensor_msgs/LaserScan'), s
assert s['messages'] == '40' and s['duration_s'] == '3.900000000', s"
  expect 2 "2 sensor_msgs/msg/PointCloud2 topics; choose one with --topic: /velodyne_points" -- \
    "$MM" odometry "$BAGS/$b"
  expect 2 "no topic /nope" -- "$MM" odometry "$BAGS/$b" --topic /nope
done
expect 2 "only a bag has topics" -- "$MM" odometry "$DATA/kitti_odometry_00" --topic /points

# Odometry: the KITTI-frames bag and the KITTI layout, the same three frames and settings (the
# bag in its first scan's frame: a bag's default world is levelled by its ground, KITTI's is
# camera 0's).
"$MM" odometry "$BAGS/kitti3_zstd.mcap" --profile kitti --world-frame first-scan \
  --out-poses "$tmp/bag.txt" >/dev/null
check "odometry on the bag runs" test $? -eq 0
"$MM" odometry "$DATA/kitti_odometry_00" --frames 0-2 --out-poses "$tmp/kitti.txt" >/dev/null
check "the bag's sensor poses are the KITTI layout's (camera 0: Tr P Tr^-1)" $PY -c "
import numpy as np
def rows(p): return [np.vstack([np.array(l.split(), float).reshape(3, 4), [0, 0, 0, 1]]) for l in open(p)]
tr = [l for l in open('$DATA/kitti_odometry_00/sequences/00/calib.txt') if l.startswith('Tr:')][0]
Tr = np.vstack([np.array(tr.split()[1:], float).reshape(3, 4), [0, 0, 0, 1]])
a, b = rows('$tmp/kitti.txt'), rows('$tmp/bag.txt')
assert len(a) == len(b) == 3
for x, y in zip(a, b):
    assert np.abs(x - Tr @ y @ np.linalg.inv(Tr)).max() < 1e-6, (x, y)
assert np.linalg.norm(b[2][:3, 3]) > 0.5"
"$MM" map "$BAGS/kitti3_zstd.mcap" --poses odometry --profile kitti --out-cloud "$tmp/map.pcd" >/dev/null
check "map on the bag writes its cloud" test -s "$tmp/map.pcd"
# occupancy on the bag at the KITTI reference poses (velodyne frame: Tr^-1 P Tr, full precision):
# the same .bt, byte for byte, as occupancy on the KITTI layout in the velodyne world.
$PY - "$DATA/kitti_odometry_00" "$tmp/velo.txt" <<'PYEOF'
import sys, numpy as np
root, out = sys.argv[1], sys.argv[2]
tr = [l for l in open(root + '/sequences/00/calib.txt') if l.startswith('Tr:')][0].split()[1:]
Tr = np.eye(4); Tr[:3, :] = np.array(tr, float).reshape(3, 4)
with open(out, 'w') as f:
    for r in np.loadtxt(root + '/poses/00.txt')[:3]:
        P = np.eye(4); P[:3, :] = r.reshape(3, 4)
        f.write(' '.join(repr(v) for v in (np.linalg.inv(Tr) @ P @ Tr)[:3, :].ravel()) + '\n')
PYEOF
"$MM" occupancy "$BAGS/kitti3_zstd.mcap" --reference "$tmp/velo.txt" --resolution 0.2 \
  --max-range 50 --out "$tmp/bag.bt" >/dev/null
"$MM" occupancy "$DATA/kitti_odometry_00" --frames 0-2 --world velodyne --resolution 0.2 \
  --max-range 50 --out "$tmp/kitti.bt" >/dev/null
check "occupancy from the bag equals occupancy from the KITTI layout" cmp "$tmp/bag.bt" "$tmp/kitti.bt"
expect 1 "no reference poses" -- "$MM" occupancy "$BAGS/kitti3_zstd.mcap" --resolution 0.2 \
  --max-range 50 --out "$tmp/never.bt"
expect 2 "--topic applies to a scan source" -- "$MM" occupancy "$DATA/kitti_odometry_00" \
  --frames 0 --topic /points --resolution 0.2 --max-range 50 --out "$tmp/never.bt"
check "nothing written after the refusals" test ! -e "$tmp/never.bt"
"$MM" slam2d "$BAGS/mixed.db3" --topic /scan --out-poses "$tmp/slam.txt" >/dev/null 2>"$tmp/slam.err"
check "slam2d on the LaserScan topic: 40 poses" test "$(wc -l <"$tmp/slam.txt")" -eq 40
"$MM" slam2d "$BAGS/mixed_ros1_lz4.bag" --out-poses "$tmp/slam1.txt" >/dev/null 2>&1
check "slam2d takes the only LaserScan topic of the ROS 1 bag: the same poses" \
  cmp "$tmp/slam.txt" "$tmp/slam1.txt"
expect 1 "needs 2D laser scans" -- "$MM" slam2d "$BAGS/mixed.db3" --topic /odd_cloud --out-poses "$tmp/x.txt"

# Hostile bags: one line naming the file, exit 1.
head -c 300000 "$BAGS/mixed_lz4.mcap" >"$tmp/cut.mcap"
expect 1 "$tmp/cut.mcap: truncated MCAP file" -- "$MM" odometry "$tmp/cut.mcap" --topic /velodyne_points
head -c 1000 /dev/urandom >"$tmp/garbage.mcap"
expect 1 "$tmp/garbage.mcap: not a bag" -- "$MM" info "$tmp/garbage.mcap"
head -c 350000 "$BAGS/mixed.db3" >"$tmp/half.db3"
expect 1 "$tmp/half.db3" -- "$MM" odometry "$tmp/half.db3" --topic /velodyne_points
$PY - "$BAGS/mixed_lz4.mcap" "$tmp/crc.mcap" <<'PYEOF'
import sys
b = bytearray(open(sys.argv[1], 'rb').read())
at = 8
while b[at] != 6:
    at += 9 + int.from_bytes(b[at + 1:at + 9], 'little')
b[at + 9 + 24] ^= 0x55  # the chunk's uncompressed CRC
open(sys.argv[2], 'wb').write(b)
PYEOF
expect 1 "chunk CRC mismatch" -- "$MM" odometry "$tmp/crc.mcap" --topic /velodyne_points
head -c 200000 "$BAGS/mixed_ros1_bz2.bag" >"$tmp/cut.bag"
expect 1 "$tmp/cut.bag: truncated ROS 1 bag" -- "$MM" odometry "$tmp/cut.bag" --topic /scan
finish
