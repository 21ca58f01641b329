#!/usr/bin/env python3
"""Draws the key drawings of the geometric paper examples as SVG and rasterizes them to PNG.

  scripts/draw_examples.py [ASSETS]   (default: the source tree's assets/)

Writes, in each example's folder beside its scene.json, one SVG and one 512 x 512 PNG per key:
  arch-stretch/, arch-split/   a sandstone block and the arch it becomes (paper Figure 2)
  star-regular/, star-hard3/, star-hard6/
                               a pentagon badge and the star it becomes, the star's spokes
                               thinner in each (paper Figures 4 and 18)
The PNGs are committed; this script is how they were made (rsvg-convert, Debian's
librsvg2-bin, does the rasterizing). The drawings are made for the project, CC0 1.0.
"""
import math
import os
import subprocess
import sys

SIZE = 512
INK = "#4a2c17"


def write(folder, name, body):
    os.makedirs(folder, exist_ok=True)
    svg = os.path.join(folder, name + ".svg")
    with open(svg, "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">\n' % (SIZE, SIZE, SIZE, SIZE))
        f.write("  <!-- %s: drawn for inbetween's examples by scripts/draw_examples.py (CC0 1.0) -->\n" % name)
        f.write(body)
        f.write("</svg>\n")
    subprocess.run(["rsvg-convert", "-w", str(SIZE), "-h", str(SIZE), svg, "-o", os.path.join(folder, name + ".png")], check=True)


# Sandstone: a block of bricks with moss on top, and the arch it becomes. The block is
# 200 x 200 px at (156, 166); the arch 260 x 210 at (126, 186) with a 120 px opening whose round
# top is centred at (256, 306): about the same area (40,000 and 38,100 px^2).
BLOCK = "M156,166 H356 V366 H156 Z"
ARCH = "M126,396 V186 H386 V396 H316 V306 A60,60 0 0 0 196,306 V396 Z"


def stone(outline, mortar, moss):
    return ('  <defs><clipPath id="inside"><path d="%s"/></clipPath></defs>\n'
            '  <path d="%s" fill="#d9a066"/>\n'
            '  <g clip-path="url(#inside)" fill="none" stroke="#a8703c" stroke-width="5" stroke-linecap="round">%s</g>\n'
            '  <path d="%s" fill="#6a9a3a" clip-path="url(#inside)"/>\n'
            '  <path d="%s" fill="none" stroke="%s" stroke-width="6" stroke-linejoin="round"/>\n') % (outline, outline, mortar, moss, outline, INK)


def block():
    rows = [166, 216, 266, 316, 366]
    mortar = "".join('<path d="M150,%d H362"/>' % y for y in rows[1:-1])
    for i in range(len(rows) - 1):
        x0 = 206 if i % 2 == 0 else 181
        mortar += "".join('<path d="M%d,%d V%d"/>' % (x, rows[i] + 4, rows[i + 1] - 4) for x in range(x0, 356, 50))
    moss = "M150,160 H362 V182 Q331,196 306,184 Q281,196 256,184 Q231,196 206,184 Q181,196 150,182 Z"
    return stone(BLOCK, mortar, moss)


def arch():
    mortar = "".join('<path d="M120,%d H392"/>' % y for y in (236, 286, 336))
    mortar += "".join('<path d="M%d,%d V%d"/>' % (x, y0, y1) for x, y0, y1 in
                      ((176, 190, 232), (336, 190, 232), (151, 240, 282), (356, 240, 282), (166, 290, 332),
                       (346, 290, 332), (156, 340, 392), (356, 340, 392)))
    for k in range(1, 6):  # voussoirs round the opening
        a = math.pi * k / 6
        mortar += '<path d="M%.1f,%.1f L%.1f,%.1f"/>' % (256 - 62 * math.cos(a), 306 - 62 * math.sin(a),
                                                          256 - 100 * math.cos(a), 306 - 100 * math.sin(a))
    moss = "M120,180 H392 V202 Q359,216 321,204 Q288,216 256,204 Q224,216 191,204 Q153,216 120,202 Z"
    return stone(ARCH, mortar, moss)


# A badge: a pentagon (circumradius 160) that becomes a five-pointed star (tips at 230 px, inner
# corners at RATIO * 230), both centred at (256, 266), with a face and a stripe along every spoke.
CENTRE = (256, 266)


def polar(r, degrees):
    a = math.radians(degrees)
    return CENTRE[0] + r * math.cos(a), CENTRE[1] + r * math.sin(a)


def polygon_path(points):
    return "M" + " L".join("%.2f,%.2f" % p for p in points) + " Z"


def badge(outline, reach):
    stripes = "".join('<path d="M%.1f,%.1f L%.1f,%.1f"/>' % (polar(0.3 * reach, -90 + 72 * k) + polar(0.78 * reach, -90 + 72 * k))
                      for k in range(5))
    return ('  <path d="%s" fill="#f2c14e" stroke="%s" stroke-width="6" stroke-linejoin="round"/>\n'
            '  <g fill="none" stroke="#e07a2e" stroke-width="6" stroke-linecap="round">%s</g>\n'
            '  <circle cx="256" cy="266" r="44" fill="#f7dc8a"/>\n'
            '  <circle cx="240" cy="256" r="8" fill="#2a1a0a"/><circle cx="272" cy="256" r="8" fill="#2a1a0a"/>\n'
            '  <path d="M238,280 Q256,296 274,280" fill="none" stroke="#2a1a0a" stroke-width="5" stroke-linecap="round"/>\n'
            ) % (outline, INK, stripes)


def pentagon():
    return badge(polygon_path([polar(160, -90 + 72 * k) for k in range(5)]), 160)


def star(ratio):
    points = []
    for k in range(5):
        points.append(polar(230, -90 + 72 * k))
        points.append(polar(230 * ratio, -54 + 72 * k))
    return badge(polygon_path(points), 230)


def main():
    assets = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets")
    for name in ("arch-stretch", "arch-split"):
        write(os.path.join(assets, name), "square", block())
        write(os.path.join(assets, name), "arch", arch())
    for name, ratio in (("star-regular", 0.5), ("star-hard3", 0.3), ("star-hard6", 0.15)):
        write(os.path.join(assets, name), "pentagon", pentagon())
        write(os.path.join(assets, name), "star", star(ratio))


if __name__ == "__main__":
    main()
