// node browser_vs_render.mjs FILE.glb RENDER_DIR REFERENCE.json --frames F1,F2,... [--side-by-side OUT.png] [--break WHAT]
// Headless Chromium (Debian's, software WebGL through ANGLE on SwiftShader) draws an exported file
// with three.js's WebGLRenderer (antialias, transparent clear, an OrthographicCamera covering exactly
// the canvas, the KHR_animation_pointer plugin so the artwork cross-fades) at the times of the
// given frames; RENDER_DIR holds `inbetween render`'s frames of the same scene and multimesh
// (frame_NNNN.png, straight alpha), REFERENCE.json its solved frames (tests/tools/welded_frames,
// for the keys' weights). First, the layers' alpha factors in the browser must composite to the
// keys' weights (within 1e-3). Then both pictures premultiplied, per frame:
//   alpha:  |a - a'| over the pixels either picture covers (alpha > 0): mean and 99th percentile
//   colour: the largest channel's |c - c'| over the pixels both cover more than half: mean, 99th
// (in units of 1 = 255). Fails when any figure exceeds its tolerance (TOLERANCE below, docs/export.md):
// a frame is at a key when one key has all the weight.
// --side-by-side writes the first frame between the keys as three.js | inbetween render, over grey.
// --break flip|shift|no-crossfade draws wrongly on purpose (y-flipped camera, camera 1 drawing
// pixel off, no pointer plugin) to see the check fail.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fail, here, launchChromium, usage, inbetweenExtras, compositeWeights, readJson } from './common.mjs';
import { readPng, writePng } from './png.mjs';

// Tolerances (units of 1 = 255), measured on square-arch-notch and pentagon-star recoloured
// (docs/export.md "How the export is tested"), with about twice the largest figure as margin. At a
// key one layer is in play and only rasterization differs (MSAA coverage, texture filtering);
// between keys the over-compositing of the layers differs from the renderer's weighted sum where
// the keys' outlines disagree (docs/export.md "Where the two differ"). Colour p99 at a key is 0.1:
// on drawings with inner lines (a 512 px fish with outlined stripes) a frame a fraction of a texel
// off the drawing's grid shows every colour edge 1 px wide up to 0.063 apart, since a client
// filters the sRGB texture in linear light and the renderer filters the stored values. Alpha p99
// at a key is 0.3: the silhouette is the mesh's multisampled edge (the drawings' rims are made
// opaque, engine/output/silhouette_artwork.h), and SwiftShader's 4 samples sit elsewhere in the
// pixel than lavapipe's, so an edge pixel can differ by one sample in four (0.25, seen 0.251).
// Alpha mean at a key is 0.01: `inbetween render` draws a key as its drawing, with the drawing's
// own antialiased edge (docs/rendering.md "Keys are the drawings"), which the export does not yet
// do (its edge is the mesh's): pentagon-star recoloured's frame 24 measured 0.0052 (0.0041 at
// frame 0), against at most 0.0025 before render drew the keys' own edges.
export const TOLERANCE = {
  key: { alphaMean: 0.01, alphaP99: 0.3, colourMean: 0.003, colourP99: 0.1 },
  between: { alphaMean: 0.02, alphaP99: 0.4, colourMean: 0.015, colourP99: 0.2 },
};

const args = process.argv.slice(2);
const option = (name) => {
  const at = args.indexOf(name);
  return at >= 0 ? args.splice(at, 2)[1] : undefined;
};
const framesText = option('--frames'), sideBySide = option('--side-by-side'), breakWhat = option('--break');
usage('node browser_vs_render.mjs FILE.glb RENDER_DIR REFERENCE.json --frames F1,F2,... [--side-by-side OUT.png] [--break flip|shift|no-crossfade]',
      args.length === 3 && framesText && (!breakWhat || ['flip', 'shift', 'no-crossfade'].includes(breakWhat)));
