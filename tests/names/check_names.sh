#!/usr/bin/env bash
# A doctest case whose name holds a ';' never runs under CTest: CMake splits
# the name doctest_discover_tests hands it at the ';', so the test's
# --test-case filter matches nothing, runs no case and passes. This lists
# every discovered binary's cases and fails on such a name.
#   check_names.sh BINARY...
set -euo pipefail
bad=0
for binary in "$@"; do
  while IFS= read -r name; do
    echo "check_names: $(basename "$binary"): a test case name with ';' never runs under CTest: $name"
    bad=1
  done < <("$binary" --list-test-cases --no-version | grep ';' || true)
done
exit "$bad"
