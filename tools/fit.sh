#!/usr/bin/env bash
# Quick start, one command: set up, build, and run the default mold fit into results/mold.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tools/setup.sh
build/fabform run scenes/mold.toml --out results/mold "$@"
