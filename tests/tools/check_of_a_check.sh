# Sourced by the tests of a source-tree check (format_test.sh, registry_names_test.sh,
# error_tiers_test.sh, layering_test.sh, function_length_test.sh,
# public_headers_test.sh): the check must pass on the tree and
# on a good copy, and fail on a broken copy naming what broke it. Counts failures in $failures;
# `verdict` prints the result and exits.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0

# passes WHAT CMD...: CMD succeeds; else FAIL: WHAT, and CMD's output.
passes() {
  local what="$1"
  shift
  if ! "$@" >"$work/log" 2>&1; then
    echo "FAIL: $what:" >&2
    cat "$work/log" >&2
    failures=$((failures + 1))
  fi
}

# catches WHAT LINE CMD...: CMD fails, printing LINE.
catches() {
  local what="$1" line="$2"
  shift 2
  if "$@" >"$work/log" 2>&1; then
    echo "FAIL: $what is not caught" >&2
    failures=$((failures + 1))
  elif ! grep -qF "$line" "$work/log"; then
    echo "FAIL: $what is caught without the line '$line':" >&2
    cat "$work/log" >&2
    failures=$((failures + 1))
  fi
}

# verdict PASS-MESSAGE: prints it if nothing failed; exits 0 or 1.
verdict() {
  [ "$failures" -eq 0 ] && echo "PASS: $1"
  exit $((failures > 0))
}
