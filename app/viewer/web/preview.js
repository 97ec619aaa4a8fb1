// The scene preview in plain WebGL: its triangles, spheres, lights and the render camera, with an
// orbit/pan/zoom camera whose projection is the path tracer's (horizontal field of view fixed,
// the vertical one from the aspect), so "use this view" renders what the preview shows.
'use strict';

const V = {
  sub: (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]],
  add: (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]],
  scale: (a, s) => [a[0] * s, a[1] * s, a[2] * s],
  dot: (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2],
  cross: (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]],
  len: (a) => Math.hypot(a[0], a[1], a[2]),
  norm: (a) => { const l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; },
  // Rodrigues' rotation of v about the unit axis k by angle t.
  rotate: (v, k, t) => {
    const c = Math.cos(t), s = Math.sin(t), kv = V.cross(k, v), kd = V.dot(k, v) * (1 - c);
    return [v[0] * c + kv[0] * s + k[0] * kd, v[1] * c + kv[1] * s + k[1] * kd, v[2] * c + kv[2] * s + k[2] * kd];
  },
};

function lookAt(eye, target, up) {
  const z = V.norm(V.sub(eye, target)), x = V.norm(V.cross(up, z)), y = V.cross(z, x);
  return [x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
    -V.dot(x, eye), -V.dot(y, eye), -V.dot(z, eye), 1];
}

function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
  return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0];
}

function multiply(a, b) {
  const o = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c) for (let r = 0; r < 4; ++r) for (let k = 0; k < 4; ++k) o[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return o;
}

const SURFACE_VS = `attribute vec3 p; attribute vec3 n; attribute vec3 c; uniform mat4 mvp; uniform vec3 eye;
varying vec3 vc; void main() { gl_Position = mvp * vec4(p, 1.0);
float l = abs(dot(normalize(n), normalize(eye - p))); vc = c * (0.3 + 0.7 * l); }`;
const SURFACE_FS = `precision mediump float; varying vec3 vc; uniform float alpha; void main() { gl_FragColor = vec4(vc, alpha); }`;
const LINE_VS = `attribute vec3 p; attribute vec3 c; uniform mat4 mvp; varying vec3 vc; void main() { gl_Position = mvp * vec4(p, 1.0); vc = c; }`;
const LINE_FS = `precision mediump float; varying vec3 vc; void main() { gl_FragColor = vec4(vc, 1.0); }`;

class Preview {
  constructor(canvas) {
    this.canvas = canvas;
    const gl = canvas.getContext('webgl', { antialias: true, preserveDrawingBuffer: true });
    if (!gl) throw new Error('this browser has no WebGL');
    this.gl = gl;
    this.surface = this.program(SURFACE_VS, SURFACE_FS);
    this.lineProgram = this.program(LINE_VS, LINE_FS);
    this.meshes = {};   // name -> {buffer, count} of surfaces (p, n, c interleaved)
    this.lines = {};    // name -> {buffer, count} of line segments (p, c interleaved)
    this.eye = [0, 0, 5]; this.target = [0, 0, 0]; this.up = [0, 1, 0]; this.hfov = 45;
    this.installControls();
  }

