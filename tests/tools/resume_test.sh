#!/usr/bin/env bash
# Tests of `vahf run --resume` (docs/reproducibility.md, "Resume"): a run and
# a calibration killed with SIGKILL midway (once their journal holds finished
# work) and resumed end with the results digest of an uninterrupted run, and
# run only what was missing; a run stopped by SIGINT resumes too; a journal
# whose last record was torn (as by a power loss) resumes to the same digest;
# --resume with nothing journaled yet (no output directory; a run killed
# before its first result) starts afresh, saying so on one line, and ends
# with the uninterrupted digest; --resume of another command (another seed)
# or after a lab table changed, --resume of a finished run, and a fresh run
# onto a stopped run's journal exit 2 with one line.
#
# Usage: resume_test.sh VAHF_EXECUTABLE REPO_ROOT
set -uo pipefail

# shellcheck source=tests/tools/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh" "$@"

# digest DIR: the results digest in DIR/manifest.json.
digest() {
  sed -n 's/.*"results_digest": *"\([0-9a-f]*\)".*/\1/p' "$1/manifest.json"
}

# entries DIR: the records journaled in DIR.partial so far.
entries() {
  cat "$1.partial"/journal/batch-*.log 2>/dev/null | grep -ac '^entry '
}

# kill_when SIGNAL DIR MIN PID: sends SIGNAL to PID once DIR's journal holds
# at least MIN records (or the run ended); waits for it; sets $status.
kill_when() {
  local i
  for ((i = 0; i < 1200; ++i)); do
    if ! kill -0 "$4" 2>/dev/null || (($(entries "$2") >= $3)); then break; fi
    sleep 0.1
  done
  kill "-$1" "$4" 2>/dev/null
  wait "$4"
  status=$?
}

# --- a run: Table 1 with 6 cycles, uninterrupted, then killed and resumed.
table1=$root/experiments/table1.json
run run "$table1" --trials 6 --out "$tmp/reference"
expect_status "run table1" 0
"$vahf" run "$table1" --trials 6 --out "$tmp/killed" >"$out" 2>"$err" &
kill_when KILL "$tmp/killed" 2 $!
expect_status "run table1 killed by SIGKILL" 137
journaled=$(entries "$tmp/killed")
if [[ ! -e "$tmp/killed" ]] && ((journaled >= 2 && journaled < 6)); then
  pass "run table1 killed by SIGKILL: no output, $journaled of 6 cycles journaled"
else
  fail "run table1 killed by SIGKILL: $journaled cycles journaled (want 2 to 5)"
fi
run run "$table1" --trials 6 --out "$tmp/killed"
expect_status "a fresh run onto a stopped run's journal" 2
expect_lines "a fresh run onto a stopped run's journal" "$err" 1
expect_in "a fresh run onto a stopped run's journal" "$err" \
  "holds the journal of a stopped run: the same command with --resume continues it"
run run "$table1" --trials 6 --seed 2 --out "$tmp/killed" --resume
expect_status "--resume with another seed" 2
expect_lines "--resume with another seed" "$err" 1
expect_in "--resume with another seed" "$err" "journal/identity.json: /invocation/seed = 1: "
run run "$table1" --trials 6 --out "$tmp/killed" --resume
expect_status "--resume after SIGKILL" 0
expect_in "--resume after SIGKILL" "$out" \
  "resumed: $journaled results taken from the journal, $((6 - journaled)) computed"
if [[ "$(digest "$tmp/killed")" == "$(digest "$tmp/reference")" &&
      -n "$(digest "$tmp/reference")" ]]; then
  pass "--resume after SIGKILL: the uninterrupted run's results digest"
else
  fail "--resume after SIGKILL: digest $(digest "$tmp/killed"), want $(digest "$tmp/reference")"
fi
if [[ ! -e "$tmp/killed.partial" && ! -e "$tmp/killed/journal" ]]; then
  pass "--resume after SIGKILL: the journal is gone with the staging directory"
else
  fail "--resume after SIGKILL: a journal or staging directory was left"
fi

# --- --resume with nothing journaled yet starts afresh, saying why on one
# line, and ends with the uninterrupted run's digest. Table 1 with 2 cycles.
run run "$table1" --trials 2 --out "$tmp/small"
expect_status "run table1 --trials 2" 0
small=$(digest "$tmp/small")
# expect_afresh NAME OUT REASON: the last run started afresh, for REASON,
# said so on one line (beside the progress lines a slow machine prints),
# and ended as the uninterrupted run.
expect_afresh() {
  expect_status "$1" 0
  if [[ $(grep -c '^vahf:' "$err") -eq 1 ]]; then
    pass "$1: one line of stderr from vahf"
  else
    fail "$1: $(grep -c '^vahf:' "$err") lines of stderr from vahf, want 1"
  fi
  expect_in "$1" "$err" "vahf: $2: nothing journaled to resume ($3): the run starts afresh"
  if [[ "$(digest "$2")" == "$small" && -n "$small" && ! -e "$2.partial" ]]; then
    pass "$1: the uninterrupted run's results digest"
  else
    fail "$1: digest $(digest "$2"), want $small"
  fi
}
run run "$table1" --trials 2 --out "$tmp/never" --resume
expect_afresh "--resume with no output directory" "$tmp/never" "there is no $tmp/never.partial"
# What a kill before the first result leaves: from a run killed once its
# batch file appears (cut back to its header, wherever the kill fell), a
# header alone, half a header, an empty batch file, identity.json alone, an
# empty journal, an empty staging directory.
"$vahf" run "$table1" --trials 2 --out "$tmp/early" >"$out" 2>"$err" &
pid=$!
for ((i = 0; i < 3000; ++i)); do
  if [[ -s "$tmp/early.partial/journal/batch-0.log" ]] || ! kill -0 "$pid" 2>/dev/null; then
    break
  fi
  sleep 0.01
