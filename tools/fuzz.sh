#!/usr/bin/env bash
# Bounded fuzzing of the scene, material and X3D parsers (libFuzzer, AddressSanitizer, UBSan).
#   tools/fuzz.sh build               configure and build the targets in build-fuzz/ (clang)
#   tools/fuzz.sh run TARGET SECONDS  replay TARGET's regression inputs, then fuzz for SECONDS
# Inputs that crashed once are kept in tests/fuzz/regressions/TARGET/ and replayed every run.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

case "${1:-}" in
  build)
    CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFABFORM_FUZZ=ON \
      -DBUILD_TESTING=OFF >/dev/null
    cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene fuzz_material fuzz_x3d >/dev/null
    ;;
  run)
    target=$2 seconds=$3
    binary=build-fuzz/tests/fuzz/fuzz_$target
    regressions=tests/fuzz/regressions/$target
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    cp tests/fuzz/corpus/"$target"/* "$work"/
    if compgen -G "$regressions/*" >/dev/null; then
      "$binary" -runs=0 "$regressions"/* 2>"$work/replay.log" || { cat "$work/replay.log"; exit 1; }
    fi
    # A crash leaves its input in $regressions, to be committed as a regression test.
    "$binary" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$regressions/" "$work" 2>"$work/fuzz.log" || {
      tail -40 "$work/fuzz.log"
      exit 1
    }
    grep -E "stat::number_of_executed_units|Done" "$work/fuzz.log" | tail -2
    ;;
  *)
    echo "usage: tools/fuzz.sh build | run TARGET SECONDS" >&2
    exit 2
    ;;
esac
