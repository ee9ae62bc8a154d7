// Debian's headless Chromium driven by npm playwright-core (tools/node_modules), with software
// WebGL (SwiftShader), for the browser checks (load_in_three.js, tests/assets/open_view.js).
// A check that cannot run Chromium exits 77, which its test reports as skipped.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');

const tools = path.join(__dirname, '..', '..', '..', 'tools', 'node_modules');
const CHROMIUM = process.env.RAMUS_CHROMIUM || '/usr/bin/chromium';

function cannotRun(why) {
  console.error(`chromium cannot run: ${why}`);
  process.exit(77);
}

// A fresh browser context (removed again by close()): { context, close }.
async function launch() {
  let chromium;
  try {
    ({ chromium } = require(path.join(tools, 'playwright-core')));
  } catch (e) {
    console.error('playwright-core is not installed: run scripts/install-deps.sh (npm install in tools/)');
    process.exit(2);
  }
  if (!fs.existsSync(CHROMIUM)) cannotRun(`${CHROMIUM} does not exist (Debian package chromium)`);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'ramus-chromium-'));
  const remove = () => fs.rmSync(profile, { recursive: true, force: true });
  try {
    const context = await chromium.launchPersistentContext(profile, {
      executablePath: CHROMIUM,
      headless: true,
      timeout: 60000,
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
    });
    return { context, close: async () => { await context.close(); remove(); } };
  } catch (e) {
    remove();
    cannotRun(String(e.message || e).split('\n')[0]);
  }
}

module.exports = { tools, launch, cannotRun };
