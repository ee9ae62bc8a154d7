// The ramus runtime in the browser: a small ES-module wrapper over the C API of
// runtime/ramus_runtime.h compiled to WebAssembly (ramus_runtime.wasm, loaded by emscripten's
// ramus_runtime.mjs next to this file). See docs/runtime.md, "In the browser".
//
//   import { loadRamus } from './ramus.mjs';
//   const ramus = await loadRamus();
//   const grammar = ramus.load(new Uint8Array(await (await fetch('tree.rmb')).arrayBuffer()));
//   const tree = grammar.grow();              // or grow({ steps: 5, seed: 7n })
//   tree.positions, tree.radii, tree.parents, tree.organPositions, tree.organSizes
//   tree.free(); grammar.free();
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

  track(object, free) {
    const token = { free, handle: object.handle };
    this.freer.register(object, token, object);
  }
}

export class Grammar {
  constructor(ramus, handle) {
    this.ramus = ramus;
    this.handle = handle;
    ramus.track(this, (h) => ramus.m._ramus_free_grammar(h));
  }

  // The grammar's own `derive N` and `seed S` (a BigInt: seeds are 64-bit).
  get steps() { return this.ramus.m._ramus_grammar_steps(this.handle); }
  get seed() { return this.ramus.m._ramus_grammar_seed(this.handle); }

  // Derives and interprets: steps -1 is the grammar's `derive N`; seed defaults to the
  // grammar's. Equals what `ramus build` grows from the source grammar with the same seed.
  grow({ steps = -1, seed = this.seed } = {}) {
    const r = this.ramus;
    if (!this.handle) throw new RamusError('grow: the grammar was freed');
    const handle = r.m._ramus_grow(this.handle, steps, BigInt.asUintN(64, BigInt(seed)), r.err,
      kErrorBytes);
    if (!handle) throw new RamusError(r.error());
    return new Tree(r, handle);
  }

  free() {
    if (!this.handle) return;
    this.ramus.freer.unregister(this);
    this.ramus.m._ramus_free_grammar(this.handle);
    this.handle = 0;
  }
}

// A grown skeleton: a forest of nodes (the segment of node i runs from its parent's position
// to its own) and the organs placed with `~`. The arrays are copies made on first use.
export class Tree {
  constructor(ramus, handle) {
    this.ramus = ramus;
    this.handle = handle;
    ramus.track(this, (h) => ramus.m._ramus_free_skeleton(h));
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

  free() {
    if (!this.handle) return;
    this.ramus.freer.unregister(this);
    this.ramus.m._ramus_free_skeleton(this.handle);
    this.handle = 0;
  }

  cached(key, make) {
    if (!this.handle) throw new RamusError('the tree was freed');
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
