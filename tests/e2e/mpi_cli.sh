#!/usr/bin/env bash
# --distributed against one process: `mpirun -np 1|2|3 metricmap grid FILES --distributed` gives
# the JSON statistics, the per-cell CSV and the means PCD of `metricmap grid FILES --origin world`
# (the cells' means are printed to 9 digits / stored as float: identical text and bytes), and
# `occupancy` over the KITTI frames the same voxel counts and the same map_server map. A rank that
# cannot read its input ends the whole job with exit 1, naming the file, within 10 s.
# Usage: mpi_cli.sh METRICMAP DATA MPIRUN
MM=$1
DATA=$2
MPIRUN=$3
source "$(dirname "$0")/lib.sh"
run() { "$MPIRUN" --allow-run-as-root --oversubscribe -np "$@"; }
# the JSON without timings and memory figures (the merged map's blocks are laid out differently)
strip() { grep -v '"seconds"\|"load"\|"grid": [0-9]\|"insert"\|"write"\|"bytes\|ms_per_scan' "$1"; }

# same_floats A B: two binary PCDs of x y z floats: same header, every float within 1 ulp.
same_floats() {
  local header
  header=$(head -n 11 "$1" | wc -c)
  cmp -s <(head -c "$header" "$1") <(head -c "$header" "$2") || return 1
  [ "$(wc -c <"$1")" = "$(wc -c <"$2")" ] || return 1
  paste <(tail -c +$((header + 1)) "$1" | od -An -v -t d4 -w4) \
    <(tail -c +$((header + 1)) "$2" | od -An -v -t d4 -w4) |
    awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 1) bad++; if (d == 1) ulp++; n++ }
         END { printf "    %d floats, %d one ulp apart, %d further\n", n, ulp, bad; exit (bad > 0 || n == 0) }'
}

same_grid() {  # same_grid NAME CELL FILES...: one process vs 1, 2, 3 ranks
  local name=$1 cell=$2
  shift 2
  "$MM" grid "$@" --cell-size "$cell" --origin world --format json --cells "$tmp/$name.csv" \
    --out "$tmp/$name.pcd" >"$tmp/$name.json" 2>/dev/null || { echo "FAIL: one-process $name"; fails=$((fails + 1)); return; }
  check "$name: cells counted" grep -q '"occupied_cells": [1-9]' "$tmp/$name.json"
  for np in 1 2 3; do
    local d="$tmp/$name.np$np"
    if ! timeout 120 "$MPIRUN" --allow-run-as-root --oversubscribe -np $np "$MM" grid "$@" \
      --cell-size "$cell" --origin world --distributed --format json --cells "$d.csv" --out "$d.pcd" \
      >"$d.json" 2>"$d.err"; then
      echo "FAIL: $name -np $np: $(head -c 300 "$d.err")"
      fails=$((fails + 1))
      continue
    fi
    check "$name -np $np: same statistics" diff <(strip "$tmp/$name.json") <(strip "$d.json")
    check "$name -np $np: same cells, counts and means" cmp "$tmp/$name.csv" "$d.csv"
    check "$name -np $np: same means cloud (1 ulp)" same_floats "$tmp/$name.pcd" "$d.pcd"
    # statistics only: the cells are not gathered, a few numbers per rank are reduced
    timeout 120 "$MPIRUN" --allow-run-as-root --oversubscribe -np $np "$MM" grid "$@" \
      --cell-size "$cell" --origin world --distributed --format json >"$d.stats.json" 2>/dev/null
    check "$name -np $np: same statistics without gathering the cells" \
      diff <(strip "$tmp/$name.json") <(strip "$d.stats.json")
  done
}

same_grid study 0.1 "$DATA"/ua_mapas_metricos_pcd/*.pcd
same_grid pcl 0.01 "$DATA"/pcl_test_pcd/*.pcd
same_grid kitti_bins 0.2 "$DATA"/kitti_odometry_00/sequences/00/velodyne/*.bin

# occupancy over the KITTI frames (frame ranges per rank)
K="$DATA/kitti_odometry_00"
occ=(occupancy "$K" --frames 0-5 --resolution 0.2 --max-range 30 --band -1,1 --format json)
"$MM" "${occ[@]}" --out-map "$tmp/occ.pgm" >"$tmp/occ.json"
check "occupancy: voxels known" grep -q '"known": [1-9]' "$tmp/occ.json"
for np in 1 2 3; do
  d="$tmp/occ.np$np"
  timeout 120 "$MPIRUN" --allow-run-as-root --oversubscribe -np $np "$MM" "${occ[@]}" \
    --out-map "$d.pgm" --distributed >"$d.json" 2>"$d.err" || echo "FAIL: occupancy -np $np: $(head -c 300 "$d.err")"
  check "occupancy -np $np: same counts" diff <(strip "$tmp/occ.json") <(strip "$d.json")
  check "occupancy -np $np: same map" cmp "$tmp/occ.pgm" "$d.pgm"
done

# faults: one unreadable input -> every rank exits 1 quickly, the file named
fault() {  # fault NEEDLE NP ARGS...
  local needle=$1 np=$2
  shift 2
  local start rc=0
  start=$(date +%s%N)
  timeout 30 "$MPIRUN" --allow-run-as-root --oversubscribe -np "$np" "$MM" "$@" >"$tmp/f.out" \
    2>"$tmp/f.err" || rc=$?
  local ms=$((($(date +%s%N) - start) / 1000000))
  if [ "$rc" = 1 ] && grep -q "metricmap: error: .*$needle" "$tmp/f.err" && [ "$ms" -lt 10000 ] &&
    [ ! -s "$tmp/f.out" ]; then
    echo "ok: -np $np exit 1 in $ms ms: $(grep 'metricmap: error' "$tmp/f.err")"
  else
    echo "FAIL: -np $np $* -> exit $rc in $ms ms: $(head -c 400 "$tmp/f.err")"
    fails=$((fails + 1))
  fi
}
S="$DATA/ua_mapas_metricos_pcd"
head -c 2000 "$S/poli000.pcd" >"$tmp/truncated.pcd"
fault "$tmp/missing.pcd" 3 grid "$S/ciencias000.pcd" "$tmp/missing.pcd" "$S/poli000.pcd" --cell-size 0.1 --distributed
fault "$tmp/truncated.pcd" 2 grid "$S/ciencias000.pcd" "$tmp/truncated.pcd" --cell-size 0.1 --distributed
fault "$tmp/truncated.pcd" 3 grid "$tmp/truncated.pcd" "$S/ciencias000.pcd" "$S/museo000.pcd" --cell-size 0.1 --distributed --format json
cp -r "$K" "$tmp/kitti"
head -c 1000 "$K/sequences/00/velodyne/000004.bin" >"$tmp/kitti/sequences/00/velodyne/000004.bin"
fault "000004.bin" 3 occupancy "$tmp/kitti" --frames 0-5 --resolution 0.2 --max-range 30 --distributed --out-map "$tmp/never.pgm" --band -1,1
check "no output written by the failed job" test ! -e "$tmp/never.pgm"

finish
