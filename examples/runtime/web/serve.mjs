#!/usr/bin/env node
// Serves the example page with the WebAssembly runtime on localhost:
//   node examples/runtime/web/serve.mjs BUILD_DIR [--data DIR] [--port N]
// then open http://localhost:N/?rmb=/data/TREE.rmb. The URL space:
//   /         this folder (index.html, main.mjs)
//   /ramus/   BUILD_DIR/runtime/wasm (ramus.mjs, ramus_runtime.mjs, ramus_runtime.wasm)
//   /three/   tools/node_modules/three (npm three, installed by scripts/install-deps.sh)
//   /data/    DIR (default: the current directory): the .rmb files
// Any static server with the same layout works; this one only maps folders and sets the MIME
// types browsers insist on (application/wasm, text/javascript). The headless test
// (tests/runtime/browser/grow_in_chromium.mjs) starts it through serve().
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '..', '..', '..');

const kTypes = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.json': 'application/json', '.png': 'image/png',
};

// Starts the server; resolves to { server, url } once it listens (port 0: any free port).
export function serve({ build, data = process.cwd(), port = 0, host = '127.0.0.1' }) {
  const mounts = [
    ['/ramus/', path.resolve(build, 'runtime', 'wasm')],
    ['/three/', path.join(root, 'tools', 'node_modules', 'three')],
    ['/data/', path.resolve(data)],
    ['/', here],
  ];
  const server = http.createServer((req, res) => {
    const url = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    const [prefix, dir] = mounts.find(([p]) => url.startsWith(p));
    let file = path.join(dir, url.slice(prefix.length));
    if (!file.startsWith(dir)) {  // no ../ out of a mounted folder
      res.writeHead(403).end();
      return;
    }
    if (url === '/') file = path.join(here, 'index.html');
    fs.readFile(file, (err, body) => {
      if (err) {
        res.writeHead(404, { 'Content-Type': 'text/plain' }).end(`not found: ${url}\n`);
        return;
      }
      const type = kTypes[path.extname(file)] || 'application/octet-stream';
      res.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-store' }).end(body);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      resolve({ server, url: `http://${host}:${server.address().port}` });
    });
  });
}

if (process.argv[1] && fileURLToPath(import.meta.url) === path.resolve(process.argv[1])) {
  const args = process.argv.slice(2);
  const option = (name, fallback) => {
    const i = args.indexOf(name);
    if (i < 0) return fallback;
    const value = args[i + 1];
    args.splice(i, 2);
    return value;
  };
  const data = option('--data', process.cwd());
  const port = Number(option('--port', 8080));
  if (args.length !== 1 || !Number.isInteger(port)) {
    console.error('usage: serve.mjs BUILD_DIR [--data DIR] [--port N]');
    process.exit(2);
  }
  const wasm = path.resolve(args[0], 'runtime', 'wasm', 'ramus_runtime.wasm');
  if (!fs.existsSync(wasm)) {
    console.error(`${wasm} does not exist: build the target ramus_runtime_wasm first`);
    process.exit(1);
  }
  const { url } = await serve({ build: args[0], data, port });
  console.log(`serving ${url}/?rmb=/data/TREE.rmb (data: ${path.resolve(data)})`);
}
