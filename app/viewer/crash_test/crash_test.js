// A crash in the student's code, for real, in headless Chromium: the viewer built with a Part 3
// whose DiffuseBsdf::sample_f writes through a null pointer (crashing_diffuse_bsdf.cpp). The page
// renders (-m 1 never samples the BSDF), then
//  1. the sampling panel runs sample_f in a request: the server's process dies of SIGSEGV; the
//     page shows the crash's note, naming the request, and the terminal (the viewer's standard
//     error) says it;
//  2. the next request works: a render finishes, on the server started again;
//  3. a render with -m 2 crashes in the render's threads (not a request's): the same again,
//     naming the render's pathtracer command, and the server still answers.
// The viewer itself (the supervisor) is alive at the end.
//
// node crash_test.js --viewer EXE --scene FILE [--chromium EXE] [--out DIR]
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawn } = require('child_process');

function args() {
  const a = { chromium: '/usr/bin/chromium' };
  for (let i = 2; i < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
  for (const n of ['viewer', 'scene']) if (!a[n]) throw new Error(`missing --${n}`);
  return a;
}

let viewer = null;
let terminal = '';
function fail(message) {
  console.error(`FAILED: ${message}\nthe viewer's terminal:\n${terminal}`);
  if (viewer) viewer.kill('SIGTERM');
  process.exit(1);
}

function startViewer(a) {
  return new Promise((resolve, reject) => {
    viewer = spawn(a.viewer, [a.scene, '--port', '0', '-t', '2', '-r', '120', '90', '-s', '2', '-l', '1', '-m', '1'],
      { stdio: ['ignore', 'pipe', 'pipe'] });
    const timer = setTimeout(() => reject(new Error('the viewer printed no address in 30 s')), 30000);
    viewer.stdout.on('data', (d) => {
      terminal += d;
      const m = /open (http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]+)/.exec(terminal);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    viewer.stderr.on('data', (d) => { terminal += d; });
    viewer.on('exit', (code, signal) => { viewer.exited = `${code} ${signal}`; });
  });
}

async function waitDone(page, count) {
  await page.waitForFunction((n) => {
    const v = window.viewerState, s = v.status;
    return s && s.state === 'done' && v.times.imagesDrawn > n && !v.fetching;
  }, count, { timeout: 60000 });
}

/// Waits for the n-th crash's note, naming what the server was doing (`doing`, a regular
/// expression's text), in the terminal and on the page.
async function waitCrash(page, n, doing, what) {
  const note = `server crashed \\(Segmentation fault\\) while it ${doing}.*\\(crash ${n}\\)`;
  const deadline = Date.now() + 30000;
  while (!new RegExp(note).test(terminal)) {
    if (Date.now() > deadline) fail(`${what}: the terminal does not say /${note}/`);
    await new Promise((r) => setTimeout(r, 50));
  }
  await page.waitForFunction((re) => !document.getElementById('crash').hidden &&
    new RegExp(re).test(document.getElementById('crash').textContent), note, { timeout: 30000 })
    .catch(() => fail(`${what}: the page does not say /${note}/`));
  console.log(`${what}: the page says: ${await page.textContent('#crash')}`);
}

async function main() {
  const a = args();
  const { chromium } = require('playwright-core');
  const url = await startViewer(a);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'pt-viewer-crash-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: a.chromium, headless: true, viewport: { width: 1100, height: 1000 },
    args: ['--headless', '--no-sandbox', '--use-gl=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
      '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const shoot = async (page, name) => { if (a.out) { fs.mkdirSync(a.out, { recursive: true }); await page.screenshot({ path: path.join(a.out, name), fullPage: true }); } };
  try {
    const page = context.pages()[0] || await context.newPage();
    await page.goto(url);
    await waitDone(page, 0);
    console.log(`the first render: ${(await page.evaluate(() => window.viewerState.status.summary))}`);

    // 1. A crash in a request: the sampling panel's Part 3 sample_f.
    await page.selectOption('#sampler', 'diffuse_bsdf');
    await page.click('#sampling-run');
    await waitCrash(page, 1, 'answered POST /api/sampling', 'the sampling panel');
    await shoot(page, '1-crash-in-a-request.png');

    // 2. The next request works: a render, on the server started again.
    const drawn = await page.evaluate(() => window.viewerState.times.imagesDrawn);
    await page.click('#render');
    await waitDone(page, drawn);
    const again = await page.evaluate(() => window.viewerState.status);
    if (!/render: 120x90/.test(again.summary)) fail(`the render after the crash: '${again.summary}'`);
    console.log(`after the crash, a render: ${again.summary}`);

    // 3. A crash in the render's threads: -m 2 samples the BSDF at each bounce.
    await page.fill('#m', '2');
    await page.click('#render');
    await waitCrash(page, 2, 'rendered: pathtracer .*-m 2', 'a render with -m 2');
    await page.fill('#m', '1');
    const drawn2 = await page.evaluate(() => window.viewerState.times.imagesDrawn);
    await page.click('#render');
    await waitDone(page, drawn2);
    await shoot(page, '2-render-after-crashes.png');
    if (viewer.exited) fail(`the viewer exited (${viewer.exited})`);
    console.log('passed: two crashes, each told on the page and in the terminal; the server answered after each');
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
    viewer.kill('SIGTERM');
  }
  process.exit(0);
}

main().catch((e) => fail(e.stack || String(e)));
