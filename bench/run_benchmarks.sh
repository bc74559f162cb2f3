#!/usr/bin/env bash
# Build the benchmarks in Release and run each one in its own process, so that each process's
# peak RSS (VmHWM, counter peak_rss_MiB) belongs to one contender; BM_DataOnly is the baseline
# (the replicated cloud alone). Usage: bench/run_benchmarks.sh [extra benchmark flags]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DMETRICMAP_BUILD_BENCH=ON \
      -DMETRICMAP_BUILD_TESTS=OFF -DMETRICMAP_BUILD_APPS=OFF >/dev/null
cmake --build build/bench -j "${JOBS:-2}" --target metricmap_bench >/dev/null
for b in BM_DataOnly BM_OccupancyGrid BM_OccupancyGridFresh BM_PclVoxelGrid BM_SortBasedGridFloor \
         BM_AdaptiveOctree BM_AdaptiveOctreeFresh BM_PclOctreeDynamicDepth \
         BM_SplitAndMergeUrg BM_SequentialRansacUrg BM_HeightMapKinectFrame \
         BM_DepthToCloudKinectFrame BM_ScanMapperAddScan; do
  build/bench/bench/metricmap_bench --benchmark_filter="^$b(/|\$)" --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true "$@" 2>/dev/null | grep -E "_median|^BM_DataOnly"
done
