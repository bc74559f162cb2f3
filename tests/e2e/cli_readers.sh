#!/usr/bin/env bash
# Issue 24, class 11: reader consistency. The same bad token gets the same answer in every
# reader: an ASCII PLY vertex holding a word, hex or a value beyond float range is refused as
# an ASCII PCD value is (PCL's PLY parser turned them into NaN points and succeeded); a header
# key given twice (a second VIEWPOINT, WIDTH, FIELDS) is refused as in calib and OctoMap files;
# `compare --config` refuses empty items and repeated keys as every other option list does.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
bun=$D/pcl_test_pcd/bunny.pcd
o=$tmp/o
mkdir -p "$o"

ply() {  # ply NAME BODY...: an ASCII PLY with x y z float vertices, one body line per argument
  local f=$tmp/$1
  shift
  { printf 'ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\nend_header\n' $#
    printf '%s\n' "$@"; } >"$f"
}
pcd() {  # pcd NAME EXTRA_HEADER_LINES BODY...: an ASCII PCD of x y z points
  local f=$tmp/$1 extra=$2
  shift 2
  { printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n%bPOINTS %d\nDATA ascii\n' $# "$extra" $#
    printf '%s\n' "$@"; } >"$f"
}
ply word.ply "1 2 3" "abc 2 3" "4 5 6"
ply hex.ply "1 2 3" "0x10 2 3"
ply big.ply "1 2 3" "1e39 2 3"
ply short.ply "1 2 3" "4 5"
ply long.ply "1 2 3" "4 5 6 7"
ply empty_token.ply "1 2 3" "4 5 six"
ply good.ply "1 2 3" "4 5 6" "nan nan nan" "-1.5e3 .5 +2."
pcd word.pcd "" "1 2 3" "abc 2 3"
pcd vp2.pcd 'VIEWPOINT 1 0 0 1 0 0 0\n' "1 2 3" "4 5 6"
pcd width2.pcd 'WIDTH 2\n' "1 2 3" "4 5 6"
pcd fields2.pcd 'FIELDS x y z\n' "1 2 3" "4 5 6"
pcd good.pcd "" "1 2 3" "4 5 6"
# header counts and types with a NUL byte inside: refused whole, the message not cut at the NUL
hdr='# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\n'
printf "${hdr}SIZE 4 4\0X 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n" >"$tmp/nul_size.pcd"
printf "${hdr}SIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\0X\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n" >"$tmp/nul_width.pcd"
printf "${hdr}SIZE 4 4 4\nTYPE F F\0X F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n" >"$tmp/nul_type.pcd"
# a PLY whose vertices follow another element (its lines are skipped, not checked as vertices)
printf 'ply\nformat ascii 1.0\nelement camera 1\nproperty float fx\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n500\n1 2 3\n4 5 6\n' >"$tmp/camera_first.ply"

cfg=cell_size=1,min_cell_size=1,max_points=100
cases=(
  "1|word.ply: line 9: 'abc' is not a number|info $tmp/word.ply"
  "1|word.ply|grid $tmp/word.ply --cell-size 0.5"
  "1|hex.ply: line 9: '0x10' is not a number|info $tmp/hex.ply"
  "1|big.ply: line 9: '1e39' is not a number|info $tmp/big.ply"
  "1|short.ply: line 9|info $tmp/short.ply"
  "1|long.ply: line 9|info $tmp/long.ply"
  "1|empty_token.ply|octree $tmp/empty_token.ply --max-points 10 --min-cell-size 0.1"
  "1|word.pcd|info $tmp/word.pcd"
  "1|vp2.pcd: a second 'VIEWPOINT' line|info $tmp/vp2.pcd"
  "1|vp2.pcd: a second 'VIEWPOINT' line|occupancy $tmp/vp2.pcd --resolution 0.5 --max-range 20 --out $o/a.bt"
  "1|nul_size.pcd: SIZE '4\\x00X' is not a valid count|info $tmp/nul_size.pcd"
  "1|nul_width.pcd: WIDTH '1\\x00X' is not a valid count|info $tmp/nul_width.pcd"
  "1|nul_type.pcd: TYPE 'F\\x00X' is not F, I or U|info $tmp/nul_type.pcd"
  "1|width2.pcd: a second 'WIDTH' line|info $tmp/width2.pcd"
  "1|fields2.pcd: a second 'FIELDS' line|grid $tmp/fields2.pcd --cell-size 0.5"
  "2|--config|compare $bun --config $cfg,"
  "2|--config|compare $bun --config ,$cfg"
  "2|--config|compare $bun --config cell_size=1,,min_cell_size=1,max_points=100"
  "2|cell_size' is given twice|compare $bun --config $cfg,cell_size=2"
  "2|max_points' is given twice|compare $bun --config max_points=5,$cfg"
  "2|--config|compare $bun --config ''"
)
for row in "${cases[@]}"; do
  IFS='|' read -r code needle cmd <<<"$row"
  # shellcheck disable=SC2086
  eval "expect \"\$code\" \"\$needle\" -- \"\$MM\" $cmd"
done
check "nothing written" test -z "$(ls -A "$o")"

check "a valid ASCII PLY (nan points included) is read" bash -c \
  "'$MM' info '$tmp/good.ply' --format json | grep -q '\"points_in_file\": 4'"
check "an ASCII PLY whose vertices follow another element is read" bash -c \
  "'$MM' info '$tmp/camera_first.ply' --format json | grep -q '\"points\": 2'"
check "a valid ASCII PCD is read" bash -c "'$MM' info '$tmp/good.pcd' >/dev/null"
check "compare takes a valid --config" bash -c "'$MM' compare '$bun' --config '$cfg' >/dev/null"
finish
