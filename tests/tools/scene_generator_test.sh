#!/usr/bin/env bash
# The shipped cylinder scenes are what tools/scenes/hydraulic_cylinder.py
# writes: the generator run into a scratch folder gives every one of them
# byte for byte, so a change to one without the other fails here.
#
# Usage: scene_generator_test.sh REPO_ROOT
set -uo pipefail
root="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$root" && python3 tools/scenes/hydraulic_cylinder.py "$work") || {
  echo "FAIL: the generator did not run" >&2
  exit 1
}
failures=0
count=0
for generated in "$work"/*.json; do
  name="$(basename "$generated")"
  count=$((count + 1))
  if ! cmp -s "$generated" "$root/experiments/scenes/$name"; then
    echo "FAIL: experiments/scenes/$name differs from what the generator writes:" >&2
    diff "$generated" "$root/experiments/scenes/$name" | head -20 >&2
    failures=$((failures + 1))
  fi
done
if [ "$count" -ne 4 ]; then
  echo "FAIL: the generator wrote $count scenes, not the 4 shipped ones" >&2
  failures=$((failures + 1))
fi
[ "$failures" -eq 0 ] && echo "PASS: $count scenes match the generator"
exit $((failures > 0))
