// Reads exported textures with readers pbrfit did not write, for tests/mpi/export_tables.sh to compare with
// the HDF5 tables: three.js's EXRLoader and HDRLoader (as in a browser, run here in node), three.js's
// KTX2Loader for 2D and 3D KTX2 files, and ktx-parse (the KTX2 parser three.js bundles, from npm) for texture
// arrays, which KTX2Loader does not load.
//
// Usage: node read_textures.mjs MODULES_DIR LIST
//   MODULES_DIR  a node_modules folder holding three and ktx-parse (make web-deps: $(BUILD)/web/node_modules)
//   LIST         lines "FORMAT FILE OUT.json", FORMAT one of exr, hdr, ktx2
// Each OUT.json holds {reader, width, height, depth, layers, channels, levels: [[value, ...], ...]}: every
// level's values as float numbers (halves widened), texel after texel, channels innermost, rows in the
// file's order (EXRLoader writes rows bottom-up for OpenGL; they are put back in the file's order here).
// `channels` is how many values a texel holds in the reader's output (EXRLoader and HDRLoader give RGBA).
// Exit 1 with one line on stderr when a file cannot be read.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [modules, list] = process.argv.slice(2);
if (!modules || !list) {
  console.error('usage: node read_textures.mjs MODULES_DIR LIST');
  process.exit(2);
}
const load = (path) => import(pathToFileURL(join(modules, path)).href);
const THREE = await load('three/build/three.module.js');
const { EXRLoader } = await load('three/examples/jsm/loaders/EXRLoader.js');
const { HDRLoader } = await load('three/examples/jsm/loaders/HDRLoader.js');
const { KTX2Loader } = await load('three/examples/jsm/loaders/KTX2Loader.js');
const ktxParse = await load('ktx-parse/dist/index.mjs');

const arrayBuffer = (file) => {
  const bytes = readFileSync(file);
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
};

// Rows of `data` (width x height texels of `channels` values) in reverse order.
function flipRows(data, width, height, channels) {
  const out = new Float32Array(data.length);
  const row = width * channels;
  for (let y = 0; y < height; ++y) out.set(data.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return out;
}

function readExr(file) {
  const loader = new EXRLoader();
  loader.setDataType(THREE.FloatType);
  const t = loader.parse(arrayBuffer(file));
  const channels = t.data.length / (t.width * t.height);
  return { reader: 'three.EXRLoader', width: t.width, height: t.height, depth: 1, layers: 1, channels,
    levels: [Array.from(flipRows(t.data, t.width, t.height, channels))] };
}

function readHdr(file) {
  const loader = new HDRLoader();
  loader.setDataType(THREE.FloatType);
  const t = loader.parse(arrayBuffer(file));
  return { reader: 'three.HDRLoader', width: t.width, height: t.height, depth: 1, layers: 1, channels: 4,
    levels: [Array.from(t.data)] };
}

// vkFormat -> [channels, bytes per channel] of the uncompressed float formats pbrfit writes.
const VK_FLOAT = { 76: [1, 2], 83: [2, 2], 90: [3, 2], 97: [4, 2], 100: [1, 4], 103: [2, 4], 106: [3, 4], 109: [4, 4] };

function floats(bytes, size) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = [];
  for (let i = 0; i < bytes.byteLength; i += size)
    out.push(size === 4 ? view.getFloat32(i, true) : THREE.DataUtils.fromHalfFloat(view.getUint16(i, true)));
  return out;
}

async function readKtx2(file) {
  const container = ktxParse.read(new Uint8Array(arrayBuffer(file)));
  const format = VK_FLOAT[container.vkFormat];
  if (!format) throw new Error(`vkFormat ${container.vkFormat} is not an uncompressed float format`);
  const [channels, size] = format;
  const shape = { width: container.pixelWidth, height: Math.max(1, container.pixelHeight),
    depth: Math.max(1, container.pixelDepth), layers: Math.max(1, container.layerCount), channels };
  if (container.layerCount === 0 && channels !== 3) {
    // A 2D or 3D texture, as three.js loads it for a renderer.
    const texture = await new KTX2Loader()._createTexture(arrayBuffer(file));
    const levels = texture.mipmaps.map((m) =>
      m.data instanceof Float32Array ? Array.from(m.data) : Array.from(m.data, THREE.DataUtils.fromHalfFloat));
    return { reader: 'three.KTX2Loader', ...shape, levels };
  }
  // Arrays (and RGB formats, which KTX2Loader has no three.js format for): the container's level data.
  return { reader: 'ktx-parse', ...shape, levels: container.levels.map((l) => floats(l.levelData, size)) };
}

const readers = { exr: readExr, hdr: readHdr, ktx2: readKtx2 };
for (const line of readFileSync(list, 'utf8').split('\n')) {
  if (!line.trim()) continue;
  const [format, file, out] = line.trim().split(/\s+/);
  try {
    if (!readers[format]) throw new Error(`no reader for format '${format}'`);
    writeFileSync(out, JSON.stringify(await readers[format](file)));
  } catch (e) {
    console.error(`${file}: ${e.message}`);
    process.exit(1);
  }
}
