// What the client checks share: failing with a one-line reason, the npm packages (loaded only
// after checking they are installed, so a missing `npm ci` says what to do), reading a glTF's
// JSON and the drawing-pixel coordinates of the export's contract (docs/export.md).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const here = path.dirname(fileURLToPath(import.meta.url));
const script = path.basename(process.argv[1] ?? 'clients');

// Prints "SCRIPT: reason" and exits 1.
export function fail(reason) {
  console.error(`${script}: ${reason}`);
  process.exit(1);
}

export function usage(text, ok) {
  if (!ok) {
    console.error(`usage: ${text}`);
    process.exit(2);
  }
}

// import() of an installed package, or a failure telling how to install them.
export async function need(specifier) {
  const top = specifier.startsWith('@') ? specifier.split('/').slice(0, 2).join('/') : specifier.split('/')[0];
  const manifest = path.join(here, 'node_modules', top, 'package.json');
  if (!fs.existsSync(manifest))
    fail(`${path.join(here, 'node_modules', top)} is missing: run scripts/setup.sh (or \`npm ci\` in tests/clients)`);
  const subpath = specifier.slice(top.length);
  if (!subpath) return import(top);
  return import(pathToFileURL(path.join(here, 'node_modules', top, subpath)).href);
}

// The glTF JSON of a .glb or .gltf file.
export function gltfJson(file) {
  const bytes = fs.readFileSync(file);
  if (bytes.readUInt32LE(0) !== 0x46546c67) return JSON.parse(bytes.toString('utf8'));
  const length = bytes.readUInt32LE(12);
  if (bytes.readUInt32LE(16) !== 0x4e4f534a) fail(`${file}: the first GLB chunk is not JSON`);
  return JSON.parse(bytes.toString('utf8', 20, 20 + length));
}

// asset.extras.inbetween, checked for the fields the contract names.
export function inbetweenExtras(file, json = gltfJson(file)) {
  const extras = json.asset?.extras?.inbetween;
  if (!extras) fail(`${file}: no asset.extras.inbetween`);
  for (const field of ['canvas', 'pixelsPerUnit', 'fps', 'frames', 'shapeSize', 'bounds'])
    if (extras[field] === undefined) fail(`${file}: asset.extras.inbetween has no ${field}`);
  return extras;
}

// glTF world-space point (X, Y) to drawing pixels.
export function toPixels(X, Y, extras) {
  const [W, H] = extras.canvas, p = extras.pixelsPerUnit;
  return [X * p + W / 2, H / 2 - Y * p];
}

export function readJson(file) {
  try {
    return JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (e) {
    fail(`${file}: ${e.message}`);
  }
}

// Opaque-layer weights the over-compositing of the layers gives, bottom (0) to top, from the
// layers' alpha factors: layer k keeps f_k times what the layers above let through.
export function compositeWeights(factors) {
  const out = new Array(factors.length);
  let through = 1;
  for (let k = factors.length - 1; k >= 0; --k) {
    out[k] = factors[k] * through;
    through *= 1 - factors[k];
  }
  return out;
}

// Debian's Chromium (or INBETWEEN_CHROMIUM), headless, in a fresh profile: { context, close() },
// close() also removing the profile. `extraArgs` go on its command line after the shared ones.
export async function launchChromium(extraArgs = []) {
  const { chromium } = await need('playwright-core');
  const executablePath = process.env.INBETWEEN_CHROMIUM ?? ['/usr/lib/chromium/chromium', '/usr/bin/chromium'].find((p) => fs.existsSync(p));
  if (!executablePath) fail('no Chromium: install Debian\'s chromium (scripts/setup.sh) or set INBETWEEN_CHROMIUM');
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'inbetween-chromium-'));
  const removeProfile = () => fs.rmSync(profile, { recursive: true, force: true });
  let context;
  try {
    context = await chromium.launchPersistentContext(profile, {
      executablePath, headless: true,
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
             '--disable-component-update', '--disable-sync', ...extraArgs],
    });
  } catch (e) {
    removeProfile();
    throw e;
  }
  return { context, close: async () => { await context.close(); removeProfile(); } };
}
