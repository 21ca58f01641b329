#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) and runs each
# for a bounded time from seed corpora made from the bundled examples. Usage:
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [BUILD_DIR] [TARGET...]
# (default 60 s, build-fuzz, every target: scene scene_document png_tracing multimesh gltf_writer). CI runs it
# with a short time; run it longer by hand. The corpora grow in BUILD_DIR/fuzz-corpus/TARGET and
# are kept from run to run. An input that crashes a target, trips a sanitizer or throws what the
# target does not expect is saved as BUILD_DIR/fuzz-artifacts/TARGET/crash-*: the script then
# exits 1. Fix the bug, copy the input into tests/fuzz/regressions/TARGET/ (every build replays
# those as a test) and run again. Each target's last line reports the executions run.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${2:-"$here/build-fuzz"}
shift $(( $# > 2 ? 2 : $# ))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene scene_document png_tracing multimesh gltf_writer)

INBETWEEN_SETUP_ONLY=1 "$here/scripts/setup.sh"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 -DINBETWEEN_ENGINE=OFF \
  -DINBETWEEN_FUZZ=ON -DINBETWEEN_SANITIZE=address,undefined
cmake --build "$build" -j "$(nproc)" --target make_fuzz_seeds $(printf 'fuzz_%s ' "${targets[@]}")

seeds="$build/fuzz-seeds"
rm -rf "$seeds"
ASAN_OPTIONS=detect_leaks=0 "$build/tests/fuzz/make_fuzz_seeds" "$here/assets" "$seeds"

export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
failed=0
for t in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$t"
  artifacts="$build/fuzz-artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  log="$build/fuzz-$t.log"
  echo "fuzz.sh: $t for $seconds s"
  # -timeout: one input taking over 10 s is a hang; -rss_limit_mb: over 2 GiB is a finding.
  if ! "$build/tests/fuzz/fuzz_$t" "$corpus" "$seeds/$t" "$here/tests/fuzz/regressions/$t" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    failed=1
    echo "fuzz.sh: $t FAILED; the input is in $artifacts/, the log in $log" >&2
    grep -E "ERROR|SUMMARY|terminate|what\(\)" "$log" | head -5 >&2 || true
  fi
  runs=$(grep -E "stat::number_of_executed_units" "$log" | awk '{print $2}' | tail -1)
  echo "fuzz.sh: $t: ${runs:-?} executions, corpus $(ls "$corpus" | wc -l) inputs"
done
exit $failed
