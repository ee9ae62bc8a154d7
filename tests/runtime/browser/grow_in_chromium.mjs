#!/usr/bin/env node
// Opens the example page (examples/runtime/web/) in Debian's headless Chromium (software WebGL,
// tests/pieces/browser/chromium.js) on each .rmb: the WebAssembly runtime grows the tree in the
// page and three.js draws it. Prints one JSON line per file:
//   {"file", "nodes", "organs", "meshTriangles", "triangles", "drawCalls", "drawnPixels",
//    "pixels", "growMs", "meshMs", "wasmBytes", "positions", "radii", "parents",
//    "organPositions", "organSizes", "parts"}
// meshTriangles is the drawn level's index count / 3, triangles and drawCalls come from
// three.js's renderer.info after one render; positions ... organSizes are the grown
// skeleton's, the doubles as the hex of their little-endian bytes (exact), parents as numbers;
// parts has per part of level 0 (bark, leaves, surfaces) its arrays, the floats in hex as
// above and the indices as numbers: {"positions", "normals", "uvs", "indices"}, or null for an
// empty part.
//   node grow_in_chromium.mjs BUILD_DIR FILE.rmb[#seed=S&steps=N]...
// What follows '#' goes to the page's query: seed (any uint64) and steps replace the grammar's.
// With RAMUS_WEB_SCREENSHOTS=1 the picture of each file is kept as FILE.web.png.
// A file the page reports an error for (a corrupt .rmb) gives {"file", "error"} instead.
// Exit codes: 0 every page finished, 1 a page did not (it threw or hung; stderr says why), 2
// usage, 77 Chromium cannot run here (the message on stderr says why).
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { serve } from '../../../examples/runtime/web/serve.mjs';

const require = createRequire(import.meta.url);
const { launch } = require('../../pieces/browser/chromium.js');

const args = process.argv.slice(2);
if (args.length < 2) {
  console.error('usage: grow_in_chromium.mjs BUILD_DIR FILE.rmb[#seed=S&steps=N]...');
  process.exit(2);
}
const [build, ...files] = args;
const wasm = path.resolve(build, 'runtime', 'wasm', 'ramus_runtime.wasm');
if (!fs.existsSync(wasm)) {
  console.error(`${wasm} does not exist: build the target ramus_runtime_wasm`);
  process.exit(2);
}

const browser = await launch();
let failed = false;
try {
  for (const arg of files) {
    const hash = arg.indexOf('#');
    const file = hash < 0 ? arg : arg.slice(0, hash);
    const q = new URLSearchParams(hash < 0 ? '' : arg.slice(hash + 1));
    const { server, url } = await serve({ build, data: path.dirname(path.resolve(file)) });
    const page = await browser.context.newPage();
    const messages = [];
    page.on('console', (m) => messages.push(`console.${m.type()}: ${m.text()}`));
    page.on('pageerror', (e) => messages.push(`page error: ${e.message}`));
    q.set('rmb', `/data/${encodeURIComponent(path.basename(file))}`);
    q.set('size', '256');
    await page.goto(`${url}/?${q}`);
    try {
      await page.waitForFunction(() => window.ramusResult !== undefined, null, { timeout: 120000 });
    } catch (e) {
      console.error(`${file}: the page did not finish\n${messages.join('\n')}`);
      failed = true;
      await page.close();
      server.close();
      continue;
    }
    const result = await page.evaluate(() => {
      const r = window.ramusResult;
      if (r.error) return r;
      const hex = (a) => Array.from(new Uint8Array(a.buffer, a.byteOffset, a.byteLength),
        (b) => b.toString(16).padStart(2, '0')).join('');
      const t = window.ramusTree, mesh = window.ramusMesh;
      const parts = !mesh ? [] : [0, 1, 2].map((part) => {
        const a = mesh.part(0, part);
        return a && { positions: hex(a.positions), normals: hex(a.normals), uvs: hex(a.uvs),
          indices: Array.from(a.indices) };
      });
      return { ...r, positions: hex(t.positions), radii: hex(t.radii),
        parents: Array.from(t.parents), organPositions: hex(t.organPositions),
        organSizes: hex(t.organSizes), parts };
    });
    if (result.error) {
      console.log(JSON.stringify({ file: arg, error: result.error }));
    } else {
      if (process.env.RAMUS_WEB_SCREENSHOTS === '1') {
        await page.locator('canvas').screenshot({ path: `${file}.web.png` });
      }
      console.log(JSON.stringify({ file: arg, ...result, wasmBytes: fs.statSync(wasm).size }));
    }
    await page.close();
    server.close();
  }
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
