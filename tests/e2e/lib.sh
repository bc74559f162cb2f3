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

finish() {
  if [ "$fails" -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
  echo "all passed"
}
