#!/bin/sh
# Fuzzes the scene loader and the --set parser: builds tests/fuzz with clang (libFuzzer,
# AddressSanitizer, UndefinedBehaviorSanitizer) and runs it from the checked-in corpus
# and the repository's scenes (docs/reliability.md). CTest runs it for 60 s as the test
# `fuzz`.
#
#   scripts/fuzz_scenes.sh [--build DIR] [--seconds N] [LIBFUZZER_OPTION ...]
#
#   --build DIR       the fuzzer's build tree (default: build-fuzz)
#   --seconds N       how long to fuzz (default: 60)
#   LIBFUZZER_OPTION  e.g. -jobs=2 -workers=2, -runs=0 to only replay the corpus, or
#                     more directories of seed inputs
#
# New inputs go to DIR/corpus (add the interesting ones to tests/fuzz/corpus), findings
# to DIR/findings/. Exit status: 0 nothing found; 1 the build failed or a finding.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build="build-fuzz"
seconds=60
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    *) break ;;
  esac
done

cmake -S "$root/tests/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null || exit 1
cmake --build "$build" -j2 || exit 1
mkdir -p "$build/corpus" "$build/findings"

export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp"
# An input that never returns is reported by -timeout. Out of memory, libFuzzer first
# prints AddressSanitizer's memory profile, which can take many minutes: the outer
# timeout ends that.
timeout -s KILL $((seconds + 300)) "$build/scene_fuzzer" -max_total_time="$seconds" -timeout=5 \
  -rss_limit_mb=4096 -artifact_prefix="$build/findings/" -print_final_stats=1 \
  "$build/corpus" "$root/tests/fuzz/corpus" "$root/configs" "$root/tests/scene/data/malformed" "$@" || exit 1
