#!/usr/bin/env bash
# roofsweep match on real images with annotated line correspondences
# (Oxford VGG Merton College I, colour, 3 views; Model House, grey, 10
# views): the scores are printed, and floors well below the measured
# figures guard against regressions. The issue's target (95 % match
# precision) is not reached; see the issue-5 notes for the figures.
source "$(dirname "$0")/lib.sh"

# score SET MIN_PRECISION MIN_RECALL
score() {
  local name=$1 min_p=$2 min_r=$3 s
  s=$(shared_or_skip "data/multiview/oxford-vgg/$name")
  [[ -n "$s" ]] || return
  expect_ok "import_$name" import vgg "$s" -o "$WORK/$name.json" -q || return
  expect_ok "match_$name" match "$WORK/$name.json" -o "$WORK/$name.gpkg" -truth "$s" || return
  grep -E "match precision|recall|3D:" "$WORK/stdout.txt"
  python3 - "$WORK/stdout.txt" "$min_p" "$min_r" <<'PY' && pass "${name}_scores" || fail "${name}_scores" "$(tail -5 "$WORK/stdout.txt")"
import re, sys
t = open(sys.argv[1]).read()
p = float(re.search(r"match precision ([0-9.]+)%", t).group(1))
r = float(re.search(r"recall ([0-9.]+)% of annotated pairs", t).group(1))
d = float(re.search(r"\(([0-9.]+)% of the scene size", t).group(1))
assert p >= float(sys.argv[2]), ("precision", p)
assert r >= float(sys.argv[3]), ("recall", r)
# The correctly matched lines lie close to the annotated 3D lines.
assert d < 1.0, ("3D distance", d)
PY
}

test_merton1() { score merton1 60 20; }
test_model_house() { score model_house 60 40; }

run_tests
