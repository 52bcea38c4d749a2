#!/usr/bin/env bash
# Tests of the vahf command's exit status and output: `check` on a valid scene,
# a malformed scene (one-line error naming the file, JSON pointer and rule,
# exit 2), a missing file and invalid JSON (exit 2), the precision experiment
# (its settings listed) and a bad precision setting (exit 2); `reference`;
# `--help`; and bad options (exit 2); `run`: the same results digest on 1 and
# 2 threads, a bad experiment (exit 2), an --out that is not a vahf output
# (refused, exit 2, untouched) and SIGINT (exit 130, no output directory left).
#
# Usage: cli_test.sh VAHF_EXECUTABLE REPO_ROOT
set -uo pipefail

if [[ $# -ne 2 ]]; then
  echo "usage: $0 VAHF_EXECUTABLE REPO_ROOT" >&2
  exit 2
fi
vahf=$1
root=$2
if [[ ! -x "$vahf" ]]; then
  echo "$0: $vahf is not an executable" >&2
  exit 2
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/vahf_cli_test.XXXXXX") || exit 1
trap 'rm -rf -- "$tmp"' EXIT

passed=0
failed=0
out=$tmp/stdout
err=$tmp/stderr

pass() {
  passed=$((passed + 1))
  echo "PASS: $1"
}

fail() {
  failed=$((failed + 1))
  echo "FAIL: $1"
  echo "  --- stdout:"
  sed 's/^/  | /' "$out"
  echo "  --- stderr:"
  sed 's/^/  | /' "$err"
}

# run ARGS...: runs vahf, leaving its output in $out and $err and its exit
# status in $status.
run() {
  "$vahf" "$@" >"$out" 2>"$err"
  status=$?
}

# expect_status NAME WANT: checks the last run's exit status.
expect_status() {
  if [[ $status -eq $2 ]]; then
    pass "$1: exit status $2"
  else
    fail "$1: exit status $status, want $2"
  fi
}

# expect_in NAME FILE TEXT: FILE ($out or $err) contains TEXT literally.
expect_in() {
  if grep -qF -- "$3" "$2"; then
    pass "$1: $(basename "$2") has '$3'"
  else
    fail "$1: $(basename "$2") lacks '$3'"
  fi
}

# expect_lines NAME FILE N: FILE has exactly N lines.
expect_lines() {
  local n
  n=$(wc -l <"$2")
  if [[ $n -eq $3 ]]; then
    pass "$1: $(basename "$2") has $3 line(s)"
  else
    fail "$1: $(basename "$2") has $n lines, want $3"
  fi
}

# --- check: the example scene is valid.
scene=$root/experiments/scenes/peg_in_hole.json
run check "$scene"
expect_status "check valid scene" 0
expect_in "check valid scene" "$out" "valid scene"
# It builds each part's trial model, as a run would, and says what it holds.
expect_in "check valid scene" "$out" "trial model 'peg': contact shell, 3831 shell points, radial clearance 50 um, penetration bound 5 um, V by ray casting"
expect_lines "check valid scene" "$err" 0

# --- check: a scene whose peg has a negative mass.
bad=$tmp/negative_mass.json
cat >"$bad" <<'EOF'
{
  "format": "vahf-scene/1",
  "name": "negative_mass",
  "operator": {"height": 1.75, "arm_length": 0.74, "position": [0.0, -0.45],
               "facing_deg": 90},
  "parts": [
    {
      "name": "bore",
      "role": "base",
      "geometry": {"type": "revolution", "profile": [
        [0.0, -0.05], [0.03, -0.05], [0.03, 0.0], [0.01, 0.0], [0.01, -0.04],
        [0.0, -0.04], [0.0, -0.05]]},
      "density": 7850,
      "friction": 0.15,
      "pose": {"position": [0.0, 0.0, 0.95]}
    },
    {
      "name": "peg",
      "role": "assembling",
      "geometry": {"type": "revolution", "profile": [
        [0.0, 0.0], [0.0095, 0.0], [0.0095, 0.05], [0.0, 0.05], [0.0, 0.0]]},
      "mass": -0.1,
      "friction": 0.15,
      "pose": {"position": [0.0, 0.0, 0.97]},
      "target": {"position": [0.0, 0.0, 0.91]}
    }
  ],
  "sequence": ["peg"]
}
EOF
run check "$bad"
expect_status "check negative mass" 2
expect_lines "check negative mass" "$err" 1
expect_in "check negative mass" "$err" "$bad"
expect_in "check negative mass" "$err" "/parts/1/mass"
expect_in "check negative mass" "$err" "-0.1"
expect_in "check negative mass" "$err" "must be > 0"
if [[ -s $out ]]; then
  fail "check negative mass: prints nothing on stdout"
else
  pass "check negative mass: prints nothing on stdout"
fi

# --- check: a file that does not exist.
missing=$tmp/no_such_scene.json
run check "$missing"
expect_status "check missing file" 2
expect_lines "check missing file" "$err" 1
expect_in "check missing file" "$err" "$missing"

# --- check: a file that is not JSON (NaN is not a JSON number).
nan=$tmp/nan.json
printf '{"format": NaN}\n' >"$nan"
run check "$nan"
expect_status "check invalid JSON" 2
expect_lines "check invalid JSON" "$err" 1
expect_in "check invalid JSON" "$err" "$nan"
expect_in "check invalid JSON" "$err" "not valid JSON"

# --- check: an experiment file naming the example scene.
experiment=$tmp/experiment.json
cat >"$experiment" <<EOF
{"format": "vahf-experiment/1", "name": "cli_test", "kind": "table1",
 "scene": "$scene", "seed": 3, "trials": 2}
EOF
run check "$experiment"
expect_status "check experiment" 0
expect_in "check experiment" "$out" "valid experiment"

# --- check: the precision experiment lists its scenes, reference and settings.
run check "$root/experiments/precision.json"
expect_status "check precision" 0
for text in "kind precision" "peg_in_hole (" "hydraulic_cylinder (" \
    "reference: RungeKuttaMerson 1e-8 (/reference)" "settings (18):" \
    "RungeKuttaMerson 1e-3" "CPodes 1e-6" "CVODE 1e-4" "(/settings/8): simulation/accuracy = 1e-06" "visibility/grid 32" "contact/shell_spacing 5e-4" \
    "valid experiment"; do
  expect_in "check precision" "$out" "$text"
done

# --- check: a precision setting naming no parameter: one line, the pointer, the rule.
bad_precision=$tmp/bad_precision.json
cat >"$bad_precision" <<EOF
{"format": "vahf-experiment/1", "name": "bad_precision", "kind": "precision",
 "scenes": ["$scene"], "reference": {"simulation/accuracy": 1e-8},
 "settings": [{"simulation/acuracy": 1e-4}]}
EOF
run check "$bad_precision"
expect_status "check precision with an unknown parameter" 2
expect_lines "check precision with an unknown parameter" "$err" 1
expect_in "check precision with an unknown parameter" "$err" \
  "$bad_precision: /settings/0/simulation~1acuracy = 0.0001: unknown key 'simulation/acuracy' (did you mean 'simulation/accuracy'?)"

# --- check without a file is a usage error.
run check
expect_status "check without FILE" 2

# --- reference: the paper's Table 1.
run reference --table "$root/reference/paper/table1.json"
expect_status "reference --table" 0
if [[ -s $out ]]; then
  pass "reference --table: prints the table check"
else
  fail "reference --table: prints nothing"
fi

# --- trial: the peg scene completes, and two runs of a seed write the same bytes.
trace_a="$tmp/peg_a.csv"
trace_b="$tmp/peg_b.csv"
run trial "$scene" --seed 1 --trace "$trace_a"
expect_status "trial peg seed 1" 0
expect_in "trial peg seed 1" "$out" "status: completed"
run trial "$scene" --seed 1 --trace "$trace_b"
if cmp -s "$trace_a" "$trace_b"; then
  pass "trial peg seed 1: identical trace bytes on a second run"
else
  fail "trial peg seed 1: traces differ between two runs"
fi
if [[ ! -e "$trace_a.partial" ]]; then
  pass "trial: no partial file left behind"
else
  fail "trial: a .partial file was left behind"
fi
run trial "$scene" --seed 1 --trace "$tmp/no_such_dir/peg.csv"
expect_status "trial with an unwritable trace path" 2
expect_in "trial with an unwritable trace path" "$err" "no_such_dir/peg.csv"
run trial "$scene" --seed 1 --integrator NoSuchIntegrator
expect_status "trial with an unknown integrator" 2
# --- trial --sample: dense rows with a trace; without one, or not positive: exit 2, one line.
run trial "$scene" --seed 1 --trace "$tmp/sampled.csv" --sample 0.001
expect_status "trial --sample 0.001" 0
expect_in "trial --sample 0.001" "$out" "sample rows)"
expect_in "trial --sample rows" "$tmp/sampled.csv" "sample,0.001,"
run trial "$scene" --seed 1 --sample 0.001
expect_status "trial --sample without --trace" 2
expect_in "trial --sample without --trace" "$err" "needs --trace FILE"
expect_lines "trial --sample without --trace" "$err" 1
run trial "$scene" --seed 1 --trace "$tmp/sampled.csv" --sample -1
expect_status "trial --sample -1" 2
expect_in "trial --sample -1" "$err" "must be > 0 s"
expect_lines "trial --sample -1" "$err" 1

for position in 1 -1; do
  run trial "$scene" --seed 1 --position "$position"
  expect_status "trial --position $position (one part in the sequence)" 2
  expect_in "trial --position $position" "$err" "--position = $position: must be 0 to 0"
  expect_lines "trial --position $position" "$err" 1
done

# --- help and bad options.
run --help
expect_status "--help" 0
expect_in "--help" "$out" "check"

run --no-such-option
expect_status "unknown option" 2

run check "$scene" --no-such-option
expect_status "unknown option after a subcommand" 2

run no-such-command
expect_status "unknown subcommand" 2

# --- run: Table 1 with 2 cycles, on 1 and on 2 threads: the same results.
table1=$root/experiments/table1.json
run run "$table1" --trials 2 --out "$tmp/a"
expect_status "run table1" 0
expect_in "run table1" "$out" "results digest"
run run "$table1" --trials 2 --threads 2 --out "$tmp/b"
expect_status "run table1 --threads 2" 0
for f in manifest.json report.md summary.json table1_instants.csv plots/table1_eta.png; do
  if [[ -s "$tmp/a/$f" && -s "$tmp/b/$f" ]]; then
    pass "run table1: wrote $f"
  else
    fail "run table1: no $f"
  fi
done
if [[ ! -e "$tmp/a.partial" && ! -e "$tmp/b.partial" ]]; then
  pass "run table1: no staging directory left behind"
else
  fail "run table1: a .partial directory was left behind"
fi
# digest DIR: the results digest in DIR/manifest.json.
digest() {
  sed -n 's/.*"results_digest": *"\([0-9a-f]*\)".*/\1/p' "$1/manifest.json"
}
digest_a=$(digest "$tmp/a")
digest_b=$(digest "$tmp/b")
if [[ ${#digest_a} -eq 64 && "$digest_a" == "$digest_b" ]]; then
  pass "run table1: the same results digest on 1 and 2 threads"
else
  fail "run table1: results digest '$digest_a' on 1 thread, '$digest_b' on 2"
fi

# --- run: an experiment whose operator's height is out of range, or a string.
bad=$tmp/bad_operator.json
for height in 3.0 '"NaN"'; do
  cat >"$bad" <<EOF
{"format": "vahf-experiment/1", "name": "bad_operator", "kind": "assembly_time",
 "scene": "$root/experiments/scenes/hydraulic_cylinder.json", "trials": 1,
 "operators": [{"name": "tall", "sex": "male", "height": $height, "arm_length": 0.74}]}
EOF
  run run "$bad" --out "$tmp/bad_out"
  expect_status "run with operator height $height" 2
  expect_lines "run with operator height $height" "$err" 1
  expect_in "run with operator height $height" "$err" "vahf: error: $bad"
  expect_in "run with operator height $height" "$err" "/operators/0/height = $height"
  if [[ ! -e "$tmp/bad_out" && ! -e "$tmp/bad_out.partial" ]]; then
    pass "run with operator height $height: no output directory"
  else
    fail "run with operator height $height: an output directory was written"
  fi
done
expect_in "run with operator height \"NaN\"" "$err" "must be a number, not a string"

# --- run: --out naming a directory that holds other files is refused, untouched.
mine=$tmp/mine
mkdir -p "$mine/sub"
echo "keep me" >"$mine/notes.txt"
echo "and me" >"$mine/sub/data.txt"
listing() {
  (cd "$mine" && find . -exec ls -ld --time-style=full-iso {} + | sort &&
     cat notes.txt sub/data.txt)
}
before=$(listing)
run run "$table1" --trials 1 --out "$mine"
expect_status "run --out a directory that is not a vahf output" 2
expect_lines "run --out a directory that is not a vahf output" "$err" 1
expect_in "run --out a directory that is not a vahf output" "$err" "vahf: error: $mine"
if [[ "$(listing)" == "$before" && ! -e "$mine.partial" ]]; then
  pass "run --out a directory that is not a vahf output: left untouched"
else
  fail "run --out a directory that is not a vahf output: it was changed"
fi

# --- run: SIGINT stops the run with exit status 130 and writes nothing.
"$vahf" run "$root/experiments/fatigue.json" --trials 50 --out "$tmp/int" >"$out" 2>"$err" &
pid=$!
sleep 1.5
kill -INT "$pid"
wait "$pid"
status=$?
expect_status "run interrupted by SIGINT" 130
expect_in "run interrupted by SIGINT" "$err" "interrupted"
if [[ ! -e "$tmp/int" && ! -e "$tmp/int.partial" ]]; then
  pass "run interrupted by SIGINT: no output or staging directory"
else
  fail "run interrupted by SIGINT: an output or staging directory was left"
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
