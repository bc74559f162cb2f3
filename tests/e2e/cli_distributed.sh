#!/usr/bin/env bash
# Issue 24, class 13: the distributed grid's defaults are the one-process defaults. `grid FILES
# --distributed` used to refuse the default --origin cloud-min (the study's origin); now the ranks
# agree on the minimum of the whole input first (one all-reduce of three numbers) and every rank
# bins its share from it. For either origin, `mpirun -np 2|3 metricmap grid FILES --distributed`
# writes the files `metricmap grid FILES` writes: the same JSON statistics (timings aside) and
# the same per-cell CSV, byte for byte; the means PCD has the same header and cells, each float
# within one ulp (a cell's points are summed in another order when ranks share it: the double
# sums differ in their last bits and a float may round the other way, as for --origin world in
# mpi_cli.sh). Skipped (passing) without MPI.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
if ! command -v mpirun >/dev/null; then
  skip "no mpirun"
fi
if "$MM" grid "$D/pcl_test_pcd/milk.pcd" --cell-size 1 --distributed 2>&1 >/dev/null |
  grep -q "built without MPI"; then
  skip "built without MPI"
fi
strip() { grep -v '"seconds"\|"load"\|"grid": [0-9]' "$1"; }

# same_floats A B: two binary PCDs of x y z floats: same header and size, every float within 1 ulp.
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

# same NAME CELL ORIGIN-ARGS -- FILES...: one process against 2 and 3 ranks
same() {
  local name=$1 cell=$2 origin=$3
  shift 4
  local one=$tmp/$name.one
  # shellcheck disable=SC2086
  "$MM" grid "$@" --cell-size "$cell" $origin --format json --cells "$one.csv" --out "$one.pcd" \
    >"$one.json" 2>"$one.err" || { echo "FAIL: one process $name: $(head -c 300 "$one.err")"; fails=$((fails + 1)); return; }
  for np in 2 3; do
    local d=$tmp/$name.np$np
    # shellcheck disable=SC2086
    if ! timeout 120 mpirun --allow-run-as-root --oversubscribe -np $np "$MM" grid "$@" \
      --cell-size "$cell" $origin --distributed --format json --cells "$d.csv" --out "$d.pcd" \
      >"$d.json" 2>"$d.err"; then
      echo "FAIL: $name -np $np: $(head -c 300 "$d.err")"
      fails=$((fails + 1))
      continue
    fi
    check "$name -np $np: same statistics" diff <(strip "$one.json") <(strip "$d.json")
    check "$name -np $np: same cells CSV" cmp "$one.csv" "$d.csv"
    check "$name -np $np: same means PCD (floats within 1 ulp)" same_floats "$one.pcd" "$d.pcd"
    # shellcheck disable=SC2086
    timeout 120 mpirun --allow-run-as-root --oversubscribe -np $np "$MM" grid "$@" \
      --cell-size "$cell" $origin --distributed --format json >"$d.stats.json" 2>/dev/null
    check "$name -np $np: same statistics without the cells gathered" \
      diff <(strip "$one.json") <(strip "$d.stats.json")
  done
}

study=("$D"/ua_mapas_metricos_pcd/*.pcd)
# the default origin (cloud-min), the study's files in two orders (the minimum of each axis
# lies in another rank's share), other clouds and cell sizes
same study_default 1.0 "" -- "${study[@]}"
same study_reversed 0.5 "" -- "${study[3]}" "${study[2]}" "${study[1]}" "${study[0]}"
same study_cloud_min 0.1 "--origin cloud-min" -- "${study[@]}"
same pcl_default 0.01 "" -- "$D"/pcl_test_pcd/*.pcd
same kitti_default 0.2 "" -- "$D"/kitti_odometry_00/sequences/00/velodyne/*.bin
# world-aligned cells, as before
same study_world 0.5 "--origin world" -- "${study[@]}"
check "the JSON names the default origin" grep -q '"origin": "cloud-min"' "$tmp/study_default.np2.json"
finish
