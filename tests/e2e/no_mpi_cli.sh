#!/usr/bin/env bash
# Built without MPI: --distributed is a usage error (exit 2, one line), the commands otherwise
# unchanged. Usage: no_mpi_cli.sh METRICMAP DATA
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
S="$DATA/ua_mapas_metricos_pcd/poli000.pcd"
expect 2 "built without MPI" -- "$MM" grid "$S" --cell-size 0.1 --distributed
expect 2 "built without MPI" -- "$MM" occupancy "$DATA/kitti_odometry_00" --frames 0-1 \
  --resolution 0.2 --max-range 30 --distributed
check "grid without --distributed still works" "$MM" grid "$S" --cell-size 0.1 --format json
finish
