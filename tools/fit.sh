#!/usr/bin/env bash
# Quick start, one command: set up, build, run the default mold fit into results/mold, and
# write its report (results/mold/report.html).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tools/setup.sh
status=0
build/fabform run scenes/mold.toml --out results/mold "$@" || status=$?
# The report says plainly when the fit did not converge; only bad input leaves none to report.
if [[ $status -ne 2 ]]; then /usr/bin/python3 tools/report.py results/mold; fi
exit $status
