// Test oracle: decompresses a LAZ file with laz-perf (npm, the LASzip decoder of PDAL's authors,
// compiled to WebAssembly) into an uncompressed LAS file, so the tests can compare our own decoder
// with an independent one. Usage: node laz_oracle.js IN.laz OUT.las [--time]
// The output keeps the input's header and VLRs except the "laszip encoded" VLR; the point format
// byte loses its compression bits. With --time it prints "<points> <seconds>" of the decoding.
'use strict';
const fs = require('fs');
const path = require('path');

function lazPerf() {
  const here = path.join(__dirname, '..', '..', '..', 'tools', 'node_modules', 'laz-perf');
  return require(here);
}

async function main() {
  const [input, output, flag] = process.argv.slice(2);
  if (!input || !output) throw new Error('usage: node laz_oracle.js IN.laz OUT.las [--time]');
  const bytes = fs.readFileSync(input);
  const { createLazPerf } = lazPerf();
  const lp = await createLazPerf();
  const headerSize = bytes.readUInt16LE(94);
  const pointOffset = bytes.readUInt32LE(96);
  const vlrCount = bytes.readUInt32LE(100);

  const started = process.hrtime.bigint();
  const filePtr = lp._malloc(bytes.length);
  lp.HEAPU8.set(bytes, filePtr);
  const laszip = new lp.LASZip();
  laszip.open(filePtr, bytes.length);
  const count = laszip.getCount();
  const length = laszip.getPointLength();
  const points = Buffer.alloc(count * length);
  const pointPtr = lp._malloc(length);
  for (let i = 0; i < count; ++i) {
    laszip.getPoint(pointPtr);
    points.set(lp.HEAPU8.subarray(pointPtr, pointPtr + length), i * length);
  }
  const seconds = Number(process.hrtime.bigint() - started) / 1e9;
  laszip.delete();
  lp._free(pointPtr);
  lp._free(filePtr);

  // Header and VLRs without the laszip VLR.
  const vlrs = [];
  let pos = headerSize;
  let kept = 0;
  for (let i = 0; i < vlrCount; ++i) {
    const user = bytes.subarray(pos + 2, pos + 18).toString('latin1').replace(/\0.*$/s, '');
    const id = bytes.readUInt16LE(pos + 18);
    const len = bytes.readUInt16LE(pos + 20);
    if (!(user === 'laszip encoded' && id === 22204)) {
      vlrs.push(bytes.subarray(pos, pos + 54 + len));
      ++kept;
    }
    pos += 54 + len;
  }
  const header = Buffer.from(bytes.subarray(0, headerSize));
  const vlrBytes = Buffer.concat(vlrs);
  const gap = bytes.subarray(pos, pointOffset);  // user bytes between VLRs and points
  header.writeUInt32LE(headerSize + vlrBytes.length + gap.length, 96);
  header.writeUInt32LE(kept, 100);
  header[104] = header[104] & 0x3f;
  fs.writeFileSync(output, Buffer.concat([header, vlrBytes, gap, points]));
  if (flag === '--time') console.log(`${count} ${seconds}`);
}

main().catch((e) => {
  console.error(e.message || e);
  process.exit(1);
});
