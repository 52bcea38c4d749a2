#!/usr/bin/env bash
# Oracle tests of tools/penetration_check, the independent check of
# penetration on the true solids of revolution, against closed forms:
# - a peg of radius 9.9 mm in a bore of 10 mm (100 um radial clearance),
#   axes parallel, offset e: the depth is e - 100 um (0 at and below 100 um);
# - the same peg standing on a plate, sunk d below its top face: depth d;
# - the peg tilted by theta about x over the plate, its frame origin at
#   height 0.01 + R sin(theta) - d: its lowest rim point is d deep;
# - a part earlier in the sequence is fixed at its target;
# - bad input: a missing pose column, a box part and a part without a
#   profile (exit 2, one line).
#
# Usage: penetration_check_test.sh REPO_ROOT
set -uo pipefail
root="$1"
check="$root/tools/penetration_check"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

cat >"$work/scene.json" <<'JSON'
{"format": "vahf-scene/1", "name": "oracle",
 "operator": {"height": 1.75, "arm_length": 0.74, "position": [0, -0.4], "facing_deg": 90},
 "parts": [
  {"name": "bore", "role": "base", "density": 7850, "friction": 0.1,
   "geometry": {"type": "revolution",
                "profile": [[0.01, 0], [0.02, 0], [0.02, 0.05], [0.01, 0.05], [0.01, 0]]},
   "pose": {"position": [0, 0, 0]}},
  {"name": "plate", "role": "base", "density": 7850, "friction": 0.1,
   "geometry": {"type": "revolution",
                "profile": [[0, 0], [0.05, 0], [0.05, 0.01], [0, 0.01], [0, 0]]},
   "pose": {"position": [1, 0, 0]}},
  {"name": "peg", "role": "assembling", "density": 7850, "friction": 0.1,
   "geometry": {"type": "revolution",
                "profile": [[0, 0], [0.0099, 0], [0.0099, 0.03], [0, 0.03], [0, 0]]},
   "pose": {"position": [0, 0, 0.1]}, "target": {"position": [0, 0, 0.01]}},
  {"name": "cap", "role": "assembling", "density": 7850, "friction": 0.1,
   "geometry": {"type": "revolution",
                "profile": [[0, 0], [0.0099, 0], [0.0099, 0.01], [0, 0.01], [0, 0]]},
   "pose": {"position": [0, 0, 0.2]}, "target": {"position": [0, 0, 0.04]}}],
 "sequence": ["peg", "cap"]}
JSON

# trace X Y Z QW QX QY QZ: a one-row trace at that pose.
trace() {
  printf 't,x,y,z,qw,qx,qy,qz\n0.001,%s,%s,%s,%s,%s,%s,%s\n' "$@" >"$work/trace.csv"
}
# depth [--position N]: the deepest penetration the check prints, um.
depth() {
  "$check" "$work/scene.json" "$work/trace.csv" "$@" |
    sed -n 's/^deepest penetration: \([0-9.]*\) um.*/\1/p'
}
# expect NAME GOT WANT: |GOT - WANT| <= 0.01 um.
expect() {
  if ! awk -v g="$2" -v w="$3" 'BEGIN { exit !(g != "" && (g - w) ^ 2 <= 1e-4) }'; then
    fail "$1: got '$2' um, want $3 um"
  fi
}

for e_um in 50 100 130 175; do
  trace "$(awk -v e="$e_um" 'BEGIN { printf "%.9f", e * 1e-6 }')" 0 0.01 1 0 0 0
  want=$(awk -v e="$e_um" 'BEGIN { print (e > 100 ? e - 100 : 0) }')
  expect "peg offset $e_um um in the bore" "$(depth)" "$want"
done

trace 1 0 0.00998 1 0 0 0
expect "peg sunk 20 um into the plate" "$(depth)" 20

theta_deg=3
d_um=7
read -r z qw qx < <(awk -v t="$theta_deg" -v d="$d_um" 'BEGIN {
  th = t * atan2(0, -1) / 180
  printf "%.12f %.12f %.12f\n", 0.01 + 0.0099 * sin(th) - d * 1e-6, cos(th / 2), sin(th / 2) }')
trace 1 0 "$z" "$qw" "$qx" 0 0
expect "peg tilted $theta_deg deg, lowest rim $d_um um deep" "$(depth)" "$d_um"

# The cap at position 1: the peg is fixed at its target (0, 0, 0.01), top at
# 0.04; the cap 30 um lower than that top, on the peg's axis.
trace 0 0 0.03997 1 0 0 0
expect "cap sunk 30 um into the peg at its target" "$(depth --position 1)" 30
out=$("$check" "$work/scene.json" "$work/trace.csv" --position 1)
grep -q "cap in peg" <<<"$out" || fail "the pair is not named: $out"

# Bad input: exit 2 and one line naming the file and what is wrong.
printf 't,x,y,z,qw,qx,qy\n0,0,0,0,1,0,0\n' >"$work/short.csv"
err=$("$check" "$work/scene.json" "$work/short.csv" 2>&1 >/dev/null)
status=$?
[[ $status -eq 2 ]] || fail "a trace without qz: exit $status, want 2"
[[ $(wc -l <<<"$err") -eq 1 && $err == *short.csv*qz* ]] || fail "a trace without qz: '$err'"
cat "$work/scene.json" |
  python3 -c 'import json,sys; s=json.load(sys.stdin); s["parts"][1]["geometry"]={"type":"box","size":[1,1,1]}; json.dump(s,sys.stdout)' \
  >"$work/box.json"
err=$("$check" "$work/box.json" "$work/trace.csv" 2>&1 >/dev/null)
status=$?
[[ $status -eq 2 && $err == *box.json*plate*box* ]] || fail "a box part: exit $status, '$err'"

cat "$work/scene.json" |
  python3 -c 'import json,sys; s=json.load(sys.stdin); del s["parts"][0]["geometry"]["profile"]; json.dump(s,sys.stdout)' \
  >"$work/noprofile.json"
err=$("$check" "$work/noprofile.json" "$work/trace.csv" 2>&1 >/dev/null)
status=$?
[[ $status -eq 2 && $(wc -l <<<"$err") -eq 1 && $err == *noprofile.json*profile* ]] ||
  fail "a part without a profile: exit $status, '$err'"

if [[ $failures -gt 0 ]]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "all penetration_check oracles pass"
