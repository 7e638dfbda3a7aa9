// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive editor's page: draws the mesh with one colour per patch, the crest
// lines, creases and patch boundaries, and turns the gestures of the authors' tool into
// the JSON edits of the program's /api/edit (editor_api.h documents them). Edits are
// sent one at a time; a global alpha moved while an edit runs is sent once it returns.

import * as THREE from 'three';
import { OrbitControls } from './OrbitControls.js';

const $ = (id) => document.getElementById(id);
const view = $('view');

// ---- the server -------------------------------------------------------------------
// The session token of the address the program printed (?token=...): kept for the tab's
// reloads, sent with every API call as a header and as a same-site cookie.
const token = new URLSearchParams(location.search).get('token') || sessionStorage.getItem('fs_editor_token') || '';
if (token) {
  sessionStorage.setItem('fs_editor_token', token);
  document.cookie = `fs_editor_token=${encodeURIComponent(token)}; path=/; SameSite=Strict`;
}

async function api(path, body) {
  const headers = { 'X-Editor-Token': token };
  const init = body === undefined ? { headers } : {
    method: 'POST', headers: { ...headers, 'Content-Type': 'application/json' }, body: JSON.stringify(body) };
  const res = await fetch(path, init);
  const json = await res.json();
  if (!res.ok) throw new Error(json.error || res.statusText);
  return json;
}

// GET of a binary answer (/api/mesh?format=binary, /api/labels?format=runs), or POST
// of `body` as JSON (/api/edit?labels=runs): its bytes.
async function apiBytes(path, body) {
  const headers = { 'X-Editor-Token': token };
  const init = body === undefined ? { headers } : {
    method: 'POST', headers: { ...headers, 'Content-Type': 'application/json' }, body: JSON.stringify(body) };
  const res = await fetch(path, init);
  if (!res.ok) throw new Error((await res.json().catch(() => ({}))).error || res.statusText);
  return res.arrayBuffer();
}

// One edit and its labels in one message (POST /api/edit?labels=runs: uint32 J, the
// state's JSON in J bytes, then the labels as /api/labels?format=runs).
async function apiEdit(request) {
  const bytes = await apiBytes('/api/edit?labels=runs', request);
  const length = new DataView(bytes, 0, 4).getUint32(0, true);
  const state = JSON.parse(new TextDecoder().decode(new Uint8Array(bytes, 4, length)));
  return { state, labels: bytes, labelsAt: 4 + length };
}

function status(text, isError = false) {
  $('status').textContent = text;
  $('status').classList.toggle('error', isError);
}

// ---- the scene ----------------------------------------------------------------------
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setClearColor(0xffffff);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
camera.add(sun);
sun.position.set(0.5, 1, 1);
scene.add(camera);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = false;

let mesh = null;            // THREE.Mesh, non-indexed: three vertices per triangle
let triangles = null;       // Uint32Array of the server's triangles
let positions = null;       // Float32Array of the server's vertices
let centroids = null;       // Float32Array, 3 per triangle
let facePatches = null;     // per triangle
let runEnds = null, runPatches = null; // the labels as runs of triangles (showLabels)
let diagonal = 1;
const region = new Set();   // painted triangles
const overlays = { lines: new THREE.Group(), creases: new THREE.Group(), boundaries: new THREE.Group() };
for (const g of Object.values(overlays)) scene.add(g);
const strokeLine = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xff00ff }));
scene.add(strokeLine);

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
  render();
}
function render() { renderer.render(scene, camera); }
controls.addEventListener('change', render);
window.addEventListener('resize', resize);

// A patch's colour: hues spread by the golden ratio, so that neighbours differ.
function patchColor(p, out) {
  out.setHSL((p * 0.618033988749895) % 1, 0.55, 0.62);
  return out;
}

// The colours are looked up on the GPU: a texture holds the patch of every triangle
// (bit 31: painted), another the colour of every patch, and the vertex shader reads
// both at its triangle (gl_VertexID / 3 of the non-indexed mesh). An edit uploads the
// triangles' patches (4 bytes per triangle) and the palette, not three colours per
// triangle.
const TEXTURE_WIDTH = 2048;   // texels per row of both textures
const PAINTED = 0x80000000;   // a painted triangle's bit in its texel
let faceTexture = null, paletteTexture = null;

