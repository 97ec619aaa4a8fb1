// The viewer's page: the settings as pathtracer flags, the progressive render (polled), the cell
// and pixel tools, the BVH walk and the terminal's lines. Every request goes to the server that
// served the page, which checks its token (the cookie the first request set).
'use strict';

const $ = (id) => document.getElementById(id);
const state = {
  camera: null,        // --camera text from "use this view", or null: the scene's camera
  cell: null,          // [x, y, w, h] of the last cell render
  scene: null,
  status: null,
  logNext: 0,
  shownDone: -1,
  shownJob: '',
  fetching: false,
  bvh: null,
  node: 0,
  level: 0,
  pixel: null,
  sizeGiven: false,    // the viewer's command line named the image's size (-r)
  unreachable: false,  // the last status request went unanswered
  lastImageAt: 0,      // when the last image was asked for (performance.now())
  stubs: new Map(),    // "part N: NAME" -> FILE:LINE, for each stub the student's code ran
  times: { requested: 0, firstImage: 0, imagesDrawn: 0 },
};
window.viewerState = state;  // read by the browser test

async function api(path, body) {
  const options = body === undefined ? {} : { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) };
  let r;
  try {
    r = await fetch(path, options);
  } catch (e) {
    // No reply at all: the server's process ended while it answered (a crash in a part ends it;
    // the viewer starts it again and says so above), or the viewer was stopped.
    throw new Error(`${path.split('?')[0]}: no reply from the viewer (${e.message}); if your code crashed, ` +
      'the red note above and the terminal say so, and the viewer starts again: try again');
  }
  const type = r.headers.get('Content-Type') || '';
  const data = type.includes('json') ? await r.json() : await r.arrayBuffer();
  if (!r.ok) throw new Error((data && data.error) || `${path}: HTTP ${r.status}`);
  return data;
}

function showError(message) {
  const e = $('error');
  e.hidden = !message;
  e.textContent = message || '';
}

// ---- settings as flags --------------------------------------------------------------------

/// The page's settings as pathtracer flags; withoutSize leaves -r out (the scene's own size).
function flags(withCell, withoutSize) {
  const f = ['-s', $('s').value, '-l', $('l').value, '-m', $('m').value];
  if ($('H').checked) f.push('-H');
  if ($('adaptive').checked) f.push('-a', $('batch').value, $('tol').value);
  if (!withoutSize) f.push('-r', $('w').value, $('h').value);
  if ($('seed').value !== '0') f.push('--seed', $('seed').value);
  if ($('normals').checked) f.push('--normals');
  if (state.camera) f.push('--camera', state.camera);
  const extra = $('extra').value.trim();
  if (extra) f.push(...extra.split(/\s+/));
  if (withCell && state.cell) f.push('-p', ...state.cell.map(String));
  return f;
}

function applyFlags(list) {
  for (let i = 0; i < list.length; ++i) {
    const f = list[i];
    if (f === '-s' || f === '-l' || f === '-m') $(f[1]).value = list[++i];
    else if (f === '-H') $('H').checked = true;
    else if (f === '-a') { $('adaptive').checked = true; $('batch').value = list[++i]; $('tol').value = list[++i]; }
    else if (f === '-r') { $('w').value = list[++i]; $('h').value = list[++i]; state.sizeGiven = true; }
    else if (f === '--seed') $('seed').value = list[++i];
    else if (f === '--camera') state.camera = list[++i];
  }
}

// ---- render ---------------------------------------------------------------------------------

async function render(withCell, withoutSize) {
  showError('');
  if (!withCell) state.cell = null;
  try {
    state.times.requested = performance.now();
    state.times.firstImage = 0;
    // The reply comes when the first tile's pixels are done (or a second has passed).
    const s = await api('/api/render', { flags: flags(withCell, withoutSize) });
    state.shownDone = -1;
    onStatus(s);
    pollSoon();
  } catch (e) {
    showError(e.message);
  }
}

