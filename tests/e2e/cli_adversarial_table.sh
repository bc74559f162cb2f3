#!/usr/bin/env bash
# Issue 24: a table-driven adversarial pass over every command (bad numbers, bad paths, special
# files — /dev/null, /dev/full, FIFOs, directories —, truncated and garbage files, outputs equal
# to inputs, a report that cannot be printed). Every case keeps the promise of
# docs/RELIABILITY.md: exit 1 (2 for a usage error), exactly one line on stderr naming the file or
# value, nothing on stdout, no output or stray file, within 60 s. Prints the number of cases.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
SHARED=$(cd "$D/../../shared/data" 2>/dev/null && pwd || true)
k=$D/kitti_odometry_00
museo=$D/ua_mapas_metricos_pcd/museo000.pcd
milk=$D/pcl_test_pcd/milk.pcd
csv=$D/pythonrobotics_lidar01/lidar01.csv
mines=$D/breezyslam_mines_urg04lx/exp2.dat
tumd=$D/open3d_tum_depth/TUM_depth.png
tumrgb=$D/open3d_tum_depth/TUM_color.png
tumc=$D/open3d_tum_depth/camera_primesense.json
kin=$D/pcl_grabber_kinect_depth
kdepth=$kin/tiff/frame_20121214T142255.814212_depth.tiff
kxml=$kin/xml/frame_20121214T142255.814212.xml
bt=$D/octomap_geb079/geb079.bt
o=$tmp/o
in=$tmp/in
mkdir -p "$o" "$in"
cases=0

