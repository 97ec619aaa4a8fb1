// The browser test of the write-up generator. Opens pages over file:// in headless Chromium and
// checks what a reader sees:
//  1. a small page rendered with the given pathtracer: every image loads, the math is typeset
//     with KaTeX's fonts from the folder, the console is clean;
//  2. the starting write-up (`website init`, then `website build` with the given pathtracer and
//     bench): every part's section, the error-against-time plot, every image shown at least as
//     wide as it says it is (the renders a reader compares at least 320 pixels), the zoomed crops,
//     the sample-rate key, the BVH timing table, and sliders that move under the keyboard and the
//     pointer.
// With --site DIR it checks a write-up built already (tools/writeup's out/writeup) as in 2.
// Saves a screenshot of each page in --out.
//
// node generated_page_test.js --website EXE --pathtracer EXE --bench EXE --out DIR
//                             [--starter-pathtracer EXE] [--site DIR] [--chromium EXE]
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');

function args() {
  const a = { chromium: '/usr/bin/chromium' };
  for (let i = 2; i < process.argv.length; i += 2) a[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
  const need = a.site ? ['out'] : ['website', 'pathtracer', 'bench', 'out'];
  for (const n of need) {
    if (!a[n]) throw new Error(`missing --${n}`);
  }
  return a;
}

function fail(message) {
  console.error(`FAILED: ${message}`);
  process.exit(1);
}

function run(exe, argv) {
  const r = spawnSync(exe, argv, { encoding: 'utf8' });
  process.stderr.write(r.stderr || '');
  if (r.status !== 0) fail(`${path.basename(exe)} ${argv[0]} exited with ${r.status}`);
}

/// The small page of step 1, built with the given pathtracer.
function buildSmallPage(a, out) {
  const src = path.join(out, 'small-src');
  fs.rmSync(src, { recursive: true, force: true });
  fs.mkdirSync(src, { recursive: true });
  fs.writeFileSync(path.join(src, 'convergence.csv'),
    'strategy,samples,seconds,relMSE\n' +
    'uniform,1,0.05,0.8\nuniform,4,0.2,0.21\nuniform,16,0.8,0.052\nuniform,64,3.2,0.013\n' +
    'adaptive,1,0.05,0.6\nadaptive,4,0.15,0.11\nadaptive,16,0.5,0.02\nadaptive,64,1.7,0.004\n');
  fs.writeFileSync(path.join(src, 'writeup.md'), [
    '# Browser test write-up',
    '',
    'Renders at $s = 1, l = 4$ and $s = 4$:',
    '',
    '$$L_o = \\int_{H^2} f_r\\, L_i \\cos\\theta \\, d\\omega$$',
    '',
    '```grid columns=2 flags="-t 0 -r 64 48 -l 4 -m 1"',
    'scene=cornell_spheres.dae flags="-s 1" caption="$s = 1$"',
    'scene=cornell_spheres.dae flags="-s 4" caption="$s = 4$"',
    '```',
    '',
    '```plot csv=convergence.csv title="Error against time"',
    '```',
    '',
  ].join('\n'));
  run(a.website, ['build', path.join(src, 'writeup.md'), '-o', path.join(out, 'small'),
    '--pathtracer', a.pathtracer, '--bench', a.bench, '--cache', path.join(out, 'cache')]);
  return path.join(out, 'small');
}

/// The starting write-up of step 2.
function buildStarter(a, out) {
  const src = path.join(out, 'starter-src');
  run(a.website, ['init', src, '--force']);
  const renderer = a['starter-pathtracer'] || a.pathtracer;
  run(a.website, ['build', path.join(src, 'writeup.md'), '-o', path.join(out, 'starter'),
    '--pathtracer', renderer, '--bench', a['starter-bench'] || a.bench,
    '--cache', path.join(out, 'cache')]);
  return path.join(out, 'starter');
}

/// Opens `site`/index.html; calls `check(page, problems)`; saves a screenshot as `shot`.
async function inspect(context, site, shot, check) {
  const problems = [];
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`failed to load ${r.url()}: ${r.failure().errorText}`));
  await page.goto('file://' + path.join(path.resolve(site), 'index.html'), { waitUntil: 'load' });
  await page.evaluate(() => document.fonts.ready);
  await check(page, problems);
  await page.screenshot({ path: shot, fullPage: true });
  await page.close();
  return problems.map((p) => `${path.basename(site)}: ${p}`);
}

