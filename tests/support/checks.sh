# Checks shared by the shell tests. Source it from a test script:
#   . "$(dirname "$0")/../support/checks.sh"
# It makes the scratch folder $TMP (removed on exit), counts failed checks,
# and `finish` ends the script: exit 1 if any check failed.

TMP=$(mktemp -d) || exit 1
trap 'rm -rf "$TMP"' EXIT
failures=0

pass() { echo "ok   $1"; }
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
# expect_eq NAME ACTUAL EXPECTED
expect_eq() {
  if [ "$2" = "$3" ]; then pass "$1"; else
    fail "$1"; printf '  expected: [%s]\n  actual:   [%s]\n' "$3" "$2"; fi
}
# expect_contains NAME TEXT NEEDLE
expect_contains() {
  case "$2" in *"$3"*) pass "$1" ;; *) fail "$1"; printf '  [%s] not in:\n%s\n' "$3" "$2" ;; esac
}
# finish: the summary line and the exit code.
finish() {
  if [ "$failures" -ne 0 ]; then
    echo "$failures check(s) failed"
    exit 1
  fi
  echo "all checks passed"
}
