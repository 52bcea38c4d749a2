#!/usr/bin/env bash
# Tests of the vahf command's exit status and output: `check` on a valid scene,
# a malformed scene (one-line error naming the file, JSON pointer and rule,
# exit 2), a missing file and invalid JSON (exit 2), the precision experiment
# (its settings listed) and a bad precision setting (exit 2); a lab dataset
# (valid: exit 0; a bad value or a missing file: one line naming the file and
# line or pointer, exit 2); the calibration files (docs/calibration.md): the
# calibrate experiment, the synthetic generator and its dataset, a parameter
# override file (valid: exit 0; malformed: one line naming it, exit 2);
# `reference`;
# duplicate keys in a scene, experiment, override file and lab dataset, and
# a value nested 100 000 deep (exit 2, one line);
# a scene accuracy of 1 (exit 2);
# `trial` ending unreachable at its first decision (exit 1, zero integrator
# counts, one line on stderr), under every stepper `vahf params` lists;
# strict command-line numbers for `trial` and `run` (exit 2, one line);
# `trial` on another kind of vahf file (exit 2, the kind named);
# `--help`; and bad options (exit 2); `run`: the same results digest on 1 and
# 2 threads, a bad experiment (exit 2), an --out that is not a vahf output
# (refused, exit 2, untouched) and SIGINT (exit 130, no output directory
# left, the finished cycles journaled);
# `synthesize` (the shipped synthetic dataset's bytes, on 1 and 2 threads);
# `run` on the calibrate experiment (calibrated.json, an override file; the
# same results digest on 2 threads) and `run --overrides` with its output, or
# an override that breaks an operator's reach rule (exit 2, no output).
#
# Usage: cli_test.sh VAHF_EXECUTABLE REPO_ROOT
set -uo pipefail

# shellcheck source=tests/tools/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh" "$@"

# --- check: the example scene is valid.
scene=$root/experiments/scenes/peg_in_hole.json
run check "$scene"
expect_status "check valid scene" 0
expect_in "check valid scene" "$out" "valid scene"
# It builds each part's trial model, as a run would, and says what it holds.
expect_in "check valid scene" "$out" "trial model 'peg': contact resolving, 0 shell points, radial clearance 50 um, penetration bound 5 um, V by ray casting"
expect_in "check valid scene" "$out" "hand: wrist torque law, rotational stiffness 20 N m/rad, damping 1 N m s/rad"
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
expect_in "check negative mass" "$err" "must lie in [1e-4, 10000]"
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
for text in "kind precision" "peg_in_hole_shell (" "hydraulic_cylinder_shell (" \
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

# --- check: a lab dataset (docs/lab-data.md) is valid and described.
lab=$tmp/lab
mkdir -p "$lab"
cat >"$lab/dataset.json" <<'EOF'
{"format": "vahf-lab/1", "name": "cli_lab", "description": "Two trials of one operator.",
 "provenance": {"source": "synthetic: tests/tools/cli_test.sh"},
 "trials": {"file": "trials.csv", "units": {"height": "m", "arm_length": "m", "time": "s"}}}
EOF
cat >"$lab/trials.csv" <<'EOF'
operator,sex,height,arm_length,condition,part,repetition,time,success
male 1,male,1.75,0.74,good,all,1,16.2,1
male 1,male,1.75,0.74,good,all,2,,0
EOF
run check "$lab/dataset.json"
expect_status "check lab dataset" 0
for text in "lab dataset 'cli_lab'" "provenance: synthetic: tests/tools/cli_test.sh" \
    "trials (trials.csv): 2 trials, 1 operator, 1 part, 1 condition; 1 successful" \
    "$lab/dataset.json: valid lab dataset"; do
  expect_in "check lab dataset" "$out" "$text"
done
expect_lines "check lab dataset" "$err" 0

# --- check: a lab dataset with a negative time: one line, the file, line, column, value, rule.
sed -i 's/,,0$/,-3,0/' "$lab/trials.csv"
run check "$lab/dataset.json"
expect_status "check lab dataset with a negative time" 2
expect_lines "check lab dataset with a negative time" "$err" 1
expect_in "check lab dataset with a negative time" "$err" \
  "vahf: error: $lab/trials.csv: line 3, column time = -3: an assembly time is > 0"
