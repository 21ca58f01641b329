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

// { gltf, json }. pointer: register the KHR_animation_pointer plugin.
export async function loadGltf(file, { pointer = true } = {}) {
  if (!fs.existsSync(file)) fail(`${file} does not exist`);
  let data = fs.readFileSync(file);
  let json;
  if (data.readUInt32LE(0) !== 0x46546c67) {
    // .gltf: Node's fetch cannot read file: URLs, so the buffers beside it go in as data: URIs.
    json = JSON.parse(data.toString('utf8'));
    for (const buffer of json.buffers ?? []) {
      if (!buffer.uri || buffer.uri.startsWith('data:')) continue;
      const bytes = fs.readFileSync(path.resolve(path.dirname(file), decodeURIComponent(buffer.uri)));
      buffer.uri = 'data:application/octet-stream;base64,' + bytes.toString('base64');
    }
    data = JSON.stringify(json);
  } else {
    const length = data.readUInt32LE(12);
    json = JSON.parse(data.toString('utf8', 20, 20 + length));
    data = data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
  }
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
