# Helpers for the end-to-end tests of the roofsweep program. Each test
# script sources this, defines test_* functions and calls run_tests.
set -u
RS=${RS:?RS must point at the roofsweep program}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/roofsweep_e2e.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
PASSED=0
FAILED=0
FAILED_NAMES=()

# expect_fail NAME OUTPUT_THAT_MUST_NOT_EXIST PATTERN -- roofsweep args...
#   The command must exit non-zero, print exactly one "ERROR" line on stderr
#   matching PATTERN (grep -E), and leave no output file behind.
expect_fail() {
  local name=$1 out=$2 pattern=$3
  shift 4
  local err="$WORK/stderr.txt" rc=0
  "$RS" "$@" >"$WORK/stdout.txt" 2>"$err" || rc=$?
  local nerr
  nerr=$(grep -c '^ERROR' "$err" || true)
  if [[ $rc -eq 0 ]]; then
    fail "$name" "exit code 0 (expected failure)"
  elif [[ $nerr -ne 1 ]]; then
    fail "$name" "expected one ERROR line, got $nerr: $(head -c 400 "$err")"
  elif ! grep -qE -- "$pattern" "$err"; then
    fail "$name" "error does not match /$pattern/: $(head -c 400 "$err")"
  elif [[ -n "$out" && -e "$out" ]]; then
    fail "$name" "output $out was left behind"
  elif [[ -n "$out" ]] && compgen -G "$out.*tmp*" >/dev/null; then
    fail "$name" "temporary file left behind: $(compgen -G "$out.*tmp*")"
  else
    pass "$name"
  fi
}

expect_ok() {
  local name=$1
  shift
  local rc=0
  "$RS" "$@" >"$WORK/stdout.txt" 2>"$WORK/stderr.txt" || rc=$?
  if [[ $rc -ne 0 ]]; then
    fail "$name" "exit $rc: $(head -c 600 "$WORK/stderr.txt")"
    return 1
  fi
  pass "$name"
}

pass() { PASSED=$((PASSED + 1)); echo "ok   $1"; }
fail() { FAILED=$((FAILED + 1)); FAILED_NAMES+=("$1"); echo "FAIL $1: $2"; }

# shared_or_skip REL: path below the shared data folder, or "" (and a
# visible message); a failure when ROOFSWEEP_REQUIRE_SHARED=1.
shared_or_skip() {
  local dir=${ROOFSWEEP_SHARED_DIR:-${ROOFSWEEP_SHARED_DIR_DEFAULT:-}}
  if [[ -n "$dir" && -e "$dir/$1" ]]; then
    echo "$dir/$1"
    return
  fi
  if [[ "${ROOFSWEEP_REQUIRE_SHARED:-0}" == 1 ]]; then
    fail "shared:$1" "shared data missing (ROOFSWEEP_REQUIRE_SHARED=1)" >&2
  else
    echo "SKIP: shared data not found: $1" >&2
  fi
  echo ""
}

# run_tests: every test_* function, or those whose names match the
# extended regular expression E2E_TESTS (E2E_SKIP: leave those matching it
# out), so that one script's tests can run as several CTest tests, each
# within its time limit. The seconds each took follow its name.
run_tests() {
  local t start
  for t in $(declare -F | awk '{print $3}' | grep '^test_'); do
    [[ -n "${E2E_TESTS:-}" ]] && ! grep -qE -- "$E2E_TESTS" <<<"$t" && continue
    [[ -n "${E2E_SKIP:-}" ]] && grep -qE -- "$E2E_SKIP" <<<"$t" && continue
    start=$SECONDS
    "$t"
    echo "--   $t: $((SECONDS - start)) s"
  done
  echo "$PASSED passed, $FAILED failed"
  [[ $FAILED -eq 0 ]]
}
