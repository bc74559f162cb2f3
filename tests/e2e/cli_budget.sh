#!/usr/bin/env bash
# Issue 24, class 1: unbounded work from small inputs. A .bt/.ot file of 70-120 bytes can
# describe a tree whose leaves expand to 2^26 voxels, or span OctoMap's whole key space. Every
# consumer of a decoded tree (the viewer's cubes, occupancy's exports: .bt/.ot, the cloud of
# voxel centres, the 2D map; info) checks the work the tree implies against the memory budget
# before building anything: exit 1, one line naming the file and the budget, within a second,
# memory staying under the budget, nothing written.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
limit_ms=${HARDENING_TIME_LIMIT_MS:-1000}
o=$tmp/o
mkdir -p "$o"

# A .bt, byte by byte: the header, then per inner node 2 bytes, 2 bits per child (lsb first,
# liboctomap's OcTreeNode::readBinary): low bit only a free leaf, high bit only an occupied
# leaf, both an inner node. `chain N LAST` is a root with one inner child,
# N-1 levels down, whose last node holds the children LAST (hex, little endian).
bt_header() { printf '# Octomap OcTree binary file\nid OcTree\nsize %d\nres 0.1\ndata\n' "$1"; }
chain_bt() {  # chain_bt FILE DEPTH LAST_LO LAST_HI LEAVES
  local f=$1 depth=$2 lo=$3 hi=$4 leaves=$5
  { bt_header $((depth + 1 + leaves))
    for ((i = 0; i < depth; ++i)); do printf '\x03\x00'; done
    printf "\\x$lo\\x$hi"; } >"$f"
}
# four occupied leaves at depth 8: 4 x 8^8 = 2^26 voxels (the map of them alone fits in 1 GiB)
chain_bt "$tmp/occ4.bt" 7 aa 00 4
# four free leaves at depth 8 (2^26 voxels), and eight (2^27: the map alone is over 1 GiB)
chain_bt "$tmp/free4.bt" 7 55 00 4
chain_bt "$tmp/free8.bt" 7 55 55 8
# four occupied and four free leaves at depth 8
chain_bt "$tmp/mixed.bt" 7 aa 55 8
# two single voxels at opposite corners of the key space (65536 voxels apart on every axis)
{ bt_header 33
  printf '\x03\xc0'                                  # root: children 0 and 7 inner
  for ((i = 0; i < 14; ++i)); do printf '\x03\x00'; done; printf '\x02\x00'  # down child 0
  for ((i = 0; i < 14; ++i)); do printf '\x00\xc0'; done; printf '\x00\x80'  # down child 7
} >"$tmp/far.bt"
# The same as .ot: per node a float log-odds and a child mask, depth first.
{ printf '# Octomap OcTree file\nid OcTree\nsize 12\nres 0.1\ndata\n'
  for ((i = 0; i < 7; ++i)); do printf '\x00\x00\x80\x3f\x01'; done   # 1.0, child 0
  printf '\x00\x00\x80\x3f\x0f'                                        # children 0-3
  for ((i = 0; i < 4; ++i)); do printf '\x00\x00\x00\x40\x00'; done   # leaves, log-odds 2.0
} >"$tmp/occ4.ot"
for f in occ4.bt free4.bt free8.bt mixed.bt far.bt occ4.ot; do
  check "$f is under 160 bytes" test "$(stat -c %s "$tmp/$f")" -lt 160
done

