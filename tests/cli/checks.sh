# Sourced by the cli tests: a scratch folder ($work, removed on exit), a
# failure count, `check DESCRIPTION COMMAND...` (the command must succeed) and
# `finish NAME` (the summary line and the exit status).
work=$(mktemp -d /tmp/ssao-cli.XXXXXX)
trap 'rm -rf "$work"' EXIT
failures=0
check() {
  local what=$1; shift
  if "$@"; then echo "ok      $what"; else echo "FAILED  $what"; failures=$((failures + 1)); fi
}
finish() {
  [ "$failures" -eq 0 ] && echo "$1: all passed" || echo "$1: $failures FAILED"
  exit $((failures > 0))
}
