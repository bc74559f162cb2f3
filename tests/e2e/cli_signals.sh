#!/usr/bin/env bash
# Issue 24, class 3: interrupted runs. A run interrupted by SIGINT, SIGTERM, SIGHUP or SIGPIPE
# while its outputs are being written leaves no `NAME.tmp-PID-N` temporary and no output, and
# ends by that signal. A run killed by SIGKILL cannot clean up; the next run writing the same
# output removes the temporaries of the dead run (and leaves those of live processes and of
# other outputs alone). Real signals, sent while a temporary exists.
MM=$1
DATA=$2
source "$(dirname "$0")/lib.sh"
D=$(cd "$DATA" && pwd)
tum=$D/open3d_tum_depth
k=$D/kitti_odometry_00
o=$tmp/o
mkdir -p "$o"

# Long writes: a 5000 x 5000 height map (three PNGs and a 300 MB .npy, seconds of writing) and
# a KITTI global cloud of six frames written as ASCII PCD.
long_heightmap=("$MM" heightmap "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json"
  --auto-floor --resolution 0.002 --map-size 5000 --z-bins 0.1,1 --out-prefix "$o/hm")
long_kitti=("$MM" kitti "$k" --frames 0-5 --voxel 0 --out-cloud "$o/k.pcd" --pcd-format ascii
  --out-poses "$o/poses.txt" --out-map "$o/m.pgm" --map-resolution 0.05)

signum() { kill -l "$1"; }

# interrupt SIG CMD...: start CMD, wait until a temporary appears in $o, send SIG, then the run
# must end by SIG and leave $o empty.
interrupt() {
  local sig=$1
  shift
  rm -rf "${o:?}"/* "$o"/.[!.]* 2>/dev/null
  # a background job of a script ignores SIGINT and SIGQUIT: give the command the defaults back
  env --default-signal=INT,QUIT "$@" >/dev/null 2>"$tmp/err" &
  local pid=$! saw=0
  for ((i = 0; i < 6000; ++i)); do
    if ls -A "$o" | grep -q '\.tmp-'; then saw=1; break; fi
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  kill -"$sig" "$pid" 2>/dev/null
  local rc=0
  { wait "$pid"; } 2>/dev/null || rc=$?  # the shell's "Hangup" notice is not the command's
  local left
  left=$(ls -A "$o" | tr '\n' ' ')
  if [ "$saw" != 1 ]; then
    echo "FAIL: SIG$sig: no temporary seen before the run ended (exit $rc): $*"
    fails=$((fails + 1))
  elif [ "$rc" != $((128 + $(signum "$sig"))) ] || [ -n "$left" ]; then
    echo "FAIL: SIG$sig: exit $rc (want $((128 + $(signum "$sig")))), left in the output directory: '$left': $*"
    fails=$((fails + 1))
  else
    echo "ok: SIG$sig mid-write: ended by the signal, nothing left"
  fi
}

for sig in INT TERM HUP; do interrupt "$sig" "${long_heightmap[@]}"; done
for sig in INT TERM; do interrupt "$sig" "${long_kitti[@]}"; done

# SIGKILL, then the same command again: the dead run's temporaries are removed by the rerun.
for cmd in heightmap kitti; do
  declare -n long="long_$cmd"
  rm -rf "${o:?}"/*
  "${long[@]}" >/dev/null 2>&1 &
  pid=$!
  for ((i = 0; i < 6000; ++i)); do
    ls -A "$o" | grep -q '\.tmp-' && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  check "$cmd: SIGKILL mid-write leaves temporaries (nothing can run)" test -n "$(ls -A "$o" | grep '\.tmp-')"
  sleep 100 &
  live=$!
  touch "$o/hm_counts.tmp-$live-0.npy" "$o/k.tmp-$live-3.pcd"  # a live process's temporaries
  check "$cmd: the rerun succeeds" "${long[@]}" >/dev/null
  check "$cmd: the rerun removed the dead run's temporaries" test -z "$(ls -A "$o" | grep '\.tmp-' | grep -v "\.tmp-$live-")"
  check "$cmd: a live process's temporaries are left alone" test "$(ls -A "$o" | grep -c "\.tmp-$live-")" = 2
  kill "$live"
  wait "$live" 2>/dev/null
done
unset -n long

# Stale temporaries of every output form, by a dead PID: removed by the run writing that output;
# temporaries of other names, and files that only look alike, stay.
dead=$(bash -c 'echo $$')
stale_case() {  # stale_case "STALE NAMES" "KEPT NAMES" CMD...
  local stale=$1 kept=$2
  shift 2
  rm -rf "${o:?}"/* "$o"/.[!.]* 2>/dev/null
  for f in $stale $kept; do
    if [[ $f == */ ]]; then mkdir -p "$o/$f" && touch "$o/$f/x"; else touch "$o/$f"; fi
  done
  local rc=0
  "$@" >/dev/null 2>"$tmp/err" || rc=$?
  local bad=""
  for f in $stale; do [ -e "$o/$f" ] && bad="$bad $f"; done
  for f in $kept; do [ -e "$o/$f" ] || bad="$bad (removed:$f)"; done
  if [ "$rc" != 0 ] || [ -n "$bad" ]; then
    echo "FAIL: stale temporaries: exit $rc, left/removed wrongly:$bad: $* ($(head -c 200 "$tmp/err"))"
    fails=$((fails + 1))
  else
    echo "ok: stale temporaries removed: $stale"
  fi
}
bun=$D/pcl_test_pcd/bunny.pcd
stale_case "g.tmp-$dead-0.pcd g.tmp-$dead-0.tmp-$dead-1.pcd" "other.tmp-$dead-0.pcd g.tmp-x-0.pcd g.tmp-$dead-0.csv" \
  "$MM" grid "$bun" --cell-size 0.01 --out "$o/g.pcd"
stale_case "cells.tmp-$dead-12.csv" "g.tmp-$dead-0.pcd" "$MM" grid "$bun" --cell-size 0.01 --cells "$o/cells.csv"
stale_case "poses.tmp-$dead-2.txt poses.tmp-$dead-2.tmp-$dead-3.txt" "posesx.tmp-$dead-2.txt" \
  "$MM" kitti "$k" --frames 0 --out-poses "$o/poses.txt"
stale_case "m.tmp-$dead-1.pgm m.tmp-$dead-2.yaml m.tmp-$dead-4.pcd" "" \
  "$MM" occupancy "$k" --frames 0 --resolution 0.5 --max-range 20 --out-map "$o/m.pgm" --band -1,1 --out-cloud "$o/m.pcd"
stale_case "hm_counts.tmp-$dead-5.npy hm_layers.tmp-$dead-4.png" "" \
  "$MM" heightmap "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" --auto-floor \
  --resolution 0.05 --map-size 100 --z-bins 0.1,1 --out-prefix "$o/hm"
stale_case "d.tmp-$dead-0.pcd" "" "$MM" depth-to-cloud "$tum/TUM_depth.png" --camera "$tum/camera_primesense.json" --out "$o/d.pcd"
finish
