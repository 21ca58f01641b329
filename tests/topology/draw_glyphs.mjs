// Draws the glyph drawings of the topology-change scenes (tests/topology/glyph-*/): letters of
// DejaVu Sans Bold (Debian's fonts-dejavu-core) that open or split between keys, as an animator
// would letter them: a coloured fill inside a dark ink line 3 px wide, 256 px. Chromium's canvas
// rasterizes them (the font, antialiased), so the drawings come from a real font renderer:
//   node tests/topology/draw_glyphs.mjs     (needs tests/clients' npm packages; rewrites the PNGs)
// The scenes' cut points and features were read off these drawings (glyph_features.py).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium } from '../clients/common.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const SIZE = 256;
// [folder, file, letter, fill]
const glyphs = [
  ['glyph-l-i', 'l.png', 'l', '#3a8fd8'], ['glyph-l-i', 'i.png', 'i', '#3a8fd8'],
  ['glyph-o-c', 'o.png', 'O', '#e0543c'], ['glyph-o-c', 'c.png', 'C', '#e0543c'],
];

const browser = await launchChromium();
try {
  const page = await browser.context.newPage();
  await page.setContent('<canvas id="c" width="256" height="256"></canvas>');
  for (const [folder, file, letter, fill] of glyphs) {
    const dataUrl = await page.evaluate(async ([letter, fill, size]) => {
      const canvas = document.getElementById('c');
      const ctx = canvas.getContext('2d');
      ctx.clearRect(0, 0, size, size);
      ctx.font = 'bold 210px "DejaVu Sans"';
      await document.fonts.load(ctx.font);
      ctx.textAlign = 'center';
      ctx.textBaseline = 'alphabetic';
      // Ink: the outline stroked 6 px wide (3 px outside the letter), the fill drawn over its inner half.
      ctx.lineJoin = 'round';
      ctx.lineWidth = 6;
      ctx.strokeStyle = '#281e3c';
      ctx.strokeText(letter, size / 2, 205);
      ctx.fillStyle = fill;
      ctx.fillText(letter, size / 2, 205);
      return canvas.toDataURL('image/png');
    }, [letter, fill, SIZE]);
    fs.mkdirSync(path.join(here, folder), { recursive: true });
    fs.writeFileSync(path.join(here, folder, file), Buffer.from(dataUrl.split(',')[1], 'base64'));
    console.log(`wrote ${folder}/${file}`);
  }
} finally {
  await browser.close();
}
