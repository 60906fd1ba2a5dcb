#!/bin/bash
# End-to-end test of the ellipsoidDistance utility: output columns and values
# for a sphere pair with a closed form, every method with -method all, and a
# clear error (row number, exit status 1) for each kind of bad input.
#   ellipsoidDistanceCli.sh <path to ellipsoidDistance>
set -euo pipefail
exe="$1"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
header="a1,b1,c1,x1,y1,z1,qw1,qx1,qy1,qz1,a2,b2,c2,x2,y2,z2,qw2,qx2,qy2,qz2"
fail() { echo "FAIL: $*"; exit 1; }

# spheres of radii 1 and 0.5, centres 3 apart: distance 1.5
printf '%s\n%s\n%s\n' "$header" \
    "1,1,1,0,0,0,1,0,0,0,0.5,0.5,0.5,3,0,0,1,0,0,0" \
    "2,1,1,0,0,0,1,0,0,0,1,1,1,2.5,0,0,1,0,0,0" > "$tmp/pairs.csv"
"$exe" -method all -eps 1e-9 -o "$tmp/out.csv" "$tmp/pairs.csv"
head -n 1 "$tmp/out.csv" | grep -qx "row,method,status,distance,lower,upper,iterations,p1x,p1y,p1z,p2x,p2y,p2z,overlap" \
    || fail "output header"
[ "$(wc -l < "$tmp/out.csv")" -eq 17 ] || fail "expected 16 result rows (2 pairs x 8 methods)"
/usr/bin/python3 - "$tmp/out.csv" <<'PY' || fail "values"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    if r["row"] == "1":
        assert r["status"] == "converged", r
        assert abs(float(r["distance"]) - 1.5) < 1e-8, r
        assert float(r["lower"]) <= 1.5 <= float(r["upper"]), r
        assert r["overlap"] == "separated", r
    else:
        assert r["status"] == "overlapping" and r["overlap"] == "overlapping", r
        if r["method"] == "dual":
            assert abs(float(r["distance"]) + 0.5) < 1e-8, r   # signed: minus the depth
        else:
            assert float(r["distance"]) == 0, r
assert {r["method"] for r in rows} == {"movingBalls", "gjk", "newtonCoulomb", "exteriorPenalty", "jain", "dual", "auto", "paper"}
PY

# -method paper: Moving Balls near Ar 1 (the spheres), certified to the tolerance
"$exe" -method paper -eps 1e-9 "$tmp/pairs.csv" | tail -n +2 | head -n 1 \
    | grep -q "^1,paper,converged,1.5" || fail "-method paper"

# standard input and -epsRel
printf '%s\n%s\n' "$header" "1,1,1,0,0,0,1,0,0,0,1,1,1,0,3,0,1,0,0,0" \
    | "$exe" -method dual -epsRel 1e-10 - | tail -n 1 | grep -q "^1,dual,converged,1," || fail "stdin"

# bad input: exit status 1 and a message naming the row and the column
# expectError WHAT ROW PATTERN [OPTION...]: exit status 1 (never an abort) and a message matching PATTERN
expectError() {
    local what="$1" line="$2" pattern="$3" status
    shift 3
    printf '%s\n%s\n' "$header" "$line" > "$tmp/bad.csv"
    set +e
    "$exe" "$@" "$tmp/bad.csv" > "$tmp/out" 2> "$tmp/err"
    status=$?
    set -e
    [ "$status" -eq 1 ] || { cat "$tmp/err"; fail "$what: exit status $status, expected 1"; }
    grep -q -- "$pattern" "$tmp/err" || { cat "$tmp/err"; fail "$what: message lacks '$pattern'"; }
    echo "ok: $what: $(head -n 1 "$tmp/err")"
}
expectError "malformed row" "1,1,1,0,0,0,1,0,0" "row 1 .*fields"
expectError "not a number" "1,1,1,0,0,0,1,0,0,0,1,1,1,x,0,0,1,0,0,0" "row 1 .*column x2"
expectError "non-positive semi-axis" "1,0,1,0,0,0,1,0,0,0,1,1,1,3,0,0,1,0,0,0" "row 1 .*semi-axis b1"
expectError "quaternion far from unit" "1,1,1,0,0,0,1,0,0,0,1,1,1,3,0,0,1.1,0,0,0" "row 1 .*quaternion"
# outside the geometry core's supported range (they would overflow): a message naming the row and column
expectError "semi-axes 1e200" "1e200,1e200,1e200,0,0,0,1,0,0,0,1e200,1e200,1e200,3e200,0,0,1,0,0,0" \
    "row 1 .*semi-axis a1 = 1e200 must be in \[1e-35, 1e+35\]"
expectError "semi-axis 1e-300" "1,1,1,0,0,0,1,0,0,0,1,1e-300,1,3,0,0,1,0,0,0" "row 1 .*semi-axis b2 = 1e-300"
expectError "elongation 200" "200,1,1,0,0,0,1,0,0,0,1,1,1,300,0,0,1,0,0,0" "row 1 .*(a1,b1,c1).*at most 100"
expectError "centre 1e36" "1,1,1,1e36,0,0,1,0,0,0,1,1,1,3,0,0,1,0,0,0" "row 1 .*centre x1 = 1e36"
# a tolerance that rounds to 0 for a tiny pair
expectError "zero tolerance" "1e-35,1e-35,1e-35,0,0,0,1,0,0,0,1e-35,1e-35,1e-35,3e-35,0,0,1,0,0,0" \
    "row 1.*epsD" -epsRel 1e-300
# within 1e-6 of unit norm: normalised silently
printf '%s\n%s\n' "$header" "1,1,1,0,0,0,1.0000005,0,0,0,1,1,1,3,0,0,1,0,0,0" | "$exe" - > /dev/null \
    || fail "near-unit quaternion rejected"
# bad options: a message and exit status 1
set +e
"$exe" -method nope "$tmp/pairs.csv" 2> "$tmp/err"
status=$?
set -e
[ "$status" -eq 1 ] || fail "unknown method: exit status $status, expected 1"
grep -q "valid methods" "$tmp/err" || fail "unknown method message"
if "$exe" -eps 1e-6 -epsRel 1e-5 "$tmp/pairs.csv" > /dev/null 2> "$tmp/err"; then fail "-eps with -epsRel accepted"; fi
grep -q -- "-eps and -epsRel exclude each other" "$tmp/err" || { cat "$tmp/err"; fail "-eps with -epsRel message"; }
echo "PASS"
