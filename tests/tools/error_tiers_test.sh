#!/usr/bin/env bash
# Every `throw` under src/ and tools/vahf/ throws one of the error tiers of
# src/vahf/core/error.h (docs/design.md, "Errors"): vahf::InputError,
# vahf::ComputationError, vahf::InternalError (a failed check, thrown only in
# the Python module's process), a class declared under src/ that derives from one of
# them, or experiment::Interrupted (a stop the user asked for). A rethrow
# (`throw;`) is allowed. Then the check itself is checked: a copy with a
# standard exception thrown must fail, naming the file and line, and a copy
# with only tiers must pass.
#
# Usage: error_tiers_test.sh REPO_ROOT
set -uo pipefail
root="$1"
source "$(dirname "$0")/check_of_a_check.sh"

sources() { grep -rlP --include='*.h' --include='*.cc' '\bthrow\b' "$@"; }

# The tiers: the three classes of core/error.h, Interrupted, and every class
# declared in DIR... deriving (through any number of steps) from one of them.
tiers() {
  local known=" InputError ComputationError InternalError Interrupted " grew=1 name base
  local pairs
  pairs=$(grep -rhoP --include='*.h' --include='*.cc' \
    'class\s+\w+\s*(final\s*)?:\s*public\s+[\w:]+' "$@" |
    sed -E 's/class +([A-Za-z0-9_]+).*public +([A-Za-z0-9_:]+)/\1 \2/; s/ .*::/ /')
  while [ "$grew" -eq 1 ]; do
    grew=0
    while read -r name base; do
      [ -z "$name" ] && continue
      if [[ "$known" == *" $base "* && "$known" != *" $name "* ]]; then
        known+="$name "
        grew=1
      fi
    done <<<"$pairs"
  done
  echo "$known"
}

# check DIR...: prints each throw that is not a tier as FILE:LINE: CODE; exit 1
# if there is one.
check() {
  local known bad=0 file line code rest class
  known=$(tiers "$@")
  while IFS=: read -r file line code; do
    code="${code%%//*}"  # a comment may say "must not throw"
    rest="$code"
    while [[ "$rest" =~ (^|[^A-Za-z0-9_])throw([^A-Za-z0-9_].*|$) ]]; do
      rest="${BASH_REMATCH[2]}"
      [[ "$rest" =~ ^[[:space:]]*\; ]] && continue  # rethrow
      if [[ "$rest" =~ ^[[:space:]]+([A-Za-z0-9_:]+)[[:space:]]*[\(\{] ]]; then
        class="${BASH_REMATCH[1]##*::}"
        [[ "$known" == *" $class "* ]] && continue
      fi
      echo "$file:$line: throws what is not an error tier: ${code#"${code%%[![:space:]]*}"}"
      bad=1
      break
    done
  done < <(sources "$@" | xargs -r grep -nP '\bthrow\b' /dev/null | grep -vP '^[^:]+:\d+:\s*//')
  return "$bad"
}

passes "throws outside the error tiers (src/vahf/core/error.h)" check "$root/src" "$root/tools/vahf"

mkdir -p "$work/copy"
cp "$root/src/vahf/core/error.h" "$work/copy/"
cat >"$work/copy/good.cc" <<'EOF'
class SlopeError : public vahf::ComputationError {};
void F(int k) {
  if (k < 0) throw vahf::InputError("f.json", "/k", "-1", "must be >= 0");
  if (k == 0) throw ComputationError(ComputationError::Reason::kTooFewValues, "none");
  if (k == 1) throw SlopeError();  // derives from a tier
  try { G(); } catch (...) { throw; }
}
EOF
passes "the check refuses throws of the tiers" check "$work/copy"
printf 'void H() {\n  throw std::invalid_argument("h");\n}\n' >"$work/copy/bad.cc"
catches "a std::invalid_argument" "bad.cc:2: throws what is not an error tier" check "$work/copy"
verdict "every throw is an error tier, and a stray one is caught"
