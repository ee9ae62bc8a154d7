#include "cli/view_page.h"

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <vector>

#include "cli/command.h"
#include "cli/read_file.h"

namespace ramus::cli {
namespace {

namespace fs = std::filesystem;

std::string base64(const std::string& bytes) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                       (unsigned char)bytes[i + 2];
    out += {abc[v >> 18], abc[(v >> 12) & 63], abc[(v >> 6) & 63], abc[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16;
    out += {abc[v >> 18], abc[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
    out += {abc[v >> 18], abc[(v >> 12) & 63], abc[(v >> 6) & 63], '='};
  }
  return out;
}

// The import-map name of a file of the three package: "three" for its entry module, else
// "three/<path>".
std::string module_name(const fs::path& rel) {
  return rel == "build/three.module.js" ? "three" : "three/" + rel.generic_string();
}

// Adds `rel` and every module it imports by a relative path to `modules` (name -> source), with
// the relative specifiers rewritten to import-map names (a data: URL has no base to resolve
// them against).
void collect(const fs::path& root, const fs::path& rel,
             std::map<std::string, std::string>& modules) {
  const std::string name = module_name(rel);
  if (modules.count(name)) return;
  modules[name] = "";
  std::string text = read_file_bytes((root / rel).string());
  static const std::regex spec(R"((from\s*|import\s*\(?\s*)(['"])(\.{1,2}/[^'"]+)\2)");
  std::string out;
  std::sregex_iterator it(text.begin(), text.end(), spec), end;
  std::size_t at = 0;
  std::vector<fs::path> deps;
  for (; it != end; ++it) {
    const fs::path dep = (rel.parent_path() / (*it)[3].str()).lexically_normal();
    deps.push_back(dep);
    out += text.substr(at, it->position() - at);
    out += (*it)[1].str() + "'" + module_name(dep) + "'";
    at = it->position() + it->length();
  }
  out += text.substr(at);
  // A data: URL is no base for `new URL(x, import.meta.url)` (DRACOLoader's default decoder
  // paths): give each module the address it has in the package instead; the page never fetches
  // it (the decoders come from the page's files).
  const std::string meta = "import.meta.url";
  for (std::size_t p = out.find(meta); p != std::string::npos; p = out.find(meta, p)) {
    const std::string url = "'file:///three/" + rel.generic_string() + "'";
    out.replace(p, meta.size(), url);
    p += url.size();
  }
  modules[name] = std::move(out);
  for (const fs::path& d : deps) collect(root, d, modules);
}

// The page's script; ${...} are not used, so it is a plain raw string.
const char* kViewer = R"JS(
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { FoliageImpostors, foliageClouds, isLeafMesh } from 'ramus/impostors.js';
const bytes = (b64) => Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
const files = JSON.parse(document.getElementById('files').textContent);
const urls = {};
for (const [name, b64] of Object.entries(files)) urls[name] = URL.createObjectURL(new Blob([bytes(b64)]));
// Every file the loaders ask for (a .gltf's .bin and images, the Draco decoder) is in the page.
const manager = new THREE.LoadingManager();
manager.setURLModifier((url) => urls[url] || urls[decodeURIComponent(url)] || url);
const loader = new GLTFLoader(manager);
const asset = document.getElementById('asset');
const text = asset.dataset.kind === 'glb' ? null : new TextDecoder().decode(bytes(asset.textContent));
if (urls['draco/draco_decoder.wasm']) {
  const { DRACOLoader } = await import('three/examples/jsm/loaders/DRACOLoader.js');
  loader.setDRACOLoader(new DRACOLoader(manager).setDecoderPath('draco/'));
}
if (document.getElementById('meshopt')) {
  const { MeshoptDecoder } = await import('three/examples/jsm/libs/meshopt_decoder.module.js');
  loader.setMeshoptDecoder(MeshoptDecoder);
}
const gltf = await loader.parseAsync(text ?? bytes(asset.textContent).buffer, '');

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
document.body.appendChild(renderer.domElement);
const background = new THREE.Color(0xc9d6df);
const scene = new THREE.Scene();
scene.background = background;
const sky = new THREE.HemisphereLight(0xffffff, 0x6b5a45, 2.0);
scene.add(sky);
const sun = new THREE.DirectionalLight(0xffffff, 2.0);
sun.position.set(3, 10, 6);
scene.add(sun);
scene.add(gltf.scene);

// Levels of detail: LOD0 is the scene's root node, the others the nodes its MSFT_lod names
// (three's loader leaves them out of the scene; they share the root's skin and bones).
const json = gltf.parser.json;
const rootIndex = json.scenes[json.scene ?? 0].nodes[0];
const lod = json.nodes[rootIndex].extensions?.MSFT_lod;
const coverage = json.nodes[rootIndex].extras?.MSFT_screencoverage ?? [];
const meshesOf = (o) => (o.isMesh ? [o] : o.children.filter((c) => c.isMesh));
const root = await gltf.parser.getDependency('node', rootIndex);
const levels = [meshesOf(root)];
// A file whose first node has no mesh (the pieces' bones): every mesh in the scene is LOD0.
if (!levels[0].length) gltf.scene.traverse((o) => { if (o.isMesh) levels[0].push(o); });
for (const id of lod?.ids ?? []) {
  const node = await gltf.parser.getDependency('node', id);
  gltf.scene.add(node);
  levels.push(meshesOf(node));
}
const triangles = (ms) => ms.reduce((n, m) => n + (m.geometry.index ? m.geometry.index.count : m.geometry.attributes.position.count) / 3, 0);
let level = 0, autoLevel = levels.length > 1;
// Foliage as the glTF's leaf cards or as 2.5D impostors of its leaf clouds (cli/view_impostors.cpp).
const params = new URLSearchParams(location.search);
let impostors = null, foliage = 'cards';
// The leaves of the full-detail view: LOD0's, or (pieces) the leaf meshes anywhere in the scene.
const coarser = new Set(levels.slice(1).flat()), leafMeshes = [];
gltf.scene.traverse((o) => { if (isLeafMesh(o) && !coarser.has(o)) leafMeshes.push(o); });
const show = (k) => {
  level = k;
  const hidden = (m) => foliage === 'impostors' && isLeafMesh(m);
  for (const m of leafMeshes) m.visible = !hidden(m);
  levels.forEach((ms, i) => ms.forEach((m) => { m.visible = i === k && !hidden(m); m.frustumCulled = false; }));
  if (impostors) impostors.group.visible = foliage === 'impostors';
  document.getElementById('info').textContent =
    `LOD${k}: ${triangles(levels[k].filter((m) => m.visible)).toLocaleString('en')} triangles`;
};
const panel = document.getElementById('lods');
const choices = levels.length > 1 ? ['auto', ...levels.map((_, k) => k)] : [];
for (const c of choices) {
  const label = document.createElement('label');
  label.innerHTML = `<input type="radio" name="lod" value="${c}" ${c === 'auto' ? 'checked' : ''}> ${c === 'auto' ? 'auto' : 'LOD' + c} `;
  label.firstChild.onchange = () => { autoLevel = c === 'auto'; if (!autoLevel) show(c); };
  panel.appendChild(label);
}
show(0);

// The camera frames LOD0 from the front (glTF's +Z), a little above, looking at its middle.
const box = new THREE.Box3();
gltf.scene.updateMatrixWorld(true);
for (const m of levels[0]) box.expandByObject(m);
const centre = box.getCenter(new THREE.Vector3());
const size = box.getSize(new THREE.Vector3());
const radius = Math.max(size.length() / 2, 1e-6);
const camera = new THREE.PerspectiveCamera(40, window.innerWidth / window.innerHeight, radius / 100, radius * 100);
const fit = Math.max(size.y, size.x * 0.8) / 2 / Math.tan((20 * Math.PI) / 180) * 1.15;
camera.position.set(centre.x, centre.y + size.y * 0.1, centre.z + fit + size.z / 2);
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(centre);
controls.update();

gltf.scene.updateMatrixWorld(true);
const clouds = foliageClouds(json);
if (clouds.length && leafMeshes.length) {
  impostors = new FoliageImpostors(clouds, leafMeshes, [sky, sun]);
  scene.add(impostors.group);
  if (params.get('foliage') === 'impostors') foliage = 'impostors';
} else {
  document.getElementById('foliage').style.display = 'none';
}
const setFoliage = (mode) => {
  foliage = impostors && mode === 'impostors' ? 'impostors' : 'cards';
  document.getElementById('foliage').textContent =
    foliage === 'impostors' ? 'show leaf cards' : 'show impostors';
  show(level);
};
document.getElementById('foliage').onclick = () => setFoliage(foliage === 'cards' ? 'impostors' : 'cards');
setFoliage(foliage);

const mixer = new THREE.AnimationMixer(gltf.scene);
const wind = document.getElementById('wind');
if (gltf.animations.length) mixer.clipAction(gltf.animations[0]).play();
else wind.parentElement.style.display = 'none';
const timer = new THREE.Timer();
let playing = true;
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
});
// Screen coverage of LOD0's bounding sphere, as MSFT_screencoverage means it: the share of the
// view's height it covers.
const screenCoverage = () => {
  const d = camera.position.distanceTo(centre);
  return radius / (d * Math.tan((camera.fov * Math.PI) / 360));
};
// One frame: the impostors whose view turned are rendered again, then the scene.
const draw = () => {
  if (impostors && foliage === 'impostors') {
    gltf.scene.updateMatrixWorld();
    impostors.update(renderer, camera);
  }
  renderer.render(scene, camera);
};
// Frame time with the GPU's work included (reading one pixel waits for it), and the triangles
// the scene's pass drew, per foliage mode.
const gl = renderer.getContext(), pixel = new Uint8Array(4);
const timed = { cards: {}, impostors: {} };
const timedDraw = () => {
  const t0 = performance.now();
  draw();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  const ms = performance.now() - t0, t = timed[foliage];
  t.ms = t.ms === undefined ? ms : 0.9 * t.ms + 0.1 * ms;
  t.triangles = renderer.info.render.triangles;
  return ms;
};
const fmt = (n) => Math.round(n).toLocaleString('en');
const showTimes = () => {
  if (!impostors) return;
  const line = (name, t, tris) => `${name}: ${fmt(tris)} foliage triangles, ` +
    (t.ms === undefined ? 'not drawn yet' : `${t.ms.toFixed(1)} ms/frame, ${fmt(t.triangles)} in the frame`);
  document.getElementById('times').innerHTML = line('leaf cards', timed.cards, impostors.cardTriangles) +
    '<br>' + line(`impostors (${impostors.clouds.length} clouds)`, timed.impostors, impostors.triangles) +
    `<br>${fmt(impostors.refreshes)} impostor renders, ${fmt(impostors.refreshTriangles)} leaf triangles in them`;
};
let frames = 0;
function frame() {
  timer.update();
  if (playing && wind.checked) mixer.update(timer.getDelta());
  if (autoLevel) {
    const c = screenCoverage();
    let k = 0;
    while (k + 1 < levels.length && coverage[k] !== undefined && c < coverage[k]) k++;
    if (k !== level) show(k);
  }
  controls.update();
  timedDraw();
  if (++frames % 15 === 0) showTimes();
}
renderer.setAnimationLoop(frame);

// The camera on its orbit around the tree's middle: turned by azimuth (degrees, about y, 0 is
// the front), raised by elevation, at `distance` times the distance that frames the tree.
const framing = camera.position.distanceTo(controls.target);
const place = (azimuth, elevation, distance = 1) => {
  const d = framing * distance, a = (azimuth * Math.PI) / 180, e = (elevation * Math.PI) / 180;
  camera.position.set(Math.sin(a) * Math.cos(e), Math.sin(e), Math.cos(a) * Math.cos(e)).multiplyScalar(d).add(controls.target);
  camera.lookAt(controls.target);
  controls.update();
};

// For tests and scripts: pick a level, stop the wind at a time, and measure the picture.
window.ramusView = {
  levels: levels.length,
  animations: gltf.animations.length,
  period: gltf.animations[0]?.duration ?? 0,
  setLevel(k) {
    autoLevel = false;
    show(k);
    for (const r of document.getElementsByName('lod')) r.checked = r.value === String(k);
    draw();
  },
  setTime(t) { playing = false; mixer.setTime(t); draw(); },
  setFoliage(mode) { setFoliage(mode); draw(); },
  orbit(azimuth, elevation, distance = 1) { place(azimuth, elevation, distance); draw(); },
  // Frames until every impostor picture is up to date (the budget spreads a big turn over a few).
  settle() {
    let n = 0;
    do { draw(); n++; } while (impostors && foliage === 'impostors' && impostors.pending > 0 && n < 100);
    return n;
  },
  // The foliage mode and its numbers; frameTriangles: what the last frame's scene pass drew.
  foliage() {
    return { mode: foliage, clouds: impostors?.clouds.length ?? 0, cardTriangles: impostors?.cardTriangles ?? 0,
      impostorTriangles: impostors?.triangles ?? 0, refreshes: impostors?.refreshes ?? 0,
      frameTriangles: renderer.info.render.triangles };
  },
  // false: the impostors' fragments keep their quad's depth instead of their picture's (a test
  // measures what the 2.5D depth adds).
  setPictureDepth(on) { if (impostors) impostors.pictureDepth.value = on; draw(); },
  // The impostors' offscreen pictures (RGBA bytes per cloud).
  impostorPictures() { return impostors ? impostors.pictures(renderer) : []; },
  // Median milliseconds per frame in each foliage mode over `count` frames of each, the modes
  // taking turns frame by frame (so both see the same load on a shared machine); the camera
  // turns by `step` degrees every other frame (0: still; beyond the threshold the impostors are
  // rendered again) from 10 degrees above, at `distance` times the framing distance.
  measure(count, step = 0, distance = 1) {
    const home = camera.position.clone(), mode = foliage;
    const ms = { cards: [], impostors: [] }, tris = {};
    for (let i = -2; i < count; i++) {
      place(i * step, 10, distance);
      for (const m of ['cards', 'impostors']) {
        setFoliage(m);
        const t = timedDraw();
        if (i >= 0) ms[m].push(t);
        tris[m] = renderer.info.render.triangles;
      }
    }
    const median = (a) => a.sort((x, y) => x - y)[a.length >> 1];
    camera.position.copy(home);
    controls.update();
    setFoliage(mode);
    draw();
    return { cards: { ms: median(ms.cards), triangles: tris.cards },
      impostors: { ms: median(ms.impostors), triangles: tris.impostors } };
  },
  stats() {
    draw();
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const bg = background.clone().convertLinearToSRGB();
    const ref = [bg.r * 255, bg.g * 255, bg.b * 255];
    let drawn = 0, x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
      const i = 4 * (y * w + x);
      if (Math.abs(px[i] - ref[0]) + Math.abs(px[i + 1] - ref[1]) + Math.abs(px[i + 2] - ref[2]) < 24) continue;
      drawn++; x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
    const world = new THREE.Box3();
    for (const m of levels[level]) world.expandByObject(m);
    return { pixels: w * h, drawnPixels: drawn, drawnWidth: x1 - x0 + 1, drawnHeight: y1 - y0 + 1,
      visibleMeshes: levels.flat().filter((m) => m.visible).length, level,
      sizeX: world.max.x - world.min.x, sizeY: world.max.y - world.min.y, sizeZ: world.max.z - world.min.z };
  },
};
window.ramusViewReady = true;
)JS";

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// JSON string contents: the keys of the files map are uris and decoder names.
std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if ((unsigned char)c < 0x20) continue;
    out += c;
  }
  return out;
}

}  // namespace

