#!/usr/bin/env bash
# Runs two builds of the command on the same inputs and compares every output file and report
# byte for byte, timings removed ("seconds", "ms", "real time" fields and lines). Used to show
# that a restructuring changed no output.
# usage: tools/compare_outputs.sh OLD_METRICMAP NEW_METRICMAP [DATA]
set -uo pipefail
old=$(realpath "$1") new=$(realpath "$2")
data=${3:-$(cd "$(dirname "$0")/../data" && pwd)}
shared=$(cd "$(dirname "$0")/../../shared/data" 2>/dev/null && pwd || true)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
k=$data/kitti_odometry_00
cases=(
  "info $data/pcl_test_pcd/bunny.pcd --format json"
  "grid $data/pcl_test_pcd/bunny.pcd --cell-size 0.01 --format json --out @/g.pcd"
  "octree $data/pcl_test_pcd/milk.pcd --max-points 50 --min-cell-size 0.005 --format json --out @/o.pcd"
  "lines $data/breezyslam_mines_urg04lx/exp2.dat --preset urg04lx-mines --format json"
  "kitti $k --frames 0-3 --out-cloud @/k.pcd --out-map @/k.pgm --out-poses @/k.txt --format json"
  "odometry $k --frames 0-5 --out-poses @/p.txt --format json"
  "map $k --frames 0-5 --poses reference --out-map @/m.pgm --out-cloud @/m.pcd --format json"
  "occupancy $k --frames 0-2 --resolution 0.2 --max-range 40 --out @/o.bt --out-map @/o.pgm --band -2,1 --format json"
  "evaluate $k/poses/00.txt --reference $k/poses/00.txt --format json"
)
if [ -n "$shared" ]; then
  cases+=(
    "slam2d $shared/radish_clf_raw/intel.clf.bz2 --frames 0-1500 --out-poses @/s.tum --out-map @/s.pgm --out-graph @/s.g2o --format json"
    "posegraph $shared/posegraph_g2o/MIT.g2o --out @/mit.g2o --format json"
    "odometry $shared/balm_realworld_dev --frames 0-10 --out-poses @/b.txt --format json"
  )
fi
# Reports without their timings: JSON with every time-like key removed, text without the lines
# that print times.
strip() {
  /usr/bin/python3 - "$1" <<'PY'
import json, re, sys
text = open(sys.argv[1], errors="replace").read()
TIME = re.compile(r"(^|_)(seconds|ms|s|load|write|total|real_time_factor|per_second|ms_per_scan)$")
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items() if not (TIME.search(k) or k in ("seconds", "timing"))}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return v
try:
    print(json.dumps(clean(json.loads(text)), sort_keys=True, indent=1))
except ValueError:
    for line in text.splitlines():
        if not re.search(r"seconds|ms/scan| ms\b|real time|time:|[0-9] s\b", line):
            print(line)
PY
}
differ=0
for c in "${cases[@]}"; do
  for side in old new; do
    d=$work/$side
    rm -rf "$d" && mkdir -p "$d"
    bin=$old; [ $side = new ] && bin=$new
    # shellcheck disable=SC2086
    (cd "$d" && "$bin" ${c//@/$d} >"$d/stdout" 2>"$d/stderr"; echo $? >"$d/rc")
  done
  same=1
  for f in $(cd "$work/old" && ls); do
    if [ "$f" = stdout ] || [ "$f" = stderr ]; then
      cmp -s <(strip "$work/old/$f") <(strip "$work/new/$f") || { same=0; echo "  $f differs"; }
    else
      cmp -s "$work/old/$f" "$work/new/$f" || { same=0; echo "  $f differs"; }
    fi
  done
  if [ $same = 1 ]; then echo "same: ${c%% *} (exit $(cat "$work/new/rc"), $(ls "$work/new" | wc -l) files)"; else echo "DIFFERENT: $c"; differ=1; fi
done
exit $differ
