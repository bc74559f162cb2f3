#!/usr/bin/env bash
# Issue 24, class 9: integer narrowing. Every integer option of every command is checked against
# the range of the type it is stored in before it is narrowed: a value beyond it is a usage error
# (exit 2, one line naming the option), never a wrapped value (`heightmap --obstacle-threshold
# 4294967296` used to become 0 and mark every cell an obstacle). The largest value each type
# holds is still accepted.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
k=$D/kitti_odometry_00
bun=$D/pcl_test_pcd/bunny.pcd
tum=$D/open3d_tum_depth
mines=$D/breezyslam_mines_urg04lx/exp2.dat
o=$tmp/o
mkdir -p "$o"
hm="heightmap $tum/TUM_depth.png --camera $tum/camera_primesense.json --auto-floor --resolution 0.05 --z-bins 0.1,1"
big=18446744073709551616  # 2^64
u32=4294967296            # 2^32

# Each row: exit code | text the one stderr line must hold | command.
cases=(
  # uint32 targets: the heightmap's obstacle threshold, kitti's min-hits
  "2|--obstacle-threshold|$hm --map-size 100 --obstacle-threshold $u32 --out-prefix $o/hm"
  "2|--obstacle-threshold|$hm --map-size 100 --obstacle-threshold 999999999999999999 --out-prefix $o/hm"
  "2|--obstacle-threshold|$hm --map-size 100 --obstacle-threshold $big --out-prefix $o/hm"
  "2|--obstacle-threshold|$hm --map-size 100 --obstacle-threshold -1 --out-prefix $o/hm"
  "2|--min-hits|kitti $k --frames 0 --min-hits $u32 --out-map $o/m.pgm"
  "2|--min-hits|kitti $k --frames 0 --min-hits 4294967297 --out-map $o/m.pgm"
  "2|--min-hits|kitti $k --frames 0 --min-hits 999999999999999999 --out-map $o/m.pgm"
  "2|--min-hits|kitti $k --frames 0 --min-hits $big --out-map $o/m.pgm"
  # the map side: cells = side^2 must be countable (64 bits)
  "2|--map-size|$hm --map-size $u32 --out-prefix $o/hm"
  "2|--map-size|$hm --map-size 999999999999999999 --out-prefix $o/hm"
  "2|--map-size|$hm --map-size $big --out-prefix $o/hm"
  # unsigned: kitti --seed, grid --threads
  "2|--seed|kitti $k --frames 0 --perturb 0.1,1 --seed $u32 --out-poses $o/p.txt"
  "2|--seed|kitti $k --frames 0 --perturb 0.1,1 --seed -1 --out-poses $o/p.txt"
  "2|--threads|grid $bun --cell-size 0.01 --threads 4294967297"
  "2|--threads|grid $bun --cell-size 0.01 --threads $big"
  # size_t / long long targets: 2^64 and beyond
  "2|--first|kitti $k --first $big --count 1"
  "2|--count|kitti $k --first 0 --count $big"
  "2|--frames|kitti $k --frames $big"
  "2|--frames|occupancy $k --frames $big --resolution 0.5"
  "2|--max-points|octree $bun --max-points $big --min-cell-size 0.01"
  "2|--max-points|view $bun --octree --max-points $big"
  "2|--scan|view $mines --preset urg04lx-mines --scan $big"
  "2|--scan|lines $mines --preset urg04lx-mines --scan $big"
  "2|--min-points|lines $mines --preset urg04lx-mines --min-points $big"
  "2|--count|lines $mines --skip-tokens 24 --count $big"
  "2|--skip-tokens|lines $mines --skip-tokens $big --count 682"
  "2|--window-size|view $bun --window-size ${u32}x800"
  "2|--window-size|view $bun --window-size 800x${big}"
  "2|--max-memory|--max-memory $big info $bun"
  "2|max_points|compare $bun --config cell_size=1,min_cell_size=1,max_points=$u32"
)
expect_cases "${cases[@]}"
check "nothing written by a refused option" test -z "$(ls -A "$o")"

# The largest value of each target type is accepted and kept.
check "--obstacle-threshold 4294967295 is accepted: no cell is an obstacle" bash -c \
  "'$MM' $hm --map-size 100 --obstacle-threshold 4294967295 --out-prefix '$o/hm' >'$tmp/hm.json' &&
   grep -q '\"obstacle_cells\": 0' '$tmp/hm.json'"
# (without --out-map: a map_server map with no occupied cell is refused)
check "--min-hits 4294967295 is accepted: no cell is occupied" bash -c \
  "'$MM' kitti '$k' --frames 0 --min-hits 4294967295 --format json >'$tmp/k.json' &&
   grep -q '\"occupied_cells\": 0' '$tmp/k.json'"
finish