if [[ -s $out ]]; then
  fail "check lab dataset with a negative time: prints nothing on stdout"
else
  pass "check lab dataset with a negative time: prints nothing on stdout"
fi

# --- check: a lab dataset naming a file that is not there: the manifest's pointer.
rm "$lab/trials.csv"
run check "$lab/dataset.json"
expect_status "check lab dataset with a missing file" 2
expect_lines "check lab dataset with a missing file" "$err" 1
expect_in "check lab dataset with a missing file" "$err" \
  "$lab/dataset.json: /trials/file = \"trials.csv\": no such file: $lab/trials.csv"

# --- check: the calibration's files (docs/calibration.md) are valid.
calibrate=$root/experiments/calibrate_synthetic.json
generator=$root/data/synthetic_block/generator.json
synthetic_dataset=$root/data/synthetic_block/dataset.json
run check "$calibrate"
expect_status "check calibrate experiment" 0
for text in "kind calibrate" "fits guidance/kappa from 400 within [50, 2000]" "target " \
    "$calibrate: valid experiment"; do
  expect_in "check calibrate experiment" "$out" "$text"
done
expect_lines "check calibrate experiment" "$err" 0
run check "$generator"
expect_status "check synthetic generator" 0
for text in "synthetic lab 'synthetic_block'" "6 operator(s) x 10 repetitions, seed 20261123" \
    "guidance/kappa = 250 (stated)" "$generator: valid synthetic lab generator"; do
  expect_in "check synthetic generator" "$out" "$text"
done
run check "$synthetic_dataset"
expect_status "check synthetic dataset" 0
expect_in "check synthetic dataset" "$out" "$synthetic_dataset: valid lab dataset"

# --- check: the comparison against the paper's numbers reads what the paper
# reports (no trials) for each quantity; one that names no condition where the
# paper reports two is refused before any simulation (one line, exit 2).
compare_paper=$root/experiments/compare_paper.json
run check "$compare_paper"
expect_status "check compare_paper" 0
for text in "compares assembly_time of all, virtual within +-1 s: lab 9.2 s from reported once, no spread (a single draw)" \
    "compares assembly_time of all within +-1 s: lab 16 s from reported, no spread" \
    "compares success_rate of all, segment 4, real within +-0.1: lab 0.68 from reported" \
    "segments from the fatigue design: 60 min in 4 segments, 4 pilot cycles" \
    "$compare_paper: valid experiment"; do
  expect_in "check compare_paper" "$out" "$text"
done
expect_lines "check compare_paper" "$err" 0
ambiguous=$tmp/compare_ambiguous.json
python3 - "$compare_paper" "$ambiguous" "$root" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
e["scene"] = sys.argv[3] + "/experiments/scenes/hydraulic_cylinder.json"
e["lab"] = sys.argv[3] + "/data/paper/dataset.json"
del e["quantities"][2]["condition"]
json.dump(e, open(sys.argv[2], "w"))
PY
run check "$ambiguous"
expect_status "check compare with an ambiguous condition" 2
expect_lines "check compare with an ambiguous condition" "$err" 1
expect_in "check compare with an ambiguous condition" "$err" \
  "$ambiguous: /quantities/2/condition = (missing): the lab reports success_rate of all, segment 1 for condition 'virtual'"

# --- check: a parameter override file is valid and listed.
overrides=$tmp/overrides.json
cat >"$overrides" <<'EOF'
{"format": "vahf-overrides/1", "source": "cli_test",
 "parameters": {"guidance/kappa": 300, "simulation/accuracy": 0.0002}}
EOF
run check "$overrides"
expect_status "check override file" 0
for text in "parameter overrides ($overrides): cli_test" "guidance/kappa = 300" \
    "simulation/accuracy = 0.0002" "$overrides: valid parameter override file"; do
  expect_in "check override file" "$out" "$text"
done
expect_lines "check override file" "$err" 0

