#!/usr/bin/env bash
# Installs, builds and runs the main job on the bundled example. For now that is the
# interpolation benchmark on strips built in code; its JSON lines land in out/bench-interp.jsonl.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh" "$here/build"
mkdir -p "$here/out"
"$here/build/apps/inbetween" bench interp --sizes 1k,10k | tee "$here/out/bench-interp.jsonl.tmp"
mv "$here/out/bench-interp.jsonl.tmp" "$here/out/bench-interp.jsonl"
echo "results: $here/out/bench-interp.jsonl"
