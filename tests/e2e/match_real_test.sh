#!/usr/bin/env bash
# roofsweep match on real images with annotated line correspondences
# (Oxford VGG Merton College I, colour, 3 views; Model House, grey, 10
# views), and on a real drone block against its DSM: the scores are printed, and floors well below the measured
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

# The real drone block (ODM, four oblique views, hilly: 56 m of relief) has no
# reference model; its DSM is the check, which the matching does not use. The
# lines seen in three views or more lie on the surface: 40 lines, 93.9 % of
# their length in session 36; 25 lines, 86.5 %, before the height range
# followed the ground under each point.
test_odm_drone() {
  local s
  s=$(shared_or_skip data/multiview/orthority-odm-drone)
  [[ -n "$s" ]] || return
  expect_ok import_odm import opensfm "$s/opensfm/reconstruction.json" -images "$s/images" \
    -dsm "$s/odm_dem/dsm.tif" -terrain_window 40 -o "$WORK/odm.json" -q || return
  expect_ok match_odm match "$WORK/odm.json" -o "$WORK/odm_lines.gpkg" || return
  grep "surface model" "$WORK/stdout.txt"
  python3 - "$WORK/stdout.txt" <<'PY' && pass odm_lines_on_the_dsm || fail odm_lines_on_the_dsm "$(tail -c 600 "$WORK/stdout.txt")"
import re, sys
t = open(sys.argv[1]).read()
m = re.search(r"3D lines on the surface model \(within 2 m\): two views ([0-9.]+)% of [0-9]+ m "
              r"\(([0-9]+) lines\); three or more ([0-9.]+)% of [0-9]+ m \(([0-9]+) lines\)", t)
assert m, t[-800:]
assert int(m.group(4)) >= 30 and float(m.group(3)) >= 90, m.group(0)
PY
}

run_tests