  program(vs, fs) {
    const gl = this.gl;
    const make = (type, src) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, src); gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
      return s;
    };
    const p = gl.createProgram();
    gl.attachShader(p, make(gl.VERTEX_SHADER, vs)); gl.attachShader(p, make(gl.FRAGMENT_SHADER, fs));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    return p;
  }

  upload(floats) {
    const gl = this.gl, b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(floats), gl.STATIC_DRAW);
    return b;
  }

  setMesh(name, floats) { this.meshes[name] = floats.length ? { buffer: this.upload(floats), count: floats.length / 9 } : null; }
  setLines(name, floats) { this.lines[name] = floats.length ? { buffer: this.upload(floats), count: floats.length / 6 } : null; }

  /// The scene's triangles and spheres, coloured by material (emitters light yellow), its lights
  /// in yellow and the render camera's frustum in cyan.
  setScene(scene) {
    this.scene = scene;
    const pos = scene.positions, tri = scene.triangles, mats = scene.materials;
    const colour = (m) => {
      const mat = mats[m];
      if (!mat) return [0.7, 0.7, 0.7];
      if (mat.emission.some((e) => e > 0)) return [1, 0.95, 0.6];
      if (mat.kind === 'mirror') return [0.75, 0.85, 0.95];
      if (mat.kind === 'glass') return [0.6, 0.9, 0.85];
      return mat.albedo.map((a) => Math.min(1, 0.15 + a));
    };
    const f = [];
    const corner = (i) => [pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]];
    for (let t = 0; t < tri.length / 3; ++t) {
      const a = corner(tri[3 * t]), b = corner(tri[3 * t + 1]), c = corner(tri[3 * t + 2]);
      const n = V.norm(V.cross(V.sub(b, a), V.sub(c, a))), col = colour(scene.triangle_materials[t]);
      for (const p of [a, b, c]) f.push(...p, ...n, ...col);
    }
    for (const s of scene.spheres) this.sphereTriangles(s.center, s.radius, colour(s.material), f);
    this.setMesh('scene', f);
    const l = [];
    const yellow = [1, 0.85, 0.1];
    for (const light of scene.lights) {
      const p = light.position;
      if (light.kind === 'area') {
        const u = V.scale(light.edge_u, 0.5), v = V.scale(light.edge_v, 0.5);
        const c = [V.sub(V.sub(p, u), v), V.sub(V.add(p, u), v), V.add(V.add(p, u), v), V.add(V.sub(p, u), v)];
        for (let i = 0; i < 4; ++i) l.push(...c[i], ...yellow, ...c[(i + 1) % 4], ...yellow);
        l.push(...p, ...yellow, ...V.add(p, V.scale(V.norm(light.direction), 0.3 * V.len(light.edge_u))), ...yellow);
      } else {
        const r = 0.03 * this.sceneSize();
        for (const axis of [[r, 0, 0], [0, r, 0], [0, 0, r]]) l.push(...V.sub(p, axis), ...yellow, ...V.add(p, axis), ...yellow);
      }
    }
    this.setLines('lights', l);
    this.setRenderCamera(scene.camera, scene.width / scene.height);
  }

  sceneSize() {
    const b = this.scene.bounds;
    return V.len(V.sub(b[1], b[0])) || 1;
  }

  sphereTriangles(c, r, col, out) {
    const rings = 16, segs = 24;
    const at = (i, j) => {
      const th = Math.PI * i / rings, ph = 2 * Math.PI * j / segs;
      return [Math.sin(th) * Math.cos(ph), Math.cos(th), Math.sin(th) * Math.sin(ph)];
    };
    for (let i = 0; i < rings; ++i) for (let j = 0; j < segs; ++j) {
      const q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
      for (const k of [0, 1, 2, 0, 2, 3]) out.push(...V.add(c, V.scale(q[k], r)), ...q[k], ...col);
    }
  }

  setRenderCamera(cam, aspect) {
    const d = 0.15 * this.sceneSize(), cyan = [0.2, 0.9, 1];
    const fwd = V.norm(V.sub(cam.target, cam.eye)), right = V.norm(V.cross(fwd, cam.up)), up = V.cross(right, fwd);
    const tx = Math.tan(cam.hfov * Math.PI / 360), ty = tx / aspect;
    const corners = [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([sx, sy]) =>
      V.add(cam.eye, V.scale(V.add(fwd, V.add(V.scale(right, sx * tx), V.scale(up, sy * ty))), d)));
    const l = [];
    for (let i = 0; i < 4; ++i) l.push(...cam.eye, ...cyan, ...corners[i], ...cyan, ...corners[i], ...cyan, ...corners[(i + 1) % 4], ...cyan);
    this.setLines('camera', l);
  }

  setView(cam) {
    this.eye = cam.eye.slice(); this.target = cam.target.slice(); this.up = V.norm(cam.up); this.hfov = cam.hfov;
    this.draw();
  }

  view() { return { eye: this.eye.slice(), target: this.target.slice(), up: this.up.slice(), hfov: this.hfov }; }

  matrices() {
    const aspect = this.canvas.width / this.canvas.height;
    const dist = V.len(V.sub(this.eye, this.target));
    const fovy = 2 * Math.atan(Math.tan(this.hfov * Math.PI / 360) / aspect);
    const size = this.scene ? this.sceneSize() : 10;
    return multiply(perspective(fovy, aspect, Math.max(1e-4, dist * 0.01), dist + 4 * size), lookAt(this.eye, this.target, this.up));
  }

  /// The world-space ray through canvas point (x, y), as the path tracer's pinhole makes it.
  ray(x, y) {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    const sx = 2 * (x / w) - 1, sy = 1 - 2 * (y / h);
    const fwd = V.norm(V.sub(this.target, this.eye)), right = V.norm(V.cross(fwd, this.up)), up = V.cross(right, fwd);
    const tx = Math.tan(this.hfov * Math.PI / 360), ty = tx * this.canvas.height / this.canvas.width;
    return { origin: this.eye.slice(), direction: V.norm(V.add(fwd, V.add(V.scale(right, sx * tx), V.scale(up, sy * ty)))) };
  }

  draw() {
    const gl = this.gl, mvp = this.matrices();
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(0.12, 0.12, 0.14, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.useProgram(this.surface);
    gl.uniformMatrix4fv(gl.getUniformLocation(this.surface, 'mvp'), false, mvp);
    gl.uniform3fv(gl.getUniformLocation(this.surface, 'eye'), this.eye);
    gl.uniform1f(gl.getUniformLocation(this.surface, 'alpha'), 1);
    for (const name of ['scene', 'highlight']) {
      const m = this.meshes[name];
      if (!m) continue;
      if (name === 'highlight') { gl.enable(gl.POLYGON_OFFSET_FILL); gl.polygonOffset(-1, -1); }
      this.bind(this.surface, m.buffer, [['p', 3], ['n', 3], ['c', 3]]);
      gl.drawArrays(gl.TRIANGLES, 0, m.count);
      gl.disable(gl.POLYGON_OFFSET_FILL);
    }
    gl.useProgram(this.lineProgram);
    gl.uniformMatrix4fv(gl.getUniformLocation(this.lineProgram, 'mvp'), false, mvp);
    for (const name of Object.keys(this.lines)) {
      const l = this.lines[name];
      if (!l) continue;
      // Overlays (boxes, rays) are drawn over the surfaces, so a box inside a wall still shows.
      if (name !== 'lights' && name !== 'camera') gl.disable(gl.DEPTH_TEST); else gl.enable(gl.DEPTH_TEST);
      this.bind(this.lineProgram, l.buffer, [['p', 3], ['c', 3]]);
      gl.drawArrays(gl.LINES, 0, l.count);
    }
  }

  bind(program, buffer, attributes) {
    const gl = this.gl, stride = attributes.reduce((s, [, n]) => s + n, 0) * 4;
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    let offset = 0;
    for (const [name, n] of attributes) {
      const loc = gl.getAttribLocation(program, name);
      if (loc >= 0) { gl.enableVertexAttribArray(loc); gl.vertexAttribPointer(loc, n, gl.FLOAT, false, stride, offset); }
      offset += n * 4;
    }
  }

  installControls() {
    const c = this.canvas;
    let last = null, button = 0, moved = false;
    c.addEventListener('contextmenu', (e) => e.preventDefault());
    c.addEventListener('mousedown', (e) => { last = [e.clientX, e.clientY]; button = e.button; moved = false; });
    window.addEventListener('mouseup', (e) => {
      if (last && !moved && this.onClick) {
        const r = c.getBoundingClientRect();
        this.onClick(e.clientX - r.left, e.clientY - r.top);
      }
      last = null;
    });
    window.addEventListener('mousemove', (e) => {
      if (!last) return;
      const dx = e.clientX - last[0], dy = e.clientY - last[1];
      if (Math.abs(dx) + Math.abs(dy) > 2) moved = true;
      if (!moved) return;
      last = [e.clientX, e.clientY];
      if (button === 2 || e.shiftKey) this.pan(dx, dy); else this.orbit(dx, dy);
    });
    c.addEventListener('wheel', (e) => { e.preventDefault(); this.zoom(Math.exp(e.deltaY * 0.001)); }, { passive: false });
  }

  orbit(dx, dy) {
    let offset = V.sub(this.eye, this.target);
    offset = V.rotate(offset, this.up, -dx * 0.008);
    const right = V.norm(V.cross(this.up, offset));
    const turned = V.rotate(offset, right, -dy * 0.008);
    // Stop short of the poles, where "up" would no longer say which way is up.
    if (Math.abs(V.dot(V.norm(turned), this.up)) < 0.98) offset = turned;
    this.eye = V.add(this.target, offset);
    this.draw();
  }

  pan(dx, dy) {
    const dist = V.len(V.sub(this.eye, this.target));
    const fwd = V.norm(V.sub(this.target, this.eye)), right = V.norm(V.cross(fwd, this.up)), up = V.cross(right, fwd);
    const k = dist * 2 * Math.tan(this.hfov * Math.PI / 360) / this.canvas.clientWidth;
    const move = V.add(V.scale(right, -dx * k), V.scale(up, dy * k));
    this.eye = V.add(this.eye, move); this.target = V.add(this.target, move);
    this.draw();
  }

  zoom(factor) {
    this.eye = V.add(this.target, V.scale(V.sub(this.eye, this.target), factor));
    this.draw();
  }
}

window.Preview = Preview;
window.V = V;
