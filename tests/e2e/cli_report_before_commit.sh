#!/usr/bin/env bash
# Issue 24, class 4: late failures after commit. The rule (docs/RELIABILITY.md): a command
# prints its report to standard output, flushes and checks it, and only then commits its
# output files. When the report cannot be printed (stdout is /dev/full, or closed), the run
# exits 1 with one line naming standard output, and none of its outputs appears.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
bun=$D/pcl_test_pcd/bunny.pcd
tum=$D/open3d_tum_depth
o=$tmp/o
mkdir -p "$o"
"$MM" occupancy "$k" --frames 0 --resolution 0.5 --max-range 20 --out "$tmp/in.bt" >/dev/null ||
  { echo "FAIL: cannot make the .bt input"; exit 1; }

# run_bad_stdout HOW CMD...: HOW is "full" (stdout = /dev/full) or "closed" (stdout closed):
# exit 1, one stderr line naming standard output, no file in $o, within 60 s.
run_bad_stdout() {
  local how=$1
  shift
  rm -rf "${o:?}"/* "$o"/.[!.]* 2>/dev/null
  local rc=0
  if [ "$how" = full ]; then
    timeout 60 "$@" >/dev/full 2>"$tmp/err" || rc=$?
  else
    timeout 60 "$@" >&- 2>"$tmp/err" || rc=$?
  fi
  local lines left
  lines=$(wc -l <"$tmp/err")
  left=$(ls -A "$o" | tr '\n' ' ')
  if [ "$rc" != 1 ] || [ "$lines" != 1 ] || ! grep -qF "standard output" "$tmp/err" || [ -n "$left" ]; then
    echo "FAIL: stdout $how: $* -> exit $rc (want 1), stderr ($lines lines): $(head -c 200 "$tmp/err"); left in the output directory: '$left'"
    fails=$((fails + 1))
  else
    echo "ok: stdout $how: exit $rc: $(cat "$tmp/err")"
  fi
}

cases=(
  "grid $bun --cell-size 0.01 --out $o/g.pcd"
  "grid $bun --cell-size 0.01 --out $o/g.pcd --cells $o/c.csv --format csv"
  "grid $bun --cell-size 0.01 --cells $o/c.csv --format json"
  "octree $bun --max-points 100 --min-cell-size 0.01 --out $o/t.pcd --leaves $o/l.csv"
  "octree $bun --max-points 100 --min-cell-size 0.01 --leaves $o/l.csv --format json"
  "depth-to-cloud $tum/TUM_depth.png --camera $tum/camera_primesense.json --out $o/d.pcd"
  "heightmap $tum/TUM_depth.png --camera $tum/camera_primesense.json --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix $o/hm"
  "heightmap $tum/TUM_depth.png --camera $tum/camera_primesense.json --auto-floor --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix $o/hm --format table"
  "kitti $k --frames 0 --out-cloud $o/k.pcd"
  "kitti $k --frames 0 --out-poses $o/p.txt --out-map $o/m.pgm --format json"
  "occupancy $k --frames 0 --resolution 0.5 --max-range 20 --out $o/m.bt"
  "occupancy $k --frames 0 --resolution 0.5 --max-range 20 --out-ot $o/m.ot --out-cloud $o/c.pcd --format json"
  "occupancy $k --frames 0 --resolution 0.5 --max-range 20 --out-map $o/m.pgm --band -1,1 --map-preview $o/m.png"
  "occupancy $tmp/in.bt --out $o/copy.bt"
  "occupancy $tmp/in.bt --out-cloud $o/c.pcd --format json"
)
for how in full closed; do
  for cmd in "${cases[@]}"; do
    # shellcheck disable=SC2086
    run_bad_stdout "$how" "$MM" $cmd
  done
done
# The same commands with a writable stdout still write every output.
rm -rf "${o:?}"/*
check "grid writes both outputs when stdout works" bash -c \
  "'$MM' grid '$bun' --cell-size 0.01 --out '$o/g.pcd' --cells '$o/c.csv' >'$tmp/report' && test -s '$o/g.pcd' -a -s '$o/c.csv' -a -s '$tmp/report'"
check "occupancy writes its outputs when stdout works" bash -c \
  "'$MM' occupancy '$k' --frames 0 --resolution 0.5 --max-range 20 --out '$o/m.bt' --format json >'$tmp/report' && test -s '$o/m.bt' && grep -q known '$tmp/report'"
check "no temporary left" test -z "$(find "$tmp" -name '*.tmp-*')"
finish
