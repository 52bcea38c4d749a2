#!/usr/bin/env bash
# Tests of `vahf replay RUN_DIR --cycle TABLE:ROW` (docs/reproducibility.md,
# "Replay"): a cycle of every cycles table of a paper run (table1, assembly
# time, working conditions, fatigue segments with their accumulated work and
# the fatigue pilot) and of a comparison against a lab replays to its rows
# bit for bit (exit 0), with a trace of every part, sampled; a table edited
# by one digit exits 1 naming the row and column; a bad --cycle, a table
# that is no cycles table, a row past the end, --sample without --trace or
# too fine exit 2 with one line.
#
# Usage: replay_test.sh VAHF_EXECUTABLE REPO_ROOT

# shellcheck source=tests/tools/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh" "$@"
set -uo pipefail

cd "$root" || exit 1
run run experiments/paper.json --trials 1 --threads 2 --out "$tmp/paper"
expect_status "run paper --trials 1" 0

# --- the first row of each cycles table, and a later one of fatigue's (its
# segments start with the work the pilot's rate gives).
for cycle in table1_cycles.csv:1 assembly_time_cycles.csv:4 \
  human_factors_groups_cycles.csv:7 fatigue_pilot_cycles.csv:1 fatigue_cycles.csv:10; do
  run replay "$tmp/paper" --cycle "$cycle"
  expect_status "replay $cycle" 0
  expect_in "replay $cycle" "$out" "replay: identical: the cycle's 3 rows of ${cycle%:*}"
done
expect_in "replay fatigue_cycles.csv:10" "$out" "condition '45-60 min', cycle 0, seed 1, initial work 8"

# --- a trace of every part, sampled.
run replay "$tmp/paper" --cycle assembly_time_cycles.csv:4 --trace "$tmp/trace.csv" \
  --sample 0.05
expect_status "replay --trace --sample" 0
expect_in "replay --trace --sample" "$tmp/trace.csv" "part,row,t,"
for part in piston_rod guide_sleeve seal_ring; do
  expect_in "replay --trace --sample" "$tmp/trace.csv" "$part,sample,"
  expect_in "replay --trace --sample" "$tmp/trace.csv" "$part,decision,"
done

# --- one digit of the table changed: exit 1, the row and column named.
cp -r "$tmp/paper" "$tmp/edited"
python3 - "$tmp/edited/assembly_time_cycles.csv" <<'EOF'
import sys
path = sys.argv[1]
lines = open(path).read().split("\n")
header = lines[0].split(",")
fields = lines[5].split(",")
column = header.index("part_time_s")
fields[column] = fields[column][:-1] + ("1" if fields[column][-1] != "1" else "2")
lines[5] = ",".join(fields)
open(path, "w").write("\n".join(lines))
EOF
run replay "$tmp/edited" --cycle assembly_time_cycles.csv:4
expect_status "replay an edited table" 1
expect_in "replay an edited table" "$out" \
  "replay: different: assembly_time_cycles.csv: row 5 (line 6), column part_time_s: "

# --- a comparison against the synthetic lab: its operators' cycles.
run run experiments/compare_synthetic.json --trials 2 --out "$tmp/compare"
expect_status "run compare" 0
run replay "$tmp/compare" --cycle compare_cycles.csv:8
expect_status "replay a comparison's cycle" 0
expect_in "replay a comparison's cycle" "$out" "replay: identical: "

# --- bad input: one line, exit 2.
check_refused() {
  local name=$1 text=$2
  shift 2
  run replay "$@"
  expect_status "$name" 2
  expect_lines "$name" "$err" 1
  expect_in "$name" "$err" "$text"
}
check_refused "replay --cycle without a row" "takes TABLE:ROW" \
  "$tmp/paper" --cycle table1_cycles.csv
check_refused "replay --cycle row 0" "takes TABLE:ROW" "$tmp/paper" --cycle table1_cycles.csv:0
check_refused "replay a table that is no cycles table" "names no cycles table of the run" \
  "$tmp/paper" --cycle table1_means.csv:1
check_refused "replay a row past the end" "table1_cycles.csv has 3 data rows" \
  "$tmp/paper" --cycle table1_cycles.csv:4
check_refused "replay --sample without --trace" "needs --trace FILE" \
  "$tmp/paper" --cycle table1_cycles.csv:1 --sample 0.01
check_refused "replay --sample too fine" "at most 1e6 rows a part" \
  "$tmp/paper" --cycle table1_cycles.csv:1 --trace "$tmp/t.csv" --sample 1e-9
check_refused "replay without a run" "is not a directory" "$tmp/none" --cycle a_cycles.csv:1

finish