done
kill -KILL "$pid" 2>/dev/null
wait "$pid"
status=$?
expect_status "run table1 --trials 2 killed by SIGKILL" 137
mv "$tmp/early.partial" "$tmp/early.saved"
log=journal/batch-0.log
header=$(head -n 1 "$tmp/early.saved/$log" | wc -c)
for state in "a header alone:$header" "half a header:$((header / 2))" \
  "an empty batch file:0" "identity.json alone:rm $log" "an empty journal:rm journal/*" \
  "an empty staging directory:rm -r journal"; do
  name=${state%%:*}
  cut=${state#*:}
  rm -rf "$tmp/early" "$tmp/early.partial"
  cp -r "$tmp/early.saved" "$tmp/early.partial"
  if [[ $cut == rm* ]]; then
    (cd "$tmp/early.partial" && eval "$cut")
  else
    truncate -s "$cut" "$tmp/early.partial/$log"
  fi
  run run "$table1" --trials 2 --out "$tmp/early" --resume
  expect_afresh "--resume after a kill before the first result ($name)" "$tmp/early" \
    "$tmp/early.partial holds no finished result"
done
# --- the finished run: --resume of the same command is refused, naming its
# manifest, and the output stays; a changed seed is another run, which
# starts afresh (and replaces it, as a run without --resume would).
run run "$table1" --trials 2 --out "$tmp/small" --resume
expect_status "--resume of a finished run" 2
expect_lines "--resume of a finished run" "$err" 1
expect_in "--resume of a finished run" "$err" \
  "$tmp/small/manifest.json: /results_digest = \"$small\": this same run has finished"
if [[ "$(digest "$tmp/small")" == "$small" && ! -e "$tmp/small.partial" ]]; then
  pass "--resume of a finished run: the output stays"
else
  fail "--resume of a finished run: the output changed"
fi
cp -r "$tmp/small" "$tmp/small2"
run run "$table1" --trials 2 --seed 2 --out "$tmp/small2" --resume
expect_status "--resume onto another run's finished output" 0
expect_in "--resume onto another run's finished output" "$err" \
  "nothing journaled to resume (there is no $tmp/small2.partial): the run starts afresh"

# --- SIGINT, then a torn last record (as a power loss may leave), then resume.
"$vahf" run "$table1" --trials 6 --out "$tmp/stopped" >"$out" 2>"$err" &
kill_when INT "$tmp/stopped" 2 $!
expect_status "run table1 stopped by SIGINT" 130
expect_in "run table1 stopped by SIGINT" "$err" "--resume continues the run"
log=$tmp/stopped.partial/journal/batch-0.log
size=$(stat -c %s "$log")
truncate -s $((size - 100)) "$log"
run run "$table1" --trials 6 --out "$tmp/stopped" --resume
expect_status "--resume after SIGINT and a torn record" 0
if [[ "$(digest "$tmp/stopped")" == "$(digest "$tmp/reference")" ]]; then
  pass "--resume after SIGINT and a torn record: the uninterrupted run's results digest"
else
  fail "--resume after SIGINT and a torn record: digest $(digest "$tmp/stopped")"
fi

# --- a calibration: killed after several design evaluations, resumed. It
# runs from a copy of experiments/ and data/, so that a lab table can change.
mkdir -p "$tmp/repo"
cp -r "$root/experiments" "$root/data" "$tmp/repo/"
calibrate=$tmp/repo/experiments/calibrate_synthetic.json
run run "$calibrate" --trials 4 --out "$tmp/calibration"
expect_status "run calibrate" 0
"$vahf" run "$calibrate" --trials 4 --out "$tmp/cal_killed" >"$out" 2>"$err" &
kill_when KILL "$tmp/cal_killed" 40 $!
expect_status "run calibrate killed by SIGKILL" 137
batches=$(ls "$tmp/cal_killed.partial/journal" | grep -c '^batch-')
if ((batches >= 2)); then
  pass "run calibrate killed by SIGKILL: $batches design evaluations journaled"
else
  fail "run calibrate killed by SIGKILL: $batches design evaluations journaled (want 2 or more)"
fi
# A lab table edited since (a comment line: the dataset still loads) is not
# the journaled run's: --resume refuses it, naming the table's entry.
table=$tmp/repo/data/synthetic_block/trials.csv
cp "$table" "$tmp/trials.csv.orig"
echo "# edited after the run was stopped" >>"$table"
run run "$calibrate" --trials 4 --out "$tmp/cal_killed" --resume
expect_status "--resume after a lab table changed" 2
expect_lines "--resume after a lab table changed" "$err" 1
expect_in "--resume after a lab table changed" "$err" "journal/identity.json: /inputs/"
expect_in "--resume after a lab table changed" "$err" "synthetic_block~1trials.csv = \""
cp "$tmp/trials.csv.orig" "$table"
run run "$calibrate" --trials 4 --out "$tmp/cal_killed" --resume
expect_status "--resume a calibration" 0
expect_in "--resume a calibration" "$out" "resumed: "
if [[ "$(digest "$tmp/cal_killed")" == "$(digest "$tmp/calibration")" ]] &&
   cmp -s "$tmp/cal_killed/calibrated.json" "$tmp/calibration/calibrated.json"; then
  pass "--resume a calibration: the same results digest and calibrated.json"
else
  fail "--resume a calibration: digest $(digest "$tmp/cal_killed"), want $(digest "$tmp/calibration")"
fi

finish
