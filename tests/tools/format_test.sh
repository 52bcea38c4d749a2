#!/usr/bin/env bash
# tools/check_format passes on the tree, and fails on a copy of one of its
# files with the layout broken (and passes on the same copy unbroken), so
# that a misformatted file fails tools/test.
#
# Usage: format_test.sh REPO_ROOT
set -uo pipefail
root="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
if ! "$root/tools/check_format" "$root" >"$work/tree.log" 2>&1; then
  echo "FAIL: the tree is not formatted:" >&2
  head -20 "$work/tree.log" >&2
  failures=$((failures + 1))
fi
mkdir -p "$work/copy/src"
cp "$root/.clang-format" "$work/copy/"
cp "$root/src/vahf/core/error.cc" "$work/copy/src/error.cc"
if ! "$root/tools/check_format" "$work/copy" >/dev/null 2>&1; then
  echo "FAIL: check_format refuses a formatted copy" >&2
  failures=$((failures + 1))
fi
# Broken: every line's leading spaces doubled.
sed -i 's/^\( \+\)/\1\1/' "$work/copy/src/error.cc"
if "$root/tools/check_format" "$work/copy" >"$work/copy.log" 2>&1; then
  echo "FAIL: check_format accepts a misformatted copy" >&2
  failures=$((failures + 1))
elif ! grep -q "src/error.cc is not formatted" "$work/copy.log"; then
  echo "FAIL: check_format does not name the misformatted file:" >&2
  cat "$work/copy.log" >&2
  failures=$((failures + 1))
fi
[ "$failures" -eq 0 ] && echo "PASS: the tree is formatted and a broken copy is caught"
exit $((failures > 0))
