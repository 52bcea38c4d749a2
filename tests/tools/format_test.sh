#!/usr/bin/env bash
# tools/check_format passes on the tree, and fails on a copy of one of its
# files with the layout broken (and passes on the same copy unbroken), so
# that a misformatted file fails tools/test.
#
# Usage: format_test.sh REPO_ROOT
set -uo pipefail
root="$1"
source "$(dirname "$0")/check_of_a_check.sh"
passes "the tree is not formatted" "$root/tools/check_format" "$root"
mkdir -p "$work/copy/src"
cp "$root/.clang-format" "$work/copy/"
cp "$root/src/vahf/core/error.cc" "$work/copy/src/error.cc"
passes "check_format refuses a formatted copy" "$root/tools/check_format" "$work/copy"
# Broken: every line's leading spaces doubled.
sed -i 's/^\( \+\)/\1\1/' "$work/copy/src/error.cc"
catches "a misformatted copy" "src/error.cc is not formatted" \
  "$root/tools/check_format" "$work/copy"
verdict "the tree is formatted and a broken copy is caught"
