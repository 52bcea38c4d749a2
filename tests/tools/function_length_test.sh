#!/usr/bin/env bash
# No function under src/ is longer than 80 lines, from the line of its name to
# its closing brace, as universal-ctags measures it (tools/setup installs it):
# a longer one is split into functions named for what they do. The check is
# also run on a copy holding one function of 80 lines, which it must pass, and
# one of 81, which it must refuse by name, so that a broken check fails too.
#
# Usage: function_length_test.sh REPO_ROOT
set -uo pipefail
root="$1"
limit=80
if ! ctags --version 2>/dev/null | grep -q "Universal Ctags"; then
  echo "FAIL: universal-ctags is not installed (tools/setup installs it)" >&2
  exit 1
fi

# Prints "LINES FILE:LINE NAME" for each function under DIR/src longer than
# the limit, longest first.
long_functions() {
  (cd "$1" && ctags -R --languages=C++ --kinds-C++=f --fields=+ne -x \
    --_xformat='%{line} %{end} %F %{name}' src) |
    awk -v limit="$limit" '{ n = $2 - $1 + 1; if (n > limit) print n, $3 ":" $1, $4 }' |
    sort -rn
}

source "$(dirname "$0")/check_of_a_check.sh"

tree="$(long_functions "$root")"
if [ -n "$tree" ]; then
  echo "FAIL: functions under src/ longer than $limit lines (lines, where, name):" >&2
  echo "$tree" >&2
  failures=$((failures + 1))
fi

# write_function NAME N FILE: a function of N lines in all (its name's line,
# N - 3 declarations, its return and its brace).
write_function() {
  {
    echo "int $1() {"
    for ((i = 1; i <= $2 - 3; ++i)); do echo "  int x$i = $i;"; done
    echo "  return 0;"
    echo "}"
  } >"$3"
}
mkdir -p "$work/copy/src"
write_function at_limit "$limit" "$work/copy/src/at_limit.cc"
if [ -n "$(long_functions "$work/copy")" ]; then
  echo "FAIL: the check refuses a function of $limit lines" >&2
  failures=$((failures + 1))
fi
write_function past_limit $((limit + 1)) "$work/copy/src/past_limit.cc"
copy="$(long_functions "$work/copy")"
if [ "$copy" != "$((limit + 1)) src/past_limit.cc:1 past_limit" ]; then
  echo "FAIL: the check does not name exactly the function of $((limit + 1)) lines:" >&2
  echo "$copy" >&2
  failures=$((failures + 1))
fi
verdict "no function under src/ is over $limit lines"
