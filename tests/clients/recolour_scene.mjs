// node recolour_scene.mjs SCENE_DIR OUT_DIR
// A copy of a scene whose key drawings have different artwork: every bundled drawing is one dark
// grey, so a missing cross-fade would not show. Each key keeps its alpha (so the same multimesh
// comes out) and gets its own colour, lighter at the top and darker at the bottom and varying
// left to right, so that a wrong texture orientation or a y-flip shows too.
import fs from 'node:fs';
import path from 'node:path';
import { fail, usage } from './common.mjs';
import { readPng, writePng } from './png.mjs';

usage('node recolour_scene.mjs SCENE_DIR OUT_DIR', process.argv.length === 4);
const [from, to] = process.argv.slice(2);
const sceneFile = path.join(from, 'scene.json');
if (!fs.existsSync(sceneFile)) fail(`${sceneFile} does not exist`);
const scene = JSON.parse(fs.readFileSync(sceneFile, 'utf8'));
fs.mkdirSync(to, { recursive: true });
for (const name of fs.readdirSync(from))
  if (fs.statSync(path.join(from, name)).isFile() && !name.endsWith('.ibmesh')) fs.copyFileSync(path.join(from, name), path.join(to, name));
const palette = [[220, 60, 40], [40, 90, 220], [30, 160, 70], [230, 170, 20], [150, 50, 190], [20, 170, 180]];
scene.keys.forEach((key, k) => {
  const image = readPng(path.join(from, key.drawing));
  const [r, g, b] = palette[k % palette.length];
  for (let y = 0; y < image.height; ++y) for (let x = 0; x < image.width; ++x) {
    const shade = 1.2 - 0.6 * y / image.height, tilt = 0.85 + 0.3 * x / image.width;
    const i = 4 * (y * image.width + x);
    image.data[i] = Math.min(255, Math.round(r * shade * tilt));
    image.data[i + 1] = Math.min(255, Math.round(g * shade));
    image.data[i + 2] = Math.min(255, Math.round(b * shade * (2 - tilt)));
  }
  writePng(path.join(to, key.drawing), image);
});
console.log(`${to}: ${scene.keys.length} keys recoloured`);
