#!/usr/bin/env bash
# `metricmap lines` on the real CARMEN logs (bzip2 as distributed, a gzip copy, a plain copy named
# without a telling extension): the scan's valid beams as an awk parse of the text counts them, the
# same segments from every copy, and a truncated stream refused naming the file.
# usage: lines_carmen.sh METRICMAP DATA SHARED_DATA   (skipped, exit 77, without the shared data)
MM=$1
DATA=$2
SHARED=$3
source "$(dirname "$0")/lib.sh"
log=$SHARED/radish_clf_raw/intel.clf.bz2
need_shared_data "$log"

# Scan 100 (0-based): the 101st FLASER line; valid beams are the ranges > 0.
want=$(bzcat "$log" | awk '$1 == "FLASER" && ++k == 101 { n = 0; for (i = 3; i < 3 + $2; ++i) if ($i > 0) ++n; print n; exit }')
run_json() {  # run_json FILE OUT: the JSON of scan 100, without the file name and the timings
  "$MM" lines "$1" --scan 100 --format json >"$tmp/raw.json" 2>"$tmp/err" &&
    jq -S 'del(.file, .seconds, .scans_per_second)' "$tmp/raw.json" >"$2"
}
check "lines reads intel.clf.bz2" run_json "$log" "$tmp/bz2.json"
check "scan 100 has the $want valid beams awk counts" \
  test "$(jq '.scans[0].points' "$tmp/bz2.json")" = "$want"
check "scan 100 is scan 100" test "$(jq '.scans[0].scan' "$tmp/bz2.json")" = 100
check "scan 100 has segments" test "$(jq '.scans[0].segments | length' "$tmp/bz2.json")" -gt 0
check "no line skipped" test "$(jq '.skipped_lines' "$tmp/bz2.json")" = 0

bzcat "$log" | gzip -c >"$tmp/intel.clf.gz"
cp "$tmp/intel.clf.gz" "$tmp/intel.log.gz"
bzcat "$log" >"$tmp/intel.txt"
for copy in intel.clf.gz intel.log.gz intel.txt; do
  check "lines reads $copy" run_json "$tmp/$copy" "$tmp/copy.json"
  check "$copy gives the same segments" cmp -s "$tmp/bz2.json" "$tmp/copy.json"
done

head -c 1000000 "$log" >"$tmp/cut.clf.bz2"
expect 1 "$tmp/cut.clf.bz2: corrupt or truncated bzip2 stream" -- "$MM" lines "$tmp/cut.clf.bz2"
expect 1 "out of range" -- "$MM" lines "$log" --scan 13631
finish
