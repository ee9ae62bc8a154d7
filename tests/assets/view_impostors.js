#!/usr/bin/env node
// Opens a page written by `ramus view` with ?foliage=impostors in headless Chromium (software
// WebGL) and prints one JSON line about its 2.5D foliage impostors (cli/view_impostors.cpp):
//   impostorMode (1 when the page opened in it), clouds, cardTriangles (the leaf cards'), impostorTriangles (the quads'),
//   frameTrianglesCards / frameTrianglesImpostors (what the scene's pass drew in each mode),
//   refreshesSmallTurn (impostor renders after a 1 degree turn: below the threshold, none),
//   refreshesFirstFrame (in the first frame after a 60 degree turn: the per-frame budget),
//   settleFrames (frames until all are up to date), refreshesBigTurn (all renders after that
//   turn), picturesChanged (clouds whose offscreen picture
//   differs between the two views in more than 5 % of its texels), pictureChange (the mean share
//   of texels that differ), pictureReturn (the same after turning back to the first view: the
//   pictures depend on the view only), screenChange (share of foliage pixels that differ between
//   the screenshots of the two views), coverageIoU (drawn pixels of the impostors against those
//   of the leaf cards at the first view), depthChanged (share of the drawn pixels that change
//   between bark, leaf and background when the impostors take their quads' flat depth instead
//   of their pictures'), depthAgrees / flatAgrees (how often, on those pixels, the impostors
//   with the pictures' depth / the flat ones show what the leaf cards show), msCardsStill / msImpostorsStill, msCardsTurning /
//   msImpostorsTurning (5 degrees a frame), msCardsFar / msImpostorsFar (4 times as far): median
//   ms per frame over 15 frames of each mode taking turns, GPU work included; software
//   rendering on a shared machine, so only ratios mean something), networkRequests.
// With --screenshots PREFIX it saves PREFIX_cards.png, PREFIX_impostors_a.png,
// PREFIX_impostors_b.png (the two views), PREFIX_pictures_a.png / _b.png (the offscreen
// pictures side by side) and PREFIX_figure.png (both views over their pictures).
//   node view_impostors.js PAGE.html [--screenshots PREFIX]
// Exit codes: 0 shown, 1 the page failed, 2 usage, 77 Chromium cannot run here.
'use strict';
const fs = require('fs');
const path = require('path');
const { launch } = require('../pieces/browser/chromium.js');

const args = process.argv.slice(2);
const page_file = args[0];
const shots = args[1] === '--screenshots' ? args[2] : null;
if (!page_file || !fs.existsSync(page_file)) {
  console.error('usage: view_impostors.js PAGE.html [--screenshots PREFIX]');
  process.exit(2);
}

