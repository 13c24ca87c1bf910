#!/usr/bin/env bash
# The accuracy-versus-time benchmark: sets up, builds, installs gnuplot for the
# plot, and runs ssao-bench (results in ./bench-out; extra flags pass through).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
if ! command -v gnuplot >/dev/null 2>&1; then
  if [ "$(id -u)" -eq 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gnuplot-nox
  else
    echo "run-bench: gnuplot is missing (apt-get install gnuplot-nox as root); the plot will not be drawn" >&2
  fi
fi
scripts/build.sh
build/bench/ssao-bench --out bench-out "$@"
