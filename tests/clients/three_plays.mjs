// node three_plays.mjs FILE.glb|FILE.gltf REFERENCE.json [--max-px PX]
// three.js under Node plays an exported file: GLTFLoader (with meshopt decoding and the
// KHR_animation_pointer plugin), an AnimationMixer on animation 0 set to (f - A)/fps for every
// frame f, each vertex read with Mesh.getVertexPosition (morph targets applied) in world space and
// turned back into drawing pixels (docs/export.md). Compared with REFERENCE.json, the solved and
// welded frames of tests/tools/welded_frames: every vertex of every frame within 1e-4 shape sizes,
// or with --max-px within PX drawing pixels (+ 1e-4 shape sizes for float rounding). Also checks:
// the primitives share their positions and morph weights (the ink's node, if any, the weights), at
// most two weights are nonzero at a frame, the clip lasts (B - A)/fps (or one frame more, a looping timeline's closing keyframe, which
// must show frame A again), and the layers' alpha factors composite to the keys' weights (within
// 1e-3), and without the pointer plugin to frame A's (the static factors).
import { fail, usage, readJson, inbetweenExtras, toPixels, compositeWeights } from './common.mjs';
import { THREE, loadGltf, nodeMeshes } from './load_gltf.mjs';

const args = process.argv.slice(2);
const maxPxAt = args.indexOf('--max-px');
const maxPx = maxPxAt >= 0 ? Number(args.splice(maxPxAt, 2)[1]) : null;
usage('node three_plays.mjs FILE.glb|FILE.gltf REFERENCE.json [--max-px PX]', args.length === 2 && (maxPx === null || maxPx >= 0));
const [file, referenceFile] = args;
const reference = readJson(referenceFile);
const { gltf, json } = await loadGltf(file);
const extras = inbetweenExtras(file, json);
const s = reference.shapeSize;

// The contract's header against the reference.
const [A, B] = extras.frames;
if (extras.canvas[0] !== reference.canvas[0] || extras.canvas[1] !== reference.canvas[1])
  fail(`${file}: canvas ${extras.canvas} but the drawings are ${reference.canvas}`);
if (Math.abs(extras.fps - reference.fps) > 1e-9) fail(`${file}: fps ${extras.fps}, the scene's is ${reference.fps}`);
if (Math.abs(extras.shapeSize - s) > 1e-6 * s) fail(`${file}: shapeSize ${extras.shapeSize}, the solver's is ${s}`);
const frames = reference.frames.filter((f) => f.index >= A && f.index <= B);
if (frames.length !== B - A + 1) fail(`${file}: frames ${A}..${B}, the reference has ${reference.frames.map((f) => f.index).join(',')}`);
// The animation's bounds: the solved frames' extent, drawing px (x0, y0, x1, y1).
const extent = [Infinity, Infinity, -Infinity, -Infinity];
for (const f of frames)
  for (let i = 0; i < f.positions.length; i += 2) {
    extent[0] = Math.min(extent[0], f.positions[i]);
    extent[1] = Math.min(extent[1], f.positions[i + 1]);
    extent[2] = Math.max(extent[2], f.positions[i]);
    extent[3] = Math.max(extent[3], f.positions[i + 1]);
  }
if (extras.bounds.some((b, i) => Math.abs(b - extent[i]) > 1e-6 * s))
  fail(`${file}: bounds ${extras.bounds}, the solved frames reach ${extent}`);
if (gltf.animations.length < 1) fail(`${file}: no animation`);
const clip = gltf.animations[0];
const span = (B - A) / extras.fps;
const closes = Math.abs(clip.duration - (span + 1 / extras.fps)) <= 1e-5;  // a loop's closing keyframe
if (!closes && Math.abs(clip.duration - span) > 1e-5)
  fail(`${file}: the clip lasts ${clip.duration} s, frames ${A}..${B} at ${extras.fps} fps take ${span} s (${span + 1 / extras.fps} s with a loop's closing keyframe)`);

const { meshes } = await nodeMeshes(gltf);
// One layer per key that has weight in some exported frame, in key order.
const K = reference.frames[0].weights.length;
const drawn = [...Array(K).keys()].filter((k) => frames.some((f) => f.weights[k] > 0));
const layerWeights = (frame) => drawn.map((k) => frame.weights[k]);
if (meshes.length !== drawn.length)
  fail(`${file}: node 0 has ${meshes.length} primitives, the frames draw ${drawn.length} of the scene's ${K} keys`);
const n = reference.frames[0].positions.length / 2;
const mesh = meshes[0];
const position = mesh.geometry.attributes.position;
if (position.count !== n) fail(`${file}: ${position.count} vertices, the multimesh has ${n}`);
const targets = mesh.geometry.morphAttributes.position ?? [];
if (targets.length === 0) fail(`${file}: no morph targets`);
// Every primitive: the same positions and targets (so reading primitive 0 reads them all).
const same = (a, b) => a.count === b.count && a.array.length === b.array.length && Array.from({ length: a.count }, (_, i) =>
  a.getX(i) === b.getX(i) && a.getY(i) === b.getY(i) && a.getZ(i) === b.getZ(i)).every(Boolean);
