// The ramus runtime in the browser: a small ES-module wrapper over the C API of
// runtime/ramus_runtime.h compiled to WebAssembly (ramus_runtime.wasm, loaded by emscripten's
// ramus_runtime.mjs next to this file). See docs/runtime.md, "In the browser".
//
//   import { loadRamus } from './ramus.mjs';
//   const ramus = await loadRamus();
//   const grammar = ramus.load(new Uint8Array(await (await fetch('tree.rmb')).arrayBuffer()));
//   const tree = grammar.grow();              // or grow({ steps: 5, seed: 7n })
//   tree.positions, tree.radii, tree.parents, tree.organPositions, tree.organSizes
//   const mesh = tree.mesh({ lodCount: 3 });  // the mesh `ramus build --lod 2` writes
//   const bark = mesh.part(0, Part.BARK);      // { positions, normals, uvs, tangents, wind,
//                                              //   skinNodes, indices } or null when empty
//   mesh.free(); tree.free(); grammar.free();
//
// Failures throw a RamusError carrying the runtime's message ("byte 116: expected ...").
// Native objects are freed by free(), or when the JavaScript object is garbage collected.
import createRamusRuntime from './ramus_runtime.mjs';

export class RamusError extends Error {
  constructor(message) {
    super(message);
    this.name = 'RamusError';
  }
}

const kErrorBytes = 1024;

// The parts of a level (RAMUS_PART_* of ramus_runtime.h), the glTF's primitives.
export const Part = Object.freeze({ BARK: 0, LEAVES: 1, SURFACES: 2 });

// struct ramus_mesh_options as wasm32 lays it out (ints 4 bytes, doubles 8 and 8-aligned):
// { int lod_count; double pipe_exponent; int crossed_leaves; double leaf_scale; int y_up; }.
// Ramus's constructor checks it against ramus_mesh_options_init's defaults.
const kOptions = { size: 40, lodCount: 0, pipeExponent: 8, crossedLeaves: 16, leafScale: 24,
  yUp: 32 };

// Instantiates the module. `options` go to emscripten's factory (e.g. locateFile to find
// ramus_runtime.wasm elsewhere, or wasmBinary to pass its bytes).
export async function loadRamus(options = {}) {
  return new Ramus(await createRamusRuntime(options));
}

export class Ramus {
  constructor(module) {
    this.m = module;
    this.err = module._malloc(kErrorBytes);
    this.scratch = module._malloc(3 * 8);  // a double[3] out-parameter
    this.freer = new FinalizationRegistry(({ free, handle }) => free(handle));
    this.options = module._malloc(kOptions.size);
    this.checkOptionsLayout();
  }

  // ramus_mesh_options_init writes 1 level, exponent 0, no crossed leaves, scale 1, y up: a
  // runtime whose struct differs from kOptions fails here instead of meshing with garbage.
  checkOptionsLayout() {
    const m = this.m, o = this.options;
    m.HEAPU8.fill(0xff, o, o + kOptions.size);
    m._ramus_mesh_options_init(o);
    const i32 = (at) => m.HEAP32[(o + at) >> 2], f64 = (at) => m.HEAPF64[(o + at) >> 3];
    if (i32(kOptions.lodCount) !== 1 || f64(kOptions.pipeExponent) !== 0 ||
        i32(kOptions.crossedLeaves) !== 0 || f64(kOptions.leafScale) !== 1 ||
        i32(kOptions.yUp) !== 1) {
      throw new RamusError('ramus_mesh_options is not laid out as ramus.mjs expects');
    }
  }

  // The message the last call wrote into the error buffer.
  error() {
    const heap = this.m.HEAPU8;
    let end = this.err;
    while (end < this.err + kErrorBytes && heap[end] !== 0) end++;
    return new TextDecoder().decode(heap.subarray(this.err, end));
  }

  // Decodes and verifies an .rmb image (Uint8Array or ArrayBuffer); the bytes are copied.
  load(bytes) {
    const data = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
    const m = this.m;
    const ptr = m._malloc(Math.max(1, data.length));
    m.HEAPU8.set(data, ptr);
    const handle = m._ramus_load(ptr, data.length, this.err, kErrorBytes);
    m._free(ptr);
    if (!handle) throw new RamusError(this.error());
    return new Grammar(this, handle);
  }
}

// A native object of the module: freed by free(), or after the JavaScript object is garbage
// collected (the registry holds the handle and the free function, never the object).
class Native {
  constructor(ramus, handle, freeName) {
    this.ramus = ramus;
    this.handle = handle;
    this.freeName = freeName;
    ramus.freer.register(this, { free: ramus.m[freeName], handle }, this);
  }

  free() {
    if (!this.handle) return;
    this.ramus.freer.unregister(this);
    this.ramus.m[this.freeName](this.handle);
    this.handle = 0;
  }

  live() {
    if (!this.handle) throw new RamusError(`this ${this.constructor.name} was freed`);
  }
}

export class Grammar extends Native {
  constructor(ramus, handle) {
    super(ramus, handle, '_ramus_free_grammar');
  }

  // The grammar's own `derive N` and `seed S` (a BigInt: seeds are 64-bit).
  get steps() { return this.ramus.m._ramus_grammar_steps(this.handle); }
  get seed() { return this.ramus.m._ramus_grammar_seed(this.handle); }

  // Derives and interprets: steps -1 is the grammar's `derive N`; seed defaults to the
  // grammar's. Equals what `ramus build` grows from the source grammar with the same seed.
  grow({ steps = -1, seed = this.seed } = {}) {
    const r = this.ramus;
    this.live();
    const handle = r.m._ramus_grow(this.handle, steps, BigInt.asUintN(64, BigInt(seed)), r.err,
      kErrorBytes);
    if (!handle) throw new RamusError(r.error());
    return new Tree(r, handle);
  }
}

