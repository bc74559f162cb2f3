#!/usr/bin/env bash
# metricmap odometry: bad input and usage give one clear line and no pose file; a sequence
# without poses/ works; the pose file written has one 12-number line per frame.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
kr=$tmp/kitti
mkdir -p "$kr/sequences/00/velodyne" "$kr/poses"
for f in 000000 000001 000002; do
  ln -s "$DATA/kitti_odometry_00/sequences/00/velodyne/$f.bin" "$kr/sequences/00/velodyne/$f.bin"
done
cp "$DATA/kitti_odometry_00/sequences/00/calib.txt" "$kr/sequences/00/calib.txt"
out=$tmp/poses.txt

expect 2 "--frames" -- "$MM" odometry "$kr" --frames 3-1
expect 2 "--max-range" -- "$MM" odometry "$kr" --frames 0-1 --max-range nan
expect 2 "--min-range" -- "$MM" odometry "$kr" --frames 0-1 --min-range 200
for v in -1 1025 1.5 ""; do
  expect 2 "--threads" -- "$MM" odometry "$kr" --frames 0-1 --threads "$v"
done
expect 1 "frame 3 is beyond" -- "$MM" odometry "$kr" --frames 0-5 --out-poses "$out"
check "no pose file after a missing frame" test ! -e "$out"
: >"$kr/sequences/00/velodyne/000003.bin"
expect 1 "000003.bin" -- "$MM" odometry "$kr" --frames 0-3 --out-poses "$out"
check "no pose file after an empty scan" test ! -e "$out"
python3 -c "import struct,sys; sys.stdout.buffer.write(struct.pack('<4f', *([float('nan')]*4))*100)" \
  >"$kr/sequences/00/velodyne/000004.bin"
expect 1 "000004.bin" -- "$MM" odometry "$kr" --frames 0-2,4 --out-poses "$out"
check "no pose file after an all-NaN scan" test ! -e "$out"
mv "$kr/sequences/00/calib.txt" "$kr/calib.txt"
expect 1 "calib.txt" -- "$MM" odometry "$kr" --frames 0-1 --out-poses "$out"
mv "$kr/calib.txt" "$kr/sequences/00/calib.txt"

# No poses/ file at all: works, no comparison.
"$MM" odometry "$kr" --frames 0-2 --out-poses "$out" --format json >"$tmp/run.json" 2>"$tmp/err"
check "runs without a pose file" test $? -eq 0
check "three pose lines of 12 numbers" \
  test "$(awk 'NF == 12' "$out" | wc -l)" -eq 3
check "json has no pose-file comparison" grep -q '"pose_file": null' "$tmp/run.json"
for t in 1 3; do
  check "--threads $t runs" "$MM" odometry "$kr" --frames 0-2 --out-poses "$tmp/p$t.txt" --threads "$t"
done
check "the same poses for 1 and 3 threads" cmp -s "$tmp/p1.txt" "$tmp/p3.txt"
check "and for the default" cmp -s "$out" "$tmp/p1.txt"
check "about 0.7 m per frame" python3 -c "
import json; j = json.load(open('$tmp/run.json'))
s = [f['step'] for f in j['frames'][1:]]
assert all(0.6 < x < 0.8 for x in s), s"
finish
