#!/usr/bin/env bash
# Tests of `vahf verify RUN_DIR` (docs/reproducibility.md): a run verifies
# (exit 0) on 1 and 2 threads, from absolute and from relative paths, with
# --overrides, and for a kind with a run of its own (calibrate); --keep keeps
# the re-run and the temporary directory is removed otherwise; a result
# table edited by one digit exits 1 naming the file, row and column; an input
# changed or missing since the run, a missing or unusable manifest exit 2 with
# one line.
#
# Usage: verify_test.sh VAHF_EXECUTABLE REPO_ROOT
set -uo pipefail

# shellcheck source=tests/tools/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh" "$@"

# The re-runs' temporary directories go here, to see that they are removed.
export TMPDIR=$tmp/scratch
mkdir -p "$TMPDIR"
scratch_empty() {
  if [[ -z "$(ls -A "$TMPDIR")" ]]; then
    pass "$1: no temporary directory left"
  else
    fail "$1: left $(ls "$TMPDIR")"
  fi
}

# A copy of Table 1's experiment with absolute paths, to be changed later.
experiment=$tmp/table1.json
python3 - "$root" "$experiment" <<'EOF'
import json, sys
root, path = sys.argv[1], sys.argv[2]
e = json.load(open(root + "/experiments/table1.json"))
e["scene"] = root + "/experiments/scenes/hydraulic_cylinder.json"
e["paper_table"] = root + "/reference/paper/table1.json"
json.dump(e, open(path, "w"), indent=1)
EOF

# --- a run verifies, on its own thread count and on 2.
run run "$experiment" --trials 2 --seed 3 --out "$tmp/run"
expect_status "run table1" 0
run verify "$tmp/run"
expect_status "verify" 0
expect_in "verify" "$out" "verify: identical: 4 result files, results digest "
expect_in "verify" "$out" "re-running $experiment, seed 3, --trials 2, on 1 thread(s)"
expect_in "verify" "$out" "build: the run's"
scratch_empty "verify"
run verify "$tmp/run" --threads 2 --keep "$tmp/kept"
expect_status "verify --threads 2 --keep" 0
expect_in "verify --threads 2 --keep" "$out" "on 2 thread(s)"
if cmp -s "$tmp/run/table1_instants.csv" "$tmp/kept/table1_instants.csv"; then
  pass "verify --keep: the re-run's output is kept"
else
  fail "verify --keep: no kept re-run, or it differs"
fi

# --- relative paths: verified from where the run was started, not elsewhere.
cd "$root" || exit 1
run run experiments/table1.json --trials 1 --out "$tmp/relative"
expect_status "run with relative paths" 0
run verify "$tmp/relative"
expect_status "verify relative paths" 0
cd "$tmp" || exit 1
run verify "$tmp/relative"
expect_status "verify from another directory" 2
expect_lines "verify from another directory" "$err" 1
expect_in "verify from another directory" "$err" "/experiment/sha256 = "
expect_in "verify from another directory" "$err" \
  "the input experiments/table1.json is missing"

# --- one digit of a result table changed: exit 1, the file, row and column named.
cp -r "$tmp/run" "$tmp/edited"
python3 - "$tmp/edited/table1_instants.csv" <<'EOF'
import sys
path = sys.argv[1]
lines = open(path).read().split("\n")
fields = lines[2].split(",")
column = lines[0].split(",").index("eta")
digit = fields[column][-1]
fields[column] = fields[column][:-1] + ("1" if digit != "1" else "2")
lines[2] = ",".join(fields)
open(path, "w").write("\n".join(lines))
EOF
run verify "$tmp/edited"
expect_status "verify an edited table" 1
expect_in "verify an edited table" "$out" \
  "verify: different: table1_instants.csv: row 2 (line 3), column eta: "
expect_in "verify an edited table" "$out" "(1 of 4 result files differ)"
expect_in "verify an edited table" "$out" "no longer give its manifest's results digest"
scratch_empty "verify an edited table"

# --- a run with --overrides, and a calibration (a kind with a run of its own).
overrides=$tmp/overrides.json
echo '{"format": "vahf-overrides/1", "parameters": {"guidance/kappa": 300}}' >"$overrides"
run run "$experiment" --trials 1 --overrides "$overrides" --out "$tmp/overridden"
run verify "$tmp/overridden"
expect_status "verify a run with --overrides" 0
expect_in "verify a run with --overrides" "$out" "--overrides $overrides"
run run "$root/experiments/calibrate_synthetic.json" --trials 4 --out "$tmp/calibration"
expect_status "run calibrate" 0
run verify "$tmp/calibration"
expect_status "verify a calibration" 0
expect_in "verify a calibration" "$out" "verify: identical: "

# --- the override file changed since the run: exit 2, one line, nothing run.
echo '{"format": "vahf-overrides/1", "parameters": {"guidance/kappa": 301}}' >"$overrides"
run verify "$tmp/overridden"
expect_status "verify after the override file changed" 2
expect_lines "verify after the override file changed" "$err" 1
expect_in "verify after the override file changed" "$err" \
  "the input $overrides now has SHA-256 "
expect_in "verify after the override file changed" "$err" "changed since the run"
scratch_empty "verify after the override file changed"

# --- no run directory, no manifest, a manifest without its invocation.
mkdir -p "$tmp/empty"
for dir in "$tmp/no_such_run" "$tmp/empty"; do
  run verify "$dir"
  expect_status "verify $(basename "$dir")" 2
  expect_lines "verify $(basename "$dir")" "$err" 1
  expect_in "verify $(basename "$dir")" "$err" "vahf: error: $dir"
done
cp -r "$tmp/run" "$tmp/old"
python3 - "$tmp/old/manifest.json" <<'EOF'
import json, sys
m = json.load(open(sys.argv[1]))
del m["invocation"]
json.dump(m, open(sys.argv[1], "w"))
EOF
run verify "$tmp/old"
expect_status "verify a manifest without invocation" 2
expect_lines "verify a manifest without invocation" "$err" 1
expect_in "verify a manifest without invocation" "$err" "has no \"invocation\""

finish
