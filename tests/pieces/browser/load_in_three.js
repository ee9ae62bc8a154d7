#!/usr/bin/env node
// Loads glTF files in three.js (npm `three`, tools/node_modules) inside Debian's headless
// Chromium (/usr/bin/chromium, driven by npm `playwright-core`) with software WebGL, renders each
// once and prints one JSON line per file:
//   {"file", "skinnedMeshes", "bones", "skins", "meshes", "instancedMeshes", "instances",
//    "drawCalls", "triangles", "drawnPixels", "pixels", "minX", "minY", "minZ", "maxX", "maxY",
//    "maxZ", "rootX", "rootY", "rootZ", "footY", "loadMs", "animations", "period", "tipMove",
//    "baseMove", "texturedMaterials", "normalMappedMaterials", "alphaTestedPrimitives"}
// skinnedMeshes counts THREE.SkinnedMesh objects, bones the distinct THREE.Bone objects,
// skins the distinct skeletons, instances the sum of InstancedMesh counts; drawCalls and
// triangles come from renderer.info after one render; drawnPixels are the pixels of the
// 256 x 256 picture whose colour differs from the background; min/max are the world bounds of
// what is drawn, in three.js's y-up frame (glTF's), so a test can see which way is up.
// root* is the world position of the scene's first node (a georeferenced tree's offset), footY
// the lowest drawn point within 1 % of the height of it (the trunk's foot, when it is there).
// Draco and meshopt files load through three's DRACOLoader and MeshoptDecoder; loadMs is the
// time GLTFLoader took (fetch, decode, build). A file with animations plays its first clip:
// period is its duration, tipMove the largest displacement between time 0 and a quarter period
// of a drawn vertex in the top tenth of the tree, baseMove the same within 3 % of the height of
// the trunk's foot (the skin's first joint, else the lowest vertex).
// texturedMaterials counts the distinct materials with a base colour map, normalMappedMaterials
// those that also have a normal map, alphaTestedPrimitives the meshes whose material has a map
// and an alpha test (glTF alphaMode MASK: the leaves).
// The files are served from a localhost HTTP server; the browser gets a fresh profile. With
// RAMUS_THREE_SCREENSHOTS=1 the picture of each file is kept as FILE.three.png; for pictures
// RAMUS_THREE_SIZE=N draws N x N pixels, RAMUS_THREE_ZOOM=F moves the camera to F times the
// distance towards the trunk a third of the way up, RAMUS_THREE_SKY=1 draws a sky-blue ground.
//   node load_in_three.js FILE.glb...
// Exit codes: 0 loaded every file, 1 a file failed to load or render, 2 usage,
// 77 Chromium (or WebGL in it) cannot run here: the message on stderr says why.
'use strict';
const fs = require('fs');
const http = require('http');
const path = require('path');
const { tools, launch, cannotRun } = require('./chromium.js');

if (!fs.existsSync(path.join(tools, 'three', 'build', 'three.module.js'))) {
  console.error('three is not installed: run scripts/install-deps.sh (npm install in tools/)');
  process.exit(2);
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: load_in_three.js FILE.glb...');
  process.exit(2);
}

