# The helpers the command-line tests share (cli_test.sh, verify_test.sh,
# resume_test.sh), sourced with the test's arguments VAHF_EXECUTABLE
# REPO_ROOT: $vahf and $root (absolute), a scratch folder $tmp removed on
# exit, `run ARGS...` of $vahf with its output in $out and $err and its exit
# status in $status, and the checks, which count into $passed and $failed;
# `finish` prints the counts and sets the exit status.
if [[ $# -ne 2 ]]; then
  echo "usage: $0 VAHF_EXECUTABLE REPO_ROOT" >&2
  exit 2
fi
vahf=$(realpath "$1")
root=$(realpath "$2")
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

# finish: the counts, and exit status 0 when nothing failed.
finish() {
  echo "$passed passed, $failed failed"
  [[ $failed -eq 0 ]]
}