# adv CODE NEEDLE -- COMMAND...: one case. Besides `expect`'s checks, nothing may appear in $o.
adv() {
  local before=$fails
  cases=$((cases + 1))
  expect "$@"
  if [ -n "$(ls -A "$o")" ]; then
    [ "$fails" = "$before" ] && fails=$((fails + 1))
    echo "FAIL: left in the output folder: $(ls -A "$o" | head -5 | tr '\n' ' ')"
  fi
  rm -rf "${o:?}"/* "${o:?}"/.[!.]* 2>/dev/null
}

# ---------------------------------------------------------------- files to read
rnd() { head -c "$2" /dev/urandom >"$in/$1"; }
rnd garbage.pcd 300
rnd garbage.ply 300
rnd garbage.bin 301
rnd garbage.npy 300
rnd garbage.png 300
rnd garbage.tiff 300
rnd garbage.csv 300
rnd garbage.clf 300
rnd garbage.g2o 300
rnd garbage.json 300
rnd garbage.xml 300
rnd garbage.txt 300
rnd garbage.clf.bz2 300
rnd garbage.clf.gz 300
for e in pcd ply bin npy png tiff csv clf g2o json xml txt; do : >"$in/empty.$e"; done
mkdir -p "$in/dir.pcd" "$in/dir.ply" "$in/dir.png" "$in/dir.csv" "$in/dir.g2o" "$in/dir.txt" "$in/dir.json"
for e in pcd ply bin npy png csv clf g2o json txt; do mkfifo "$in/fifo.$e"; done
head -c 200 "$museo" >"$in/trunc.pcd"
head -c 1000 "$tumd" >"$in/trunc.png"
head -c 2000 "$kdepth" >"$in/trunc.tiff"
head -c 100 "$k/sequences/00/velodyne/000000.bin" >"$in/trunc.bin"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA binary\nxx' >"$in/huge.pcd"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\nnan nan nan\nnan nan nan\n' >"$in/allnan.pcd"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n' >"$in/short.pcd"
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 3 0 0 0\nPOINTS 1\nDATA ascii\n1 2 3\n' >"$in/vp3.pcd"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n' >"$in/short.ply"
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 1e39\n' >"$in/big.ply"
python3 - "$in" <<'EOF'
import struct, sys
d = sys.argv[1]
def npy(name, descr, shape, payload):
    hdr = "{'descr': '%s', 'fortran_order': False, 'shape': %s, }" % (descr, shape)
    hdr += ' ' * (64 - (10 + len(hdr) + 1) % 64) + '\n'
    with open(d + '/' + name, 'wb') as f:
        f.write(b'\x93NUMPY\x01\x00' + struct.pack('<H', len(hdr)) + hdr.encode() + payload)
npy('trunc.npy', '<f4', '(100, 3)', b'\0' * 40)
npy('int.npy', '<i4', '(2, 3)', b'\0' * 24)
npy('onecol.npy', '<f4', '(4, 1)', b'\0' * 16)
npy('big_endian.npy', '>f4', '(2, 3)', b'\0' * 24)
npy('nan.npy', '<f4', '(2, 3)', struct.pack('<6f', *[float('nan')] * 6))
npy('huge.npy', '<f4', '(4000000000, 3)', b'\0' * 24)
EOF
printf '0,1\nabc,2\n' >"$in/word.csv"
printf '0,1\n0.1\n' >"$in/onefield.csv"
printf '0,-1\n0.1,0\n' >"$in/noreturn.csv"
printf 'FLASER 3 1 2\n' >"$in/cut.clf"
printf 'FLASER 1e20 1 2 3\n' >"$in/count.clf"
printf 'FLASER 3 1 2 3 0 0 0 0 0 0 1.5 host\n' >"$in/tail.clf"
printf 'VERTEX_SE2 0 0 0 0\nEDGE_SE2 0 7 1 0 0 1 0 0 1 0 1\n' >"$in/dangling.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 0 1 0 0\nEDGE_SE2 0 0 1 0 0 1 0 0 1 0 1\n' >"$in/dupvertex.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 nan 0 0 1 0 1\n' >"$in/naninfo.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 -1 0 0 1 0 1\n' >"$in/negative_info.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0\n' >"$in/short_edge.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1e300 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n' >"$in/far.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\n' >"$in/noedge.g2o"
printf 'VERTEX_XYZ 0 0 0 0\n' >"$in/unknown.g2o"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n3 3 1 0 0 0 0 1\n' >"$in/est.txt"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n0.5 2 0 0 0 0 0 1\n' >"$in/backwards.txt"
printf '0 0 0 0 0 0 0 2\n1 1 0 0 0 0 0 1\n' >"$in/quat.txt"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1 9\n' >"$in/ninetok.txt"
printf '0 0 0 0 0 0 0 1\n1 abc 0 0 0 0 0 1\n' >"$in/word.txt"
printf '1 0 0 0 0 1 0 0 0 0 1 0\n0 0 0 0 0 0 0 0 0 0 0 0\n' >"$in/kitti_zero.txt"
printf '0 1 1 0 0 0 0 0\n0 1 1 0 0 0 0 0\n' >"$in/rel_dup.txt"
printf '1 1 1 0 0 0 0 0\n' >"$in/rel_same.txt"
printf '0 1 1 0 0\n' >"$in/rel_short.txt"
awk 'BEGIN { srand(4); for (i = 0; i < 10; ++i) printf "%d %d %.9f %.9f 0 0 0 1\n", i, i, (rand() - 0.5) * 1e-4, (rand() - 0.5) * 1e-4 }' >"$in/line_ref.txt"
awk 'BEGIN { srand(5); for (i = 0; i < 10; ++i) printf "%d %d %.9f %.9f 0 0 0 1\n", i, i, (rand() - 0.5) * 1e-4, (rand() - 0.5) * 1e-4 }' >"$in/line_est.txt"
printf '{"fx": "abc"}' >"$in/word.json"
printf '%0.s[' $(seq 1 100) >"$in/deep.json"
printf '<a><b>' >"$in/open.xml"
# scan sources
mkdir -p "$in/emptydir" "$in/garbage_scans" "$in/zero_scans"
rnd garbage_scans/000.pcd 200
rnd garbage_scans/001.pcd 200
python3 - "$in/zero_scans" <<'EOF'
import struct, sys
hdr = "{'descr': '<f4', 'fortran_order': False, 'shape': (200, 3), }"
hdr += ' ' * (64 - (10 + len(hdr) + 1) % 64) + '\n'
for n in ('000.npy', '001.npy'):
    with open(sys.argv[1] + '/' + n, 'wb') as f:
        f.write(b'\x93NUMPY\x01\x00' + struct.pack('<H', len(hdr)) + hdr.encode() + b'\0' * 2400)
EOF
printf '%s\n' "$in/nothere.pcd" >"$in/list_missing.txt"
printf '%s\n%s\n' "$museo" "$museo" >"$in/list_twice.txt"
printf '%s\nnot a scan\n' "$museo" >"$in/list_word.txt"
# a KITTI copy with its calib, poses and one scan damaged (the other scans linked)
kc() {  # kc NAME: a KITTI root whose velodyne scans link to the data's
  mkdir -p "$in/$1/sequences/00/velodyne" "$in/$1/poses"
  for f in "$k"/sequences/00/velodyne/*.bin; do ln -sf "$f" "$in/$1/sequences/00/velodyne/"; done
  cp "$k/sequences/00/calib.txt" "$k/sequences/00/times.txt" "$in/$1/sequences/00/"
  cp "$k/poses/00.txt" "$in/$1/poses/"
}
kc k_calib && grep -v '^Tr' "$k/sequences/00/calib.txt" >"$in/k_calib/sequences/00/calib.txt"
kc k_calib2 && rnd k_calib2/sequences/00/calib.txt 200
kc k_poses && head -c 300 "$k/poses/00.txt" >"$in/k_poses/poses/00.txt"
kc k_posesword && sed '2s/^[^ ]*/abc/' "$k/poses/00.txt" >"$in/k_posesword/poses/00.txt"
kc k_scan && rm "$in/k_scan/sequences/00/velodyne/000001.bin" && head -c 7 "$k/sequences/00/velodyne/000001.bin" >"$in/k_scan/sequences/00/velodyne/000001.bin"
kc k_times && printf '0\n0\n' >"$in/k_times/sequences/00/times.txt"
kc k_ok
cp "$museo" "$in/museo.pcd"
cp "$csv" "$in/lidar.csv"
cp "$in/est.txt" "$in/est_copy.txt"
cp "$tumd" "$in/hm_obstacles.png"
printf '%s\n%s\n' "$in/museo.pcd" "$milk" >"$in/pcd_list.txt"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n' >"$in/one_edge.g2o"

# ---------------------------------------------------------------- 1. unreadable cloud inputs
clouds=(missing.pcd dir.pcd fifo.pcd fifo.ply empty.pcd empty.ply empty.bin empty.npy garbage.pcd
  garbage.ply garbage.bin garbage.npy trunc.pcd trunc.bin trunc.npy huge.pcd huge.npy allnan.pcd
  short.pcd short.ply big.ply vp3.pcd int.npy onecol.npy big_endian.npy nan.npy garbage.txt)
for f in "${clouds[@]}"; do
  adv 1 "$f" -- "$MM" info "$in/$f"
  adv 1 "$f" -- "$MM" grid "$in/$f" --cell-size 1 --out "$o/g.pcd"
  adv 1 "$f" -- "$MM" octree "$in/$f" --max-points 100 --min-cell-size 0.5 --out "$o/t.pcd"
done
for f in missing.pcd fifo.pcd garbage.pcd trunc.pcd garbage.npy vp3.pcd; do
  adv 1 "$f" -- "$MM" compare "$museo" "$in/$f"
  adv 1 "$f" -- "$MM" occupancy "$in/$f" --resolution 0.5 --max-range 20 --out "$o/a.bt"
done
adv 1 "/dev/null" -- "$MM" info /dev/null
adv 1 "/dev/zero" -- "$MM" grid /dev/zero --cell-size 1

# ---------------------------------------------------------------- 2. scan logs
for f in missing.csv dir.csv fifo.csv fifo.clf empty.csv empty.clf garbage.csv garbage.clf \
  garbage.clf.bz2 garbage.clf.gz word.csv onefield.csv noreturn.csv cut.clf count.clf tail.clf; do
  adv 1 "$f" -- "$MM" lines "$in/$f"
done
adv 1 "garbage.clf" -- "$MM" lines "$in/garbage.clf" --all --format json
adv 1 "empty.txt" -- "$MM" lines "$in/empty.txt" --preset urg04lx-mines

# ---------------------------------------------------------------- 3. images and cameras
for f in missing.png dir.png fifo.png empty.png garbage.png trunc.png garbage.tiff trunc.tiff; do
  adv 1 "$f" -- "$MM" depth-to-cloud "$in/$f" --camera "$tumc" --out "$o/c.pcd"
  adv 1 "$f" -- "$MM" heightmap "$in/$f" --camera "$tumc" --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$o/hm"
done
adv 1 "TUM_color.png" -- "$MM" depth-to-cloud "$tumrgb" --camera "$tumc" --out "$o/c.pcd"
for f in missing.json dir.json fifo.json empty.json garbage.json word.json deep.json garbage.xml open.xml empty.xml; do
  adv 1 "$f" -- "$MM" depth-to-cloud "$tumd" --camera "$in/$f" --out "$o/c.pcd"
  adv 1 "$f" -- "$MM" heightmap "$tumd" --camera "$in/$f" --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$o/hm"
done
adv 1 "garbage.png" -- "$MM" depth-to-cloud "$tumd" --rgb "$in/garbage.png" --camera "$tumc" --out "$o/c.pcd"

# ---------------------------------------------------------------- 4. scan sources
for s in missing emptydir garbage_scans zero_scans list_missing.txt list_word.txt empty.txt \
  garbage.clf empty.clf fifo.clf dir.txt; do
  adv 1 "$s" -- "$MM" odometry "$in/$s"
  adv 1 "$s" -- "$MM" map "$in/$s" --poses odometry --out-cloud "$o/c.pcd"
done
adv 1 "list_twice.txt: line 2" -- "$MM" odometry "$in/list_twice.txt"
adv 1 "list_twice.txt: line 2" -- "$MM" occupancy "$in/list_twice.txt" --resolution 0.5 --max-range 20 --out "$o/a.bt"
adv 1 "Tr" -- "$MM" kitti "$in/k_calib" --frames 0-1
adv 1 "calib.txt" -- "$MM" kitti "$in/k_calib2" --frames 0-1
adv 1 "00.txt" -- "$MM" kitti "$in/k_poses" --frames 0-5
adv 1 "00.txt" -- "$MM" kitti "$in/k_posesword" --frames 0-5
adv 1 "000001.bin" -- "$MM" kitti "$in/k_scan" --frames 0-1
adv 1 "000001.bin" -- "$MM" odometry "$in/k_scan" --frames 0-1
adv 1 "000001.bin" -- "$MM" occupancy "$in/k_scan" --frames 0-1 --resolution 0.5 --max-range 20 --out "$o/a.bt"
adv 1 "times.txt" -- "$MM" odometry "$in/k_times" --frames 0-1
adv 1 "00.txt" -- "$MM" map "$in/k_poses" --frames 0-5 --out-map "$o/m.pgm"
adv 1 "frame 6 is beyond" -- "$MM" odometry "$k" --frames 6
adv 1 "missing" -- "$MM" kitti "$in/missing" --frames 0
adv 1 "no cell has --min-hits 1000000 points" -- "$MM" kitti "$k" --frames 0-1 --min-hits 1000000 --out-map "$o/m.pgm"

# ---------------------------------------------------------------- 5. graphs and trajectories
for f in missing.g2o dir.g2o fifo.g2o empty.g2o garbage.g2o dangling.g2o dupvertex.g2o naninfo.g2o \
  negative_info.g2o short_edge.g2o far.g2o noedge.g2o unknown.g2o; do
  adv 1 "$f" -- "$MM" posegraph "$in/$f" --out "$o/p.g2o"
done
for f in missing.txt dir.txt fifo.txt empty.txt garbage.txt backwards.txt quat.txt ninetok.txt word.txt; do
  adv 1 "$f" -- "$MM" evaluate "$in/$f" --reference "$in/est.txt"
  adv 1 "$f" -- "$MM" evaluate "$in/est.txt" --reference "$in/$f"
done
adv 1 "kitti_zero.txt: line 2" -- "$MM" evaluate "$in/kitti_zero.txt" --reference "$in/kitti_zero.txt"
for f in rel_dup.txt rel_same.txt rel_short.txt garbage.txt empty.txt fifo.txt; do
  adv 1 "$f" -- "$MM" evaluate "$in/est.txt" --relations "$in/$f"
done
adv 1 "nearly collinear" -- "$MM" evaluate "$in/line_est.txt" --reference "$in/line_ref.txt"

# ---------------------------------------------------------------- 6. bad numbers in options
floats=(nan inf -inf 1e999 0x10 abc "" "1 2" 1, 1e-320)
num() {  # num OPTION COMMAND...: every bad float value for OPTION, appended last
  local opt=$1
  shift
  local v
  for v in "${floats[@]}"; do adv 2 "$opt" -- "$MM" "$@" "$opt" "$v"; done
}
num --cell-size grid "$museo"
num --min-cell-size octree "$museo" --max-points 100
num --resolution occupancy "$museo" --max-range 20 --out "$o/a.bt"
num --distance-threshold lines "$csv"
num --map-resolution kitti "$k" --frames 0 --out-map "$o/m.pgm"
num --voxel-size odometry "$k" --frames 0-1
num --max-range map "$k" --poses odometry --out-cloud "$o/c.pcd"
num --loss-scale posegraph "$in/noedge.g2o"
num --max-time-diff evaluate "$in/est.txt" --reference "$in/est.txt"
num --resolution heightmap "$tumd" --camera "$tumc" --auto-floor --map-size 100 --z-bins 0.1,1 --out-prefix "$o/hm"
counts=(-1 1.5 010 18446744073709551616 abc "" 0x10)
cnt() {
  local opt=$1
  shift
  local v
  for v in "${counts[@]}"; do adv 2 "$opt" -- "$MM" "$@" "$opt" "$v"; done
}
cnt --max-points octree "$museo" --min-cell-size 0.5
cnt --scan lines "$csv"
cnt --min-hits kitti "$k" --frames 0 --out-map "$o/m.pgm"
cnt --max-iterations posegraph "$in/noedge.g2o"
cnt --threads odometry "$k" --frames 0-1
for v in 010 0,0 1,0 0-1, ,0 abc 0--1 99999999999; do
  adv 2 "--frames" -- "$MM" odometry "$k" --frames "$v"
done

# ---------------------------------------------------------------- 7. outputs
outs() {  # outs OPTION EXT COMMAND...: bad destinations for OPTION
  local opt=$1 ext=$2
  shift 2
  adv 1 "$o/nodir/x.$ext" -- "$MM" "$@" "$opt" "$o/nodir/x.$ext"
  mkdir -p "$tmp/isdir.$ext"
  adv 1 "isdir.$ext" -- "$MM" "$@" "$opt" "$tmp/isdir.$ext"
  adv 2 "/dev/full" -- "$MM" "$@" "$opt" /dev/full  # no extension: refused first
  ln -sf /dev/full "$tmp/devfull.$ext"
  adv 1 "devfull.$ext" -- "$MM" "$@" "$opt" "$tmp/devfull.$ext"
  [ -p "$tmp/ofifo.$ext" ] || mkfifo "$tmp/ofifo.$ext"
  adv 1 "ofifo.$ext" -- "$MM" "$@" "$opt" "$tmp/ofifo.$ext"
  adv 2 "$opt" -- "$MM" "$@" "$opt" ""
  adv 2 "$opt" -- "$MM" "$@" "$opt" "$o/x.wrong"
}
outs --out pcd grid "$in/museo.pcd" --cell-size 1
outs --cells csv grid "$in/museo.pcd" --cell-size 1
outs --out pcd octree "$in/museo.pcd" --max-points 100 --min-cell-size 0.5
outs --out pcd depth-to-cloud "$tumd" --camera "$tumc"
outs --out bt occupancy "$in/museo.pcd" --resolution 0.5 --max-range 20
outs --out-map pgm kitti "$k" --frames 0
outs --out-poses txt odometry "$k" --frames 0-1
outs --out g2o posegraph "$SHARED/posegraph_g2o/MIT.g2o"
outs --svg svg lines "$csv"
outs --out md compare "$museo" --format markdown
# an output naming an input, however spelled
same() {  # same NEEDLE COMMAND...: exit 2, the input unchanged
  local needle=$1
  shift
  adv 2 "$needle" -- "$MM" "$@"
}
same "the same file" grid "$in/museo.pcd" --cell-size 1 --out "$in/museo.pcd"
same "the same file" grid "$in/museo.pcd" --cell-size 1 --out "$in/../in/museo.pcd"
same "the same file" octree "$in/museo.pcd" --max-points 100 --min-cell-size 0.5 --out "$in/./museo.pcd"
same "the same file" occupancy "$in/museo.pcd" --resolution 0.5 --max-range 20 --out "$o/a.bt" --out-cloud "$in/museo.pcd"
same "the same file" odometry "$in/k_ok" --frames 0-1 --out-poses "$in/k_ok/poses/00.txt"
same "the same file" kitti "$in/k_ok" --frames 0-1 --out-poses "$in/k_ok/poses/00.txt"
same "the same file" map "$in/pcd_list.txt" --poses odometry --out-cloud "$in/museo.pcd"
same "the same file" posegraph "$in/one_edge.g2o" --out "$in/./one_edge.g2o"
same "the same file" heightmap "$in/hm_obstacles.png" --camera "$tumc" --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$in/hm"
same "both write" grid "$in/museo.pcd" --cell-size 1 --out "$o/a.pcd" --cells "$o/../o/a.pcd"
check "inputs unchanged" cmp -s "$in/museo.pcd" "$museo"
check "poses unchanged" cmp -s "$in/k_ok/poses/00.txt" "$k/poses/00.txt"

# ---------------------------------------------------------------- 8. the report cannot be printed
full() {  # full COMMAND...: stdout /dev/full: exit 1, nothing committed
  cases=$((cases + 1))
  local rc=0
  timeout 60 "$MM" "$@" >/dev/full 2>"$tmp/err" || rc=$?
  if [ "$rc" != 1 ] || ! grep -q "cannot write to standard output" "$tmp/err" || [ -n "$(ls -A "$o")" ]; then
    echo "FAIL: $* > /dev/full -> exit $rc, $(head -c 200 "$tmp/err"), left: $(ls -A "$o" | tr '\n' ' ')"
    fails=$((fails + 1))
  else
    echo "ok: > /dev/full: $*"
  fi
  rm -rf "${o:?}"/*
}
full grid "$museo" --cell-size 1 --out "$o/g.pcd"
full octree "$museo" --max-points 100 --min-cell-size 0.5 --leaves "$o/l.csv"
full kitti "$k" --frames 0 --out-map "$o/m.pgm"
full odometry "$k" --frames 0-1 --out-poses "$o/p.txt"
full occupancy "$museo" --resolution 0.5 --max-range 20 --out "$o/a.bt"
full lines "$csv" --svg "$o/l.svg"
full depth-to-cloud "$tumd" --camera "$tumc" --out "$o/c.pcd"
full compare "$museo" --format markdown  # (with --out the table goes to the file: nothing to print)
# a plot without an X display: the error names the destination, never its temporary
adv 1 "$o/p.svg: plotting needs an X display" -- env -u DISPLAY "$MM" compare "$museo" --plot "$o/p.svg"
full heightmap "$tumd" --camera "$tumc" --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$o/hm"
full info "$museo"

echo "$cases cases"
finish