// A texture of `count` texels of `components` elements of `Array`, TEXTURE_WIDTH a row.
function dataTexture(Array, count, format, type, internalFormat) {
  const rows = Math.max(1, Math.ceil(count / TEXTURE_WIDTH));
  const channels = format === THREE.RGBAFormat ? 4 : 1;
  const t = new THREE.DataTexture(new Array(channels * TEXTURE_WIDTH * rows), TEXTURE_WIDTH, rows, format, type);
  t.internalFormat = internalFormat;
  t.minFilter = t.magFilter = THREE.NearestFilter;
  t.generateMipmaps = false;
  t.needsUpdate = true;
  return t;
}

// The bytes r, g, b and 255 of patches 0 .. n-1, in a texture.
function patchPalette(n) {
  const c = new THREE.Color();
  const t = dataTexture(Uint8Array, n, THREE.RGBAFormat, THREE.UnsignedByteType, 'RGBA8');
  const bytes = t.image.data;
  for (let p = 0; p < n; ++p) {
    patchColor(p, c);
    bytes[4 * p] = Math.round(255 * c.r);
    bytes[4 * p + 1] = Math.round(255 * c.g);
    bytes[4 * p + 2] = Math.round(255 * c.b);
    bytes[4 * p + 3] = 255;
  }
  return t;
}

// The patches of the triangles into their texture (one fill per run), the painted ones
// marked; then a redraw.
function colorFaces() {
  const ids = faceTexture.image.data;
  for (let r = 0, start = 0; r < runEnds.length; start = runEnds[r++]) ids.fill(runPatches[r], start, runEnds[r]);
  for (const f of region) ids[f] = (facePatches[f] | PAINTED) >>> 0;
  faceTexture.needsUpdate = true;
  render();
}

