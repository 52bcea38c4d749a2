#!/usr/bin/env bash
# Tests of `mpirun -n K vahf run` (docs/reproducibility.md, "Many machines:
# MPI"): the paper run (2 cycles per condition) alone on 2 threads and on 2
# and 3 ranks of 1 thread, a Table 1 run on 2 ranks of 2 threads and on 4, and a
# calibration on 2 and 3 ranks end with the same results digest (and the same
# calibrated.json); the manifest records the rank count; the ranks other than
# 0 leave no files; a run stopped by Ctrl-C on 2 ranks resumes on 3 to the
# same digest, and one of another seed is refused by rank 0 and stops every
# rank; a refused output path stops every rank with one error line; other
# commands are refused on ranks.
#
# Usage: mpi_test.sh VAHF_EXECUTABLE REPO_ROOT, with VAHF_MPIEXEC the mpirun
# of the MPI vahf was built with (default: mpirun).
set -uo pipefail

# shellcheck source=tests/tools/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh" "$@"

mpirun=${VAHF_MPIEXEC:-mpirun}
# The ranks' temporary directories (and Open MPI's session files) go here.
export TMPDIR=$tmp/scratch
mkdir -p "$TMPDIR"
# Open MPI refuses to start as root unless told; CI machines run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Shared-memory transport without cross-memory attach, which containers
# often forbid (Open MPI's vader then fails with "Read -1, expected ...").
export OMPI_MCA_btl_vader_single_copy_mechanism=none

# on_ranks K ARGS...: `vahf ARGS...` on K ranks, as `run` does; a job that
# hangs (a rank waiting for one that stopped) is killed after 10 minutes.
on_ranks() {
  local k=$1
  shift
  timeout 600 "$mpirun" --oversubscribe -n "$k" "$vahf" "$@" >"$out" 2>"$err"
  status=$?
}

digest() {
  sed -n 's/.*"results_digest": *"\([0-9a-f]*\)".*/\1/p' "$1/manifest.json"
}

# same_digest NAME DIR REFERENCE: DIR's results digest is REFERENCE's.
same_digest() {
  if [[ -n "$(digest "$3")" && "$(digest "$2")" == "$(digest "$3")" ]]; then
    pass "$1: the results digest of $(basename "$3")"
  else
    fail "$1: results digest '$(digest "$2")', want '$(digest "$3")'"
  fi
}

# --- the paper run: 1 x 2, 2 x 1 and 3 x 1 ranks x threads.
paper=$root/experiments/paper.json
run run "$paper" --trials 2 --threads 2 --out "$tmp/paper-1x2"
expect_status "paper alone on 2 threads" 0
for k in 2 3; do
  on_ranks "$k" run "$paper" --trials 2 --out "$tmp/paper-${k}x1"
  expect_status "paper on $k ranks" 0
  expect_in "paper on $k ranks" "$out" "on 1 thread(s) x $k ranks"
  same_digest "paper on $k ranks" "$tmp/paper-${k}x1" "$tmp/paper-1x2"
  expect_in "paper on $k ranks: manifest" "$tmp/paper-${k}x1/manifest.json" "\"ranks\": $k"
done
if ls "$TMPDIR" | grep -q '^vahf-rank'; then
  fail "the ranks other than 0 left their temporary output behind"
else
  pass "the ranks other than 0 removed their temporary output"
fi

# --- Table 1 on 2 ranks of 2 threads and on 4 ranks.
table1=$root/experiments/table1.json
run run "$table1" --trials 12 --out "$tmp/table1"
expect_status "table1 alone" 0
on_ranks 2 run "$table1" --trials 12 --threads 2 --out "$tmp/table1-2x2"
expect_status "table1 on 2 ranks x 2 threads" 0
same_digest "table1 on 2 ranks x 2 threads" "$tmp/table1-2x2" "$tmp/table1"
on_ranks 4 run "$table1" --trials 12 --out "$tmp/table1-4x1"
expect_status "table1 on 4 ranks" 0
same_digest "table1 on 4 ranks" "$tmp/table1-4x1" "$tmp/table1"

# --- a calibration: its design evaluations spread the same way.
calibrate=$root/experiments/calibrate_synthetic.json
run run "$calibrate" --trials 4 --out "$tmp/calibration"
expect_status "calibrate alone" 0
for k in 2 3; do
  on_ranks "$k" run "$calibrate" --trials 4 --out "$tmp/calibration-$k"
  expect_status "calibrate on $k ranks" 0
  same_digest "calibrate on $k ranks" "$tmp/calibration-$k" "$tmp/calibration"
  if cmp -s "$tmp/calibration-$k/calibrated.json" "$tmp/calibration/calibrated.json"; then
    pass "calibrate on $k ranks: the same calibrated.json"
  else
    fail "calibrate on $k ranks: calibrated.json differs"
  fi
done

# --- Ctrl-C on 2 ranks once rank 0 journaled 2 of its 6 cycles, then resume
# on 3.
# mpirun passes Ctrl-C on as SIGTERM and kills the ranks a second later
# (odls_base_sigkill_timeout): rank 0's journal keeps at least its own cycles.
"$mpirun" --oversubscribe -n 2 "$vahf" run "$table1" --trials 12 --out "$tmp/stopped" \
  >"$out" 2>"$err" &
pid=$!
for ((i = 0; i < 1200; ++i)); do
  n=$(cat "$tmp/stopped.partial"/journal/batch-*.log 2>/dev/null | grep -ac '^entry ')
  if ! kill -0 "$pid" 2>/dev/null || ((n >= 2)); then break; fi
  sleep 0.1
done
kill -INT "$pid" 2>/dev/null
wait "$pid"
if [[ ! -e "$tmp/stopped" && -d "$tmp/stopped.partial/journal" ]]; then
  pass "table1 on 2 ranks stopped by Ctrl-C: no output, the journal kept"
else
  fail "table1 on 2 ranks stopped by Ctrl-C: an output was written or no journal kept"
fi
on_ranks 3 run "$table1" --trials 12 --seed 2 --out "$tmp/stopped" --resume
expect_status "--resume of another seed on 3 ranks (rank 0 refuses)" 2
expect_in "--resume of another seed on 3 ranks (rank 0 refuses)" "$err" \
  "journal/identity.json: /invocation/seed = "
on_ranks 3 run "$table1" --trials 12 --out "$tmp/stopped" --resume
expect_status "--resume on 3 ranks" 0
expect_in "--resume on 3 ranks" "$out" "resumed: "
same_digest "--resume on 3 ranks" "$tmp/stopped" "$tmp/table1"

# --- errors: rank 0's refused output stops every rank, said once.
mkdir -p "$tmp/not-an-output" && touch "$tmp/not-an-output/keep"
on_ranks 3 run "$table1" --trials 12 --out "$tmp/not-an-output"
expect_status "a refused output path on 3 ranks" 2
if [[ $(grep -c '^vahf: error:' "$err") -eq 1 ]]; then
  pass "a refused output path on 3 ranks: one error line"
else
  fail "a refused output path on 3 ranks: $(grep -c '^vahf: error:' "$err") error lines, want 1"
fi
expect_in "a refused output path on 3 ranks" "$err" "is not a vahf output"
on_ranks 2 check "$table1"
expect_status "check on 2 ranks" 2
expect_in "check on 2 ranks" "$err" "only \`vahf run\` spreads over MPI ranks"

finish