# --- check: an override file with a value that breaks its rule: one line, the file.
bad_overrides=$tmp/bad_overrides.json
cat >"$bad_overrides" <<'EOF'
{"format": "vahf-overrides/1", "parameters": {"guidance/kappa": -1}}
EOF
run check "$bad_overrides"
expect_status "check malformed override file" 2
expect_lines "check malformed override file" "$err" 1
expect_in "check malformed override file" "$err" \
  "vahf: error: $bad_overrides: /parameters/guidance~1kappa = -1: must lie in (0, 1e6]"
if [[ -s $out ]]; then
  fail "check malformed override file: prints nothing on stdout"
else
  pass "check malformed override file: prints nothing on stdout"
fi

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
expect_in "trial with an unknown integrator" "$err" "--integrator: NoSuchIntegrator not in {RungeKuttaMerson,"
expect_lines "trial with an unknown integrator" "$err" 1
# --- trial --sample: dense rows with a trace; without one, or not positive: exit 2, one line.
run trial "$scene" --seed 1 --trace "$tmp/sampled.csv" --sample 0.001
expect_status "trial --sample 0.001" 0
expect_in "trial --sample 0.001" "$out" "sample rows)"
expect_in "trial --sample rows" "$tmp/sampled.csv" "sample,0.001,"
run trial "$scene" --seed 1 --sample 0.001
expect_status "trial --sample without --trace" 2
expect_in "trial --sample without --trace" "$err" "needs --trace FILE"
expect_lines "trial --sample without --trace" "$err" 1
# A trace is held in memory until written: at most 1e6 rows over the time limit.
run trial "$scene" --seed 1 --trace "$tmp/dense.csv" --sample 1e-7
expect_status "trial --sample 1e-7" 2
expect_in "trial --sample 1e-7" "$err" "at most 1e6 rows over the time limit"
expect_lines "trial --sample 1e-7" "$err" 1
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

# --- trial: an operator who cannot reach the part (standing 5 m away) ends the
# trial at its first decision: the summary on stdout with zero integrator
# counts (once garbage read from an integrator that never stepped), one line
# on stderr naming the status, exit 1.
unreachable=$tmp/unreachable.json
sed 's/"position": \[0.0, -0.35\]/"position": [0.0, -5.0]/' "$scene" >"$unreachable"
run trial "$unreachable" --seed 1
expect_status "trial unreachable" 1
expect_in "trial unreachable" "$out" "status: unreachable"
expect_in "trial unreachable" "$out" ": 0 steps taken, 0 attempted, 0 error-test failures, 0 realizations"
expect_lines "trial unreachable" "$err" 1
expect_in "trial unreachable" "$err" "vahf: trial ended unreachable: "
run trial "$unreachable" --seed 1 --integrator RungeKuttaMerson
expect_status "trial unreachable (RungeKuttaMerson)" 1
expect_in "trial unreachable (RungeKuttaMerson)" "$out" ": 0 steps taken, 0 attempted, 0 error-test failures, 0 realizations"
# Every stepper of the registry, as `vahf params` lists them in
# simulation/integrator's rule, is one of --integrator's choices.
run params
steppers=$(grep -F '| `simulation/integrator` |' "$out" | cut -d'|' -f4 | tr -d ' ' | tr ',' ' ')
if [[ -n "$steppers" ]]; then
  pass "params: simulation/integrator lists the steppers ($steppers)"
else
  fail "params: no steppers in simulation/integrator's rule"
fi
for stepper in $steppers; do
  run trial "$unreachable" --seed 1 --integrator "$stepper"
  expect_status "trial unreachable (--integrator $stepper)" 1
  expect_in "trial unreachable (--integrator $stepper)" "$out" "integrator: $stepper at accuracy"
done

# --- trial and run: command-line numbers are read strictly (CLI11 once
# wrapped --seed -1 to 2^64 - 1); a leading zero is decimal, not octal.
for args in "--seed -1" "--seed 1e23" "--seed 1.5" "--seed 18446744073709551616" \
    "--seed 0x10" "--seed 1 --trial -1" "--seed 1 --trial 2.5"; do
  run trial "$scene" $args
  expect_status "trial $args" 2
  expect_in "trial $args" "$err" "must be a decimal integer from 0 to 18446744073709551615"
  expect_lines "trial $args" "$err" 1