for (const [k, other] of meshes.entries()) {
  const g = other.geometry;
  if (!same(g.attributes.position, position)) fail(`${file}: primitive ${k}'s positions differ from primitive 0's`);
  const t = g.morphAttributes.position ?? [];
  if (t.length !== targets.length || t.some((a, i) => !same(a, targets[i]))) fail(`${file}: primitive ${k}'s morph targets differ from primitive 0's`);
}

// Node 1, when there, draws opened cuts' outline ink: one primitive whose morph targets (positions
// and COLOR_0, the ink's fading alpha) are the shape's kept frames, moved by the same weights, so it
// plays without the pointer plugin too (GLTFLoader gives it vertex colours with alpha).
const inkNode = json.nodes.length > 1 ? await gltf.parser.getDependency('node', 1) : null;
const inkMesh = inkNode ? (inkNode.isMesh ? inkNode : inkNode.children.find((c) => c.isMesh)) : null;
if (inkNode) {
  if (!inkMesh) fail(`${file}: node 1 (the ink) has no mesh`);
  const g = inkMesh.geometry;
  if ((g.morphAttributes.position ?? []).length !== targets.length || (g.morphAttributes.color ?? []).length !== targets.length)
    fail(`${file}: the ink has ${(g.morphAttributes.position ?? []).length} position and ${(g.morphAttributes.color ?? []).length} colour morph targets, the shape ${targets.length}`);
  if (g.attributes.color?.itemSize !== 4 || inkMesh.material.vertexColors !== true || inkMesh.material.transparent !== true)
    fail(`${file}: the ink's material does not draw its RGBA vertex colours blended`);
}

// Without the pointer plugin: the static alpha factors, frame A's.
{
  const plain = await nodeMeshes((await loadGltf(file, { pointer: false })).gltf);
  const factors = plain.meshes.map((m) => m.material.opacity);
  const shares = compositeWeights(factors);
  const expected = layerWeights(frames[0]);
  if (shares.some((w, l) => !(Math.abs(w - expected[l]) <= 1e-3)))
    fail(`${file}: the static alpha factors ${factors} composite to ${shares}, frame ${A}'s weights are ${expected}`);
}

const mixer = new THREE.AnimationMixer(gltf.scene);
const action = mixer.clipAction(clip);
action.setLoop(THREE.LoopOnce);  // LoopRepeat would wrap the last frame's time to 0
action.clampWhenFinished = true;
gltf.scene.updateMatrixWorld(true);
const v = new THREE.Vector3();
let worst = { px: 0, frame: A, vertex: 0 }, worstAlpha = { error: 0, frame: A };
let mostNonzero = 0;
// Plays the clip at `time` and compares with the reference frame `frame` (`label` names it).
function check(time, frame, label) {
  action.reset().play();
  mixer.setTime(time);
  gltf.scene.updateMatrixWorld(true);
  const influences = mesh.morphTargetInfluences;
  for (const [k, other] of meshes.entries())
    if (other.morphTargetInfluences.some((w, i) => w !== influences[i])) fail(`${file}: ${label}: primitive ${k}'s morph weights differ from primitive 0's`);
  if (inkMesh && inkMesh.morphTargetInfluences.some((w, i) => w !== influences[i])) fail(`${file}: ${label}: the ink's morph weights differ from the shape's`);
  mostNonzero = Math.max(mostNonzero, influences.filter((w) => w !== 0).length);
  for (let i = 0; i < n; ++i) {
    mesh.getVertexPosition(i, v).applyMatrix4(mesh.matrixWorld);
    const [x, y] = toPixels(v.x, v.y, extras);
    const d = Math.hypot(x - frame.positions[2 * i], y - frame.positions[2 * i + 1]);
    if (!(d <= worst.px)) worst = { px: d, frame: label, vertex: i };  // NaN counts as worst
    if (Number.isNaN(d)) break;
  }
  const composite = compositeWeights(meshes.map((m) => m.material.opacity));
  const expected = layerWeights(frame);
  const alphaError = Math.max(...composite.map((c, l) => Math.abs(c - expected[l])));
  if (!(alphaError <= worstAlpha.error)) worstAlpha = { error: alphaError, frame: label };
}
for (const frame of frames) check((frame.index - A) / extras.fps, frame, `frame ${frame.index}`);
if (closes) check(clip.duration, frames[0], `the closing keyframe (frame ${A} again)`);
const bound = (maxPx ?? 0) + 1e-4 * s;
const alphaBound = 1e-3;
console.log(`${file}: largest error ${worst.px.toPrecision(3)} px = ${(worst.px / s).toExponential(2)} shape sizes` +
            ` (${worst.frame}, vertex ${worst.vertex}; bound ${bound.toPrecision(3)} px) over ${frames.length} frames${closes ? ' and the closing keyframe' : ''} x ${n} vertices;` +
            ` ${targets.length} morph targets, at most ${mostNonzero} nonzero; cross-fade weights within ${worstAlpha.error.toExponential(2)} (${worstAlpha.frame}; bound ${alphaBound})`);
if (mostNonzero > 2) fail(`${file}: ${mostNonzero} morph weights nonzero at once, the contract says at most 2`);
if (!(worst.px <= bound)) fail(`${file}: ${worst.frame} vertex ${worst.vertex} is ${worst.px} px from the solved frame, more than ${bound}`);
if (!(worstAlpha.error <= alphaBound)) fail(`${file}: ${worstAlpha.frame}: the layers' alpha factors composite to weights ${worstAlpha.error} off the keys'`);
