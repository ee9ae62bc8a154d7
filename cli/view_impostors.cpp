// The 2.5D foliage impostors of the `ramus view` page (Burkus, Karpati & Szecsi, section 6, after
// Decoret et al.'s "2.5D impostors"): each leaf cloud of the glTF's ramus_foliage extras is
// rendered offscreen (colour and depth) from the current view direction and drawn as one
// camera-facing quad whose fragments take their depth from that picture, so clouds are
// depth-tested against each other and the branches; a cloud is rendered again when the
// direction to it turns by more than a threshold. docs/textures.md describes it.
#include "cli/view_page.h"

namespace ramus::cli {

// An ES module; ${...} is not used, so it is a plain raw string.
const char* view_impostors_module() {
  return R"JS(
import * as THREE from 'three';

// The leaf clouds of the glTF (the mesh writer's k-means clusters of the leaf cards, or a pieces
// file's foliage anchors): {"ramus_foliage": {"clouds": [{"centre": [x,y,z], "radius": r}]}} on
// a root node of the scene, in the scene's frame.
export function foliageClouds(json) {
  for (const s of json.scenes ?? []) for (const n of s.nodes ?? []) {
    const clouds = json.nodes?.[n]?.extras?.ramus_foliage?.clouds;
    if (!Array.isArray(clouds)) continue;
    return clouds.filter((c) => Array.isArray(c.centre) && c.centre.length === 3 &&
        c.centre.every(Number.isFinite) && Number.isFinite(c.radius) && c.radius > 0)
      .map((c) => ({ centre: new THREE.Vector3(...c.centre), radius: c.radius }));
  }
  return [];
}

// Leaf materials are the alpha-tested ones (glTF alphaMode MASK) or those named for leaves.
export const isLeafMesh = (m) => m.isMesh && !m.isInstancedMesh &&
  (m.material.alphaTest > 0 || /leaf|leaves|foliage/i.test(m.material.name ?? ''));

const vertexShader = `
varying vec2 vUv;
varying vec3 vWorld;
void main() {
  vUv = uv;
  vec4 w = modelMatrix * vec4(position, 1.0);
  vWorld = w.xyz;
  gl_Position = projectionMatrix * viewMatrix * w;
}`;

// The quad lies in the plane through the cloud's centre facing the direction it was rendered
// from; the depth picture gives how far behind or before that plane the leaf seen at each texel
// is (orthographic, so linear: 0 at centre - radius * dir, 1 at centre + radius * dir). That
// point, projected by the viewing camera, is the fragment's depth.
const fragmentShader = `
uniform sampler2D colourMap;
uniform sampler2D depthMap;
uniform vec3 direction;
uniform float radius;
uniform mat4 viewProjection;
uniform bool pictureDepth;  // false: the quad's own depth, to show what the picture's adds
varying vec2 vUv;
varying vec3 vWorld;
void main() {
  vec4 c = texture2D(colourMap, vUv);
  if (c.a < 0.5) discard;
  float z = texture2D(depthMap, vUv).r;
  vec4 clip = viewProjection * vec4(vWorld + direction * ((2.0 * z - 1.0) * radius), 1.0);
  gl_FragDepth = pictureDepth ? clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0) : gl_FragCoord.z;
  gl_FragColor = vec4(c.rgb / c.a, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}`;

// The leaves at rest in world coordinates as one plain geometry (skinned leaves through their
// bones' rest pose), and for each vertex the joint that moves it most as `mesh:bone` (null when
// not skinned).
function restLeaves(meshes) {
  const pos = [], nrm = [], uv = [], index = [], joint = [];
  const v = new THREE.Vector3(), n = new THREE.Vector3(), nm = new THREE.Matrix3();
  for (const [mi, m] of meshes.entries()) {
    m.updateWorldMatrix(true, false);
    if (m.isSkinnedMesh) m.skeleton.update();
    nm.getNormalMatrix(m.matrixWorld);
    const g = m.geometry, a = g.attributes, base = pos.length / 3;
    for (let i = 0; i < a.position.count; i++) {
      v.fromBufferAttribute(a.position, i);
      if (m.isSkinnedMesh) m.applyBoneTransform(i, v);
      v.applyMatrix4(m.matrixWorld);
      pos.push(v.x, v.y, v.z);
      if (a.normal) n.fromBufferAttribute(a.normal, i).applyMatrix3(nm).normalize();
      else n.set(0, 1, 0);
      nrm.push(n.x, n.y, n.z);
      uv.push(a.uv ? a.uv.getX(i) : 0, a.uv ? a.uv.getY(i) : 0);
      let best = -1, w = 0;
      if (m.isSkinnedMesh && a.skinIndex && a.skinWeight)
        for (let k = 0; k < 4; k++) {
          const wk = a.skinWeight.getComponent(i, k);
          if (wk > w) { w = wk; best = a.skinIndex.getComponent(i, k); }
        }
      joint.push(best < 0 ? null : `${mi}:${best}`);
    }
    const count = g.index ? g.index.count : a.position.count;
    for (let i = 0; i < count; i++) index.push(base + (g.index ? g.index.getX(i) : i));
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
  geometry.setAttribute('normal', new THREE.Float32BufferAttribute(nrm, 3));
  geometry.setAttribute('uv', new THREE.Float32BufferAttribute(uv, 2));
  return { geometry, index, joint };
}

// Where a bone has moved a point of the rest pose to: W B^-1 (bone * boneInverse) B W^-1 of
// its skinned mesh, relative to the same at rest.
function boneMotion(j) {
  const m = j.mesh, s = m.skeleton;
  const now = new THREE.Matrix4().multiplyMatrices(s.bones[j.bone].matrixWorld, s.boneInverses[j.bone]);
  return new THREE.Matrix4().copy(m.matrixWorld).multiply(m.bindMatrixInverse).multiply(now)
    .multiply(m.bindMatrix).multiply(new THREE.Matrix4().copy(m.matrixWorld).invert());
}

export class FoliageImpostors {
  // clouds: foliageClouds(); leafMeshes: the LOD0 leaves; lights: the scene's lights (the
  // offscreen pictures are lit as the leaf cards are).
  constructor(clouds, leafMeshes, lights) {
    this.group = new THREE.Group();
    this.group.name = 'foliage impostors';
    this.scene = new THREE.Scene();  // the offscreen one: lights and one cloud's leaves
    for (const l of lights) this.scene.add(l.clone());
    this.thresholdDegrees = 4;  // turn of the view direction that renders a cloud again
    // Clouds rendered again per frame at most, those whose view turned most first: a fast turn
    // costs a few offscreen passes a frame instead of one per cloud; the others keep their
    // picture (and its orientation) a few frames longer.
    this.budget = Math.max(4, Math.ceil(clouds.length / 4));
    this.pending = 0;            // clouds whose picture is out of date after the last update
    this.refreshes = 0;          // offscreen renders so far
    this.refreshTriangles = 0;   // leaf triangles those renders drew
    this.viewProjection = { value: new THREE.Matrix4() };
    this.pictureDepth = { value: true };
    this.cardTriangles = leafMeshes.reduce((t, m) => t + (m.geometry.index ? m.geometry.index.count : m.geometry.attributes.position.count) / 3, 0);
    const rest = restLeaves(leafMeshes);
    const material = leafMeshes[0]?.material;  // the pictures show every leaf in the first's
    // Each leaf triangle belongs to the cloud whose centre is nearest its own centre (the
    // writer's k-means assignment); a cloud's radius grows to hold all of its triangles.
    const members = clouds.map(() => []), reach = clouds.map((c) => c.radius);
    const p = rest.geometry.attributes.position, a = new THREE.Vector3(), t = new THREE.Vector3();
    for (let i = 0; clouds.length && i + 2 < rest.index.length; i += 3) {
      t.set(0, 0, 0);
      for (let k = 0; k < 3; k++) t.add(a.fromBufferAttribute(p, rest.index[i + k]));
      t.multiplyScalar(1 / 3);
      let best = 0;
      for (let c = 1; c < clouds.length; c++)
        if (t.distanceToSquared(clouds[c].centre) < t.distanceToSquared(clouds[best].centre)) best = c;
      members[best].push(rest.index[i], rest.index[i + 1], rest.index[i + 2]);
      for (let k = 0; k < 3; k++)
        reach[best] = Math.max(reach[best], a.fromBufferAttribute(p, rest.index[i + k]).distanceTo(clouds[best].centre));
    }
    this.clouds = [];
    clouds.forEach((c, i) => {
      if (!members[i].length || !material) return;
      // The cloud's triangles over the shared vertex buffers (one upload for all clouds).
      const geometry = new THREE.BufferGeometry();
      for (const [name, attribute] of Object.entries(rest.geometry.attributes)) geometry.setAttribute(name, attribute);
      geometry.setIndex(members[i]);
      const radius = reach[i] * 1.01;
      // sRGB texels: 8 bits per channel without banding in the shadows; sampling decodes them.
      const target = new THREE.WebGLRenderTarget(64, 64, { depthTexture: new THREE.DepthTexture(64, 64),
        colorSpace: THREE.SRGBColorSpace });
      const quad = new THREE.Mesh(new THREE.PlaneGeometry(2 * radius, 2 * radius), new THREE.ShaderMaterial({
        uniforms: {
          colourMap: { value: target.texture }, depthMap: { value: target.depthTexture },
          direction: { value: new THREE.Vector3(0, 0, -1) }, radius: { value: radius },
          viewProjection: this.viewProjection, pictureDepth: this.pictureDepth,
        },
        vertexShader, fragmentShader,
      }));
      quad.name = `foliage cloud ${i}`;
      quad.frustumCulled = false;
      this.group.add(quad);
      // The joint most of the cloud's vertices follow: the quad sways with it in the wind.
      const votes = new Map();
      for (const v of members[i]) { const j = rest.joint[v]; if (j) votes.set(j, (votes.get(j) ?? 0) + 1); }
      let joint = null, most = 0;
      for (const [j, n] of votes) {
        if (n <= most) continue;
        most = n;
        const [mi, bone] = j.split(':').map(Number);
        joint = { mesh: leafMeshes[mi], bone };
      }
      const restInverse = joint ? boneMotion(joint).invert() : null;
      this.clouds.push({ centre: c.centre.clone(), radius, triangles: members[i].length / 3,
        mesh: new THREE.Mesh(geometry, material), target, quad, joint, restInverse,
        camera: new THREE.OrthographicCamera(-radius, radius, radius, -radius, radius, 3 * radius),
        direction: null, size: 0 });
    });
    this.triangles = 2 * this.clouds.length;  // one quad per cloud
  }

  // Before each frame: follow the wind, render again the clouds whose view direction turned by
  // more than the threshold or whose picture size on screen changed by 2x (at most `budget`,
  // the most turned first), and hand the viewing camera to the quads' depth.
  update(renderer, camera) {
    camera.updateMatrixWorld();
    this.viewProjection.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    const up = new THREE.Vector3(0, 1, 0).applyQuaternion(camera.quaternion);
    const cos = Math.cos((this.thresholdDegrees * Math.PI) / 180);
    const height = renderer.getDrawingBufferSize(new THREE.Vector2()).y;
    const stale = [];
    for (const c of this.clouds) {
      const centre = c.centre.clone();
      if (c.joint) centre.applyMatrix4(boneMotion(c.joint).multiply(c.restInverse));
      c.quad.position.copy(centre);
      const d = centre.clone().sub(camera.position);
      const distance = Math.max(d.length(), 1e-9);
      d.divideScalar(distance);
      // Texels for the cloud's diameter on screen, as a power of two in 32..512.
      const pixels = (c.radius / (distance * Math.tan((camera.fov * Math.PI) / 360))) * height;
      const size = Math.min(512, Math.max(32, 2 ** Math.ceil(Math.log2(Math.max(pixels, 1)))));
      // How much the picture is out of date: the cosine of the turn, -2 for a new size.
      const fresh = !c.direction || size !== c.size ? -2 : c.direction.dot(d);
      if (fresh < cos) stale.push({ c, centre, d, size, fresh });
    }
    stale.sort((a, b) => a.fresh - b.fresh);
    for (const s of stale.slice(0, this.budget)) this.render(renderer, s.c, s.centre, s.d, up, s.size);
    this.pending = Math.max(0, stale.length - this.budget);
  }

  render(renderer, c, centre, d, up, size) {
    if (size !== c.size) { c.target.setSize(size, size); c.size = size; }
    c.direction = d.clone();
    c.camera.position.copy(centre).addScaledVector(d, -2 * c.radius);
    c.camera.up.copy(Math.abs(up.dot(d)) > 0.999 ? new THREE.Vector3(0, 0, 1) : up);
    c.camera.lookAt(centre);
    c.camera.updateMatrixWorld();
    c.quad.quaternion.copy(c.camera.quaternion);
    c.quad.material.uniforms.direction.value.copy(d);
    this.scene.add(c.mesh);
    const before = renderer.getRenderTarget(), clear = renderer.getClearColor(new THREE.Color());
    const alpha = renderer.getClearAlpha();
    renderer.setRenderTarget(c.target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(this.scene, c.camera);
    renderer.setRenderTarget(before);
    renderer.setClearColor(clear, alpha);
    this.scene.remove(c.mesh);
    this.refreshes++;
    this.refreshTriangles += c.triangles;
  }

  // The offscreen pictures' colours (RGBA bytes, one array per cloud), for tests.
  pictures(renderer) {
    return this.clouds.map((c) => {
      const px = new Uint8Array(c.size * c.size * 4);
      renderer.readRenderTargetPixels(c.target, 0, 0, c.size, c.size, px);
      return px;
    });
  }
}
)JS";
}

}  // namespace ramus::cli
