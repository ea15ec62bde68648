// anim-view.js -- the script of an anim-view page (built into bin/anim-view,
// written inline into every page).  Reads the meta data (#stopmo-meta) and
// the deflated base64 arrays (#b0, #b1, ...), builds one three.js mesh per
// view, and draws all views with one renderer and one shared camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const meta = JSON.parse(document.getElementById('stopmo-meta').textContent);
const $ = (id) => document.getElementById(id);

// ---- decoding ----
function base64Bytes(id) {
  const s = $(id).textContent;
  if (Uint8Array.fromBase64) return Uint8Array.fromBase64(s);
  const bin = atob(s), u = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) u[i] = bin.charCodeAt(i);
  return u;
}
async function blob(ref) {
  const z = base64Bytes(ref.blob);
  const stream = new Blob([z]).stream().pipeThrough(new DecompressionStream('deflate'));
  const u = new Uint8Array(await new Response(stream).arrayBuffer());
  if (u.length !== ref.bytes) throw new Error(`data ${ref.blob}: ${u.length} bytes, expected ${ref.bytes}`);
  return u;
}
async function int32s(ref) { const u = await blob(ref); return new Int32Array(u.buffer, 0, u.length / 4); }

// positions: 16-bit quantised, differenced between frames, low bytes then
// high bytes per frame (libcommon/anim_pack.h)
async function positions(a) {
  const u = await blob(a.pos), m = a.nv * 3, Q = new Uint16Array(a.nframes * m);
  const prev = new Uint16Array(m);
  for (let k = 0; k < a.nframes; k++) {
    const b = k * 2 * m, q = k * m;
    for (let i = 0; i < m; i++) {
      prev[i] = (prev[i] + (u[b + i] | (u[b + m + i] << 8))) & 65535;
      Q[q + i] = prev[i];
    }
  }
  a.Q = Q;
  a.scale = [0, 1, 2].map((i) => (a.hi[i] - a.lo[i]) / 65535);
  return a;
}
function framePositions(a, k, out) {
  const m = a.nv * 3, Q = a.Q, base = Math.min(k, a.nframes - 1) * m;
  const l0 = a.lo[0], l1 = a.lo[1], l2 = a.lo[2], s0 = a.scale[0], s1 = a.scale[1], s2 = a.scale[2];
  for (let i = 0; i < m; i += 3) {
    out[i] = l0 + Q[base + i] * s0;
    out[i + 1] = l1 + Q[base + i + 1] * s1;
    out[i + 2] = l2 + Q[base + i + 2] * s2;
  }
  return out;
}
// area-weighted vertex normals of an indexed mesh
function vertexNormals(P, F, N) {
  N.fill(0);
  for (let f = 0; f < F.length; f += 3) {
    const a = 3 * F[f], b = 3 * F[f + 1], c = 3 * F[f + 2];
    const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
    const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    for (const v of [a, b, c]) { N[v] += nx; N[v + 1] += ny; N[v + 2] += nz; }
  }
  for (let i = 0; i < N.length; i += 3) {
    const l = Math.hypot(N[i], N[i + 1], N[i + 2]) || 1;
    N[i] /= l; N[i + 1] /= l; N[i + 2] /= l;
  }
  return N;
}
// expanded (one vertex per face corner) geometry, so faces can have their own colour
function cornerGeometry(nf) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(nf * 9), 3));
  g.setAttribute('normal', new THREE.BufferAttribute(new Float32Array(nf * 9), 3));
  g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(nf * 9), 3));
  return g;
}
function scatter(F, src, dst) {   // per-vertex vec3 -> per-corner vec3
  for (let c = 0; c < F.length; c++) {
    const v = 3 * F[c];
    dst[3 * c] = src[v]; dst[3 * c + 1] = src[v + 1]; dst[3 * c + 2] = src[v + 2];
  }
}

const PLAIN = [0.80, 0.78, 0.74];
const srgb = (x) => new THREE.Color().setRGB(x[0] / 255, x[1] / 255, x[2] / 255, THREE.SRGBColorSpace);