const PAGE = `<!doctype html><html><head><meta charset="utf-8">
<script type="importmap">{"imports": {"three": "/three/build/three.module.js",
  "three/addons/": "/three/examples/jsm/"}}</script></head><body style="margin:0">
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
const draco = new DRACOLoader().setDecoderPath('/three/examples/jsm/libs/draco/gltf/');
// The drawn vertices of every mesh (skinned ones posed), in world space.
function drawnVertices(scene) {
  const out = [];
  const v = new THREE.Vector3();
  scene.updateMatrixWorld(true);
  scene.traverse((o) => {
    if (!o.isMesh || o.isInstancedMesh) return;
    if (o.isSkinnedMesh) o.skeleton.update();
    const pos = o.geometry.attributes.position;
    for (let i = 0; i < pos.count; i++) {
      if (o.isSkinnedMesh) o.getVertexPosition(i, v); else v.fromBufferAttribute(pos, i);
      v.applyMatrix4(o.matrixWorld);
      out.push(v.x, v.y, v.z);
    }
  });
  return out;
}
// Plays the first clip: how far the top and the base of the tree move by a quarter period.
function sampleWind(gltf, box) {
  const clip = gltf.animations[0];
  const mixer = new THREE.AnimationMixer(gltf.scene);
  mixer.clipAction(clip).play();
  mixer.setTime(0);
  const rest = drawnVertices(gltf.scene);
  mixer.setTime(clip.duration / 4);
  const moved = drawnVertices(gltf.scene);
  mixer.setTime(0);
  gltf.scene.updateMatrixWorld(true);
  const h = box.max.y - box.min.y;
  // The trunk's foot: the first joint of the skin (ramus puts it there), else the lowest vertex;
  // its base the vertices within 3 % of the height of it.
  let foot = null;
  gltf.scene.traverse((o) => {
    if (!foot && o.isSkinnedMesh) foot = o.skeleton.bones[0].getWorldPosition(new THREE.Vector3());
  });
  if (!foot) {
    let low = 0;
    for (let i = 0; i < rest.length; i += 3) if (rest[i + 1] < rest[low + 1]) low = i;
    foot = new THREE.Vector3(rest[low], rest[low + 1], rest[low + 2]);
  }
  let tip = 0, base = 0;
  for (let i = 0; i < rest.length; i += 3) {
    const d = Math.hypot(moved[i] - rest[i], moved[i + 1] - rest[i + 1], moved[i + 2] - rest[i + 2]);
    if (rest[i + 1] >= box.min.y + 0.9 * h) tip = Math.max(tip, d);
    const near = Math.hypot(rest[i] - foot.x, rest[i + 1] - foot.y, rest[i + 2] - foot.z);
    if (near <= 0.03 * h) base = Math.max(base, d);
  }
  return { period: clip.duration, tipMove: tip, baseMove: base };
}
window.loadAndRender = async (url, look = {}) => {
  const start = performance.now();
  const gltf = await new GLTFLoader().setDRACOLoader(draco).setMeshoptDecoder(MeshoptDecoder)
    .loadAsync(url);
  const loadMs = performance.now() - start;
  const scene = new THREE.Scene();
  const background = new THREE.Color(look.sky ? 0xbcd4e6 : 0x000000);
  scene.background = background;
  scene.add(new THREE.AmbientLight(0xffffff, 1.5));
  const sun = new THREE.DirectionalLight(0xffffff, 2.0);
  sun.position.set(1, 2, 3);
  scene.add(sun);
  scene.add(gltf.scene);
  const bones = new Set(), skins = new Set(), textured = new Set(), normalMapped = new Set();
  let skinned = 0, meshes = 0, instanced = 0, instances = 0, alphaTested = 0;
  gltf.scene.updateMatrixWorld(true);
  gltf.scene.traverse((o) => {
    if (o.isBone) bones.add(o);
    if (o.isMesh) {
      meshes++;
      o.frustumCulled = false;
      const mat = o.material;
      if (mat && mat.map) textured.add(mat);
      if (mat && mat.map && mat.normalMap) normalMapped.add(mat);
      if (mat && mat.map && mat.alphaTest > 0) alphaTested++;
    }
    if (o.isSkinnedMesh) {
      skinned++;
      skins.add(o.skeleton);
      o.skeleton.update();
    }
    if (o.isInstancedMesh) {
      instanced++;
      instances += o.count;
    }
  });
  // Bounds of what is drawn: skinned vertices where there are skins, instances where instanced.
  const box = new THREE.Box3();
  const v = new THREE.Vector3(), m = new THREE.Matrix4();
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    const pos = o.geometry.attributes.position;
    const copies = o.isInstancedMesh ? o.count : 1;
    for (let c = 0; c < copies; c++) {
      if (o.isInstancedMesh) o.getMatrixAt(c, m);
      for (let i = 0; i < pos.count; i++) {
        if (o.isSkinnedMesh) {
          o.getVertexPosition(i, v);
          v.applyMatrix4(o.matrixWorld);
        } else {
          v.fromBufferAttribute(pos, i);
          if (o.isInstancedMesh) v.applyMatrix4(m);
          v.applyMatrix4(o.matrixWorld);
        }
        box.expandByPoint(v);
      }
    }
  });
  const size = look.size || 256;
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  document.body.appendChild(canvas);
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(size, size, false);
  // From the front as glTF defines it (looking along -z, y up), far enough that the wider of
  // the x and y extents fills 90% of the picture.
  const centre = box.getCenter(new THREE.Vector3());
  const extent = box.getSize(new THREE.Vector3());
  const fov = 40;
  const fit = Math.max(extent.x, extent.y, 1e-6) / 2 / Math.tan((fov / 2) * Math.PI / 180) / 0.9;
  const distance = (fit + extent.z / 2) * (look.zoom || 1);
  const camera = new THREE.PerspectiveCamera(fov, 1, distance * 0.01, distance * 4 + extent.z);
  // A close look (zoom < 1) aims at the trunk a third of the way up.
  const target = look.zoom ? new THREE.Vector3(centre.x, box.min.y + extent.y / 3, centre.z) : centre;
  camera.position.copy(target).add(new THREE.Vector3(0, 0, distance));
  camera.up.set(0, 1, 0);
  camera.lookAt(target);
  renderer.info.autoReset = false;
  renderer.info.reset();
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const px = new Uint8Array(size * size * 4);
  gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, px);
  let drawn = 0;
  for (let i = 0; i < size * size; i++) {
    if (px[4 * i] > 8 || px[4 * i + 1] > 8 || px[4 * i + 2] > 8) drawn++;
  }
  const result = { skinnedMeshes: skinned, bones: bones.size, skins: skins.size, meshes,
    instancedMeshes: instanced, instances, drawCalls: renderer.info.render.calls,
    triangles: renderer.info.render.triangles, drawnPixels: drawn, pixels: size * size,
    minX: box.min.x, minY: box.min.y, minZ: box.min.z, maxX: box.max.x, maxY: box.max.y,
    maxZ: box.max.z, loadMs, animations: gltf.animations.length,
    texturedMaterials: textured.size, normalMappedMaterials: normalMapped.size,
    alphaTestedPrimitives: alphaTested };
  // The root node's world position (a georeferenced tree's offset) and the lowest drawn point
  // within 1 % of the height of it (the trunk's foot, for a tree grown from the origin).
  const root = gltf.scene.children[0].getWorldPosition(new THREE.Vector3());
  const all = instanced ? [] : drawnVertices(gltf.scene);
  let footY = Infinity;
  for (let i = 0; i < all.length; i += 3) {
    if (Math.hypot(all[i] - root.x, all[i + 1] - root.y, all[i + 2] - root.z) <=
        0.01 * (box.max.y - box.min.y))
      footY = Math.min(footY, all[i + 1]);
  }
  Object.assign(result, { rootX: root.x, rootY: root.y, rootZ: root.z,
    footY: Number.isFinite(footY) ? footY : null });
  if (gltf.animations.length) Object.assign(result, sampleWind(gltf, box));
  if (window.screenshotWanted) result.png = canvas.toDataURL('image/png');
  renderer.dispose();
  canvas.remove();
  return result;
};
window.pageReady = true;
</script></body></html>`;

