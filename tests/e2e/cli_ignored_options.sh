#!/usr/bin/env bash
# Issue 24, class 6: options silently ignored or overridden. An option that does not apply to
# the run is refused (exit 2, one line naming it), never dropped: scan options given with a
# .bt/.ot input to `occupancy` (the map is exported as it is), KITTI options given with PCD scans,
# `--band` without `--out-map`, and `lines` layout options given with `--preset` (which used to
# override an explicit --min-range/--max-range/--count).
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
mines=$D/breezyslam_mines_urg04lx/exp2.dat
o=$tmp/o
mkdir -p "$o"
"$MM" occupancy "$k" --frames 0 --resolution 0.5 --max-range 20 --out "$tmp/in.bt" \
  --out-ot "$tmp/in.ot" >/dev/null || { echo "FAIL: cannot make the .bt input"; exit 1; }
# a PCD scan with its pose as VIEWPOINT
printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n1 0 0\n0 2 0\n0 0 3\n' >"$tmp/s.pcd"

cases=(
  # a .bt/.ot map is exported as it is
  "2|--resolution|occupancy $tmp/in.bt --resolution 0.2 --out $o/a.bt"
  "2|--max-range|occupancy $tmp/in.bt --max-range 5 --out $o/a.bt"
  "2|--frames|occupancy $tmp/in.bt --frames 0 --out-cloud $o/a.pcd"
  "2|--world|occupancy $tmp/in.bt --world camera --out-cloud $o/a.pcd"
  "2|--sequence|occupancy $tmp/in.bt --sequence 01 --out-cloud $o/a.pcd"
  "2|--resolution|occupancy $tmp/in.ot --resolution 0.2 --max-range 5 --out-ot $o/a.ot"
  # PCD scans carry their own pose: no KITTI options
  "2|--frames|occupancy $tmp/s.pcd --resolution 0.5 --max-range 20 --frames 0 --out $o/a.bt"
  "2|--world|occupancy $tmp/s.pcd --resolution 0.5 --max-range 20 --world camera --out $o/a.bt"
  "2|--sequence|occupancy $tmp/s.pcd --resolution 0.5 --max-range 20 --sequence 01 --out $o/a.bt"
  # --band shapes --out-map only
  "2|--band|occupancy $tmp/in.bt --band -1,1 --out $o/a.bt"
  "2|--band|occupancy $k --frames 0 --resolution 0.5 --max-range 20 --band -1,1 --out $o/a.bt"
  # lines: --preset sets the whole layout; explicit layout options are not overridden silently
  "2|--min-range|lines $mines --preset urg04lx-mines --min-range 1"
  "2|--max-range|lines $mines --preset urg04lx-mines --max-range 2"
  "2|--count|lines $mines --preset urg04lx-mines --count 100"
  "2|--skip-tokens|lines $mines --preset urg04lx-mines --skip-tokens 3"
  "2|--range-scale|lines $mines --preset urg04lx-mines --range-scale 2"
  "2|--angle-min-deg|lines $mines --preset urg04lx-mines --angle-min-deg 0"
  "2|--angle-increment-deg|lines $mines --preset urg04lx-mines --angle-increment-deg 1"
)
expect_cases "${cases[@]}"
check "nothing written by a refused option" test -z "$(ls -A "$o")"

# What applies is still accepted.
check "occupancy exports a .bt, with --band for --out-map" bash -c \
  "'$MM' occupancy '$tmp/in.bt' --out-cloud '$o/c.pcd' --out-map '$o/m.pgm' --band -1,1 >/dev/null"
check "occupancy casts a PCD scan" bash -c \
  "'$MM' occupancy '$tmp/s.pcd' --resolution 0.5 --max-range 20 --out '$o/s.bt' >/dev/null"
check "lines takes --preset alone, and the layout options alone" bash -c \
  "'$MM' lines '$mines' --preset urg04lx-mines >/dev/null &&
   '$MM' lines '$mines' --skip-tokens 24 --count 682 --angle-min-deg -120 --angle-increment-deg 0.3519 --range-scale 0.001 --min-range 0.02 --max-range 5.6 >/dev/null"
finish
