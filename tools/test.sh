#!/usr/bin/env bash
# Quick start, the other command: set up, build, and run the whole test suite; then the C++
# tests again under AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tools/setup.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
tools/sanitize.sh
