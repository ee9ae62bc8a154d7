// The example page: fetches a binary grammar (.rmb), grows and meshes it with the WebAssembly
// runtime (/ramus/ramus.mjs) and draws it with three.js. Only the rules travel over the
// network; the tree and its mesh are made here. Query: ?rmb=URL, &seed=S and &steps=N
// (replace the grammar's), &lods=K (levels to build, default 1) and &level=L (the one drawn),
// &skeleton=1 (draw the skeleton as lines instead of the mesh), &size=N (an N x N canvas).
// When it is drawn, window.ramusResult holds what the page did (the headless test,
// tests/runtime/browser/grow_in_chromium.mjs, reads it):
//   { nodes, organs, growMs, meshMs, meshTriangles, triangles, drawCalls, drawnPixels, pixels,
//     rmbBytes }  or  { error }
// meshTriangles is the index count / 3 of the drawn level's parts, triangles what three.js
// drew (renderer.info) in one render.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { loadRamus, Part } from '/ramus/ramus.mjs';

const params = new URLSearchParams(location.search);
const status = document.getElementById('status');

// The skeleton as line segments parent -> node, and a point per organ. ramus's world is z up;
// the group turns it to three.js's y up ((x, y, z) -> (x, z, -y), as the glTF writer does).
function skeletonObject(tree) {
  const group = new THREE.Group();
  group.rotation.x = -Math.PI / 2;
  const p = tree.positions, parents = tree.parents;
  const segments = [];
  for (let i = 0; i < parents.length; i++) {
    const q = parents[i];
    if (q < 0) continue;
    segments.push(p[3 * q], p[3 * q + 1], p[3 * q + 2], p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  }
  const lines = new THREE.BufferGeometry();
  lines.setAttribute('position', new THREE.Float32BufferAttribute(segments, 3));
  group.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial({ color: 0x5b3a1e })));
  if (tree.organCount > 0) {
    const organs = new THREE.BufferGeometry();
    organs.setAttribute('position', new THREE.Float32BufferAttribute(tree.organPositions, 3));
    group.add(new THREE.Points(organs, new THREE.PointsMaterial({ color: 0x3f8f3a, size: 3,
      sizeAttenuation: false })));
  }
  return group;
}

// The alpha mask of the leaf cards: the runtime hands out geometry only (the .glb `ramus build`
// writes carries its own leaf picture), so the page draws a pointed oval, long along v as the
// cards are.
function leafTexture() {
  const canvas = document.createElement('canvas');
  canvas.width = 64;
  canvas.height = 128;
  const g = canvas.getContext('2d');
  g.fillStyle = '#ffffff';
  g.beginPath();
  g.moveTo(32, 2);
  g.bezierCurveTo(62, 40, 62, 90, 32, 126);
  g.bezierCurveTo(2, 90, 2, 40, 32, 2);
  g.fill();
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  return texture;
}

// One level of the mesh: a three.js mesh per non-empty part, with the part's arrays as they
// come (y up, like the .glb). Returns the group and the number of triangles its indices hold.
function meshObject(mesh, level) {
  const group = new THREE.Group();
  const [ox, oy, oz] = mesh.origin;
  group.position.set(ox, oy, oz);
  const materials = {
    [Part.BARK]: new THREE.MeshStandardMaterial({ color: 0x6b4a2f, roughness: 0.9 }),
    [Part.LEAVES]: new THREE.MeshStandardMaterial({ color: 0x4a8a2e, roughness: 0.6,
      alphaMap: leafTexture(), alphaTest: 0.5 }),
    [Part.SURFACES]: new THREE.MeshStandardMaterial({ color: 0x46872d, roughness: 0.6 }),
  };
  let triangles = 0;
  for (const part of [Part.BARK, Part.LEAVES, Part.SURFACES]) {
    const a = mesh.part(level, part);
    if (!a) continue;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(a.positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(a.normals, 3));
    geometry.setAttribute('uv', new THREE.BufferAttribute(a.uvs, 2));
    geometry.setIndex(new THREE.BufferAttribute(a.indices, 1));
    const object = new THREE.Mesh(geometry, materials[part]);
    object.frustumCulled = false;  // one render must draw every triangle (the test counts them)
    group.add(object);
    triangles += a.indices.length / 3;
  }
  return { group, triangles };
}