# bounded CODE NEEDLE -- CMD...: like expect, plus the wall time within limit_ms, the peak RSS
# under the 1 GiB budget (plus the program's own ~300 MB), and no file in $o; a run is stopped
# after 10 s (it has failed by then). Virtual memory is
# capped at 6 GiB so that a run that ignores the budget fails instead of taking the machine.
bounded() {
  local code=$1 needle=$2
  shift 3
  rm -rf "${o:?}"/*
  local rc=0 t0 t1
  t0=$(date +%s%N)
  (ulimit -v 6291456; exec /usr/bin/time -f "%M" -o "$tmp/rss" timeout 10 "$@") >"$tmp/out" 2>"$tmp/err" || rc=$?
  t1=$(date +%s%N)
  local ms=$(((t1 - t0) / 1000000)) rss
  rss=$(tail -1 "$tmp/rss" 2>/dev/null)
  # /usr/bin/time adds a line when the command fails ("Command exited with non-zero status")
  sed -i '/^Command exited with non-zero status/d;/^Command terminated by signal/d' "$tmp/err"
  local lines left
  lines=$(wc -l <"$tmp/err")
  left=$(ls -A "$o" | tr '\n' ' ')
  if [ "$rc" != "$code" ] || [ "$lines" != 1 ] || ! grep -qF -- "$needle" "$tmp/err" ||
    [ -s "$tmp/out" ] || [ "$ms" -gt "$limit_ms" ] || [ "${rss:-0}" -gt 1400000 ] || [ -n "$left" ]; then
    echo "FAIL: $* -> exit $rc (want $code), ${ms} ms, peak RSS ${rss:-?} KiB, left '$left', stderr ($lines lines): $(head -c 300 "$tmp/err")"
    fails=$((fails + 1))
  else
    echo "ok: exit $rc, ${ms} ms, peak RSS ${rss} KiB: $(cat "$tmp/err")"
  fi
}

budget="more than the memory budget"
MM1=("$MM" --max-memory 1G)
# The viewer: occupied cubes, free cubes with --free. DISPLAY names no server: the budget is
# checked before the display is opened (and before any voxel is expanded).
for f in occ4.bt occ4.ot mixed.bt; do
  bounded 1 "$budget" -- env DISPLAY=:424242 "${MM1[@]}" view "$tmp/$f"
done
bounded 1 "$budget" -- env DISPLAY=:424242 "${MM1[@]}" view "$tmp/free4.bt" --free
bounded 1 "$budget" -- env DISPLAY=:424242 "${MM1[@]}" view "$tmp/far.bt" "$tmp/occ4.bt"
# occupancy with a .bt/.ot input: every export
for f in occ4.bt occ4.ot mixed.bt; do
  bounded 1 "$budget" -- "${MM1[@]}" occupancy "$tmp/$f" --out-cloud "$o/c.pcd"
  bounded 1 "$budget" -- "${MM1[@]}" occupancy "$tmp/$f" --out "$o/c.bt"
  bounded 1 "$budget" -- "${MM1[@]}" occupancy "$tmp/$f" --out-ot "$o/c.ot"
done
bounded 1 "$budget" -- "${MM1[@]}" occupancy "$tmp/free8.bt"
bounded 1 "$budget" -- "${MM1[@]}" occupancy "$tmp/far.bt" --out-map "$o/m.pgm" --band -4000,4000
bounded 1 "$budget" -- "${MM1[@]}" occupancy "$tmp/far.bt" --out-map "$o/m.pgm" --band -4000,4000 --map-preview "$o/m.png"
# info: a .bt/.ot is not a point cloud; it is refused (or summarised) without expanding it
for f in occ4.bt far.bt occ4.ot; do
  bounded 1 "$f" -- "${MM1[@]}" info "$tmp/$f"
done

# Within the budget the same files are read and drawn as before: the small corner map and a
# real map export.
check "far.bt exports its two voxels" bash -c \
  "'$MM' occupancy '$tmp/far.bt' --out-cloud '$o/far.pcd' --format json | grep -q '\"occupied\": 2'"
check "the bundled geb079.bt exports within the budget" bash -c \
  "'${MM1[0]}' --max-memory 1G occupancy '$DATA/octomap_geb079/geb079.bt' --out-cloud '$o/geb.pcd' >/dev/null && test -s '$o/geb.pcd'"
finish
