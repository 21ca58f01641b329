#!/bin/sh
# Regenerates the gallery (docs/gallery.md and docs/gallery/): for every example of the paper in
# assets/ (those with a README.md), `inbetween render --preview` draws its timeline at 128 x 128 px, 12 frames a second
# over white; its contact sheet and its animated preview (APNG) are copied into docs/gallery/, and
# docs/gallery.md shows them with the example's README paragraph. Then the README's figure:
# square-arch-notch's frames 0, 12, 18, 24, 36 and 42 in a row, plain (docs/images/square-arch-notch.png)
# and with the mesh, cohesive edges and features drawn (docs/images/square-arch-notch-mesh.png).
#
#   scripts/gallery.sh [BUILD_DIR]   (default: build, as scripts/setup.sh makes it)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
inbetween=$build/apps/inbetween
[ -x "$inbetween" ] || { echo "gallery.sh: $inbetween is missing: build first (scripts/setup.sh)" >&2; exit 2; }
out=$root/docs/gallery
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$out"
page=$scratch/gallery.md
{
  echo "# Gallery"
  echo
  echo "The paper's examples, redrawn for the project (\`assets/\`), each played through its timeline by"
  echo "\`inbetween render --preview --fps 12\` at 128 x 128 px: the animated preview (APNG), then the contact"
  echo "sheet of its frames. \`scripts/gallery.sh\` makes this page again."
} > "$page"
for readme in "$root"/assets/*/README.md; do
  dir=$(dirname "$readme")
  name=$(basename "$dir")
  [ -f "$dir/scene.json" ] || continue
  echo "gallery.sh: $name" >&2
  "$inbetween" render "$dir/scene.json" -o "$scratch/$name" --size 128x128 --fps 12 --background ffffff --preview --device cpu > /dev/null
  cp "$scratch/$name/preview.png" "$out/$name.png"
  cp "$scratch/$name/contact_sheet.png" "$out/$name-sheet.png"
  {
    echo
    echo "## $name"
    echo
    # The README's paragraph: the lines after the title, up to the first blank line after text.
    awk 'NR > 1 && /^$/ && seen { exit } NR > 1 && !/^$/ { seen = 1; print }' "$readme"
    echo
    echo "![$name](gallery/$name.png) ![$name, contact sheet](gallery/$name-sheet.png)"
  } >> "$page"
done
mv "$page" "$root/docs/gallery.md"
echo "gallery.sh: wrote docs/gallery.md and docs/gallery/" >&2

figure() {  # figure NAME [OVERLAY...]: the README's frames of square-arch-notch as docs/images/NAME.png
  name=$1
  shift
  "$inbetween" render "$root/assets/square-arch-notch/scene.json" -o "$scratch/$name" --size 384x384 --background ffffff \
    --sheet-frames 0,12,18,24,36,42 --sheet-columns 6 --device cpu "$@" > /dev/null
  cp "$scratch/$name/contact_sheet.png" "$root/docs/images/$name.png"
}
figure square-arch-notch
figure square-arch-notch-mesh --wireframe --cohesive --features
echo "gallery.sh: wrote docs/images/square-arch-notch.png and square-arch-notch-mesh.png" >&2