// A camera that sees the whole box from the front (-z in three.js's frame).
function frame(camera, box) {
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3());
  const fit = Math.max(size.x, size.y, 1e-6) / 2 / Math.tan((camera.fov / 2) * Math.PI / 180);
  const distance = fit / 0.9 + size.z / 2;
  camera.near = distance * 0.01;
  camera.far = distance * 4 + size.z;
  camera.position.copy(centre).add(new THREE.Vector3(0, 0, distance));
  camera.lookAt(centre);
  camera.updateProjectionMatrix();
  return centre;
}

async function main() {
  const url = params.get('rmb');
  if (!url) throw new Error('no grammar: open this page with ?rmb=URL of an .rmb file');
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  const bytes = new Uint8Array(await response.arrayBuffer());
  const ramus = await loadRamus();
  const grammar = ramus.load(bytes);
  const options = {};
  if (params.has('seed')) options.seed = BigInt(params.get('seed'));
  if (params.has('steps')) options.steps = Number(params.get('steps'));
  const start = performance.now();
  const tree = grammar.grow(options);
  const growMs = performance.now() - start;
  window.ramusTree = tree;  // for the console and the headless test

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xdfe8ef);
  scene.add(new THREE.AmbientLight(0xffffff, 1.2));
  const sun = new THREE.DirectionalLight(0xffffff, 2.0);
  sun.position.set(1, 2, 3);
  scene.add(sun);
  let object, meshMs = 0, meshTriangles = 0, meshed = '';
  if (params.get('skeleton') === '1') {
    object = skeletonObject(tree);
  } else {
    const lods = Number(params.get('lods')) || 1;
    const level = Number(params.get('level')) || 0;
    const meshStart = performance.now();
    const mesh = tree.mesh({ lodCount: lods });
    meshMs = performance.now() - meshStart;
    ({ group: object, triangles: meshTriangles } = meshObject(mesh, level));
    meshed = `, meshed (${mesh.lodCount} level${mesh.lodCount > 1 ? 's' : ''}) in ` +
      `${meshMs.toFixed(1)} ms; level ${level}: ${meshTriangles} triangles`;
    window.ramusMesh = mesh;  // for the console and the headless test
  }
  scene.add(object);
  object.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(object);

  const size = Number(params.get('size')) || 0;  // fixed size for the test's picture
  const renderer = new THREE.WebGLRenderer({ antialias: !size, preserveDrawingBuffer: true });
  renderer.setPixelRatio(size ? 1 : window.devicePixelRatio);
  const width = size || window.innerWidth, height = size || window.innerHeight;
  renderer.setSize(width, height);
  document.body.appendChild(renderer.domElement);
  const camera = new THREE.PerspectiveCamera(40, width / height, 0.01, 100);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(frame(camera, box));
  controls.update();

  renderer.info.autoReset = false;
  renderer.info.reset();
  renderer.render(scene, camera);
  const info = { triangles: renderer.info.render.triangles, drawCalls: renderer.info.render.calls };
  const gl = renderer.getContext();
  const px = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, px);
  const bg = scene.background.getHex();  // sRGB, as the canvas holds it
  const bgRgb = [(bg >> 16) & 255, (bg >> 8) & 255, bg & 255];
  let drawn = 0;
  for (let i = 0; i < width * height; i++) {
    if (Math.abs(px[4 * i] - bgRgb[0]) + Math.abs(px[4 * i + 1] - bgRgb[1]) +
        Math.abs(px[4 * i + 2] - bgRgb[2]) > 24) drawn++;
  }
  renderer.info.autoReset = true;
  controls.addEventListener('change', () => renderer.render(scene, camera));
  window.addEventListener('resize', () => {
    if (size) return;
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    renderer.render(scene, camera);
  });

  status.textContent = `${url}: ${bytes.length} bytes grown into ${tree.nodeCount} nodes and ` +
    `${tree.organCount} organs in ${growMs.toFixed(1)} ms` +
    meshed;
  window.ramusResult = { nodes: tree.nodeCount, organs: tree.organCount, growMs, meshMs,
    meshTriangles, ...info, drawnPixels: drawn, pixels: width * height, rmbBytes: bytes.length };
}

main().catch((e) => {
  status.textContent = `error: ${e.message}`;
  window.ramusResult = { error: String(e.message || e) };
});
