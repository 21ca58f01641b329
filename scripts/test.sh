#!/usr/bin/env bash
# Installs, builds and runs the whole test suite (Catch2 tests and command-line checks, via ctest).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh" "$here/build"
ctest --test-dir "$here/build" --output-on-failure -j "$(nproc)"