function drawRgba(buffer) {
  const head = new DataView(buffer, 0, 8);
  const w = head.getUint32(0, true), h = head.getUint32(4, true);
  const canvas = $('image');
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(buffer, 8, w * h * 4), w, h), 0, 0);
}

async function refreshImage(s) {
  if (state.fetching) return;
  state.fetching = true;
  try {
    const rate = $('show-rate').checked && s.adaptive && s.state === 'done';
    drawRgba(await api(rate ? '/api/image?kind=rate' : '/api/image'));
    state.shownDone = s.done;
    state.times.imagesDrawn += 1;
    // The first image: a tile's worth of pixels (32x32) or the whole region, on the canvas.
    if (!state.times.firstImage && s.done >= Math.min(1024, s.total)) state.times.firstImage = performance.now();
  } catch (e) {
    showError(e.message);
  } finally {
    state.fetching = false;
  }
}

function onStatus(s) {
  state.status = s;
  if (s.crash) { $('crash').hidden = false; $('crash').textContent = s.crash; }
  if (s.load_error) showError(s.load_error);
  if (s.log && s.log.length) {
    const log = $('log');
    log.textContent += s.log.join('\n') + '\n';
    log.scrollTop = log.scrollHeight;
    noteStubs(s.log);
  }
  if (s.log_next !== undefined) state.logNext = s.log_next;
  if (s.command) $('command').textContent = s.command;
  if (s.state === 'error') showError(s.error);
  const job = `${s.command}|${s.region}`;
  if (s.total) $('progress').style.width = `${Math.round(480 * s.done / s.total)}px`;
  const finished = s.state === 'done' || s.state === 'cancelled' || s.state === 'error';
  // While it renders, after the first image, a new image at most every half second: each is the
  // whole RGBA image, and the browser's decoding and drawing take the cores the render needs.
  const recent = s.state === 'rendering' && state.times.firstImage && performance.now() - state.lastImageAt < 500;
  if (s.done !== undefined && !recent && (s.done !== state.shownDone || job !== state.shownJob || finished && state.lastState === 'rendering')) {
    state.lastImageAt = performance.now();
    state.shownJob = job;
    refreshImage(s);
  }
  state.lastState = s.state;
  let text = '';
  if (s.state === 'rendering') text = `rendering: ${s.done} of ${s.total} pixels, ${s.elapsed.toFixed(2)} s`;
  if (s.state === 'done') {
    text = s.summary;
    const c = s.counts;
    if (c) text += `\nintersection tests: ${c.primitive_tests_per_ray.toFixed(2)} primitive tests per camera ray ` +
      `(Part 2's tree, ${c.camera_rays} camera rays through pixel centres, ${c.hits} hit; ${c.primitives} primitives in the scene)`;
    if (s.first_pixel_seconds >= 0) text += `\nfirst pixel after ${(1000 * s.first_pixel_seconds).toFixed(0)} ms`;
  }
  if (s.state === 'cancelled') text = 'stopped';
  $('summary').textContent = text;
}

// ---- what is not written yet ------------------------------------------------------------------

/// The stubs' lines ("part 3 not implemented: NAME at FILE:LINE (see ...)"), said in each panel
/// they matter to, so a black image or an empty table says why where the student looks.
function noteStubs(lines) {
  let added = false;
  for (const line of lines) {
    const m = /^part (\d) not implemented: (.+) at (\S+)/.exec(line);
    if (!m || state.stubs.has(`${m[1]}|${m[2]}`)) continue;
    state.stubs.set(`${m[1]}|${m[2]}`, { part: m[1], name: m[2], where: m[3] });
    added = true;
  }
  if (!added) return;
  for (const box of document.querySelectorAll('.stubs')) {
    const stubs = [...state.stubs.values()].filter((s) => box.dataset.parts.includes(s.part))
      .sort((a, b) => a.part - b.part);
    box.hidden = !stubs.length;
    box.textContent = 'Not written yet (each returns a neutral value, so what depends on it is black, empty or fails):\n' +
      stubs.map((s) => `  part ${s.part}: ${s.name} in ${s.where}`).join('\n');
  }
}