done
# --accuracy and --set read a value by the parameter's rule (vahf params).
for accuracy in 1 2 0 -1e-4 1e-16; do
  run trial "$scene" --seed 1 --accuracy "$accuracy"
  expect_status "trial --accuracy $accuracy" 2
  expect_in "trial --accuracy $accuracy" "$err" "vahf: error: --accuracy: /simulation/accuracy = "
  expect_in "trial --accuracy $accuracy" "$err" "must lie in [1e-12, 0.5]"
  expect_lines "trial --accuracy $accuracy" "$err" 1
done
for accuracy in nan inf 1e-4x; do
  run trial "$scene" --seed 1 --accuracy "$accuracy"
  expect_status "trial --accuracy $accuracy" 2
  expect_in "trial --accuracy $accuracy" "$err" "must be a number"
  expect_lines "trial --accuracy $accuracy" "$err" 1
done
run trial "$scene" --seed 1 --set guidance/kappa=-1
expect_status "trial --set guidance/kappa=-1" 2
expect_in "trial --set guidance/kappa=-1" "$err" \
  "vahf: error: --set: /guidance/kappa = -1: must lie in (0, 1e6]"
run trial "$scene" --seed 1 --set guidance/kapa=1
expect_status "trial --set guidance/kapa=1" 2
expect_in "trial --set guidance/kapa=1" "$err" "names no parameter"
run trial "$scene" --seed 1 --set guidance/kappa
expect_status "trial --set without =" 2
expect_in "trial --set without =" "$err" "takes GROUP/KEY=VALUE"
run trial "$scene" --seed 1 --set contact/shell_spacing=1e-5
expect_status "trial --set a shell spacing too fine for the peg" 2
expect_in "trial --set a shell spacing too fine for the peg" "$err" "contact shell"
expect_lines "trial --set a shell spacing too fine for the peg" "$err" 1
# The work budget: a trial still running after max_steps accepted steps ends
# as step_budget, exit 1, with its summary.
run trial "$scene" --seed 1 --set simulation/max_steps=10
expect_status "trial --set simulation/max_steps=10" 1
expect_in "trial --set simulation/max_steps=10" "$out" "status: step_budget (10 accepted steps"
expect_in "trial --set simulation/max_steps=10" "$err" "vahf: trial ended step_budget"
expect_lines "trial --set simulation/max_steps=10" "$err" 1
run trial "$unreachable" --seed 010 --trial 007
expect_status "trial --seed 010 --trial 007 (unreachable)" 1
expect_in "trial --seed 010 --trial 007" "$out" "seed 10, trial 7"
for args in "--seed -1" "--seed 1e23" "--trials 010x" "--threads -2"; do
  run run "$root/experiments/table1.json" $args --out "$tmp/strict_out"
  expect_status "run $args" 2
  expect_in "run $args" "$err" "must be a decimal integer"
  if [[ ! -e "$tmp/strict_out" ]]; then
    pass "run $args: no output directory"
  else
    fail "run $args: an output directory was written"
  fi
done

# --- trial given another kind of vahf file: one line saying which it is and
# which command takes it (not "unknown key 'kind'").
run trial "$experiment" --seed 1
expect_status "trial on an experiment file" 2
expect_lines "trial on an experiment file" "$err" 1
expect_in "trial on an experiment file" "$err" \
  "vahf: error: $experiment: /format = \"vahf-experiment/1\": this is an experiment file (run it with \`vahf run\`); \`vahf trial\` takes a scene file"
run trial "$overrides" --seed 1
expect_status "trial on an override file" 2
expect_in "trial on an override file" "$err" "this is a parameter override file"
run trial "$generator" --seed 1
expect_status "trial on a synthetic generator" 2
expect_in "trial on a synthetic generator" "$err" "this is a synthetic lab generator"
run trial "$synthetic_dataset" --seed 1
expect_status "trial on a lab dataset" 2
expect_in "trial on a lab dataset" "$err" "this is a lab dataset"