std::string three_dir() {
  const char* env = std::getenv("RAMUS_THREE_DIR");
  const std::string dir = env && *env ? env : RAMUS_DEFAULT_THREE_DIR;
  if (!fs::exists(fs::path(dir) / "build" / "three.module.js")) {
    throw UserError("three.js is not in " + dir +
                    ": run scripts/install-deps.sh (npm install in tools/) or set RAMUS_THREE_DIR "
                    "to the folder of the npm package three");
  }
  return dir;
}

std::string view_page(const ViewAsset& asset, const std::string& three) {
  const fs::path root(three);
  const std::string json_part =
      asset.binary ? asset.main.substr(0, std::min<std::size_t>(asset.main.size(), 1 << 20))
                   : asset.main;
  const bool draco = json_part.find("KHR_draco_mesh_compression") != std::string::npos;
  const bool meshopt = json_part.find("EXT_meshopt_compression") != std::string::npos;
  std::map<std::string, std::string> modules;
  for (const char* m : {"build/three.module.js", "examples/jsm/loaders/GLTFLoader.js",
                        "examples/jsm/controls/OrbitControls.js"})
    collect(root, m, modules);
  if (draco) collect(root, "examples/jsm/loaders/DRACOLoader.js", modules);
  if (meshopt) collect(root, "examples/jsm/libs/meshopt_decoder.module.js", modules);
  modules["ramus/impostors.js"] = view_impostors_module();
  std::map<std::string, std::string> files = asset.files;
  if (draco) {
    const fs::path d = root / "examples/jsm/libs/draco/gltf";
    files["draco/draco_wasm_wrapper.js"] = read_file_bytes((d / "draco_wasm_wrapper.js").string());
    files["draco/draco_decoder.wasm"] = read_file_bytes((d / "draco_decoder.wasm").string());
  }
  std::string page = "<!doctype html>\n<!--\nWritten by `ramus view`. It contains three.js " +
                     std::string("(https://threejs.org), under this licence:\n\n") +
                     read_file_bytes((root / "LICENSE").string()) + "\n-->\n";
  page += "<html><head><meta charset=\"utf-8\"><title>" + html_escape(asset.name) +
          " - ramus view</title>\n<style>html,body{margin:0;height:100%;overflow:hidden;"
          "font:13px sans-serif}#panel,#times{position:absolute;left:8px;padding:6px 10px;"
          "background:rgba(255,255,255,.85);border-radius:4px}#panel{top:8px}#times{bottom:8px;"
          "font-size:12px}#times:empty{display:none}canvas{display:block}</style>\n"
          "<script type=\"importmap\">{\"imports\":{";
  bool first = true;
  for (const auto& [name, source] : modules) {
    page += std::string(first ? "" : ",") + "\n\"" + name + "\":\"data:text/javascript;base64," +
            base64(source) + "\"";
    first = false;
  }
  page += "}}</script>\n</head><body>\n<div id=\"panel\"><b>" + html_escape(asset.name) +
          "</b> <span id=\"info\"></span><div id=\"lods\"></div><label><input type=\"checkbox\" "
          "id=\"wind\" checked> wind</label> <button id=\"foliage\"></button>"
          "</div><div id=\"times\"></div>\n";
  if (meshopt) page += "<meta id=\"meshopt\">\n";
  page += "<script id=\"asset\" type=\"application/octet-stream\" data-kind=\"" +
          std::string(asset.binary ? "glb" : "gltf") + "\">" + base64(asset.main) + "</script>\n";
  page += "<script id=\"files\" type=\"application/json\">{";
  first = true;
  for (const auto& [name, bytes] : files) {
    page +=
        std::string(first ? "" : ",") + "\"" + json_escape(name) + "\":\"" + base64(bytes) + "\"";
    first = false;
  }
  page +=
      "}</script>\n<script type=\"module\">" + std::string(kViewer) + "</script>\n</body></html>\n";
  return page;
}

}  // namespace ramus::cli