function serve() {
  const roots = { '/three/': path.join(tools, 'three') + '/' };
  // /files/I/NAME is NAME in the folder of file I, so a .gltf finds its .bin beside it.
  const served = (url) => {
    const m = /^\/files\/(\d+)\/([^/]+)$/.exec(url);
    return m && files[Number(m[1])] ? path.join(path.dirname(files[Number(m[1])]), m[2]) : null;
  };
  const server = http.createServer((req, res) => {
    const url = decodeURIComponent(req.url.split('?')[0]);
    let file = null;
    if (url === '/' || url === '/index.html') {
      res.writeHead(200, { 'Content-Type': 'text/html' });
      res.end(PAGE);
      return;
    }
    if (url.startsWith('/files/')) file = served(url);
    for (const [prefix, dir] of Object.entries(roots)) {
      if (url.startsWith(prefix) && !url.includes('..')) file = dir + url.slice(prefix.length);
    }
    if (file === null || !fs.existsSync(file)) {
      res.writeHead(404);
      res.end();
      return;
    }
    const type = file.endsWith('.js') ? 'text/javascript' : 'application/octet-stream';
    res.writeHead(200, { 'Content-Type': type });
    res.end(fs.readFileSync(file));
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

(async () => {
  for (const f of files) {
    if (!fs.existsSync(f)) {
      console.error(`no such file: ${f}`);
      process.exit(2);
    }
  }
  const server = await serve();
  const port = server.address().port;
  let browser;
  try {
    browser = await launch();
  } finally {
    if (!browser) server.close();
  }
  const { context } = browser;
  let status = 0;
  try {
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(`http://127.0.0.1:${port}/index.html`);
    await page.waitForFunction(() => window.pageReady === true, null, { timeout: 60000 });
    const webgl = await page.evaluate(() => !!document.createElement('canvas').getContext('webgl2'));
    if (!webgl) cannotRun('no WebGL 2 context in headless Chromium');
    for (let i = 0; i < files.length; i++) {
      try {
        const url = `/files/${i}/${encodeURIComponent(path.basename(files[i]))}`;
        if (process.env.RAMUS_THREE_SCREENSHOTS) await page.evaluate(() => { window.screenshotWanted = true; });
        const look = { size: Number(process.env.RAMUS_THREE_SIZE) || 0,
          zoom: Number(process.env.RAMUS_THREE_ZOOM) || 0, sky: !!process.env.RAMUS_THREE_SKY };
        const r = await page.evaluate(([u, l]) => window.loadAndRender(u, l), [url, look]);
        if (r.png) {
          // RAMUS_THREE_SCREENSHOTS=1 keeps what three.js drew beside each file (FILE.three.png).
          fs.writeFileSync(files[i] + '.three.png', Buffer.from(r.png.split(',')[1], 'base64'));
          delete r.png;
        }
        console.log(JSON.stringify({ file: files[i], ...r }));
      } catch (e) {
        console.log(JSON.stringify({ file: files[i], error: String(e.message || e) }));
        status = 1;
      }
    }
    if (errors.length) {
      console.error(`page errors: ${errors.join('; ')}`);
      status = 1;
    }
  } finally {
    await browser.close();
    server.close();
  }
  process.exit(status);
})().catch((e) => {
  console.error(String(e.stack || e));
  process.exit(1);
});