# --- a scene's accuracy lies in (0, 1): Simbody asserts it.
accuracy_one=$tmp/accuracy_one.json
sed 's/"accuracy": 3e-5/"accuracy": 1/' "$scene" >"$accuracy_one"
run check "$accuracy_one"
expect_status "check a scene with accuracy 1" 2
expect_lines "check a scene with accuracy 1" "$err" 1
expect_in "check a scene with accuracy 1" "$err" \
  "$accuracy_one: /parameters/simulation/accuracy = 1: must lie in [1e-12, 0.5]"

# --- duplicate keys, in every kind of vahf file: one line, the pointer, the key.
dup_scene=$tmp/dup_scene.json
sed 's/"friction": 0.15,/"friction": 0.15, "friction": 0.3,/' "$scene" >"$dup_scene"
dup_experiment=$tmp/dup_experiment.json
sed 's/"seed": 3,/"seed": 3, "seed": 4,/' "$experiment" >"$dup_experiment"
dup_overrides=$tmp/dup_overrides.json
sed 's/"guidance\/kappa": 300,/"guidance\/kappa": 300, "guidance\/kappa": 301,/' \
  "$overrides" >"$dup_overrides"
dup_lab=$tmp/dup_lab.json
sed 's/"name": "synthetic_block",/"name": "a", "name": "b",/' "$synthetic_dataset" >"$dup_lab"
for args in "check $dup_scene|/parts/0/friction|friction" \
    "trial $dup_scene --seed 1|/parts/0/friction|friction" \
    "check $dup_experiment|/seed|seed" \
    "check $dup_overrides|/parameters/guidance~1kappa|guidance/kappa" \
    "check $dup_lab|/name|name"; do
  IFS='|' read -r command pointer key <<<"$args"
  run $command
  expect_status "$command (duplicate key)" 2
  expect_lines "$command (duplicate key)" "$err" 1
  expect_in "$command (duplicate key)" "$err" \
    ": $pointer: duplicate key \"$key\" (a key appears at most once in an object)"
done

# --- a value nested 100 000 deep (once a stack overflow printing it): one line.
deep=$tmp/deep.json
python3 -c 'import sys; n = 100000; sys.stdout.write("{\"format\": \"vahf-scene/1\", \"name\": " + "[" * n + "]" * n + "}")' >"$deep"
for command in check trial; do
  if [[ $command == trial ]]; then run trial "$deep" --seed 1; else run check "$deep"; fi
  expect_status "$command on a value nested 100000 deep" 2
  expect_lines "$command on a value nested 100000 deep" "$err" 1
  expect_in "$command on a value nested 100000 deep" "$err" \
    "nested deeper than 64 levels of arrays and objects"
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

# --- synthesize: the shipped synthetic dataset, byte for byte, on 1 and 2 threads.
run synthesize "$generator" --threads 1 --out "$tmp/synth1"
expect_status "synthesize --threads 1" 0
if cmp -s "$tmp/synth1/trials.csv" "$root/data/synthetic_block/trials.csv"; then
  pass "synthesize: trials.csv identical to data/synthetic_block/trials.csv"
else
  fail "synthesize: trials.csv differs from data/synthetic_block/trials.csv"
fi
run check "$tmp/synth1/dataset.json"
expect_status "check synthesized dataset" 0
expect_in "check synthesized dataset" "$out" "valid lab dataset"
run synthesize "$generator" --threads 2 --out "$tmp/synth2"
expect_status "synthesize --threads 2" 0
if cmp -s "$tmp/synth1/trials.csv" "$tmp/synth2/trials.csv" &&
   cmp -s "$tmp/synth1/dataset.json" "$tmp/synth2/dataset.json"; then
  pass "synthesize: the same bytes on 1 and 2 threads"
else
  fail "synthesize: 1 and 2 threads write different bytes"
fi