let pollTimer = null;
async function poll() {
  clearTimeout(pollTimer);
  pollTimer = null;
  try {
    const s = await api(`/api/status?log=${state.logNext}`);
    if (state.unreachable) showError('');
    state.unreachable = false;
    onStatus(s);
  } catch (e) {
    state.unreachable = true;
    showError('the viewer does not answer: is it still running in its terminal?');
  }
  if (!pollTimer) pollTimer = setTimeout(poll, state.status && state.status.state === 'rendering' ? 100 : 400);
}

/// Asks for the status at once (a render just started), rather than at the next slow tick.
function pollSoon() {
  clearTimeout(pollTimer);
  pollTimer = setTimeout(poll, 30);
}

// ---- the render's mouse: a cell, or a pixel ------------------------------------------------

function imagePoint(e) {
  const c = $('image'), r = c.getBoundingClientRect();
  return [Math.floor((e.clientX - r.left) * c.width / r.width), Math.floor((e.clientY - r.top) * c.height / r.height)];
}

function installImageMouse() {
  const c = $('image'), box = $('drag');
  let start = null;
  c.addEventListener('mousedown', (e) => {
    if (document.querySelector('input[name=mouse]:checked').value === 'pixel') {
      const [x, y] = imagePoint(e);
      explainPixel(x, y);
      return;
    }
    start = imagePoint(e);
  });
  window.addEventListener('mousemove', (e) => {
    if (!start) return;
    const [x, y] = imagePoint(e), k = c.getBoundingClientRect().width / c.width;
    Object.assign(box.style, { display: 'block', left: `${Math.min(x, start[0]) * k}px`, top: `${Math.min(y, start[1]) * k}px`,
      width: `${Math.abs(x - start[0]) * k}px`, height: `${Math.abs(y - start[1]) * k}px` });
  });
  window.addEventListener('mouseup', (e) => {
    if (!start) return;
    const [x, y] = imagePoint(e);
    const clamp = (v, hi) => Math.max(0, Math.min(hi, v));
    const x0 = clamp(Math.min(x, start[0]), c.width - 1), y0 = clamp(Math.min(y, start[1]), c.height - 1);
    const x1 = clamp(Math.max(x, start[0]), c.width - 1), y1 = clamp(Math.max(y, start[1]), c.height - 1);
    start = null;
    box.style.display = 'none';
    if (x1 - x0 >= 1 && y1 - y0 >= 1) {
      state.cell = [x0, y0, x1 - x0 + 1, y1 - y0 + 1];
      render(true);
    }
  });
}

// ---- one pixel explained --------------------------------------------------------------------

const fmt = (v) => (v === null || v === undefined ? 'NaN' : Math.abs(v) >= 1000 || (v !== 0 && Math.abs(v) < 1e-3) ? v.toExponential(2) : v.toFixed(4));
const rgb = (c) => `(${c.map(fmt).join(', ')})`;
const swatch = (c) => {
  const s = (v) => Math.round(255 * Math.min(1, Math.max(0, v || 0) ** (1 / 2.2)));
  return `<span class="swatch" style="background: rgb(${s(c[0])},${s(c[1])},${s(c[2])})"></span>`;
};

