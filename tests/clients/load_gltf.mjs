// three.js's GLTFLoader under Node, on an exported .glb or .gltf: meshopt decoding (the
// meshoptimizer package's MeshoptDecoder), KHR_animation_pointer when asked (the
// @needle-tools/three-animation-pointer plugin) and no texture decoding.
import fs from 'node:fs';
import path from 'node:path';
import { fail, need } from './common.mjs';

export const THREE = await need('three');
const { GLTFLoader } = await need('three/examples/jsm/loaders/GLTFLoader.js');
const { MeshoptDecoder } = await need('meshoptimizer/meshopt_decoder.mjs');
const { GLTFAnimationPointerExtension } = await need('@needle-tools/three-animation-pointer/src/index.js');

// Node has no image decoder (no createImageBitmap, no HTMLImageElement), and positions and alpha
// factors do not depend on the pixels. GLTFParser asks its plugins first for every texture
// (GLTFParser.getDependency('texture') -> plugin.loadTexture), so this one answers each with an
// empty Texture: the materials keep a map, nothing is decoded, nothing is fetched.
class NoTextureDecoding {
  constructor(parser) {
    this.name = 'inbetween_tests_no_texture_decoding';
    this.parser = parser;
  }
  loadTexture() {
    return Promise.resolve(new THREE.Texture());
  }
}

function glb(json, bin) {
  const pad = (b, fill) => Buffer.concat([b, Buffer.alloc((4 - b.length % 4) % 4, fill)]);
  const text = pad(Buffer.from(JSON.stringify(json)), 0x20), body = pad(bin, 0);
  const header = Buffer.alloc(12), textHead = Buffer.alloc(8), binHead = Buffer.alloc(8);
  header.writeUInt32LE(0x46546c67, 0); header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + text.length + (body.length ? 8 + body.length : 0), 8);
  textHead.writeUInt32LE(text.length, 0); textHead.writeUInt32LE(0x4e4f534a, 4);
  binHead.writeUInt32LE(body.length, 0); binHead.writeUInt32LE(0x004e4942, 4);
  return Buffer.concat([header, textHead, text, ...(body.length ? [binHead, body] : [])]);
}

// { gltf, json }. pointer: register the KHR_animation_pointer plugin.
export async function loadGltf(file, { pointer = true } = {}) {
  if (!fs.existsSync(file)) fail(`${file} does not exist`);
  let bytes = fs.readFileSync(file);
  let json;
  if (bytes.readUInt32LE(0) !== 0x46546c67) {
    // .gltf: FileLoader cannot read file: URLs under Node (nor data: URIs: it needs ProgressEvent),
    // so the .bin beside it becomes the binary chunk of an equivalent GLB.
    json = JSON.parse(bytes.toString('utf8'));
    const [first, ...rest] = json.buffers ?? [];
    if (rest.some((b) => b.uri !== undefined)) fail(`${file}: more than one buffer with a uri`);
    let bin = Buffer.alloc(0);
    if (first?.uri !== undefined) {
      bin = fs.readFileSync(path.resolve(path.dirname(file), decodeURIComponent(first.uri)));
      delete first.uri;
    }
    bytes = glb(json, bin);
  } else {
    const length = bytes.readUInt32LE(12);
    json = JSON.parse(bytes.toString('utf8', 20, 20 + length));
  }
  const data = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const loader = new GLTFLoader();
  await MeshoptDecoder.ready;
  loader.setMeshoptDecoder(MeshoptDecoder);
  loader.register((parser) => new NoTextureDecoding(parser));
  if (pointer) loader.register((parser) => new GLTFAnimationPointerExtension(parser));
  const gltf = await new Promise((resolve, reject) =>
    loader.parse(data, path.dirname(path.resolve(file)) + '/', resolve, reject)).catch((e) => fail(`${file}: GLTFLoader: ${e.message ?? e}`));
  return { gltf, json };
}

// The meshes of node 0, one per primitive (GLTFLoader makes a Group of them when there are several).
export async function nodeMeshes(gltf) {
  const node = await gltf.parser.getDependency('node', 0);
  const meshes = node.isMesh ? [node] : node.children.filter((c) => c.isMesh);
  return { node, meshes };
}