# --- run: the calibration writes calibrated.json, an override file; the same
# results digest on 2 threads.
run run "$calibrate" --trials 4 --out "$tmp/cal1"
expect_status "run calibrate" 0
expect_in "run calibrate" "$out" "guidance/kappa = "
digest_cal1=$(grep '^results digest ' "$out")
calibrated=$tmp/cal1/calibrated.json
run check "$calibrated"
expect_status "check calibrated.json" 0
expect_in "check calibrated.json" "$out" "$calibrated: valid parameter override file"
expect_in "check calibrated.json" "$out" "guidance/kappa = "
run run "$calibrate" --trials 4 --threads 2 --out "$tmp/cal2"
expect_status "run calibrate --threads 2" 0
digest_cal2=$(grep '^results digest ' "$out")
if [[ ${#digest_cal1} -eq 79 && "$digest_cal1" == "$digest_cal2" ]]; then
  pass "run calibrate: the same results digest on 1 and 2 threads"
else
  fail "run calibrate: '$digest_cal1' on 1 thread, '$digest_cal2' on 2"
fi

# --- run --overrides: Table 1 with the calibrated kappa; the manifest records
# the value and lists the file among its inputs.
run run "$table1" --trials 1 --overrides "$calibrated" --out "$tmp/t1_calibrated"
expect_status "run table1 --overrides calibrated.json" 0
if python3 - "$calibrated" "$tmp/t1_calibrated/manifest.json" <<'EOF'
import json, os, sys
calibrated = json.load(open(sys.argv[1]))
manifest = json.load(open(sys.argv[2]))
kappa = calibrated["parameters"]["guidance/kappa"]
got = manifest["parameters"]["guidance"]["kappa"]
assert got == kappa, (got, kappa)
paths = [os.path.realpath(i["path"]) for i in manifest["inputs"]]
assert os.path.realpath(sys.argv[1]) in paths, paths
EOF
then
  pass "run table1 --overrides: the manifest has the calibrated kappa and lists calibrated.json"
else
  fail "run table1 --overrides: the manifest lacks the calibrated kappa or calibrated.json"
fi

# --- run --overrides: a value that breaks the reach rule for one of the
# experiment's operators (D1 = 0.9 * 0.733 m > D2 = 0.39 * 1.678 m for the P50
# man of assembly_time.json): one line naming the override file, exit 2, no output.
reach_overrides=$tmp/reach_overrides.json
cat >"$reach_overrides" <<'EOF'
{"format": "vahf-overrides/1", "parameters": {"reach/d1_arm_fraction": 0.9}}
EOF
run run "$root/experiments/assembly_time.json" --trials 1 --overrides "$reach_overrides" \
  --out "$tmp/reach_out"
expect_status "run --overrides breaking an operator's reach rule" 2
expect_lines "run --overrides breaking an operator's reach rule" "$err" 1
expect_in "run --overrides breaking an operator's reach rule" "$err" \
  "vahf: error: $reach_overrides: /parameters"
expect_in "run --overrides breaking an operator's reach rule" "$err" "operator 'male P50'"
if [[ ! -e "$tmp/reach_out" && ! -e "$tmp/reach_out.partial" ]]; then
  pass "run --overrides breaking an operator's reach rule: no output directory"
else
  fail "run --overrides breaking an operator's reach rule: an output directory was written"
fi

# --- run: SIGINT stops the run with exit status 130 and writes no output; the
# finished cycles stay journaled in the staging directory, for --resume
# (resume_test.sh resumes such runs).
"$vahf" run "$root/experiments/fatigue.json" --trials 50 --out "$tmp/int" >"$out" 2>"$err" &
pid=$!
# Once a cycle has finished (its record journaled), or after 2 minutes.
for ((i = 0; i < 1200; ++i)); do
  grep -qa '^entry ' "$tmp/int.partial"/journal/batch-*.log 2>/dev/null && break
  sleep 0.1
done
kill -INT "$pid"
wait "$pid"
status=$?
expect_status "run interrupted by SIGINT" 130
expect_in "run interrupted by SIGINT" "$err" "vahf: interrupted: "
expect_in "run interrupted by SIGINT" "$err" \
  "are journaled in $tmp/int.partial (the same command with --resume continues the run); no output was written"
if [[ ! -e "$tmp/int" && "$(ls "$tmp/int.partial")" == journal ]]; then
  pass "run interrupted by SIGINT: no output directory, the staging holds the journal only"
else
  fail "run interrupted by SIGINT: an output directory, or no journal, was left"
fi

finish
