#!/usr/bin/env bash
# Builds inbetween with sanitizers and runs the test suite under them. Usage:
#   scripts/sanitize.sh address [BUILD_DIR]   AddressSanitizer + UndefinedBehaviorSanitizer with clang,
#                                             the whole suite but the soak and the glTF clients' tests:
#                                             solver, engine, player and editor under Xvfb, CLI (default
#                                             BUILD_DIR: build-asan; about 80 minutes on 2 cores)
#   scripts/sanitize.sh address-solver [BUILD_DIR]
#                                             AddressSanitizer + UBSan with clang, without the engine
#                                             (no Vulkan, window or drawing commands): the solver's, the
#                                             CPU output layer's, the exporter's and the other commands'
#                                             tests, but for the second walks over every bundled scene
#                                             listed below (default BUILD_DIR: build-asan-solver); what
#                                             CI runs (docs/hardening.md, "In CI")
#   scripts/sanitize.sh thread [BUILD_DIR]    ThreadSanitizer with clang and LLVM's OpenMP (Archer tells
#                                             it about OpenMP's barriers), without the engine: the
#                                             tests of the player's solve worker, the live solver and
#                                             the solver's threaded paths (default BUILD_DIR: build-tsan)
# Any finding fails the test it happens in. Installs the packages first (scripts/setup.sh).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
kind=${1:-address}
case "$kind" in
  address) build=${2:-"$here/build-asan"} ;;
  address-solver) build=${2:-"$here/build-asan-solver"} ;;
  thread) build=${2:-"$here/build-tsan"} ;;
  *) echo "sanitize.sh: '$kind' is not address, address-solver or thread" >&2; exit 2 ;;
esac

INBETWEEN_SETUP_ONLY=1 "$here/scripts/setup.sh"

options=(-DCMAKE_BUILD_TYPE=Release)
[ -z "${INBETWEEN_WERROR:-}" ] || options+=("-DINBETWEEN_WERROR=$INBETWEEN_WERROR")
if [ "$kind" = address-solver ]; then
  # Not the fuzzers' build (scripts/fuzz.sh): their coverage instrumentation doubles the run time.
  options+=(-DCMAKE_CXX_COMPILER=clang++-14 -DINBETWEEN_ENGINE=OFF -DINBETWEEN_SANITIZE=address,undefined)
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export LSAN_OPTIONS="suppressions=$here/scripts/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
elif [ "$kind" = address ]; then
  # clang: its ASan build of this tree takes about a third of GCC's (CGAL and Eigen at -O2).
  options+=(-DCMAKE_CXX_COMPILER=clang++-14 -DINBETWEEN_SANITIZE=address,undefined)
  # Mesa's lavapipe, the Vulkan loader and X keep allocations for the life of the process; the
  # leak check covers our code and suppresses theirs (scripts/lsan.supp). The loader unloads
  # lavapipe at exit, after which its leaks have no module to match: preloaded, it stays loaded
  # (and ASan then need not come first among the libraries).
  lavapipe=$(ls /usr/lib/*/libvulkan_lvp.so 2>/dev/null | head -1)
  [ -z "$lavapipe" ] || export LD_PRELOAD="$lavapipe"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:verify_asan_link_order=0"
  export LSAN_OPTIONS="suppressions=$here/scripts/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
else
  options+=(-DINBETWEEN_SANITIZE=thread -DCMAKE_CXX_COMPILER=clang++-14 -DINBETWEEN_ENGINE=OFF)
  archer=/usr/lib/llvm-14/lib/libarcher.so
  export OMP_TOOL_LIBRARIES="$archer"
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$here/scripts/tsan.supp"
fi
cmake -S "$here" -B "$build" "${options[@]}"
if [ "$kind" != thread ]; then
  cmake --build "$build" -j "$(nproc)"
else
  cmake --build "$build" -j "$(nproc)" --target inbetween_tests inbetween_output_tests
fi
if [ "$kind" = address ]; then
  # All but the soak (10,000 player frames, minutes under the sanitizers; leaks show at exit anyway)
  # and the glTF clients' tests (1,078 s of the suite's 4,594 under the sanitizers, 2026-12-07),
  # spent in Node, Chromium and the validator, which are not instrumented, on exports of scenes the
  # engine and CLI tests export too.
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 1500 -LE "^(soak|clients)$"
elif [ "$kind" = address-solver ]; then
  # Second walks over every bundled scene, through code that the other walks over every bundled
  # scene (the examples' builds and Comesh, the animation) and the exporter's own tests run under
  # the sanitizers too: about 1,000 s of test time under the sanitizers (2026-12-07).
  second_walks=(
    "even spacing: every bundled asset"
    "previous map: a build from the previous build"
    "previous map: after a feature moves"
    "interpolation: on every bundled asset, halving a step in w"
    "multimesh builder: every bundled asset scene builds"
    "export: every bundled scene read back by tinygltf"
    "cli: bench anim prints a JSON line per bundled scene"
  )
  skip=$(IFS='|'; echo "^(${second_walks[*]})")
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 1500 -LE "^(soak|clients)$" -E "$skip"
else
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 1500 \
    -R "solve worker|live solver|frame stream|thread|[Cc]holesky|Anderson|anderson|elimination" -E "^cli:"
fi