async function explainPixel(x, y) {
  showError('');
  $('pixel-info').textContent = `pixel (${x}, ${y}): tracing...`;
  try {
    const p = await api('/api/pixel', { flags: flags(false), x, y });
    state.pixel = p;
    const bounces = p.samples.length ? p.samples[0].bounces.length : 0;
    $('pixel-info').innerHTML = `pixel (${x}, ${y}): value ${swatch(p.value)} ${rgb(p.value)}, variance of a sample ${rgb(p.variance)}, ` +
      `${p.samples_taken} samples (${p.samples_recorded} drawn), ${p.rays} rays` +
      (p.nonfinite_samples ? `, <b>${p.nonfinite_samples} samples NaN or infinite (counted as black)</b>` : '') +
      (p.normals_view ? ' (normals view: nothing emits, or --normals)' : '') +
      '<br>White: camera ray; orange: bounce rays; green: shadow ray that reached its light; red: shadow ray blocked; grey: a ray that hit nothing. Click a row to draw only that sample.';
    let head = '<tr><th>sample</th><th>radiance</th>';
    for (let k = 0; k < bounces; ++k) head += `<th>bounce ${k} added${k === 0 ? ' (emitted)' : k === 1 ? ' (direct)' : ''}</th>`;
    head += '<th>bounces add up</th><th>rays</th><th>shadow rays blocked</th></tr>';
    const rows = p.samples.map((s, i) => {
      const shadows = s.rays.filter((r) => r.kind === 'shadow');
      return `<tr data-i="${i}"><td>${i}</td><td>${swatch(s.radiance)} ${rgb(s.radiance)}</td>` +
        s.bounces.map((b) => `<td>${swatch(b)} ${rgb(b)}</td>`).join('') +
        `<td>${s.bounces_add_up === undefined ? '' : s.bounces_add_up ? 'yes' : '<b>no</b>'}</td><td>${s.rays.length}</td><td>${shadows.filter((r) => r.blocked).length} of ${shadows.length}</td></tr>`;
    });
    $('pixel-table').innerHTML = head + rows.join('');
    for (const tr of $('pixel-table').querySelectorAll('tr[data-i]'))
      tr.addEventListener('click', () => {
        for (const o of $('pixel-table').querySelectorAll('tr')) o.classList.remove('picked');
        tr.classList.add('picked');
        drawPaths(p, Number(tr.dataset.i));
      });
    drawPaths(p, -1);
  } catch (e) {
    $('pixel-info').textContent = '';
    showError(e.message);
  }
}

function drawPaths(p, only) {
  const size = preview.scene ? preview.sceneSize() : 10;
  const l = [];
  p.samples.forEach((s, i) => {
    if (only >= 0 && i !== only) return;
    let firstTrace = true;
    for (const r of s.rays) {
      if (!r.o || !r.d || r.o.includes(null) || r.d.includes(null)) continue;
      let end, colour;
      if (r.kind === 'shadow') {
        end = V.add(r.o, V.scale(r.d, r.tmax === null ? size : Math.min(r.tmax, 4 * size)));
        colour = r.blocked ? [1, 0.2, 0.2] : [0.2, 1, 0.3];
      } else {
        end = r.hit ? r.p : V.add(r.o, V.scale(r.d, size));
        colour = !r.hit ? [0.5, 0.5, 0.5] : firstTrace ? [1, 1, 1] : [1, 0.6, 0.1];
        firstTrace = false;
      }
      l.push(...r.o, ...colour, ...end, ...colour);
    }
  });
  preview.setLines('paths', l);
  preview.draw();
}

// ---- the BVH --------------------------------------------------------------------------------

function boxLines(i, colour, out) {
  const b = state.bvh.boxes.slice(6 * i, 6 * i + 6), lo = b.slice(0, 3), hi = b.slice(3);
  const c = (x, y, z) => [x ? hi[0] : lo[0], y ? hi[1] : lo[1], z ? hi[2] : lo[2]];
  const edges = [[0, 0, 0, 1, 0, 0], [0, 1, 0, 1, 1, 0], [0, 0, 1, 1, 0, 1], [0, 1, 1, 1, 1, 1],
    [0, 0, 0, 0, 1, 0], [1, 0, 0, 1, 1, 0], [0, 0, 1, 0, 1, 1], [1, 0, 1, 1, 1, 1],
    [0, 0, 0, 0, 0, 1], [1, 0, 0, 1, 0, 1], [0, 1, 0, 0, 1, 1], [1, 1, 0, 1, 1, 1]];
  for (const e of edges) out.push(...c(e[0], e[1], e[2]), ...colour, ...c(e[3], e[4], e[5]), ...colour);
}