async function main() {
  const nframes = meta.nframes;
  const F = await int32s(meta.faces);
  for (const a of meta.anims) await positions(a);
  let labelRGB = null;
  if (meta.labels) labelRGB = await blob(meta.labels.rgb);
  const lut = meta.error ? meta.error.lut : null;

  // ---- renderer, camera, lights ----
  const stage = $('stage');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setScissorTest(true);
  stage.appendChild(renderer.domElement);
  stage.append($('legend'), $('foot'));   // placed over the views, clear of the pieces panel
  const bg = new THREE.Color(0x2b2f36);
  // the box of everything, for the camera
  const box = new THREE.Box3();
  for (const a of meta.anims) {
    box.expandByPoint(new THREE.Vector3(...a.lo));
    box.expandByPoint(new THREE.Vector3(...a.lo.map((l, i) => l + 65535 * a.scale[i])));
  }
  const centre = box.getCenter(new THREE.Vector3()), radius = box.getSize(new THREE.Vector3()).length() / 2 || 1;
  const camera = new THREE.PerspectiveCamera(30, 1, radius / 100, radius * 100);
  camera.up.set(...meta.camera.up);
  camera.position.copy(centre).add(new THREE.Vector3(...meta.camera.towards).multiplyScalar(radius * 3.6));
  camera.lookAt(centre);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();

  // ---- views ----
  const P = new Float32Array(meta.nv * 3), N = new Float32Array(meta.nv * 3), C = new Float32Array(meta.nv * 3);
  const views = meta.views.map((v) => {
    const scene = new THREE.Scene();
    scene.background = bg;
    scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 1.6));
    const g = cornerGeometry(meta.nf);
    const mat = new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.75, metalness: 0,
      side: THREE.DoubleSide, flatShading: false });
    const mesh = new THREE.Mesh(g, mat);
    scene.add(mesh);
    const col = g.attributes.color.array;
    if (v.colour === 'labels') {
      const c = new THREE.Color();
      for (let f = 0; f < meta.nf; f++)
        for (let j = 0; j < 3; j++) {
          const s = meta.labels.per_face ? 3 * f : 3 * F[3 * f + j];
          c.setRGB(labelRGB[s] / 255, labelRGB[s + 1] / 255, labelRGB[s + 2] / 255, THREE.SRGBColorSpace);
          col.set([c.r, c.g, c.b], 9 * f + 3 * j);
        }
    } else if (v.colour === 'plain') {
      const c = srgb(PLAIN.map((x) => x * 255));
      for (let i = 0; i < col.length; i += 3) { col[i] = c.r; col[i + 1] = c.g; col[i + 2] = c.b; }
    }
    const title = document.createElement('div');
    title.className = 'vtitle';
    title.textContent = v.title;
    stage.appendChild(title);
    return { ...v, scene, mesh, g, title, sun: null };
  });
  // the light that follows the camera: one directional light per scene, placed each draw
  for (const v of views) {
    v.sun = new THREE.DirectionalLight(0xffffff, 1.8);
    v.scene.add(v.sun, v.sun.target);
  }

  // ---- error colours ----
  const R = meta.error ? new Float32Array(meta.nv * 3) : null;
  const lutColours = lut ? Array.from({ length: 256 }, (_, i) => srgb(lut.slice(3 * i, 3 * i + 3))) : null;
  function errorColours(k, Pv, out) {
    framePositions(meta.anims[meta.error.ref], k, R);
    const top = meta.error.scale_max || 1;
    for (let i = 0; i < Pv.length; i += 3) {
      const d = Math.hypot(Pv[i] - R[i], Pv[i + 1] - R[i + 1], Pv[i + 2] - R[i + 2]);
      const c = lutColours[Math.min(255, Math.round(255 * d / top))];
      out[i] = c.r; out[i + 1] = c.g; out[i + 2] = c.b;
    }
  }
  if (meta.error) {
    const e = meta.error, lg = $('legend');
    const cv = document.createElement('canvas');
    cv.width = 256; cv.height = 1;
    const ctx = cv.getContext('2d'), img = ctx.createImageData(256, 1);
    for (let i = 0; i < 256; i++) img.data.set([lut[3 * i], lut[3 * i + 1], lut[3 * i + 2], 255], 4 * i);
    ctx.putImageData(img, 0, 0);
    const fmt = (x) => (x === 0 ? '0' : x.toPrecision(3));
    const mm = (x) => (e.mm_per_unit > 0 ? ` (${fmt(x * e.mm_per_unit)} mm)` : '');
    const head = document.createElement('div');
    head.textContent = `error: distance to ${e.ref_name}` +
      (e.mm_per_unit > 0 ? `; mm on a print ${e.print_height} mm tall along ${e.axis}` : '');
    lg.append(head, cv);
    const ticks = document.createElement('div');
    ticks.className = 'ticks';
    const clipped = e.scale_max < e.max;
    for (const t of [0, 0.5, 1]) {
      const s = document.createElement('span');
      s.textContent = (t === 1 && clipped ? '\u2265 ' : '') + fmt(t * e.scale_max) + (t ? mm(t * e.scale_max) : '');
      ticks.appendChild(s);
    }
    lg.appendChild(ticks);
    const sum = document.createElement('div');
    sum.textContent = `mean ${fmt(e.mean)}${mm(e.mean)}, max ${fmt(e.max)}${mm(e.max)}` +
      (e.percentile > 0 ? ` \u00b7 scale top: ${e.percentile}th percentile` : '');
    lg.appendChild(sum);
    lg.hidden = false;
  }

  // ---- scans (E-StopMotion: registered poses over the scan) ----
  const scans = [];
  let scanMode = 'transparent';
  if (meta.scans) {
    for (const s of meta.scans) {
      await positions(s);
      const SF = await int32s(s.faces), SP = framePositions(s, 0, new Float32Array(s.nv * 3));
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(SP, 3));
      g.setIndex(new THREE.BufferAttribute(new Uint32Array(SF), 1));
      g.computeVertexNormals();
      const copies = views.map((v) => {
        const mat = new THREE.MeshStandardMaterial({ color: 0x7fb3ff, transparent: true, opacity: 0.35,
          depthWrite: false, side: THREE.DoubleSide, roughness: 0.9 });
        const m = new THREE.Mesh(g, mat);
        m.renderOrder = 1;
        m.visible = false;
        v.scene.add(m);
        return m;
      });
      scans.push({ frame: s.frame, copies });
    }
    const b = $('scanmode');
    b.hidden = false;
    const modes = ['transparent', 'wireframe', 'off'];
    const m = /scan=(transparent|wireframe|off)/.exec(location.hash);   // #frame=N&scan=wireframe
    if (m) scanMode = m[1];
    b.textContent = 'scan: ' + scanMode;
    b.onclick = () => {
      scanMode = modes[(modes.indexOf(scanMode) + 1) % modes.length];
      b.textContent = 'scan: ' + scanMode;
      setFrame(frame);
    };
  }

  // ---- pieces: which piece is mounted, and the library as thumbnails ----
  const parts = [];
  if (meta.pieces) {
    const panel = $('pieces');
    panel.hidden = false;
    const thumbR = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    const TW = 64;
    thumbR.setSize(TW, TW);
    for (const p of meta.pieces) {
      const row = document.createElement('div');
      row.className = 'part';
      const name = document.createElement('span');
      name.className = 'pname';
      row.appendChild(name);
      const track = document.createElement('canvas');
      track.className = 'track';
      track.width = Math.min(2000, nframes); track.height = 1;
      const tctx = track.getContext('2d');
      const used = Math.max(...p.labels) + 1;
      for (let k = 0; k < track.width; k++) {
        const l = p.labels[Math.floor(k * nframes / track.width)];
        tctx.fillStyle = `hsl(${(l * 137.5) % 360} 60% 55%)`;
        tctx.fillRect(k, 0, 1, 1);
      }
      track.title = 'piece per frame';
      const trackBox = document.createElement('div');
      trackBox.className = 'trackbox';
      const marker = document.createElement('div');
      marker.className = 'marker';
      trackBox.append(track, marker);
      row.appendChild(trackBox);
      const thumbs = document.createElement('div');
      thumbs.className = 'thumbs';
      const cells = [];
      if (p.lib) {
        const lib = await positions(p.lib), LF = await int32s(p.lib.faces);
        const LP = new Float32Array(lib.nv * 3);
        const lbox = new THREE.Box3(new THREE.Vector3(...lib.lo), new THREE.Vector3(...lib.hi));
        const lc = lbox.getCenter(new THREE.Vector3()), lr = lbox.getSize(new THREE.Vector3()).length() / 2 || 1;
        const tscene = new THREE.Scene();
        tscene.background = new THREE.Color(0x1d2026);
        tscene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 1.6));
        const tsun = new THREE.DirectionalLight(0xffffff, 1.8);
        tsun.position.set(0.4, 0.8, 1).multiplyScalar(lr * 4).add(lc);
        tsun.target.position.copy(lc);
        tscene.add(tsun, tsun.target);
        const tg = new THREE.BufferGeometry();
        tg.setAttribute('position', new THREE.BufferAttribute(LP, 3));
        tg.setIndex(new THREE.BufferAttribute(new Uint32Array(LF), 1));
        tscene.add(new THREE.Mesh(tg, new THREE.MeshStandardMaterial({ color: 0xcfc7bc, roughness: 0.75, side: THREE.DoubleSide })));
        const tcam = new THREE.PerspectiveCamera(30, 1, lr / 100, lr * 100);
        tcam.position.copy(lc).add(new THREE.Vector3(0, 0, lr * 3.6));
        tcam.lookAt(lc);
        for (let d = 0; d < lib.nframes; d++) {
          framePositions(lib, d, LP);
          tg.attributes.position.needsUpdate = true;
          tg.computeVertexNormals();
          thumbR.render(tscene, tcam);
          const cell = document.createElement('div');
          cell.className = 'th';
          const c = document.createElement('canvas');
          c.width = TW; c.height = TW;
          c.getContext('2d').drawImage(thumbR.domElement, 0, 0);
          const num = document.createElement('span');
          num.textContent = d;
          cell.append(c, num);
          cell.title = `piece ${d}: used in ${p.labels.filter((l) => l === d).length} frames`;
          cell.onclick = () => { const k = p.labels.indexOf(d); if (k >= 0) setFrame(k); };
          thumbs.appendChild(cell);
          cells.push(cell);
        }
      }
      row.appendChild(thumbs);
      panel.appendChild(row);
      parts.push({ p, name, cells, used, marker });
    }
    thumbR.dispose();
    stage.style.bottom = panel.offsetHeight + 'px';
  }

  // ---- frames ----
  let frame = 0, playing = false;
  const slider = $('slider');
  slider.max = nframes - 1;
  const clipOf = (k) => { let c = 0; meta.cuts.forEach((s, i) => { if (s <= k) c = i; }); return c; };
  function setFrame(k, keepHash) {
    frame = Math.max(0, Math.min(nframes - 1, k | 0));
    slider.value = frame;
    const clip = clipOf(frame);
    $('frameinfo').textContent = `frame ${frame} / ${nframes - 1}` +
      (meta.cuts.length > 1 ? ` \u00b7 clip ${clip + 1} of ${meta.cuts.length}` : '');
    for (const v of views) {
      const a = meta.anims[v.anim];
      framePositions(a, frame, P);
      vertexNormals(P, F, N);
      const at = v.g.attributes;
      scatter(F, P, at.position.array);
      scatter(F, N, at.normal.array);
      at.position.needsUpdate = at.normal.needsUpdate = true;
      if (v.colour === 'error') {
        errorColours(frame, P, C);
        scatter(F, C, at.color.array);
        at.color.needsUpdate = true;
      }
      v.g.computeBoundingSphere();
    }
    for (const pt of parts) {
      const l = pt.p.labels[frame];
      pt.name.textContent = `${pt.p.name}: piece ${l}`;
      pt.cells.forEach((c, i) => c.classList.toggle('on', i === l));
      pt.marker.style.left = (100 * (frame + 0.5) / nframes) + '%';
    }
    for (const s of scans)
      s.copies.forEach((m) => {
        m.visible = s.frame === frame && scanMode !== 'off';
        m.material.wireframe = scanMode === 'wireframe';
        m.material.opacity = scanMode === 'wireframe' ? 0.6 : 0.35;
      });
    document.body.dataset.frame = frame;
    document.body.dataset.scan = scans.filter((s) => s.frame === frame && scanMode !== 'off').length;
    if (!keepHash && !playing) {
      try { history.replaceState(null, '', '#frame=' + frame + (scans.length ? '&scan=' + scanMode : '')); } catch (e) { /* some file:// setups refuse */ }
    }
    draw();
  }
  function hashFrame() {
    const m = /frame=(\d+)/.exec(location.hash);
    return m ? +m[1] : null;
  }

  // ---- drawing: one renderer, one viewport per view, one camera ----
  function layout() {
    const w = stage.clientWidth, h = stage.clientHeight;
    renderer.setSize(w, h, false);
    renderer.domElement.style.width = w + 'px';
    renderer.domElement.style.height = h + 'px';
    views.forEach((v, i) => { v.title.style.left = ((i + 0.5) * w / views.length) + 'px'; });
  }
  // start with the box of all animations filling a view (the bounding sphere
  // would leave a wide row of heads tiny)
  function fitCamera() {
    const aspect = (stage.clientWidth / views.length) / Math.max(1, stage.clientHeight);
    const t = Math.tan(THREE.MathUtils.degToRad(camera.fov / 2));
    camera.updateMatrixWorld();
    const inv = camera.matrixWorldInverse, c0 = centre.clone().applyMatrix4(inv);
    let xm = 0, ym = 0, zm = 0;
    for (let i = 0; i < 8; i++) {
      const p = new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
        i & 4 ? box.max.z : box.min.z).applyMatrix4(inv).sub(c0);
      xm = Math.max(xm, Math.abs(p.x)); ym = Math.max(ym, Math.abs(p.y)); zm = Math.max(zm, Math.abs(p.z));
    }
    const d = 1.1 * Math.max(xm / (t * aspect), ym / t) + zm;
    if (!(d > 0)) return;
    camera.position.copy(centre).add(new THREE.Vector3(...meta.camera.towards).multiplyScalar(d));
    camera.lookAt(centre);
    controls.update();
  }
  function draw() {
    const w = stage.clientWidth, h = stage.clientHeight, n = views.length;
    views.forEach((v, i) => {
      const x0 = Math.round(i * w / n), x1 = Math.round((i + 1) * w / n);
      renderer.setViewport(x0, 0, x1 - x0, h);
      renderer.setScissor(x0, 0, x1 - x0, h);
      camera.aspect = (x1 - x0) / h;
      camera.updateProjectionMatrix();
      // key light above and to the right of the camera
      v.sun.position.copy(camera.position).add(new THREE.Vector3(radius, radius * 2, 0).applyQuaternion(camera.quaternion));
      v.sun.target.position.copy(controls.target);
      v.sun.target.updateMatrixWorld();
      renderer.render(v.scene, camera);
    });
  }
  controls.addEventListener('change', draw);
  let userMoved = false;   // until the user orbits, a resize re-fits the camera
  controls.addEventListener('start', () => { userMoved = true; });
  window.addEventListener('resize', () => { layout(); if (!userMoved) fitCamera(); draw(); });
  slider.addEventListener('input', () => setFrame(+slider.value));
  window.addEventListener('hashchange', () => { const k = hashFrame(); if (k !== null && k !== frame) setFrame(k, true); });
  const playBtn = $('play');
  let last = 0;
  function tick(t) {
    if (!playing) return;
    if (t - last >= 1000 / meta.fps) { last = t; setFrame((frame + 1) % nframes); }
    requestAnimationFrame(tick);
  }
  function setPlaying(p) {
    playing = p;
    playBtn.textContent = p ? 'pause' : 'play';
    if (p) requestAnimationFrame(tick); else setFrame(frame);
  }
  playBtn.onclick = () => setPlaying(!playing);
  window.addEventListener('keydown', (e) => {
    if (e.key === 'ArrowRight') { setPlaying(false); setFrame(frame + 1); e.preventDefault(); }
    else if (e.key === 'ArrowLeft') { setPlaying(false); setFrame(frame - 1); e.preventDefault(); }
    else if (e.key === 'Home') setFrame(0);
    else if (e.key === 'End') setFrame(nframes - 1);
    else if (e.key === ' ') { setPlaying(!playing); e.preventDefault(); }
  });
  $('foot').textContent = `${meta.nv} vertices, ${meta.nf} faces, ${nframes} frames \u00b7 positions ` +
    `stored in 16 bits: error at most ${meta.quant_error_rel.toPrecision(2)} of the bounding box diagonal \u00b7 three.js ${meta.three}`;
  layout();
  fitCamera();
  setFrame(hashFrame() ?? 0, true);
  if (document.body.dataset.status === 'loading') document.body.dataset.status = 'ready';
  // one line for a headless browser's log (--enable-logging=stderr)
  console.log(`stopmo-status ${document.body.dataset.status} frame=${frame}`);
}

main().catch((e) => window.stopmoReport('error: ' + (e && e.stack ? e.stack : e)));
