#!/usr/bin/env bash
# Issue 24, class 12 (the rest): a value is quoted as the user gave it, and it is the value used.
# - Integers: CLI11 reads `010` as octal 8 (`octree --max-points 010` split at 8 points) and
#   refuses `09` as "Could not convert"; `grid --threads 0x10` took 16. Every count option wants
#   plain decimal without leading zeros and names the text given.
# - Bounds and orders: `kitti --min-range 1e2 --max-range 1e1` said "min range 100.000000
#   exceeds max range 10.000000"; CLI11's ranges said "-90.000000 to 90.000000". Now the text
#   given and the shortest bounds: "--min-range '1e2' exceeds --max-range '1e1'".
# - Under MPI (skipped when the build has no MPI or mpirun is missing): an error is printed once,
#   as the first line of stderr, by the failing rank (rank 0 for a usage error every rank finds
#   alike), before mpirun's banner; usage errors exit 2 as in one process.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
bun=$D/pcl_test_pcd/milk.pcd
csv=$D/pythonrobotics_lidar01/lidar01.csv
mines=$D/breezyslam_mines_urg04lx/exp2.dat
tumd=$D/open3d_tum_depth/TUM_depth.png
tumc=$D/open3d_tum_depth/camera_primesense.json
o=$tmp/o
mkdir -p "$o"
hm="--camera $tumc --auto-floor --resolution 0.05 --map-size 100 --out-prefix $o/hm"

cases=(
  # integers: decimal, no leading zero (CLI11 would read octal)
  "2|--max-points: '010' has a leading zero|octree $bun --max-points 010 --min-cell-size 0.01"
  "2|--map-size: '09' has a leading zero|heightmap $tumd $hm --map-size 09 --z-bins 0.1,1"
  "2|--seed: '010' has a leading zero|kitti $k --frames 0-1 --perturb 0.1,1 --seed 010"
  "2|--threads: '010' has a leading zero|grid $bun --cell-size 1 --threads 010"
  "2|--threads: must be a whole number from 0 to 1024, got '0x10'|grid $bun --cell-size 1 --threads 0x10"
  "2|--scan: '0100000' has a leading zero|lines $mines --preset urg04lx-mines --scan 0100000"
  "2|--min-hits: '01' has a leading zero|kitti $k --frames 0 --min-hits 01"
  # orders and bounds, as given
  "2|--min-range '1e2' exceeds --max-range '1e1'|kitti $k --frames 0 --min-range 1e2 --max-range 1e1"
  "2|--min-height '1e1' exceeds --max-height '1e0'|kitti $k --frames 0 --min-height 1e1 --max-height 1e0"
  "2|--min-range '1e1' must be below --max-range '1e0'|lines $mines --skip-tokens 24 --count 682 --min-range 1e1 --max-range 1e0"
  "2|--z-bins: '1e1,1e0' must be strictly increasing|heightmap $tumd $hm --z-bins 1e1,1e0"
  "2|--pitch-deg: '1e3' is out of range: -90 to 90|heightmap $tumd --camera $tumc --camera-height 1 --pitch-deg 1e3 --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix $o/hm"
  "2|--hfov-deg: '1e3' is out of range: 0 to 179.999|depth-to-cloud $tumd --hfov-deg 1e3 --out $o/x.pcd"
  "2|--angle-threshold-deg: '2e2' is out of range: 0 to 180|lines $csv --angle-threshold-deg 2e2"
)
expect_cases "${cases[@]}"
check "nothing written" test -z "$(ls -A "$o")"
check "a plain 0 and plain decimals are still counts" bash -c \
  "'$MM' octree '$bun' --max-points 10 --min-cell-size 0.01 --format json | grep -q '\"max_points\": 10,' &&
   '$MM' grid '$bun' --cell-size 1 --threads 0 >/dev/null"

# --- MPI: one line, first, once ----------------------------------------------------------------
if ! command -v mpirun >/dev/null; then
  skip_part "no mpirun"
  finish
fi
if "$MM" grid "$bun" --cell-size 1 --distributed 2>&1 >/dev/null | grep -q "built without MPI"; then
  skip_part "built without MPI"
  finish
fi
# mpi_expect NP CODE NEEDLE -- args: exit CODE; the first line of stderr holds NEEDLE; exactly one
# line of stderr comes from metricmap; nothing on stdout.
mpi_expect() {
  local np=$1 code=$2 needle=$3
  shift 4
  local rc=0
  timeout 120 mpirun --allow-run-as-root --oversubscribe -np "$np" "$MM" "$@" >"$tmp/out" 2>"$tmp/err" || rc=$?
  local mine
  mine=$(grep -c '^metricmap: ' "$tmp/err")
  if [ "$rc" != "$code" ] || ! head -n 1 "$tmp/err" | grep -qF -- "$needle" || [ "$mine" != 1 ] || [ -s "$tmp/out" ]; then
    echo "FAIL: mpirun -np $np $* -> exit $rc (want $code), $mine metricmap line(s), stderr: $(head -c 400 "$tmp/err")"
    fails=$((fails + 1))
  else
    echo "ok: -np $np exit $rc: $(head -n 1 "$tmp/err")"
  fi
}
occ=(occupancy "$k" --frames 0-1 --resolution 0.5 --max-range 20 --distributed)
# usage errors every rank finds: rank 0 says it once
mpi_expect 2 2 "metricmap: usage: --pcd-format has no effect without --out" -- grid "$bun" --cell-size 1 --distributed --pcd-format ascii
mpi_expect 3 2 "metricmap: usage: --cell-size: '1e999' is not a finite decimal number" -- grid "$bun" --cell-size 1e999 --distributed
mpi_expect 2 2 "metricmap: usage: --band is the height band of --out-map" -- "${occ[@]}" --band -1,1
mpi_expect 2 2 "metricmap: usage: --frames: frames must be in acquisition order" -- occupancy "$k" --frames 1,0 --resolution 0.5 --max-range 20 --distributed
mpi_expect 2 2 "metricmap: usage: unknown subcommand 'gird'" -- gird "$bun"
# an input only one rank reads: that rank says it, first
mpi_expect 2 1 "metricmap: error: $tmp/missing.pcd: cannot open" -- grid "$bun" "$tmp/missing.pcd" --cell-size 1 --distributed
cp "$bun" "$tmp/bun2.pcd"  # one file named twice is refused: a copy
mpi_expect 3 1 "metricmap: error: $tmp/missing.pcd: cannot open" -- grid "$tmp/missing.pcd" "$bun" "$tmp/bun2.pcd" --cell-size 1 --distributed --out "$o/g.pcd"
check "nothing written under MPI" test -z "$(ls -A "$o")"
finish