function leafTriangles(nodes, out) {
  const b = state.bvh, sc = state.scene, pos = sc.positions, tri = sc.triangles, ntri = tri.length / 3;
  for (const i of nodes) {
    const first = b.first[i];
    if (first < 0) continue;
    for (let k = first; k < first + b.count[i]; ++k) {
      const prim = b.order[k];
      if (prim >= ntri) continue;  // a sphere: its box shows it
      const cs = [0, 1, 2].map((j) => { const v = tri[3 * prim + j]; return [pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]]; });
      const n = V.norm(V.cross(V.sub(cs[1], cs[0]), V.sub(cs[2], cs[0])));
      for (const p of cs) out.push(...p, ...n, 1, 0.45, 0.1);
    }
  }
}

/// Every primitive below node i (the leaves of its subtree), at most `limit` leaves.
function leavesBelow(i, limit) {
  const b = state.bvh, out = [], stack = [i];
  while (stack.length && out.length < limit) {
    const k = stack.pop();
    if (b.left[k] < 0) out.push(k); else stack.push(b.right[k], b.left[k]);
  }
  return out;
}

function showBvh() {
  const b = state.bvh;
  if (!b) return;
  const l = [], tris = [];
  let info;
  if ($('bvh-levels').checked) {
    const nodes = [];
    for (let i = 0; i < b.depth.length; ++i) if (b.depth[i] === state.level) nodes.push(i);
    for (const i of nodes) boxLines(i, b.left[i] < 0 ? [1, 0.5, 0.1] : [0.9, 0.9, 0.2], l);
    const prims = nodes.reduce((s, i) => s + b.primitives_below[i], 0);
    const cost = nodes.reduce((s, i) => s + b.sah_cost[i], 0);
    info = `level ${state.level} of ${b.stats.depth}: ${nodes.length} nodes (${nodes.filter((i) => b.left[i] < 0).length} leaves, orange), ` +
      `${prims} primitives below them, their SAH costs summing to ${cost.toFixed(2)}`;
  } else {
    const i = state.node;
    boxLines(i, [1, 1, 1], l);
    if (b.left[i] >= 0) { boxLines(b.left[i], [0.2, 1, 0.4], l); boxLines(b.right[i], [1, 0.3, 0.6], l); }
    // Its primitives in orange, when there are few enough to draw (a node near the root holds
    // most of the scene, and its box says as much).
    const leaves = leavesBelow(i, 2001);
    if (leaves.length <= 2000) leafTriangles(leaves, tris);
    const box = b.boxes.slice(6 * i, 6 * i + 6).map(fmt);
    info = `node ${i}${b.left[i] < 0 ? ' (leaf)' : ''}: depth ${b.depth[i]}, ${b.primitives_below[i]} primitives` +
      `${b.left[i] < 0 ? ` (order[${b.first[i]} .. ${b.first[i] + b.count[i]}))` : ''}, SAH cost ${b.sah_cost[i].toFixed(3)}` +
      ` (relative to its own box), box (${box.slice(0, 3).join(', ')}) .. (${box.slice(3).join(', ')})` +
      (b.left[i] >= 0 ? `\nleft child ${b.left[i]} (green): ${b.primitives_below[b.left[i]]} primitives, SAH ${b.sah_cost[b.left[i]].toFixed(3)}; ` +
        `right child ${b.right[i]} (pink): ${b.primitives_below[b.right[i]]} primitives, SAH ${b.sah_cost[b.right[i]].toFixed(3)}` : '');
  }
  const st = b.stats;
  $('bvh-info').textContent = `tree: ${st.split}, leaf size ${st.max_leaf_size}: ${st.nodes} nodes, ${st.leaves} leaves, depth ${st.depth}, ` +
    `SAH cost ${st.sah_cost.toFixed(2)}, built in ${st.build_ms.toFixed(1)} ms\n` + info + (state.pickText ? `\n${state.pickText}` : '');
  preview.setLines('bvh', l);
  preview.setMesh('highlight', tris);
  preview.draw();
  const leaf = b.left[state.node] < 0, levels = $('bvh-levels').checked;
  $('bvh-parent').disabled = levels || b.parent[state.node] < 0;
  $('bvh-left').disabled = levels || leaf;
  $('bvh-right').disabled = levels || leaf;
  $('bvh-up').disabled = !levels || state.level <= 0;
  $('bvh-down').disabled = !levels || state.level >= st.depth;
}

