// node apng_plays.mjs RENDER_DIR FPS
// Headless Chromium (Debian's) decodes RENDER_DIR/preview.png, the animated PNG of `inbetween
// render --preview`, with the WebCodecs ImageDecoder and checks that it is what the frames beside
// it are: animated, looping forever, one frame per frame_NNNN.png, each shown for 1/FPS s (within
// 1 ms), its size the contact sheet's tile (240 px wide at most, the frames' aspect ratio within a
// pixel), and each frame covering the same share of the picture as its frame_NNNN.png (alpha summed
// over the picture, within 0.01: shrinking keeps coverage).
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fail, launchChromium, usage } from './common.mjs';
import { readPng } from './png.mjs';

const args = process.argv.slice(2);
usage('node apng_plays.mjs RENDER_DIR FPS', args.length === 2 && Number(args[1]) > 0);
const [dir, fpsText] = args;
const fps = Number(fpsText);
const preview = path.join(dir, 'preview.png');
if (!fs.existsSync(preview)) fail(`${preview} does not exist (inbetween render --preview)`);
const frameFiles = fs.readdirSync(dir).filter((f) => /^frame_\d{4}\.png$/.test(f)).sort();
if (frameFiles.length === 0) fail(`${dir} has no frame_NNNN.png`);
const coverage = (image) => {
  let sum = 0;
  for (let i = 3; i < image.data.length; i += 4) sum += image.data[i];
  return sum / 255 / (image.width * image.height);
};

const server = http.createServer((request, response) => {
  if (new URL(request.url, 'http://localhost').pathname !== '/preview.png') {
    response.writeHead(200, { 'content-type': 'text/html' }).end('<!doctype html><title>apng</title>');
    return;
  }
  response.writeHead(200, { 'content-type': 'image/png' });
  fs.createReadStream(preview).pipe(response);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const origin = `http://127.0.0.1:${server.address().port}`;
let result, browser;
try {
  browser = await launchChromium();
  const page = await browser.context.newPage();
  await page.goto(`${origin}/`);
  result = await page.evaluate(async () => {
    const data = await (await fetch('/preview.png')).arrayBuffer();
    const decoder = new ImageDecoder({ data, type: 'image/png' });
    await decoder.tracks.ready;
    const track = decoder.tracks.selectedTrack;
    const out = { count: track.frameCount, animated: track.animated, repetition: track.repetitionCount, frames: [] };
    const canvas = new OffscreenCanvas(1, 1);
    const context2d = canvas.getContext('2d', { willReadFrequently: true });
    for (let i = 0; i < track.frameCount; ++i) {
      const { image } = await decoder.decode({ frameIndex: i });
      canvas.width = image.displayWidth;
      canvas.height = image.displayHeight;
      context2d.clearRect(0, 0, canvas.width, canvas.height);
      context2d.drawImage(image, 0, 0);
      const pixels = context2d.getImageData(0, 0, canvas.width, canvas.height).data;
      let sum = 0;
      for (let p = 3; p < pixels.length; p += 4) sum += pixels[p];
      out.frames.push({ width: canvas.width, height: canvas.height, duration: image.duration, coverage: sum / 255 / (canvas.width * canvas.height) });
      image.close();
    }
    return out;
  });
} catch (e) {
  fail(`Chromium could not decode ${preview}: ${e.message.split('\n')[0]}`);
} finally {
  await browser?.close();
  server.close();
}

if (!result.animated) fail(`${preview}: Chromium does not see an animation`);
if (result.repetition !== Infinity) fail(`${preview}: repeats ${result.repetition} times, not forever`);
if (result.count !== frameFiles.length) fail(`${preview}: ${result.count} frames, but ${dir} has ${frameFiles.length}`);
const first = readPng(path.join(dir, frameFiles[0]));
const width = Math.min(240, first.width), height = Math.max(1, Math.round(width * first.height / first.width));
let worst = 0;
result.frames.forEach((f, i) => {
  if (f.width !== width || f.height !== height) fail(`${preview}: frame ${i} is ${f.width}x${f.height}, not ${width}x${height}`);
  if (Math.abs(f.duration / 1000 - 1000 / fps) > 1) fail(`${preview}: frame ${i} lasts ${f.duration / 1000} ms, not ${1000 / fps}`);
  const expected = coverage(readPng(path.join(dir, frameFiles[i])));
  worst = Math.max(worst, Math.abs(f.coverage - expected));
  if (Math.abs(f.coverage - expected) > 0.01) fail(`${preview}: frame ${i} covers ${f.coverage.toFixed(4)}, ${frameFiles[i]} ${expected.toFixed(4)}`);
});
console.log(`${preview}: ${result.count} frames of ${width}x${height}, ${1000 / fps} ms each, looping; coverage within ${worst.toFixed(5)} of the frames`);
