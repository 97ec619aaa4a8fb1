// The browser test of the write-up generator: builds a tiny write-up (two small renders, math,
// a plot from a CSV written here), opens its index.html over file:// in headless Chromium, and
// checks that every image loaded, the math is typeset with KaTeX's fonts, and the console is
// clean. Saves a screenshot of the page beside it.
//
// node generated_page_test.js --website EXE --pathtracer EXE --out DIR [--chromium EXE]
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');

function args() {
  const a = { chromium: '/usr/bin/chromium' };
  for (let i = 2; i < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
  for (const need of ['website', 'pathtracer', 'out']) {
    if (!a[need]) throw new Error(`missing --${need}`);
  }
  return a;
}

function fail(message) {
  console.error(`FAILED: ${message}`);
  process.exit(1);
}

async function main() {
  const a = args();
  let chromium;
  try {
    ({ chromium } = require('playwright-core'));
  } catch (e) {
    fail('playwright-core is not installed in website/node_modules: run tools/setup.sh');
  }
  if (!fs.existsSync(a.chromium)) fail(`no Chromium at ${a.chromium}: run tools/setup.sh`);

  const out = path.resolve(a.out);
  fs.rmSync(path.join(out, 'src'), { recursive: true, force: true });
  fs.mkdirSync(path.join(out, 'src'), { recursive: true });
  fs.writeFileSync(path.join(out, 'src', 'convergence.csv'),
    'strategy,samples,seconds,relMSE\n' +
    'uniform,1,0.05,0.8\nuniform,4,0.2,0.21\nuniform,16,0.8,0.052\nuniform,64,3.2,0.013\n' +
    'adaptive,1,0.05,0.6\nadaptive,4,0.15,0.11\nadaptive,16,0.5,0.02\nadaptive,64,1.7,0.004\n');
  fs.writeFileSync(path.join(out, 'src', 'writeup.md'), [
    '# Browser test write-up',
    '',
    'Renders at $s = 1, l = 4$ and $s = 4$:',
    '',
    '$$L_o = \\int_{H^2} f_r\\, L_i \\cos\\theta \\, d\\omega$$',
    '',
    '```grid columns=2 flags="-t 0 -r 64 48 -l 4"',
    'scene=cornell_spheres.dae flags="-s 1" caption="$s = 1$"',
    'scene=cornell_spheres.dae flags="-s 4" caption="$s = 4$"',
    '```',
    '',
    '```plot csv=convergence.csv title="Error against time"',
    '```',
    '',
  ].join('\n'));

  const build = spawnSync(a.website, ['build', path.join(out, 'src', 'writeup.md'), '-o',
    path.join(out, 'site'), '--pathtracer', a.pathtracer, '--cache', path.join(out, 'cache')],
    { encoding: 'utf8' });
  process.stderr.write(build.stderr || '');
  if (build.status !== 0) fail(`website build exited with ${build.status}`);

  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'pt-website-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: a.chromium,
    headless: true,
    viewport: { width: 1000, height: 800 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const problems = [];
  try {
    const page = await context.newPage();
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => problems.push(`failed to load ${r.url()}: ${r.failure().errorText}`));
    const url = 'file://' + path.join(out, 'site', 'index.html');
    await page.goto(url, { waitUntil: 'load' });
    await page.evaluate(() => document.fonts.ready);
    const facts = await page.evaluate(() => ({
      images: [...document.images].map((i) => ({ src: i.getAttribute('src'), complete: i.complete, width: i.naturalWidth })),
      katex: document.querySelectorAll('.katex').length,
      katexDisplay: document.querySelectorAll('.katex-display').length,
      katexWidths: [...document.querySelectorAll('.katex-html')].map((e) => e.getBoundingClientRect().width),
      rawDollar: document.body.innerText.includes('$s = 1'),
      fontLoaded: document.fonts.check('16px KaTeX_Main') &&
        [...document.fonts].some((f) => f.family.replace(/"/g, '') === 'KaTeX_Main' && f.status === 'loaded'),
      heading: document.querySelector('h1') && document.querySelector('h1').textContent,
    }));
    await page.screenshot({ path: path.join(out, 'screenshot.png'), fullPage: true });
    console.log(JSON.stringify(facts, null, 1));

    if (facts.images.length !== 3) problems.push(`expected 3 images (2 renders, 1 plot), found ${facts.images.length}`);
    for (const img of facts.images) {
      if (!img.complete || !(img.width > 0)) problems.push(`image ${img.src} did not load (natural width ${img.width})`);
    }
    // 2 inline spans in the text, 1 display, 2 in the captions.
    if (facts.katex < 5) problems.push(`expected at least 5 typeset math spans, found ${facts.katex}`);
    if (facts.katexDisplay !== 1) problems.push(`expected 1 display equation, found ${facts.katexDisplay}`);
    if (facts.katexWidths.some((w) => !(w > 0))) problems.push('a math span has no width on the page');
    if (facts.rawDollar) problems.push('raw TeX ($...$) is visible on the page');
    if (!facts.fontLoaded) problems.push("KaTeX's font was not loaded from the folder");
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
  if (problems.length) fail(problems.join('\n'));
  console.log(`passed; screenshot: ${path.join(out, 'screenshot.png')}`);
}

main().catch((e) => fail(e.stack || String(e)));
