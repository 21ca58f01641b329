#!/usr/bin/env bash
# Installs, builds and runs the main job on a bundled example: the Comesh-optimized multimesh of
# assets/square-arch-notch (out/square-arch-notch.ibmesh, the initial map beside it as
# out/square-arch-notch.initial.ibmesh, one SVG per key and version), then the
# interpolation benchmark (out/bench-interp.jsonl) and the animation benchmark
# (out/bench-anim.jsonl: every bundled scene played through its timeline).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh" "$here/build"
mkdir -p "$here/out"
"$here/build/apps/inbetween" mesh "$here/assets/square-arch-notch/scene.json" -o "$here/out/square-arch-notch.ibmesh"
"$here/build/apps/inbetween" bench interp --sizes 1k,10k | tee "$here/out/bench-interp.jsonl.tmp"
mv "$here/out/bench-interp.jsonl.tmp" "$here/out/bench-interp.jsonl"
"$here/build/apps/inbetween" bench anim | tee "$here/out/bench-anim.jsonl.tmp"
mv "$here/out/bench-anim.jsonl.tmp" "$here/out/bench-anim.jsonl"
echo "results: $here/out/bench-interp.jsonl $here/out/bench-anim.jsonl"