// In the page: helpers on window for the steps below.
function install() {
  const canvas = document.querySelector('canvas');
  const gl = canvas.getContext('webgl2');
  window.__screen = () => {
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight, px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    return px;
  };
  // Pixels that are not the background (#c9d6df).
  window.__drawn = (px) => {
    const out = new Uint8Array(px.length / 4);
    for (let i = 0; i < out.length; i++)
      out[i] = Math.abs(px[4 * i] - 201) + Math.abs(px[4 * i + 1] - 214) + Math.abs(px[4 * i + 2] - 223) >= 24 ? 1 : 0;
    return out;
  };
  // Each pixel as 0 background, 1 bark (redder than green), 2 leaf (green).
  window.__classes = (px) => {
    const drawn = window.__drawn(px), out = new Uint8Array(drawn.length);
    for (let i = 0; i < out.length; i++) out[i] = !drawn[i] ? 0 : px[4 * i] >= px[4 * i + 1] ? 1 : 2;
    return out;
  };
  window.__iou = (a, b) => {
    let both = 0, either = 0;
    for (let i = 0; i < a.length; i++) { both += a[i] & b[i]; either += a[i] | b[i]; }
    return both / Math.max(either, 1);
  };
  // Share of texels whose colour differs by more than 16 (sum over RGBA) per picture.
  window.__changes = (a, b) => a.map((p, i) => {
    const q = b[i];
    if (!q || q.length !== p.length) return 1;
    let n = 0;
    for (let k = 0; k < p.length; k += 4)
      if (Math.abs(p[k] - q[k]) + Math.abs(p[k + 1] - q[k + 1]) + Math.abs(p[k + 2] - q[k + 2]) + Math.abs(p[k + 3] - q[k + 3]) > 16) n++;
    return n / (p.length / 4);
  });
  // A 2D copy of the WebGL canvas (no page panels).
  window.__copy = () => {
    const c = document.createElement('canvas');
    c.width = canvas.width;
    c.height = canvas.height;
    c.getContext('2d').drawImage(canvas, 0, 0);
    return c;
  };
  // The two views over their impostors' pictures: the figure of docs/textures.md.
  window.__figure = (viewA, viewB, atlasA, atlasB) => {
    const crop = { x: viewA.width * 0.25, y: viewA.height * 0.12, w: viewA.width * 0.5, h: viewA.height * 0.76 };
    const c = document.createElement('canvas');
    c.width = 2 * crop.w;
    c.height = crop.h + crop.w;
    const ctx = c.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, c.width, c.height);
    [viewA, viewB].forEach((v, i) => ctx.drawImage(v, crop.x, crop.y, crop.w, crop.h, i * crop.w, 0, crop.w, crop.h));
    [atlasA, atlasB].forEach((a, i) => ctx.drawImage(a, i * crop.w + 4, crop.h + 4, crop.w - 8, crop.w - 8));
    return c.toDataURL('image/png');
  };
  // The pictures side by side on a white-and-grey checkerboard, each scaled to a 128-pixel
  // cell, as a canvas.
  window.__atlasCanvas = (pictures) => {
    const cell = 128, cols = Math.ceil(Math.sqrt(pictures.length));
    const c = document.createElement('canvas');
    c.width = cols * cell;
    c.height = Math.ceil(pictures.length / cols) * cell;
    const ctx = c.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, c.width, c.height);
    pictures.forEach((p, i) => {
      const s = Math.round(Math.sqrt(p.length / 4)), one = document.createElement('canvas');
      one.width = one.height = s;
      const img = one.getContext('2d').createImageData(s, s);
      for (let y = 0; y < s; y++) for (let x = 0; x < s; x++) {  // flip: WebGL rows go up
        const from = 4 * ((s - 1 - y) * s + x), to = 4 * (y * s + x), a = p[from + 3] / 255;
        const bg = (((x * 16) / s) ^ ((y * 16) / s)) & 1 ? 255 : 215;
        for (let k = 0; k < 3; k++) img.data[to + k] = p[from + k] * a + bg * (1 - a);
        img.data[to + 3] = 255;
      }
      one.getContext('2d').putImageData(img, 0, 0);
      ctx.drawImage(one, (i % cols) * cell + 2, Math.floor(i / cols) * cell + 2, cell - 4, cell - 4);
    });
    return c;
  };
  window.__atlas = (pictures) => window.__atlasCanvas(pictures).toDataURL('image/png');
}