// Mesh material: Lambert, its vertex colour replaced by the lookup above.
function patchMaterial() {
  const material = new THREE.MeshLambertMaterial({
    vertexColors: true, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  material.onBeforeCompile = (shader) => {
    shader.uniforms.faceIds = { get value() { return faceTexture; } };
    shader.uniforms.patchColors = { get value() { return paletteTexture; } };
    shader.uniforms.paintColor = { value: new THREE.Color(0xffe600) };
    shader.vertexShader = `uniform highp usampler2D faceIds;
uniform sampler2D patchColors;
uniform vec3 paintColor;
` + shader.vertexShader.replace('#include <color_vertex>', `
  int face = gl_VertexID / 3;
  uint id = texelFetch(faceIds, ivec2(face % ${TEXTURE_WIDTH}, face / ${TEXTURE_WIDTH}), 0).r;
  int patchId = int(id & 0x7fffffffu);
  vColor = texelFetch(patchColors, ivec2(patchId % ${TEXTURE_WIDTH}, patchId / ${TEXTURE_WIDTH}), 0).rgb;
  if ((id & 0x80000000u) != 0u) vColor = mix(vColor, paintColor, 0.55);`);
  };
  return material;
}

// `bytes`: GET /api/mesh?format=binary (editor_api.h: two uint32 counts, the float64
// diagonal, float32 x y z per vertex, uint32 i j k per triangle).
function buildMesh(bytes) {
  const header = new DataView(bytes, 0, 16);
  const vertexCount = header.getUint32(0, true), triangleCount = header.getUint32(4, true);
  diagonal = header.getFloat64(8, true);
  positions = new Float32Array(bytes, 16, 3 * vertexCount);
  triangles = new Uint32Array(bytes, 16 + 12 * vertexCount, 3 * triangleCount);
  const indexed = new THREE.BufferGeometry();
  indexed.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  indexed.setIndex(new THREE.BufferAttribute(triangles, 1));
  indexed.computeVertexNormals();
  const geometry = indexed.toNonIndexed();
  const n = triangles.length / 3;
  faceTexture = dataTexture(Uint32Array, n, THREE.RedIntegerFormat, THREE.UnsignedIntType, 'R32UI');
  centroids = new Float32Array(3 * n);
  for (let f = 0; f < n; ++f)
    for (let k = 0; k < 3; ++k)
      centroids[3 * f + k] = (positions[3 * triangles[3 * f] + k] + positions[3 * triangles[3 * f + 1] + k] +
                              positions[3 * triangles[3 * f + 2] + k]) / 3;
  mesh = new THREE.Mesh(geometry, patchMaterial());
  scene.add(mesh);
  geometry.computeBoundingSphere();
  const s = geometry.boundingSphere;
  controls.target.copy(s.center);
  camera.near = s.radius / 100; camera.far = s.radius * 100;
  camera.position.copy(s.center).add(new THREE.Vector3(1, 0.8, 1.4).normalize().multiplyScalar(s.radius * 2.6));
  camera.updateProjectionMatrix();
  controls.update();
}

function polylines(list, color, group) {
  group.clear();
  const material = new THREE.LineBasicMaterial({ color, depthTest: true });
  for (const xyz of list) {
    if (xyz.length < 6) continue;
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(Float32Array.from(xyz), 3));
    group.add(new THREE.Line(g, material));
  }
}

// The feature lines and the boundaries are drawn when they arrive: an edit's round trip
// ends with the new colours, and the next edit does not wait for these. A load started
// later replaces one still on its way (`editor.overlaysPending` counts those unfinished).
let featureLoads = 0, boundaryLoads = 0;
function refreshOverlays(features) {
  const track = (promise) => {
    ++state.overlaysPending;
    promise.catch((e) => status(e.message, true)).finally(() => { --state.overlaysPending; });
  };
  if (features) track(loadFeatures());
  track(loadBoundaries());
}

async function loadFeatures() {
  const generation = ++featureLoads;
  const f = await api('/api/features');
  if (generation !== featureLoads) return;
  overlays.lines.clear();
  const ridges = new THREE.Group(), valleys = new THREE.Group(), seams = new THREE.Group(), user = new THREE.Group();
  polylines(f.ridges, 0xd62728, ridges);
  polylines(f.valleys, 0x1f5bd6, valleys);
  polylines(f.seam_lines, 0x2ca02c, seams);
  polylines(f.user, 0xff00ff, user);
  overlays.lines.add(ridges, valleys, seams, user);
  overlays.creases.clear();
  if (f.creases.length) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(Float32Array.from(f.creases), 3));
    overlays.creases.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x111111 })));
  }
  render();
}

async function loadBoundaries() {
  const generation = ++boundaryLoads;
  if (!$('show-boundaries').checked) { overlays.boundaries.clear(); render(); return; }
  const b = await api('/api/boundaries?smooth=' + ($('smooth-boundaries').checked ? 1 : 0));
  if (generation !== boundaryLoads) return;
  polylines(b.curves, 0x000000, overlays.boundaries);
  render();
}

// Draws the labels at byte `at` of `bytes`, as GET /api/labels?format=runs gives them
// (four uint32: the patches, the triangles T, the runs R and the bytes of an id, 1, 2 or
// 4; then the end of every run of triangles of one patch, uint32; then the runs'
// patches).
function showLabels(bytes, at) {
  const header = new DataView(bytes, at, 16);
  const Ids = { 1: Uint8Array, 2: Uint16Array, 4: Uint32Array }[header.getUint32(12, true)];
  if (!Ids) throw new Error('labels: an id width that is not 1, 2 or 4 bytes');
  const runs = header.getUint32(8, true);
  runEnds = new Uint32Array(bytes, at + 16, runs);
  runPatches = new Ids(bytes, at + 16 + 4 * runs, runs);
  facePatches = new Ids(header.getUint32(4, true));
  for (let r = 0, start = 0; r < runs; start = runEnds[r++]) facePatches.fill(runPatches[r], start, runEnds[r]);
  if (paletteTexture) paletteTexture.dispose();
  paletteTexture = patchPalette(header.getUint32(0, true));
  colorFaces();
}

