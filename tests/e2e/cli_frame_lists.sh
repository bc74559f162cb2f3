#!/usr/bin/env bash
# Issue 24, class 7: duplicate or unordered selections. `kitti` and `occupancy` take `--frames`
# as `odometry` does: in acquisition order, without repeats. A repeated frame would count one
# scan twice (`occupancy --frames 0,0` passed the min-hits test on one scan); a descending list
# would map the frames out of order. Both are usage errors (exit 2, one line naming --frames).
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
o=$tmp/o
mkdir -p "$o"
occ="occupancy $k --resolution 0.5 --max-range 20 --out $o/m.bt"
kit="kitti $k --out-map $o/m.pgm --out-poses $o/p.txt"

cases=(
  "2|--frames|$kit --frames 0,0"
  "2|--frames|$kit --frames 1,0"
  "2|--frames|$kit --frames 0-2,1"
  "2|--frames|$kit --frames 0-2,2"
  "2|--frames|$kit --frames 0,1,0"
  "2|--frames|$kit --frames 0-1,0-1"
  "2|--frames|$kit --frames 2,0-1"
  "2|--frames|$occ --frames 0,0"
  "2|--frames|$occ --frames 1,0"
  "2|--frames|$occ --frames 0-2,1"
  "2|--frames|$occ --frames 0-1,0-1"
  "2|--frames|$occ --frames 2,0-1"
)
expect_cases "${cases[@]}"
check "nothing written by a refused selection" test -z "$(ls -A "$o")"

# Ascending lists, ranges and gaps are accepted.
check "kitti --frames 0,2 and 0-1" bash -c \
  "'$MM' $kit --frames 0,2 >/dev/null && test \$(wc -l <'$o/p.txt') = 2 && '$MM' $kit --frames 0-1 >/dev/null"
check "occupancy --frames 0-1 and 0,2" bash -c \
  "'$MM' $occ --frames 0-1 >/dev/null && '$MM' $occ --frames 0,2 >/dev/null"
finish