(async () => {
  const browser = await launch();
  let status = 0;
  try {
    const page = await browser.context.newPage();
    await page.setViewportSize({ width: 800, height: 600 });
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    const requests = [];
    page.on('request', (r) => { if (!/^(data|blob|file):/.test(r.url())) requests.push(r.url()); });
    await page.goto('file://' + path.resolve(page_file) + '?foliage=impostors');
    await page.waitForFunction(() => window.ramusViewReady === true || window.ramusViewFailed,
      null, { timeout: 120000 }).catch((e) => errors.push(String(e)));
    if (errors.length) throw new Error(errors.join('; '));
    await page.evaluate(install);
    const saveAtlas = async (name) => {
      if (!shots) return;
      const url = await page.evaluate(() => window.__atlas(window.ramusView.impostorPictures()));
      fs.writeFileSync(`${shots}_${name}.png`, Buffer.from(url.split(',')[1], 'base64'));
    };
    const r = await page.evaluate(() => {
      const v = window.ramusView;
      v.setTime(0);
      v.orbit(0, 10);
      v.settle();
      const f = v.foliage();
      const out = { impostorMode: f.mode === 'impostors' ? 1 : 0, clouds: f.clouds, cardTriangles: f.cardTriangles,
        impostorTriangles: f.impostorTriangles, frameTrianglesImpostors: f.frameTriangles };
      window.__a = v.impostorPictures();
      window.__screenA = window.__screen();
      window.__viewA = window.__copy();
      return out;
    });
    if (shots) await page.screenshot({ path: `${shots}_impostors_a.png` });
    await saveAtlas('pictures_a');
    Object.assign(r, await page.evaluate(() => {
      const v = window.ramusView, out = {};
      let before = v.foliage().refreshes;
      v.orbit(1, 10);
      out.refreshesSmallTurn = v.foliage().refreshes - before;
      before = v.foliage().refreshes;
      v.orbit(60, 10);
      out.refreshesFirstFrame = v.foliage().refreshes - before;
      out.settleFrames = v.settle();
      out.refreshesBigTurn = v.foliage().refreshes - before;
      const b = v.impostorPictures(), change = window.__changes(window.__a, b);
      out.picturesChanged = change.filter((c) => c > 0.05).length;
      out.pictureChange = change.reduce((s, c) => s + c, 0) / Math.max(change.length, 1);
      // Foliage pixels of either view that differ between the two screenshots.
      const screenB = window.__screen(), a = window.__screenA;
      const da = window.__drawn(a), db = window.__drawn(screenB);
      let drawn = 0, differ = 0;
      for (let i = 0; i < da.length; i++) {
        if (!da[i] && !db[i]) continue;
        drawn++;
        if (Math.abs(a[4 * i] - screenB[4 * i]) + Math.abs(a[4 * i + 1] - screenB[4 * i + 1]) + Math.abs(a[4 * i + 2] - screenB[4 * i + 2]) > 24) differ++;
      }
      out.screenChange = differ / Math.max(drawn, 1);
      return out;
    }));
    if (shots) {
      await page.screenshot({ path: `${shots}_impostors_b.png` });
      const url = await page.evaluate(() => window.__figure(window.__viewA, window.__copy(),
        window.__atlasCanvas(window.__a), window.__atlasCanvas(window.ramusView.impostorPictures())));
      fs.writeFileSync(`${shots}_figure.png`, Buffer.from(url.split(',')[1], 'base64'));
    }
    await saveAtlas('pictures_b');
    Object.assign(r, await page.evaluate(() => {
      const v = window.ramusView, out = {};
      v.orbit(0, 10);
      v.settle();
      const back = window.__changes(window.__a, v.impostorPictures());
      out.pictureReturn = back.reduce((s, c) => s + c, 0) / Math.max(back.length, 1);
      const imp = window.__screen();
      v.setPictureDepth(false);
      const flat = window.__screen();
      v.setPictureDepth(true);
      v.setFoliage('cards');
      const f = v.foliage();
      out.frameTrianglesCards = f.frameTriangles;
      const cards = window.__screen();
      out.coverageIoU = window.__iou(window.__drawn(imp), window.__drawn(cards));
      // Where branches and leaves hide each other: the pixels whose class (bark, leaf,
      // background) changes when the impostors take their quads' flat depth instead of their
      // pictures', and how often each of the two agrees there with the leaf cards.
      const ci = window.__classes(imp), cf = window.__classes(flat), cc = window.__classes(cards);
      let drawn = 0, changed = 0, depth = 0, flatAgree = 0;
      for (let i = 0; i < ci.length; i++) {
        if (ci[i] || cf[i]) drawn++;
        if (ci[i] === cf[i]) continue;
        changed++;
        if (ci[i] === cc[i]) depth++;
        if (cf[i] === cc[i]) flatAgree++;
      }
      out.depthChanged = changed / Math.max(drawn, 1);
      out.depthAgrees = depth / Math.max(changed, 1);
      out.flatAgrees = flatAgree / Math.max(changed, 1);
      return out;
    }));
    if (shots) await page.screenshot({ path: `${shots}_cards.png` });
    Object.assign(r, await page.evaluate(() => {
      const v = window.ramusView, still = v.measure(15), turning = v.measure(15, 5), far = v.measure(15, 0, 4);
      v.setFoliage('impostors');
      return { msCardsStill: still.cards.ms, msImpostorsStill: still.impostors.ms,
        msCardsTurning: turning.cards.ms, msImpostorsTurning: turning.impostors.ms,
        msCardsFar: far.cards.ms, msImpostorsFar: far.impostors.ms };
    }));
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
