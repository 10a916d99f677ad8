#!/usr/bin/env bash
# Bounded fuzzing of the parsers at fabform's edge: the scene, material table, X3D and study files
# (libFuzzer, AddressSanitizer, UBSan). Not part of the test suite, which replays every target's
# corpus and regressions (tests/fuzz/fuzz_replay_test.cpp).
#   tools/fuzz.sh build               configure and build the targets in build-fuzz/ (clang)
#   tools/fuzz.sh run TARGET SECONDS  replay TARGET's regression inputs, then fuzz for SECONDS
#   tools/fuzz.sh all [SECONDS]       build, then fuzz every target for SECONDS (default 600)
# An input that crashes a target is left in tests/fuzz/regressions/TARGET/, to be committed: the
# test suite then replays it for ever.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

case "${1:-}" in
  build)
    CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFABFORM_FUZZ=ON \
      -DBUILD_TESTING=OFF >/dev/null
    cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene fuzz_material fuzz_x3d fuzz_study >/dev/null
    ;;
  all)
    "$0" build
    for target in scene material x3d study; do
      echo "== $target"
      "$0" run "$target" "${2:-600}"
    done
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
    echo "usage: tools/fuzz.sh build | run TARGET SECONDS | all [SECONDS]" >&2
    exit 2
    ;;
esac