const [file, renderDir, referenceFile] = args;
const reference = readJson(referenceFile);
const frames = framesText.split(',').map(Number);
if (!fs.existsSync(file)) fail(`${file} does not exist`);
const extras = inbetweenExtras(file);
const [A, B] = extras.frames;
for (const f of frames) if (!(Number.isInteger(f) && f >= A && f <= B)) fail(`--frames: ${f} is not a frame of ${file} (${A}..${B})`);
const weights = frames.map((f) => {
  const frame = reference.frames.find((r) => r.index === f);
  if (!frame) fail(`${referenceFile} has no frame ${f}`);
  return frame.weights;
});
const rendered = frames.map((f) => {
  const png = path.join(renderDir, `frame_${String(f).padStart(4, '0')}.png`);
  if (!fs.existsSync(png)) fail(`${png} does not exist (inbetween render's frame ${f})`);
  return readPng(png);
});

// The page and node_modules from tests/clients, the file (and anything beside it) under /model/.
const modelDir = path.dirname(path.resolve(file));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
                '.glb': 'model/gltf-binary', '.gltf': 'model/gltf+json', '.wasm': 'application/wasm', '.png': 'image/png' };
const server = http.createServer((request, response) => {
  const url = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
  const [root, rest] = url.startsWith('/model/') ? [modelDir, url.slice(7)] : [here, url.slice(1)];
  const target = path.resolve(root, rest);
  if (!target.startsWith(root + path.sep) || !fs.existsSync(target) || !fs.statSync(target).isFile()) {
    response.writeHead(404).end();
    return;
  }
  response.writeHead(200, { 'content-type': types[path.extname(target)] ?? 'application/octet-stream' });
  fs.createReadStream(target).pipe(response);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const origin = `http://127.0.0.1:${server.address().port}`;

let result, browser;
const problems = [];
try {
  browser = await launchChromium(['--disable-quic', '--use-angle=swiftshader', '--enable-unsafe-swiftshader']);
  const page = await browser.context.newPage();
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  // (ANGLE's "GPU stall due to ReadPixels" performance note is expected: we read every picture back.)
  page.on('console', (m) => {
    if ((m.type() === 'error' || m.type() === 'warning') && !/GPU stall due to ReadPixels/.test(m.text())) problems.push(`console ${m.type()}: ${m.text()}`);
  });
  page.on('response', (r) => { if (r.status() >= 400 && !r.url().endsWith('/favicon.ico')) problems.push(`HTTP ${r.status()} for ${r.url()}`); });
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  await page.goto(`${origin}/page.html`);
  await page.waitForFunction(() => window.pageReady === true, null, { timeout: 30000 });
  const times = frames.map((f) => (f - A) / extras.fps);
  result = await page.evaluate(([url, times, options]) => window.renderTimes(url, times, options),
    [`/model/${encodeURIComponent(path.basename(file))}`, times,
     { pointer: breakWhat !== 'no-crossfade', flipY: breakWhat === 'flip', shiftPx: breakWhat === 'shift' ? 1 : 0 }]);
} catch (e) {
  problems.push(e.message.split('\n')[0]);
} finally {
  await browser?.close();
  server.close();
}
if (!result) fail(`Chromium did not draw ${file}: ${problems.join('; ')}`);
for (const p of problems) console.log(`  (browser) ${p}`);

const percentile = (values, q) => {
  if (values.length === 0) return 0;
  const sorted = Float64Array.from(values).sort();
  return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
};
const mean = (values) => values.length ? values.reduce((a, b) => a + b, 0) / values.length : 0;
const failed = [];
const pictures = result.pictures.map((b64) => new Uint8Array(Buffer.from(b64, 'base64')));
console.log(`${file}: three.js ${result.width}x${result.height} on ${result.renderer}${breakWhat ? `, broken on purpose: ${breakWhat}` : ''}`);
frames.forEach((f, j) => {
  const three = pictures[j], render = rendered[j];
  if (render.width !== result.width || render.height !== result.height)
    fail(`frame ${f}: inbetween render drew ${render.width}x${render.height}, the canvas is ${result.width}x${result.height}`);
  const alpha = [], colour = [];
  for (let i = 0; i < render.width * render.height; ++i) {
    const a = three[4 * i + 3] / 255, b = render.data[4 * i + 3] / 255;
    if (a > 0 || b > 0) alpha.push(Math.abs(a - b));
    if (a > 0.5 && b > 0.5) {
      let d = 0;
      for (let c = 0; c < 3; ++c) d = Math.max(d, Math.abs(three[4 * i + c] / 255 - render.data[4 * i + c] / 255 * b));
      colour.push(d);
    }
  }
  const figures = { alphaMean: mean(alpha), alphaP99: percentile(alpha, 0.99), colourMean: mean(colour), colourP99: percentile(colour, 0.99) };
  const shares = compositeWeights(result.opacities[j]);
  const shareError = Math.max(...weights[j].map((w, k) => Math.abs(w - (shares[k] ?? 0))));
  if (!(shareError <= 1e-3)) failed.push(`frame ${f}: the layers composite to shares ${shares.map((w) => w.toFixed(3))}, the keys' weights are ${weights[j].map((w) => w.toFixed(3))}`);
  const atKey = weights[j].filter((w) => w > 1e-6).length === 1;
  const tolerance = TOLERANCE[atKey ? 'key' : 'between'];
  const over = Object.keys(tolerance).filter((k) => !(figures[k] <= tolerance[k]));
  console.log(`  frame ${f} (t = ${((f - A) / extras.fps).toFixed(4)} s, ${atKey ? 'at a key' : 'between keys'}, weights ${weights[j].map((w) => w.toFixed(3)).join(' ')}, layer shares ${shares.map((w) => w.toFixed(3)).join(' ')}): alpha mean ${figures.alphaMean.toFixed(4)} p99 ${figures.alphaP99.toFixed(4)}` +
              ` over ${alpha.length} px; colour mean ${figures.colourMean.toFixed(4)} p99 ${figures.colourP99.toFixed(4)} over ${colour.length} px` +
              (over.length ? `  <- over the tolerance: ${over.join(', ')}` : ''));
  if (over.length) failed.push(`frame ${f}: ${over.map((k) => `${k} ${figures[k].toFixed(4)} > ${tolerance[k]}`).join(', ')}`);
});

if (sideBySide) {
  const j = Math.max(0, frames.findIndex((f, i) => i > 0 && f !== A));
  const { width: W, height: H } = rendered[j], gap = 4, zoom = W <= 128 ? 2 : 1;  // 128 px drawings shown 2x
  const out = { width: zoom * (2 * W + gap), height: zoom * H, data: new Uint8Array(zoom * zoom * (2 * W + gap) * H * 4) };
  const grey = 200;
  for (let y = 0; y < out.height; ++y) for (let x = 0; x < out.width; ++x) {
    const o = 4 * (y * out.width + x), sx = Math.floor(x / zoom), sy = Math.floor(y / zoom);
    let rgb = [grey, grey, grey];
    if (sx < W || sx >= W + gap) {
      const side = sx < W ? 0 : 1, i = 4 * (sy * W + (side ? sx - W - gap : sx));
      const src = side ? rendered[j].data : pictures[j];
      const a = src[i + 3] / 255;
      rgb = [0, 1, 2].map((c) => Math.round((side ? src[i + c] * a : src[i + c]) + grey * (1 - a)));
    }
    out.data.set([...rgb, 255], o);
  }
  writePng(sideBySide, out);
  console.log(`  wrote ${sideBySide}: frame ${frames[j]}, three.js left, inbetween render right`);
}
if (failed.length) fail(`${file}: three.js in Chromium differs from inbetween render: ${failed.join('; ')}`);
