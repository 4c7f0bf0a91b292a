#!/usr/bin/env bash
# docs/cli.md must be what scripts/gen-cli-doc.sh prints for this program.
source "$(dirname "$0")/lib.sh"
ROOT=$(cd "$(dirname "$0")/../.." && pwd)

test_cli_doc_matches_help() {
  "$ROOT/scripts/gen-cli-doc.sh" "$RS" >"$WORK/cli.md"
  if diff -u "$ROOT/docs/cli.md" "$WORK/cli.md" >"$WORK/diff.txt"; then
    pass cli_doc_up_to_date
  else
    fail cli_doc_up_to_date "docs/cli.md is stale; run scripts/gen-cli-doc.sh build/plugin/cli/roofsweep > docs/cli.md: $(head -20 "$WORK/diff.txt")"
  fi
}

test_every_command_has_an_example() {
  for cmd in $("$RS" --help | awk '/^Commands:/{on=1; next} on && /^  [a-z]/{print $1} on && /^$/{on=0}'); do
    if "$RS" "$cmd" --help | grep -q "^Example"; then pass "example_$cmd"; else fail "example_$cmd" "no example in --help"; fi
  done
}

run_tests
