#!/usr/bin/env bash
# A public header (any header under src/ outside an internal/ folder:
# docs/design.md, "Layout and dependencies") includes no internal header
# and no header of a dependency the library links PRIVATE in src/CMakeLists.txt.
# Each private library there must be known below with its headers, so that a
# new one cannot slip past. The check is also run on a copy of one public
# header with an internal include and with a private dependency's include
# added, each of which it must refuse by name.
#
# Usage: public_headers_test.sh REPO_ROOT
set -uo pipefail
root="$1"
source "$(dirname "$0")/check_of_a_check.sh"
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# The libraries after PRIVATE in target_link_libraries(vahf ...), one a line.
private_libraries() {
  awk '/^target_link_libraries\(vahf$/ { on = 1 } on { print } on && /\)/ { exit }' \
    "$root/src/CMakeLists.txt" | sed 's/#.*//; s/)//' | tr -s ' \t' '\n' |
    sed -n '/^PRIVATE$/,$p' | sed '1d' | grep -v '^$'
}

# The include paths (as an extended regular expression) of each private
# library's headers.
patterns=()
while read -r lib; do
  case "$lib" in
    vahf_flags | Threads::Threads) ;;  # compile flags; no headers of their own
    SimTK*) patterns+=("Simbody\.h|SimTK|simbody/") ;;
    SUNDIALS::*) patterns+=("(cvode|cvodes|ida|kinsol|arkode|sundials|nvector|sunlinsol|sunmatrix|sunnonlinsol|sunmemory)/") ;;
    GSL::*) patterns+=("gsl/") ;;
    OpenSSL::*) patterns+=("openssl/") ;;
    embree) patterns+=("embree[0-9]*/") ;;
    Ceres::*) patterns+=("ceres/|glog/|gflags/") ;;  # Ceres' headers include glog's
    # Siconos numerics' headers also include each other by bare name.
    Siconos::*) patterns+=("siconos/|(NonSmoothDrivers|FrictionContactProblem|Friction_cst|NumericsMatrix|SparseBlockMatrix|SolverOptions|sn_error_handling|SiconosConfig|NumericsFwd)\.h") ;;
    *) fail "src/CMakeLists.txt links $lib PRIVATE, which this script does not know: add its headers" ;;
  esac
done < <(private_libraries)
if [ "${#patterns[@]}" -eq 0 ]; then
  fail "found no private library in src/CMakeLists.txt"
fi
private="^[[:space:]]*#[[:space:]]*include[[:space:]]*[<\"]($(
  IFS='|'
  echo "${patterns[*]}"
))"
internal='^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"][^>"]*/internal/'

# Prints "FILE:LINE: TEXT" for each offending include of the public headers
# under DIR.
offending_includes() {
  (cd "$1" && find src -name '*.h' -not -path '*/internal/*' -print0 | sort -z |
    xargs -0 -r grep -nHE -e "$internal" -e "$private")
}

tree="$(offending_includes "$root")"
if [ -n "$tree" ]; then
  fail "public headers include internal headers or private dependencies' headers:"
  echo "$tree" >&2
fi

# A public header passes as it is, and is refused with either include added.
mkdir -p "$work/copy/src/vahf/sim/internal"
cp "$root/src/vahf/sim/trial.h" "$work/copy/src/vahf/sim/trial.h"
cp "$root/src/vahf/sim/internal/trial_context.h" "$work/copy/src/vahf/sim/internal/"
[ -n "$(offending_includes "$work/copy")" ] && fail "the check refuses sim/trial.h as it is"
for added in '#include "vahf/sim/internal/trial_context.h"' '#include <Simbody.h>' \
  '#include <cvode/cvode.h>' '#include <gsl/gsl_errno.h>' '#include <ceres/ceres.h>' \
  '#include <embree3/rtcore.h>' '#include <openssl/evp.h>'; do
  cp "$root/src/vahf/sim/trial.h" "$work/copy/src/vahf/sim/trial.h"
  echo "$added" >>"$work/copy/src/vahf/sim/trial.h"
  if ! offending_includes "$work/copy" | grep -qF "src/vahf/sim/trial.h:"; then
    fail "the check accepts a public header with $added"
  fi
done
verdict "no public header includes an internal or a private dependency's header"
