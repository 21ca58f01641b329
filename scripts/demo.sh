#!/usr/bin/env bash
# Installs, builds and runs the main job on a bundled example: the Comesh-optimized multimesh of
# assets/square-arch-notch (out/square-arch-notch.ibmesh, the initial map beside it as
# out/square-arch-notch.initial.ibmesh, one SVG per key and version), its animation rendered
# headless (out/square-arch-notch/frame_NNNN.png and contact_sheet.png), then the interpolation,
# animation and rendering benchmarks (out/bench-interp.jsonl, out/bench-anim.jsonl,
# out/bench-render.jsonl).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh" "$here/build"
mkdir -p "$here/out"
"$here/build/apps/inbetween" mesh "$here/assets/square-arch-notch/scene.json" -o "$here/out/square-arch-notch.ibmesh"
"$here/build/apps/inbetween" render "$here/assets/square-arch-notch/scene.json" --mesh "$here/out/square-arch-notch.ibmesh" \
  -o "$here/out/square-arch-notch" --size 384x384 --background ffffff
"$here/build/apps/inbetween" bench interp --sizes 1k,10k | tee "$here/out/bench-interp.jsonl.tmp"
mv "$here/out/bench-interp.jsonl.tmp" "$here/out/bench-interp.jsonl"
"$here/build/apps/inbetween" bench anim | tee "$here/out/bench-anim.jsonl.tmp"
mv "$here/out/bench-anim.jsonl.tmp" "$here/out/bench-anim.jsonl"
"$here/build/apps/inbetween" bench render | tee "$here/out/bench-render.jsonl.tmp"
mv "$here/out/bench-render.jsonl.tmp" "$here/out/bench-render.jsonl"
echo "results: $here/out/square-arch-notch/ (frames, contact_sheet.png), $here/out/bench-*.jsonl"