// Fetches and draws the labels; resolves to the milliseconds of the two.
async function loadLabels() {
  const t0 = performance.now();
  const bytes = await apiBytes('/api/labels?format=runs');
  const t1 = performance.now();
  showLabels(bytes, 0);
  return { fetch: t1 - t0, draw: performance.now() - t1 };
}

// ---- the state ----------------------------------------------------------------------
const state = { current: null, inflight: 0, queuedAlpha: null, ready: false, loadMs: null, lastRoundTripMs: null,
                lastSplitMs: null, overlaysPending: 0 };
window.editor = state; // for the browser test and the curious

function showState(s) {
  state.current = s;
  $('patches').textContent = s.patches;
  $('cut-cost').textContent = s.cut_cost.toFixed(3);
  $('last-edit').textContent = s.last_edit
    ? `${s.last_edit.op}: ${(1000 * s.last_edit.server_seconds).toFixed(1)} ms` : '–';
  if (!state.queuedAlpha && document.activeElement !== $('alpha')) {
    $('alpha').value = s.alpha;
  }
  $('alpha-value').textContent = Number(s.alpha).toFixed(2);
  $('radius-value').textContent = Number(s.radius).toPrecision(3);
  if (state.startRadius === undefined) state.startRadius = s.radius;
  $('undo').disabled = !s.can_undo;
  $('redo').disabled = !s.can_redo;
  $('edit-count').textContent = s.edit_count; // the list holds the last ones (the state's edits)
  const list = $('edits');
  list.replaceChildren(...s.edits.map((line) => {
    const li = document.createElement('li');
    li.textContent = line.length > 80 ? line.slice(0, 77) + '...' : line;
    return li;
  }));
  list.scrollTop = list.scrollHeight;
}

// Sends one edit; the page shows its result. Edits are queued and sent one at a time,
// in order; an alpha move made while an alpha edit still waits in the queue replaces its
// value, so that dragging the slider or turning the wheel sends few requests.
let queue = Promise.resolve();
function edit(request) {
  if (request.op === 'alpha' && state.queuedAlpha) { state.queuedAlpha.value = request.value; return queue; }
  if (request.op === 'alpha') state.queuedAlpha = request;
  ++state.inflight;
  queue = queue.then(() => runEdit(request));
  return queue;
}

async function runEdit(request) {
  if (request === state.queuedAlpha) state.queuedAlpha = null;
  document.body.style.cursor = 'progress';
  try {
    const t0 = performance.now();
    const { state: s, labels, labelsAt } = await apiEdit(request);
    const t1 = performance.now();
    showState(s);
    showLabels(labels, labelsAt);
    // the round trip: request, solve, labels, colours redrawn
    state.lastRoundTripMs = performance.now() - t0;
    state.lastSplitMs = { edit: t1 - t0, draw: state.lastRoundTripMs - (t1 - t0) };
    refreshOverlays(request.op === 'sketch' || request.op === 'undo' || request.op === 'redo');
    status(`${request.op}: ${s.patches} patches (${state.lastRoundTripMs.toFixed(0)} ms)`);
  } catch (e) {
    status(`${request.op}: ${e.message}`, true);
  } finally {
    if (--state.inflight === 0) document.body.style.cursor = '';
  }
}

// Another crest-line scale: the server recomputes curvature, feature lines and the
// oversegmentation, and the history starts again. Queued like an edit.
function restart(radius) {
  radius = Math.min(1, Math.max(0, radius));
  ++state.inflight;
  queue = queue.then(async () => {
    document.body.style.cursor = 'progress';
    status(`recomputing the features at radius ${radius.toPrecision(3)} ...`);
    try {
      const t0 = performance.now();
      const s = await api('/api/restart', { radius });
      showState(s);
      await loadLabels();
      refreshOverlays(true);
      status(`radius ${radius.toPrecision(3)}: ${s.patches} patches, ${s.feature_edges} feature edges ` +
             `(${((performance.now() - t0) / 1000).toFixed(1)} s; the edits start again)`);
    } catch (e) {
      status(`restart: ${e.message}`, true);
    } finally {
      if (--state.inflight === 0) document.body.style.cursor = '';
    }
  });
  return queue;
}