async function checkSmallPage(page, problems) {
  const facts = await page.evaluate(() => ({
    images: [...document.images].map((i) => ({ src: i.getAttribute('src'), complete: i.complete, width: i.naturalWidth })),
    katex: document.querySelectorAll('.katex').length,
    katexDisplay: document.querySelectorAll('.katex-display').length,
    katexWidths: [...document.querySelectorAll('.katex-html')].map((e) => e.getBoundingClientRect().width),
    rawDollar: document.body.innerText.includes('$s = 1'),
    fontLoaded: document.fonts.check('16px KaTeX_Main') &&
      [...document.fonts].some((f) => f.family.replace(/"/g, '') === 'KaTeX_Main' && f.status === 'loaded'),
  }));
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
}

/// Which of the slider's two images the reader sees at `fraction` of its width.
async function seenAt(page, slider, fraction) {
  return slider.evaluate((s, f) => {
    const view = s.querySelector('.slider-view');
    view.scrollIntoView({ block: 'center' });
    const box = view.getBoundingClientRect();
    const hit = document.elementFromPoint(box.left + f * box.width, box.top + box.height / 2);
    return hit && hit.classList.contains('slider-over') ? 'left' : hit && hit.classList.contains('slider-under') ? 'right' : String(hit && hit.className);
  }, fraction);
}

async function checkSlider(page, slider, n, problems) {
  const where = `slider ${n}`;
  const expect = async (fraction, side, after) => {
    const seen = await seenAt(page, slider, fraction);
    if (seen !== side) problems.push(`${where}: after ${after}, the reader sees ${seen} at ${Math.round(fraction * 100)}% of its width, not the ${side} render`);
  };
  await expect(0.25, 'left', 'loading');
  await expect(0.75, 'right', 'loading');
  const range = slider.locator('.slider-range');
  await range.focus();
  await page.keyboard.press('End');   // the split all the way right: only the left render shows
  await expect(0.9, 'left', 'pressing End on the range');
  await page.keyboard.press('Home');  // all the way left: only the right render
  await expect(0.1, 'right', 'pressing Home on the range');
  // Drag with the pointer from 20% to 70% of the picture.
  const box = await slider.locator('.slider-view').boundingBox();
  await page.mouse.move(box.x + 0.2 * box.width, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + 0.7 * box.width, box.y + box.height / 2, { steps: 5 });
  await page.mouse.up();
  await expect(0.6, 'left', 'dragging the split to 70%');
  await expect(0.8, 'right', 'dragging the split to 70%');
  const value = Number(await range.inputValue());
  if (!(Math.abs(value - 70) < 2)) problems.push(`${where}: after the drag the range reads ${value}, not about 70`);
}

async function checkWriteup(page, problems) {
  const facts = await page.evaluate(() => {
    const width = (e) => e.getBoundingClientRect().width;
    const compared = 'figure.cell img, figure.render img, .slider img, .pane img, img.crop';
    return {
      draft: !!document.querySelector('.draft'),
      headings: [...document.querySelectorAll('h2')].map((h) => h.textContent),
      images: [...document.images].map((i) => ({
        src: i.getAttribute('src'), complete: i.complete, natural: i.naturalWidth,
        stated: Number(i.getAttribute('width')), shown: width(i),
        compared: i.matches(compared), crop: i.classList.contains('crop'),
      })),
      plot: [...document.querySelectorAll('figure.plot img')].map((i) => ({
        src: i.getAttribute('src'), complete: i.complete, natural: i.naturalWidth,
        stated: Number(i.getAttribute('width')), shown: width(i),
      })),
      timeToTarget: document.querySelectorAll('table.time-to-target tbody tr').length,
      timingRows: document.querySelectorAll('figure.timing tbody tr').length,
      zoomBoxes: document.querySelectorAll('.zoom-box').length,
      keys: [...document.querySelectorAll('.rate-key')].map((k) => ({
        shown: width(k), image: width(k.parentElement.querySelector('img')),
        ramp: getComputedStyle(k.querySelector('.rate-key-bar')).backgroundImage,
        labels: k.querySelector('.rate-key-labels').textContent,
      })),
      sliders: document.querySelectorAll('.slider').length,
      renderTime: (document.querySelector('.render-time') || {}).textContent || '',
      rawDollar: /\$[a-z]+ = /.test(document.body.innerText),
    };
  });
  console.log(JSON.stringify({ ...facts, images: facts.images.length }, null, 1));
  const minimum = facts.draft ? 160 : 320;
  for (let part = 1; part <= 5; ++part) {
    if (!facts.headings.some((h) => h.startsWith(`Part ${part}:`))) problems.push(`no section for Part ${part}`);
  }
  if (facts.images.length < 40) problems.push(`expected at least 40 images, found ${facts.images.length}`);
  for (const img of facts.images) {
    if (!img.complete || !(img.natural > 0)) {
      problems.push(`image ${img.src} did not load`);
      continue;
    }
    if (img.stated && img.natural !== img.stated) problems.push(`image ${img.src} says it is ${img.stated} wide but is ${img.natural}`);
    if (img.stated && img.shown + 0.5 < img.stated) problems.push(`image ${img.src} is ${img.stated} pixels wide but shown ${img.shown.toFixed(1)} wide`);
    if (img.compared && img.natural < minimum) problems.push(`image ${img.src}, compared by eye, is only ${img.natural} pixels wide (at least ${minimum})`);
  }
  if (facts.plot.length !== 1) problems.push(`expected the error-against-time plot, found ${facts.plot.length} plots`);
  for (const p of facts.plot) {
    if (!/\.svg$/.test(p.src) || !p.complete || !(p.natural > 0)) problems.push(`the plot ${p.src} did not load`);
    if (!(p.stated >= 600) || p.shown + 0.5 < p.stated) problems.push(`the plot is shown ${p.shown} wide, not its ${p.stated}`);
  }
  if (facts.timeToTarget < 2) problems.push(`the plot's time-to-target table has ${facts.timeToTarget} rows`);
  if (facts.timingRows < 2) problems.push(`the BVH timing table has ${facts.timingRows} rows`);
  const crops = facts.images.filter((i) => i.crop).length;
  // Each crop's region is outlined on its render; a slider's two crops share one outline.
  if (crops < 8 || facts.zoomBoxes + facts.sliders < crops) problems.push(`expected zoomed crops with their regions outlined, found ${crops} crops and ${facts.zoomBoxes} outlines`);
  if (facts.keys.length !== 1) problems.push(`expected the sample-rate image's colour key, found ${facts.keys.length}`);
  for (const k of facts.keys) {
    if (!(k.shown >= minimum) || Math.abs(k.shown - k.image) > 1) problems.push(`the colour key is ${k.shown} wide beside a ${k.image}-wide image`);
    if (!/linear-gradient\(to right, rgb\(0, 0, 255\), rgb\(0, 255, 0\), rgb\(255, 0, 0\)\)/.test(k.ramp)) problems.push(`the colour key's ramp is ${k.ramp}`);
    if (!/^0.*1,024$/.test(k.labels)) problems.push(`the colour key reads '${k.labels}', not 0 to 1,024`);
  }
  if (facts.sliders < 1) problems.push('no slider on the page');
  const sliders = page.locator('.slider');
  for (let i = 0; i < facts.sliders; ++i) await checkSlider(page, sliders.nth(i), i + 1, problems);
  if (!/took .* in all/.test(facts.renderTime)) problems.push(`the page does not say how long it took to render ('${facts.renderTime}')`);
  if (facts.rawDollar) problems.push('raw TeX ($...$) is visible on the page');
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
  fs.mkdirSync(out, { recursive: true });
  const pages = a.site ? [] : [['small', buildSmallPage(a, out), checkSmallPage]];
  pages.push(['writeup', a.site ? path.resolve(a.site) : buildStarter(a, out), checkWriteup]);

  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'pt-website-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: a.chromium,
    headless: true,
    viewport: { width: 1280, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const problems = [];
  try {
    for (const [name, site, check] of pages) {
      problems.push(...await inspect(context, site, path.join(out, `${name}-screenshot.png`), check));
    }
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
  if (problems.length) fail(problems.join('\n'));
  console.log(`passed; screenshots in ${out}`);
}

main().catch((e) => fail(e.stack || String(e)));