async function loadBvh() {
  showError('');
  try {
    state.bvh = await api('/api/bvh', { flags: flags(false) });
    state.node = 0;
    state.level = 0;
    showBvh();
  } catch (e) {
    showError(e.message);
  }
}

async function pick(x, y) {
  const ray = preview.ray(x, y);
  try {
    if (!state.bvh) await loadBvh();
    const p = await api('/api/pick', { flags: flags(false), origin: ray.origin, direction: ray.direction });
    const size = preview.sceneSize();
    const end = p.hit ? p.point : V.add(ray.origin, V.scale(ray.direction, size));
    preview.setLines('pick', [...ray.origin, 0.3, 0.8, 1, ...end, 0.3, 0.8, 1]);
    if (p.hit && p.leaf !== undefined) {
      state.node = p.leaf;
      $('bvh-levels').checked = false;
      state.pickText = `picked ray: hit primitive ${p.primitive} at t = ${fmt(p.t)}, in leaf ${p.leaf}`;
    } else {
      state.pickText = p.hit ? `picked ray: hit primitive ${p.primitive}, in no leaf (the tree does not hold it)` : 'picked ray: missed everything';
    }
    showBvh();
    preview.draw();
  } catch (e) {
    showError(e.message);
  }
}

// ---- sampling, seen -------------------------------------------------------------------------

function heat(canvas, values, rows, cols, top) {
  const g = canvas.getContext('2d'), cw = canvas.width / cols, ch = canvas.height / rows;
  for (let r = 0; r < rows; ++r) for (let c = 0; c < cols; ++c) {
    const v = values[r * cols + c];
    const t = v === null ? 0 : Math.min(1, v / (top || 1));
    // dark blue through teal to yellow
    g.fillStyle = `rgb(${Math.round(30 + 225 * t * t)},${Math.round(30 + 200 * t)},${Math.round(90 + 60 * (1 - t))})`;
    // row r holds cos(theta) in [-1 + 2r/rows, ...): drawn with cos = 1 at the top
    g.fillRect(c * cw, (rows - 1 - r) * ch, Math.ceil(cw), Math.ceil(ch));
  }
}

