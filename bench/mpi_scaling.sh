#!/usr/bin/env bash
# 1 vs 2 MPI ranks on 4 copies of the bundled KITTI frames.
# Google Benchmark cannot host mpirun (one process, MPI_Init once), so this script times whole
# `mpirun -np N metricmap ... --distributed` runs with hyperfine; both sides pay mpirun's start.
#   occupancy: frames 0-5 four times (24 scans cast, 0.1 m voxels, 40 m range)
#   grid:      the six velodyne .bin files four times (24 files, 0.05 m cells); one rank builds
#              with all cores unless --threads 1 (two ranks: one thread each)
# Transport: one machine, so shared memory (pml ob1, btl self,vader), which skips UCX's start-up
# probing (~0.2 s per run here); MCA="" keeps OpenMPI's own choice.
# Usage: bench/mpi_scaling.sh [METRICMAP]   (default build/release/apps/metricmap)
set -euo pipefail
cd "$(dirname "$0")/.."
MM=${1:-build/release/apps/metricmap}
K=data/kitti_odometry_00
MCA=${MCA-"--mca pml ob1 --mca btl self,vader"}
read -r -a mca <<<"$MCA"
mpi=(mpirun --allow-run-as-root --oversubscribe --bind-to none "${mca[@]}")
bins=()
for copy in 1 2 3 4; do bins+=("$K"/sequences/00/velodyne/*.bin); done
occ="$MM occupancy $K --frames 0-5,0-5,0-5,0-5 --resolution 0.1 --max-range 40 --distributed --format json"
grid="$MM grid ${bins[*]} --cell-size 0.05 --distributed --format json"
hyperfine --warmup 1 --runs "${RUNS:-5}" --export-markdown /dev/stdout \
  -n "occupancy 1 rank" "${mpi[*]} -np 1 $occ" -n "occupancy 2 ranks" "${mpi[*]} -np 2 $occ" \
  -n "grid 1 rank" "${mpi[*]} -np 1 $grid" -n "grid 1 rank, 1 thread" "${mpi[*]} -np 1 $grid --threads 1" \
  -n "grid 2 ranks" "${mpi[*]} -np 2 $grid"
