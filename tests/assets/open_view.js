#!/usr/bin/env node
// Opens a page written by `ramus view` (file://, no server, no network) in headless Chromium and
// prints one JSON line: {"file", "levels", "animations", "period", "pixels", "drawnPixels",
// "drawnWidth", "drawnHeight", "visibleMeshes", "sizeX", "sizeY", "sizeZ", "visibleAtLevelK"...}
// drawn* describe the pixels that differ from the page's background (their bounding rectangle
// in screen pixels), size* the world box of the level shown (y up), visibleAtLevelK the meshes
// visible after choosing level K. With --screenshots PREFIX it also saves PREFIX_lod0.png (the
// page as loaded, wind stopped at time 0), PREFIX_quarter.png (at a quarter period) and
// PREFIX_lodN.png (the coarsest level).
//   node open_view.js PAGE.html [--screenshots PREFIX]
// Exit codes: 0 shown, 1 the page failed, 2 usage, 77 Chromium cannot run here.
'use strict';
const fs = require('fs');
const path = require('path');
const { launch } = require('../pieces/browser/chromium.js');

const args = process.argv.slice(2);
const page_file = args[0];
const shots = args[1] === '--screenshots' ? args[2] : null;
if (!page_file || !fs.existsSync(page_file)) {
  console.error('usage: open_view.js PAGE.html [--screenshots PREFIX]');
  process.exit(2);
}

(async () => {
  const browser = await launch();
  let status = 0;
  try {
    const page = await browser.context.newPage();
    await page.setViewportSize({ width: 800, height: 600 });
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    // The page must not reach out to the network.
    const requests = [];
    page.on('request', (r) => { if (!/^(data|blob|file):/.test(r.url())) requests.push(r.url()); });
    await page.goto('file://' + path.resolve(page_file));
    await page.waitForFunction(() => window.ramusViewReady === true || window.ramusViewFailed,
      null, { timeout: 120000 }).catch((e) => errors.push(String(e)));
    if (errors.length) throw new Error(errors.join('; '));
    const r = await page.evaluate(() => {
      const v = window.ramusView;
      v.setTime(0);
      const out = { levels: v.levels, animations: v.animations, period: v.period };
      for (let k = v.levels - 1; k >= 0; k--) {
        v.setLevel(k);
        out[`visibleAtLevel${k}`] = v.stats().visibleMeshes;
      }
      return Object.assign(out, v.stats());
    });
    if (shots) {
      await page.screenshot({ path: `${shots}_lod0.png` });
      await page.evaluate(() => window.ramusView.setTime(window.ramusView.period / 4));
      await page.screenshot({ path: `${shots}_quarter.png` });
      await page.evaluate(() => { window.ramusView.setTime(0); window.ramusView.setLevel(window.ramusView.levels - 1); });
      await page.screenshot({ path: `${shots}_lodN.png` });
    }
    r.networkRequests = requests.length;
    console.log(JSON.stringify({ file: page_file, ...r }));
  } catch (e) {
    console.log(JSON.stringify({ file: page_file, error: String(e.message || e) }));
    status = 1;
  } finally {
    await browser.close();
  }
  process.exit(status);
})().catch((e) => {
  console.error(String(e.stack || e));
  process.exit(1);
});