// ---- picking and gestures -----------------------------------------------------------
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
function pick(event) {
  const r = renderer.domElement.getBoundingClientRect();
  pointer.set(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
  raycaster.setFromCamera(pointer, camera);
  const hit = raycaster.intersectObject(mesh, false)[0];
  return hit ? { point: hit.point, face: hit.faceIndex } : null;
}

function brushRadius() { return Number($('brush').value) * diagonal; }

function facesNear(point, radius, into) {
  const r2 = radius * radius;
  for (let f = 0; f < centroids.length / 3; ++f) {
    const dx = centroids[3 * f] - point.x, dy = centroids[3 * f + 1] - point.y, dz = centroids[3 * f + 2] - point.z;
    if (dx * dx + dy * dy + dz * dz <= r2) into.add(f);
  }
}

function toolOf(event) {
  if (event.altKey) return 'sketch';
  if (event.ctrlKey || event.metaKey) return 'merge';
  if (event.shiftKey) return 'paint';
  return document.querySelector('input[name=tool]:checked').value;
}

let stroke = null; // { tool, faces: Set, points: [Vector3] }
function showStroke() {
  const pts = stroke ? stroke.points : [];
  strokeLine.geometry.dispose();
  strokeLine.geometry = new THREE.BufferGeometry().setFromPoints(pts);
  render();
}

function strokeAt(event) {
  const hit = pick(event);
  if (!hit) return;
  if (stroke.tool === 'paint') {
    const before = region.size;
    facesNear(hit.point, brushRadius(), region);
    if (region.size !== before) { $('region-size').textContent = region.size; colorFaces(); }
  } else if (stroke.tool === 'merge') {
    stroke.faces.add(hit.face);
    stroke.points.push(hit.point.clone());
    showStroke();
  } else {
    const last = stroke.points[stroke.points.length - 1];
    if (!last || last.distanceTo(hit.point) > diagonal / 400) { stroke.points.push(hit.point.clone()); showStroke(); }
  }
}

renderer.domElement.addEventListener('pointerdown', (event) => {
  if (!mesh || event.button !== 0) return;
  const tool = toolOf(event);
  if (tool === 'orbit') return;
  controls.enabled = false;
  stroke = { tool, faces: new Set(), points: [] };
  renderer.domElement.setPointerCapture(event.pointerId);
  strokeAt(event);
});
renderer.domElement.addEventListener('pointermove', (event) => { if (stroke) strokeAt(event); });
renderer.domElement.addEventListener('pointerup', async () => {
  if (!stroke) return;
  const s = stroke;
  stroke = null;
  controls.enabled = true;
  showStroke();
  if (s.tool === 'merge' && s.faces.size > 0) await edit({ op: 'merge', faces: [...s.faces] });
  else if (s.tool === 'sketch' && s.points.length >= 2)
    await edit({ op: 'sketch', points: s.points.map((p) => [p.x, p.y, p.z]) });
});

// Shift+wheel: refine/coarsen (a painted region, else the global alpha); Ctrl+Shift+wheel:
// the brush. The plain wheel zooms.
renderer.domElement.addEventListener('wheel', (event) => {
  if (!event.shiftKey) return;
  event.preventDefault();
  event.stopImmediatePropagation();
  const up = (event.deltaY || event.deltaX) < 0;
  if (event.ctrlKey || event.metaKey) {
    const b = $('brush');
    b.value = Number(b.value) * (up ? 1.15 : 1 / 1.15);
    $('brush-value').textContent = Number(b.value).toFixed(3);
    return;
  }
  if (region.size > 0) regionEdit(up ? 'refine' : 'coarsen');
  else {
    const base = state.queuedAlpha ? state.queuedAlpha.value : state.current.alpha;
    const a = Math.round((base + (up ? 0.05 : -0.05)) * 100) / 100;
    $('alpha').value = a;
    $('alpha-value').textContent = a.toFixed(2);
    edit({ op: 'alpha', value: a });
  }
}, { capture: true, passive: false });

function regionEdit(op) {
  if (region.size === 0) { status('paint a region first (Shift+drag)', true); return; }
  edit({ op, faces: [...region], amount: Number($('amount').value) });
}

// ---- the panel ----------------------------------------------------------------------
$('alpha').addEventListener('input', () => { $('alpha-value').textContent = Number($('alpha').value).toFixed(2); });
$('alpha').addEventListener('change', () => edit({ op: 'alpha', value: Number($('alpha').value) }));
$('brush').addEventListener('input', () => { $('brush-value').textContent = Number($('brush').value).toFixed(3); });
$('amount').addEventListener('input', () => { $('amount-value').textContent = Number($('amount').value).toFixed(2); });
$('refine').addEventListener('click', () => regionEdit('refine'));
$('coarsen').addEventListener('click', () => regionEdit('coarsen'));
function clearRegion() { region.clear(); $('region-size').textContent = 0; colorFaces(); }
$('clear-region').addEventListener('click', clearRegion);
$('undo').addEventListener('click', () => edit({ op: 'undo' }));
$('redo').addEventListener('click', () => edit({ op: 'redo' }));
async function save() {
  try {
    const r = await api('/api/save', {});
    status(`saved ${r.files.length} files and ${r.edits} edits into ${r.output_dir}`);
  } catch (e) { status(`save: ${e.message}`, true); }
}
$('save').addEventListener('click', save);
$('scale-finer').addEventListener('click', () => restart(state.current.radius / 1.5));
$('scale-start').addEventListener('click', () => restart(state.startRadius));
$('scale-coarser').addEventListener('click', () => restart(state.current.radius * 1.5));
$('show-lines').addEventListener('change', () => { overlays.lines.visible = $('show-lines').checked; render(); });
$('show-creases').addEventListener('change', () => { overlays.creases.visible = $('show-creases').checked; render(); });
$('show-boundaries').addEventListener('change', loadBoundaries);
$('smooth-boundaries').addEventListener('change', loadBoundaries);
window.addEventListener('keydown', (event) => {
  const ctrl = event.ctrlKey || event.metaKey;
  if (ctrl && event.key.toLowerCase() === 'z') { event.preventDefault(); edit({ op: event.shiftKey ? 'redo' : 'undo' }); }
  else if (ctrl && event.key.toLowerCase() === 'y') { event.preventDefault(); edit({ op: 'redo' }); }
  else if (ctrl && event.key.toLowerCase() === 's') { event.preventDefault(); save(); }
  else if (event.key === 'Escape') clearRegion();
  else if (ctrl || event.altKey || event.target.tagName === 'INPUT') return;
  else if (event.key === 'q' || event.key === 'Q') restart(state.current.radius / 1.5);
  else if (event.key === 'w' || event.key === 'W') restart(state.startRadius);
  else if (event.key === 'e' || event.key === 'E') restart(state.current.radius * 1.5);
});

// ---- start --------------------------------------------------------------------------
async function start() {
  $('brush-value').textContent = Number($('brush').value).toFixed(3);
  $('amount-value').textContent = Number($('amount').value).toFixed(2);
  // The binary answers are little-endian; typed arrays read them in the machine's order,
  // which is little-endian on every platform browsers run on.
  if (new Uint8Array(new Uint32Array([1]).buffer)[0] !== 1) throw new Error('this page needs a little-endian machine');
  status('loading the mesh ...');
  const [m, s] = await Promise.all([apiBytes('/api/mesh?format=binary'), api('/api/state')]);
  $('mesh-name').textContent = `${s.triangles} triangles, ${s.vertices} vertices; ${s.feature_edges} feature edges, ${s.crease_edges} creases`;
  buildMesh(m);
  resize();
  showState(s);
  await loadLabels();
  refreshOverlays(true);
  status(`${s.patches} patches`);
  state.loadMs = performance.now(); // since the page was opened: the mesh shown and coloured
  state.ready = true;
}
start().catch((e) => status(`cannot load: ${e.message}`, true));