// A grown skeleton: a forest of nodes (the segment of node i runs from its parent's position
// to its own) and the organs placed with `~`. The arrays are copies made on first use.
export class Tree extends Native {
  constructor(ramus, handle) {
    super(ramus, handle, '_ramus_free_skeleton');
  }

  get nodeCount() { return this.ramus.m._ramus_node_count(this.handle); }
  get organCount() { return this.ramus.m._ramus_organ_count(this.handle); }

  // x y z per node.
  get positions() {
    return this.cached('_positions', () => this.vectors(this.nodeCount, '_ramus_node_position'));
  }
  get radii() {
    return this.cached('_radii', () => this.scalars(this.nodeCount, '_ramus_node_radius'));
  }
  // The parent's index, -1 for a root.
  get parents() {
    return this.cached('_parents', () => {
      const n = this.nodeCount, out = new Int32Array(n);
      for (let i = 0; i < n; i++) out[i] = Number(this.ramus.m._ramus_node_parent(this.handle, i));
      return out;
    });
  }
  get organPositions() {
    return this.cached('_organPositions',
      () => this.vectors(this.organCount, '_ramus_organ_position'));
  }
  get organSizes() {
    return this.cached('_organSizes', () => this.scalars(this.organCount, '_ramus_organ_size'));
  }

  // Meshes the tree as `ramus build` does (ramus_mesh_build): lodCount levels (`--lod
  // lodCount-1`), pipeExponent (0: the turtle's radii), crossedLeaves, leafScale, and yUp
  // (true: glTF's and three.js's frame, the .glb's arrays bit for bit; false: z up).
  mesh({ lodCount = 1, pipeExponent = 0, crossedLeaves = false, leafScale = 1, yUp = true } = {}) {
    const r = this.ramus, m = r.m, o = r.options;
    this.live();
    m._ramus_mesh_options_init(o);
    m.HEAP32[(o + kOptions.lodCount) >> 2] = lodCount;
    m.HEAPF64[(o + kOptions.pipeExponent) >> 3] = pipeExponent;
    m.HEAP32[(o + kOptions.crossedLeaves) >> 2] = crossedLeaves ? 1 : 0;
    m.HEAPF64[(o + kOptions.leafScale) >> 3] = leafScale;
    m.HEAP32[(o + kOptions.yUp) >> 2] = yUp ? 1 : 0;
    const handle = m._ramus_mesh_build(this.handle, o, r.err, kErrorBytes);
    if (!handle) throw new RamusError(r.error());
    return new Mesh(r, handle);
  }

  cached(key, make) {
    this.live();
    if (!this[key]) this[key] = make();
    return this[key];
  }

  vectors(n, getter) {
    const m = this.ramus.m, at = this.ramus.scratch, out = new Float64Array(3 * n);
    for (let i = 0; i < n; i++) {
      m[getter](this.handle, i, at);
      out.set(m.HEAPF64.subarray(at / 8, at / 8 + 3), 3 * i);
    }
    return out;
  }

  scalars(n, getter) {
    const m = this.ramus.m, at = this.ramus.scratch, out = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      m[getter](this.handle, i, at);
      out[i] = m.HEAPF64[at / 8];
    }
    return out;
  }
}

// A tree mesh: for each level of detail, the parts (Part.BARK, LEAVES, SURFACES) as the arrays
// of the glTF primitives `ramus build` writes. part() copies them out of the module's memory,
// so they stay valid after free().
export class Mesh extends Native {
  constructor(ramus, handle) {
    super(ramus, handle, '_ramus_free_mesh');
  }

  get lodCount() { return this.ramus.m._ramus_mesh_lod_count(this.handle); }

  // Where the vertices' (0, 0, 0) lies in the world (a local origin for georeferenced trees).
  get origin() {
    const m = this.ramus.m, at = this.ramus.scratch;
    m._ramus_mesh_origin(this.handle, at);
    return Array.from(m.HEAPF64.subarray(at / 8, at / 8 + 3));
  }

  vertexCount(lod, part) { return this.ramus.m._ramus_mesh_vertex_count(this.handle, lod, part); }
  indexCount(lod, part) { return this.ramus.m._ramus_mesh_index_count(this.handle, lod, part); }

  // { positions, normals, uvs, tangents (bark only, else null), wind, skinNodes, indices }, or
  // null for an empty part.
  part(lod, part) {
    this.live();
    const m = this.ramus.m, h = this.handle;
    const n = this.vertexCount(lod, part), k = this.indexCount(lod, part);
    if (n === 0) return null;
    const floats = (fn, per) => {
      const at = m[fn](h, lod, part);
      return at ? new Float32Array(m.HEAPF32.buffer, at, per * n).slice() : null;
    };
    const uints = (fn, count) => {
      const at = m[fn](h, lod, part);
      return at ? new Uint32Array(m.HEAPU32.buffer, at, count).slice() : null;
    };
    return {
      positions: floats('_ramus_mesh_positions', 3), normals: floats('_ramus_mesh_normals', 3),
      uvs: floats('_ramus_mesh_uvs', 2), tangents: floats('_ramus_mesh_tangents', 4),
      wind: floats('_ramus_mesh_wind', 4), skinNodes: uints('_ramus_mesh_skin_nodes', n),
      indices: uints('_ramus_mesh_indices', k),
    };
  }
}
