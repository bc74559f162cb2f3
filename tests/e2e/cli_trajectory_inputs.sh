#!/usr/bin/env bash
# Issue 24: `heightmap --trajectory` with more pose lines than depth images. Frame k takes the
# k-th pose line, so extra lines meant images that are not the trajectory's first frames, or not
# in its order; they were read silently (even a malformed line after the last frame). Now a pose
# line beyond the images is an error naming the file and the line (exit 1); blank lines and '#'
# comments are not pose lines; CRLF and a last line without newline are read as before.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
tumd=$D/open3d_tum_depth/TUM_depth.png
tumc=$D/open3d_tum_depth/camera_primesense.json
o=$tmp/o
mkdir -p "$o"
# further frames are copies: one file named twice is refused
cp "$tumd" "$tmp/tum2.png"
cp "$tumd" "$tmp/tum3.png"
hm="--camera $tumc --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix $o/hm"
pose='0 0 0 1.5 0 0 0 1'
printf '%s\n%s\n' "$pose" "$pose" >"$tmp/two.txt"
printf '%s\n%s\n%s\n' "$pose" "$pose" "$pose" >"$tmp/three.txt"
printf '# stamp tx ty tz qx qy qz qw\n\n%s\n\n# next\n%s\n' "$pose" "$pose" >"$tmp/commented.txt"
printf '%s\ngarbage\n' "$pose" >"$tmp/garbage.txt"
printf '%s\r\n%s' "$pose" "$pose" >"$tmp/crlf_two.txt"

cases=(
  "1|two.txt: line 2 is a pose line beyond the 1 depth image(s) given|heightmap $tumd --trajectory $tmp/two.txt $hm"
  "1|three.txt: line 3 is a pose line beyond the 2 depth image(s) given|heightmap $tumd $tmp/tum2.png --trajectory $tmp/three.txt $hm"
  "1|commented.txt: line 6 is a pose line beyond the 1 depth image(s)|heightmap $tumd --trajectory $tmp/commented.txt $hm"
  "1|garbage.txt: line 2 is a pose line beyond|heightmap $tumd --trajectory $tmp/garbage.txt $hm"
  "1|crlf_two.txt: line 2 is a pose line beyond|heightmap $tumd --trajectory $tmp/crlf_two.txt $hm"
)
expect_cases "${cases[@]}"
check "nothing written" test -z "$(ls -A "$o")"

printf '%s\n\n# the end\n\n' "$pose" >"$tmp/one_trailing.txt"
printf '%s\r\n%s' "$pose" "$pose" >"$tmp/crlf.txt"
check "one pose line per image, comments and blank lines after it" bash -c \
  "'$MM' heightmap '$tumd' --trajectory '$tmp/one_trailing.txt' $hm >/dev/null"
check "CRLF lines, the last without a newline" bash -c \
  "'$MM' heightmap '$tumd' '$tmp/tum2.png' --trajectory '$tmp/crlf.txt' $hm >/dev/null"
check "too few lines stay an error" bash -c \
  "! '$MM' heightmap '$tumd' '$tmp/tum2.png' '$tmp/tum3.png' --trajectory '$tmp/two.txt' $hm 2>/dev/null"
finish
