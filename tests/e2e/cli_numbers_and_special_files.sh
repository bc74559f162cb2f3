#!/usr/bin/env bash
# The fifth adversarial pass on the command line, table-driven: tiny beam cuts (a segfault and a
# hang), FIFOs named like bags (every reader blocked), a given --min-range replaced by the
# profile's, huge poses and angles, float64 values beyond float32, depths underflowing to 0, grid
# cells finer than float32 resolves, special entries in scan folders, a run's memory over the
# budget, PCD headers with WIDTH 0 HEIGHT 0. Every refusal: one line naming the file or value,
# exit 1 (2 for usage), nothing on stdout, nothing written, within 60 s.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
SHARED=$(cd "$D/../../shared/data" 2>/dev/null && pwd || true)
museo=$D/ua_mapas_metricos_pcd/museo000.pcd
tumd=$D/open3d_tum_depth/TUM_depth.png
tumc=$D/open3d_tum_depth/camera_primesense.json
o=$tmp/o
in=$tmp/in
mkdir -p "$o" "$in"
cases=0

# case CODE NEEDLE ARGS...: one refusal; nothing may appear in $o.
case_() {
  local before=$fails
  cases=$((cases + 1))
  expect "$1" "$2" -- "$MM" "${@:3}"
  if [ -n "$(ls -A "$o")" ]; then
    [ "$fails" = "$before" ] && fails=$((fails + 1))
    echo "FAIL: left in the output folder: $(ls -A "$o" | head -5 | tr '\n' ' ')"
  fi
  rm -rf "${o:?}"/* 2>/dev/null
}

# ------------------------------------------------------------------ inputs
/usr/bin/python3 - "$in" <<'PY'
import math, os, sys
import numpy as np
d = sys.argv[1]
ring = lambda r, n=400: np.array([[r * math.cos(2 * math.pi * i / n), r * math.sin(2 * math.pi * i / n),
                                   0.1 * (i % 7)] for i in range(n)], np.float32)
os.makedirs(f'{d}/scans')
for k in range(3):
    np.save(f'{d}/scans/00{k}.npy', ring(8.0))
# float64 scans with a value no float holds, in x and in the intensity column
a = ring(8.0).astype(np.float64); a[5, 0] = 1e300
os.makedirs(f'{d}/big64'); np.save(f'{d}/big64/000.npy', a); np.save(f'{d}/big64.npy', a)
b = np.hstack([ring(8.0).astype(np.float64), np.ones((400, 1))]); b[7, 3] = -1e300
os.makedirs(f'{d}/bigi'); np.save(f'{d}/bigi/000.npy', b)
np.save(f'{d}/fine64.npy', np.hstack([ring(8.0).astype(np.float64), np.full((400, 1), 3e38)]))
# a cloud at 1e7 m
with open(f'{d}/far.pcd', 'w') as f:
    f.write('VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n'
            'POINTS 2\nDATA ascii\n10000000 0 0\n10000001 0 0\n')
# CARMEN logs: a short one; one whose odometry jumps 100 m per scan
def flaser(f, k, x):
    rs = ' '.join('%.3f' % (4.0 + 0.5 * math.sin(i * 0.2)) for i in range(180))
    f.write('FLASER 180 %s %.3f 0 0 %.3f 0 0 %.3f host %.3f\n' % (rs, x, x, 1 + 0.1 * k, 1 + 0.1 * k))
with open(f'{d}/short.clf', 'w') as f:
    for k in range(5): flaser(f, k, 0.05 * k)
with open(f'{d}/jumps.clf', 'w') as f:
    for k in range(120): flaser(f, k, 100.0 * k)
# g2o graphs and relations beyond the bounds
edge = ' 1 0 0 1 0 1\n'
open(f'{d}/far.g2o', 'w').write('VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1e30 0 0\nEDGE_SE2 0 1 1 0 0' + edge)
open(f'{d}/turn.g2o', 'w').write('VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 1e17' + edge)
open(f'{d}/yaw.txt', 'w').write('0 1 0 0 0 0 0 1e30\n')
open(f'{d}/est.txt', 'w').write(''.join('%d %d 0 0 0 0 0 1\n' % (k, k) for k in range(3)))
PY
for e in mcap db3 bag MCAP; do mkfifo "$in/fifo.$e"; done

# ------------------------------------------------------------------ class: tiny beam cuts
case_ 2 "max_range must be >= 0.001 m (infinity: no cut), got 1e-30" occupancy "$museo" --resolution 0.1 --max-range 1e-30 --out "$o/x.bt"
case_ 2 "max_range must be >= 0.001 m" occupancy "$museo" --resolution 0.1 --max-range 1e-23 --out "$o/x.bt"
case_ 2 "got 0.0005" occupancy "$museo" --resolution 0.1 --max-range 0.0005 --out "$o/x.bt"
case_ 2 "map_max_range must be >= 0.001 m" slam2d "$in/short.clf" --set map_max_range=1e-30 --out-poses "$o/p.tum"
case_ 2 "map_max_range" slam2d "$in/short.clf" --set map_max_range=1e-23 --out-poses "$o/p.tum"
check "occupancy with --max-range 0.001 runs" "$MM" occupancy "$museo" --resolution 0.1 --max-range 0.001 --out "$o/x.bt"
rm -f "$o"/*
check "slam2d with map_max_range=0.001 runs" "$MM" slam2d "$in/short.clf" --set map_max_range=0.001 --out-poses "$o/p.tum"
rm -f "$o"/*

# ------------------------------------------------------------------ class: FIFOs named like bags
for e in mcap db3 bag MCAP; do
  f=$in/fifo.$e
  case_ 1 "not a regular file: a FIFO" info "$f"
  case_ 1 "not a regular file: a FIFO" odometry "$f" --out-poses "$o/p.txt"
  case_ 1 "not a regular file: a FIFO" map "$f" --poses odometry --out-cloud "$o/c.pcd"
  case_ 1 "not a regular file: a FIFO" slam2d "$f" --out-poses "$o/p.tum"
  case_ 1 "not a regular file: a FIFO" occupancy "$f" --resolution 0.1 --max-range 10 --out "$o/x.bt"
done

# ------------------------------------------------------------------ class: a given value replaced
case_ 1 "min_range 50 m (given) is not below the max_range 10.0281 m chosen from the first scan's ranges" odometry "$in/scans" --min-range 50 --out-poses "$o/p.txt"
case_ 1 "min_range 10.03 m (given)" odometry "$in/scans" --min-range 10.03 --out-poses "$o/p.txt"
case_ 1 "min_range 50 m (given)" map "$in/scans" --poses odometry --min-range 50 --out-cloud "$o/c.pcd"
case_ 2 "--min-range '2' must be below --max-range '1'" odometry "$in/scans" --min-range 2 --max-range 1 --out-poses "$o/p.txt"

# ------------------------------------------------------------------ class: huge poses and angles
case_ 1 "far.g2o: line 2: a translation of 1e+30 m is beyond" posegraph "$in/far.g2o" --out "$o/g.g2o"
case_ 1 "turn.g2o: line 3: theta 1e+17 rad is beyond" posegraph "$in/turn.g2o" --out "$o/g.g2o"
case_ 1 "yaw.txt: line 1: yaw '1e30' is beyond" evaluate "$in/est.txt" --relations "$in/yaw.txt"

# ------------------------------------------------------------------ class: beyond float32, underflow
case_ 1 "row 5 column 0 (x) holds 1e+300" odometry "$in/big64" --out-poses "$o/p.txt"
case_ 1 "row 7 column 3 (i) holds -1e+300" odometry "$in/bigi" --out-poses "$o/p.txt"
case_ 1 "row 5 column 0 (x) holds 1e+300" info "$in/big64.npy"
case_ 1 "row 5 column 0 (x) holds 1e+300" grid "$in/big64.npy" --cell-size 1
check "a float64 intensity of 3e38 (a float) is read" "$MM" info "$in/fine64.npy"
case_ 1 "below float range" depth-to-cloud "$tumd" --camera "$tumc" --depth-scale 1e-300 --out "$o/c.pcd"
case_ 1 "below float range" depth-to-cloud "$tumd" --camera "$tumc" --depth-scale 1e-42 --out "$o/c.pcd"

# ------------------------------------------------------------------ class: cells finer than float32
case_ 1 "cell size 0.1 is finer than float32 resolves" grid "$in/far.pcd" --cell-size 0.1
case_ 1 "is finer than float32 resolves" grid "$in/far.pcd" --cell-size 1
check "a 16 m cell at 1e7 m is resolved" "$MM" grid "$in/far.pcd" --cell-size 16

# ------------------------------------------------------------------ class: special entries in folders
for kind in dir fifo dangling loop dirlink; do
  f=$tmp/folder_$kind
  mkdir -p "$f"
  cp "$in"/scans/*.npy "$f/"
  case $kind in
    dir) mkdir "$f/004.npy"; what="a directory" ;;
    fifo) mkfifo "$f/004.pcd"; what="a FIFO" ;;
    dangling) ln -s "$f/missing" "$f/004.bin"; what="a dangling link" ;;
    loop) ln -s "$f/004.ply.b" "$f/004.ply"; ln -s "$f/004.ply" "$f/004.ply.b"; what="a symbolic link loop" ;;
    dirlink) mkdir "$f/target"; ln -s "$f/target" "$f/004.NPY"; what="a directory" ;;
  esac
  case_ 1 "is named like a scan but is $what" odometry "$f" --out-poses "$o/p.txt"
  case_ 1 "is named like a scan but is $what" map "$f" --poses odometry --out-cloud "$o/c.pcd"
  case_ 1 "is named like a scan but is $what" occupancy "$f" --resolution 0.5 --max-range 20 --out "$o/a.bt"
done

# ------------------------------------------------------------------ class: a run's memory budget
# 120 scans whose odometry jumps 100 m each: a 1.3 GB peak under --max-memory 512M before every
# grid was priced beside the others. Now refused, and the peak stays near the budget.
/usr/bin/time -f %M -o "$tmp/rss" "$MM" --max-memory 256M slam2d "$in/jumps.clf" \
  --out-poses "$o/p.tum" >"$tmp/out" 2>"$tmp/err"
rc=$?
rss=$(tail -1 "$tmp/rss")
echo "slam2d --max-memory 256M on 100 m jumps: exit $rc, peak $((rss / 1024)) MiB: $(cat "$tmp/err")"
check "refused (exit 1, one line naming the budget)" test "$rc" = 1 -a "$(wc -l <"$tmp/err")" = 1
check "the message names what was held" grep -q "beside the .* already held, more than the memory budget of 256 MiB" "$tmp/err"
check "peak within the budget plus the process's own 150 MiB" test "$rss" -lt $(((256 + 150) * 1024))
check "nothing written" test -z "$(ls -A "$o")"

# ------------------------------------------------------------------ class: WIDTH 0 HEIGHT 0
hdr=$SHARED/nclt_2013_01_10_keyframes/original_headers/0.pcd
if [ -f "$hdr" ]; then
  "$MM" info "$hdr" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  echo "info on a WIDTH 0 HEIGHT 0 header: exit $rc: $(cat "$tmp/err")"
  check "read, one warning line" test "$rc" = 0 -a "$(wc -l <"$tmp/err")" = 1
  check "the warning says how it was read" grep -q "header says WIDTH 0 HEIGHT 0 but POINTS 1934: read as an unorganised cloud of 1934 points" "$tmp/err"
  check "1934 points reported" grep -q "1934" "$tmp/out"
else
  echo "skip: $hdr missing"
fi

# ------------------------------------------------------------------ class: huge angles in scan logs
# A FLASER line whose laser or odometry heading is 1e17 rad (a double's spacing there is 16 rad)
# and a CSV scan whose bearing is 1e300 were read as some other heading.
intel=$D/radish_clf_raw/intel.clf.bz2
bzcat "$intel" | head -40 | awk '/^FLASER/ && !done { n=$2; $(5+n)="1e17"; done=1 } {print}' >"$in/theta.clf"
printf '1e300,0.5\n0.1,0.6\n0.2,0.7\n' >"$in/angle.csv"
case_ 1 "theta.clf: line" slam2d "$in/theta.clf" --out-poses "$o/p.tum"
case_ 1 "heading 1e+17 rad" lines "$in/theta.clf"
case_ 1 "angle.csv: line 1: angle 1e+300" lines "$in/angle.csv"

# ------------------------------------------------------------------ class: empty selections
case_ 2 "the frame list is empty" occupancy "$in/scans" --resolution 0.2 --max-range 20 --frames "" --out "$o/x.bt"

# ------------------------------------------------------------------ class: special files in bag folders
mkdir -p "$in/bagdir" && mkfifo "$in/bagdir/bagdir_0.db3"
printf 'rosbag2_bagfile_information:\n  version: 5\n' >"$in/bagdir/metadata.yaml"
case_ 1 "bagdir_0.db3: cannot open (not a regular file: a FIFO)" info "$in/bagdir"

# ------------------------------------------------------------------ class: WIDTH 0 HEIGHT 0 (scans)
/usr/bin/python3 -c "
import numpy as np
p = np.random.default_rng(1).uniform(-3, 3, (100, 3)).astype(np.float32)
h = 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 0\nHEIGHT 0\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 100\nDATA binary\n'
open('$in/w00.pcd', 'wb').write(h.encode() + p.tobytes())"
"$MM" occupancy "$in/w00.pcd" --resolution 0.2 --max-range 20 --out "$tmp/w00.bt" >"$tmp/out" 2>"$tmp/err"
check "occupancy of a WIDTH 0 HEIGHT 0 scan: read with one warning" \
  test "$?" = 0 -a "$(grep -c 'header says WIDTH 0 HEIGHT 0 but POINTS 100' "$tmp/err")" = 1

echo "$cases refusal cases"
finish