async function runSampling() {
  showError('');
  $('sampling-verdict').textContent = 'sampling...';
  try {
    const r = await api('/api/sampling', { name: $('sampler').value, samples: Number($('sampling-n').value) });
    state.sampling = r;
    const v = $('sampling-verdict');
    v.className = r.passes ? 'mono pass' : 'mono fail';
    v.textContent = `${r.says}: ${r.passes ? 'PASSES' : 'FAILS'} the chi-square test at the 1% level\n${r.summary}` +
      (r.nonfinite ? `\n${r.nonfinite} samples or densities were NaN or infinite` : '') +
      (r.pdf_integral !== null && Math.abs(r.pdf_integral - 1) > 2e-3 ? `\nthe density integrates to ${r.pdf_integral}, not 1` : '');
    const cells = r.cos_bins * r.phi_bins;
    const top = Math.max(...r.observed.slice(0, cells), ...r.expected.slice(0, cells).map((x) => x || 0));
    heat($('sampling-observed'), r.observed, r.cos_bins, r.phi_bins, top);
    heat($('sampling-expected'), r.expected, r.cos_bins, r.phi_bins, top);
    const c = $('sampling-points'), g = c.getContext('2d'), R = c.width / 2 - 4;
    g.fillStyle = '#111'; g.fillRect(0, 0, c.width, c.height);
    g.strokeStyle = '#666'; g.beginPath(); g.arc(c.width / 2, c.height / 2, R, 0, 2 * Math.PI); g.stroke();
    for (let i = 0; i < r.points.length; i += 3) {
      g.fillStyle = r.points[i + 2] < 0 ? '#f44' : '#8cf';
      g.fillRect(c.width / 2 + R * r.points[i] - 1, c.height / 2 - R * r.points[i + 1] - 1, 2, 2);
    }
  } catch (e) {
    $('sampling-verdict').textContent = '';
    showError(e.message);
  }
}

// ---- the scene and its camera ---------------------------------------------------------------

let preview;

async function loadScene() {
  const sc = await api('/api/scene', { flags: flags(false) });
  state.scene = sc;
  $('description').textContent = sc.description;
  const p = $('preview');
  p.width = sc.width; p.height = sc.height;
  preview.setScene(sc);
  preview.setView(sc.camera);
  $('camera-text').textContent = `render camera: --camera ${sc.camera.text}`;
}

function useThisView() {
  const v = preview.view(), n = (x) => Number(x.toPrecision(7));
  state.camera = [...v.eye, ...v.target, ...v.up, v.hfov].map(n).join(',');
  $('camera-text').textContent = `this view: --camera ${state.camera}`;
  loadScene().then(() => render(false)).catch((e) => showError(e.message));
}

async function start() {
  const s = await api(`/api/status?log=0`);
  $('scene-name').textContent = s.scene;
  if (s.initial_flags) applyFlags(s.initial_flags);
  onStatus(s);
  // The first render is asked for before anything else: the preview's WebGL and the scene's
  // triangles are made while it renders. Without -r on the command line it is the scene's own
  // size, which the preview then takes.
  const first = s.state === 'empty' ? null : render(false, !state.sizeGiven);
  preview = new Preview($('preview'));
  preview.onClick = (x, y) => { if ($('pick-mode').checked) pick(x, y); };
  installImageMouse();
  $('render').onclick = () => render(false);
  $('stop').onclick = () => api('/api/cancel', {}).then(onStatus).catch((e) => showError(e.message));
  $('reload').onclick = () => api('/api/reload', {}).then(loadScene).then(() => render(false)).catch((e) => showError(e.message));
  $('use-view').onclick = useThisView;
  $('reset-view').onclick = () => { state.camera = null; loadScene().catch((e) => showError(e.message)); };
  $('show-rate').onchange = () => state.status && refreshImage(state.status);
  $('bvh-load').onclick = loadBvh;
  $('sampling-run').onclick = runSampling;
  $('bvh-parent').onclick = () => { state.node = state.bvh.parent[state.node]; showBvh(); };
  $('bvh-left').onclick = () => { state.node = state.bvh.left[state.node]; showBvh(); };
  $('bvh-right').onclick = () => { state.node = state.bvh.right[state.node]; showBvh(); };
  $('bvh-levels').onchange = showBvh;
  $('bvh-up').onclick = () => { state.level -= 1; showBvh(); };
  $('bvh-down').onclick = () => { state.level += 1; showBvh(); };
  if (!first) { poll(); return; }  // the scene did not load: the message is shown
  await first;
  const r = state.status;
  if (r && r.width) { $('w').value = r.width; $('h').value = r.height; }
  poll();
  try {
    await loadScene();
  } catch (e) {
    showError(e.message);
  }
}

start().catch((e) => showError(e.message));
