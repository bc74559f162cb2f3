# Shared helpers for the end-to-end CLI tests. Source after setting MM and DATA.
set -u
fails=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# expect CODE NEEDLE -- command...: exit code CODE, exactly one line on stderr containing NEEDLE,
# nothing on stdout, within 60 s.
expect() {
  local code=$1 needle=$2
  shift 3
  local rc=0
  timeout 60 "$@" >"$tmp/out" 2>"$tmp/err" || rc=$?
  local lines
  lines=$(wc -l <"$tmp/err")
  if [ "$rc" != "$code" ] || [ "$lines" != 1 ] || ! grep -qF -- "$needle" "$tmp/err" || [ -s "$tmp/out" ]; then
    echo "FAIL: $* -> exit $rc (want $code), stderr ($lines lines): $(head -c 300 "$tmp/err")"
    fails=$((fails + 1))
  else
    echo "ok: exit $rc: $(cat "$tmp/err")"
  fi
}

# expect_cases "CODE|NEEDLE|ARGS" ...: `expect` for each row, running "$MM" ARGS (split on spaces).
expect_cases() {
  local row code needle cmd
  for row in "$@"; do
    IFS='|' read -r code needle cmd <<<"$row"
    # shellcheck disable=SC2086
    expect "$code" "$needle" -- "$MM" $cmd
  done
}

check() {  # check DESCRIPTION command...: the command must succeed
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fails=$((fails + 1)); fi
}

# skip REASON: the whole script is skipped (exit 77, counted as skipped by ctest).
skip() {
  echo "skip: $*"
  exit 77
}

# need_shared_data PATH...: skip unless every PATH exists; with METRICMAP_REQUIRE_SHARED_DATA=1
# (scripts/test where ../shared/data exists) a missing PATH is a failure instead.
need_shared_data() {
  local p
  for p in "$@"; do
    if [ ! -e "$p" ]; then
      if [ "${METRICMAP_REQUIRE_SHARED_DATA:-0}" = 1 ]; then
        echo "FAIL: $p is missing (METRICMAP_REQUIRE_SHARED_DATA=1)"
        exit 1
      fi
      skip "$p is missing"
    fi
  done
}

# has_shared_data PATH: true when PATH exists; otherwise the part that needs it is skipped (finish
# then exits 77), or, with METRICMAP_REQUIRE_SHARED_DATA=1, counted as a failure.
skipped_parts=0
has_shared_data() {
  [ -e "$1" ] && return 0
  if [ "${METRICMAP_REQUIRE_SHARED_DATA:-0}" = 1 ]; then
    echo "FAIL: $1 is missing (METRICMAP_REQUIRE_SHARED_DATA=1)"
    fails=$((fails + 1))
  else
    echo "skip: $1 is missing"
    skipped_parts=$((skipped_parts + 1))
  fi
  return 1
}

# skip_part REASON: the cases that follow cannot run here (a tool is missing); finish exits 77.
skip_part() {
  echo "skip: $*"
  skipped_parts=$((skipped_parts + 1))
}

finish() {
  if [ "$fails" -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
  if [ "$skipped_parts" -ne 0 ]; then echo "passed, $skipped_parts part(s) skipped"; exit 77; fi
  echo "all passed"
}
