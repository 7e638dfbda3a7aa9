// SPDX-License-Identifier: GPL-3.0-or-later
// The editor's HTTP interface on fandisk (12,946 triangles) with its crest lines:
// every verb, each kind of bad request (answered 400/413 with the state unchanged),
// concurrent edits, a save whose edits.txt replays with --edits to the same labels, and
// the attacks the server withstands: foreign Host and Origin, no token, a form's
// text/plain body, a chunked body of 1 GB, 200 slow clients, malformed HTTP.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { request } from 'node:http';
import { connect } from 'node:net';
import { join } from 'node:path';
import { startEditor, check, summary, program, fandisk, crestLines, fandiskReference as ref } from './server.mjs';

const editor = await startEditor();
const url = editor.url;
const auth = { 'X-Editor-Token': editor.token };
async function get(path) {
  const r = await fetch(url + path, { headers: auth });
  return { status: r.status, body: await r.json() };
}
async function post(path, body) {
  const r = await fetch(url + path, { method: 'POST', headers: { ...auth, 'Content-Type': 'application/json' },
                                      body: typeof body === 'string' ? body : JSON.stringify(body) });
  return { status: r.status, body: await r.json() };
}
// A raw request (node:http sets any Host and Transfer-Encoding): { status, body }.
function rawRequest(method, path, headers, body) {
  if (body !== undefined && !headers['Transfer-Encoding']) headers = { ...headers, 'Content-Length': Buffer.byteLength(body) };
  return new Promise((resolve, reject) => {
    const u = new URL(url + path);
    const req = request({ host: u.hostname, port: u.port, path: u.pathname + u.search, method, headers }, (res) => {
      let text = '';
      res.on('data', (d) => { text += d; });
      res.on('end', () => resolve({ status: res.statusCode, body: text ? JSON.parse(text) : {} }));
    });
    req.on('error', reject);
    if (body !== undefined) req.write(body);
    req.end();
  });
}
// Writes `text` on a new connection and resolves to what the server answers before it closes.
function rawExchange(text) {
  return new Promise((resolve) => {
    const socket = connect(Number(new URL(url).port), '127.0.0.1');
    let answer = '';
    socket.on('data', (d) => { answer += d; });
    socket.on('error', () => {});
    socket.on('close', () => resolve(answer));
    socket.write(text);
  });
}
// The resident memory of the editor's process, in bytes.
const residentBytes = () => Number(readFileSync(`/proc/${editor.child.pid}/status`, 'utf8').match(/VmRSS:\s+(\d+)/)[1]) * 1024;
// A POST of 1 GiB of chunked body in 1 MiB chunks, sent until the server answers or closes:
// { status (or 'closed'), mib: the chunks written }.
function hugeChunkedPost() {
  return new Promise((resolve) => {
    const u = new URL(url);
    const req = request({ host: u.hostname, port: u.port, path: '/api/edit', method: 'POST',
                          headers: { ...auth, 'Content-Type': 'application/json', 'Transfer-Encoding': 'chunked' } });
    const chunk = Buffer.alloc(1 << 20, 0x20);
    let mib = 0, done = false;
    const finish = (status) => { if (!done) { done = true; req.destroy(); resolve({ status, mib }); } };
    req.on('response', (res) => finish(res.statusCode));
    req.on('error', () => finish('closed'));
    const pump = () => {
      while (!done && mib < 1024) {
        ++mib;
        if (!req.write(chunk)) { req.once('drain', pump); return; }
      }
      if (!done) req.end();
    };
    pump();
  });
}
const state = async () => (await get('api/state')).body;
const labels = async () => (await get('api/labels')).body;

try {
  check('the server listens on the loopback address by default', url.startsWith('http://127.0.0.1:'), url);
  check('the printed address carries a session token of 32 hex digits', /^[0-9a-f]{32}$/.test(editor.token), editor.token);

  // ---- only the user's requests: token, Host, Origin, JSON, no chunked bodies
  const port = new URL(url).port;
  const noToken = await fetch(url + 'api/state');
  check('no token: 403', noToken.status === 403, (await noToken.json()).error);
  const wrong = await fetch(url + 'api/state', { headers: { 'X-Editor-Token': '0'.repeat(32) } });
  check('a wrong token: 403', wrong.status === 403);
  const cookie = await fetch(url + 'api/state', { headers: { Cookie: `a=b; fs_editor_token=${editor.token}` } });
  check('the token as a cookie: 200', cookie.status === 200);
  const rebound = await rawRequest('GET', 'api/state', { Host: 'attacker.example:' + port, 'X-Editor-Token': editor.token });
  check('Host attacker.example (DNS rebinding): 403', rebound.status === 403, rebound.body.error);
  const otherPort = await rawRequest('GET', '', { Host: '127.0.0.1:1' });
  check('Host of another port, even for the page: 403', otherPort.status === 403);
  const localhost = await rawRequest('GET', 'api/state', { Host: 'localhost:' + port, 'X-Editor-Token': editor.token });
  check('Host localhost at the port: 200', localhost.status === 200);
  const form = await rawRequest('POST', 'api/edit', { 'X-Editor-Token': editor.token, 'Content-Type': 'text/plain' },
                         JSON.stringify({ op: 'alpha', value: 2 }));
  check('a text/plain body (a form\'s or a no-cors fetch\'s): 415', form.status === 415, form.body.error);
  const cross = await rawRequest('POST', 'api/edit', { 'X-Editor-Token': editor.token, 'Content-Type': 'application/json',
                                               Origin: 'http://attacker.example' }, JSON.stringify({ op: 'alpha', value: 2 }));
  check('a POST from another Origin: 403', cross.status === 403, cross.body.error);
  const chunked = await rawRequest('POST', 'api/edit', { 'X-Editor-Token': editor.token, 'Content-Type': 'application/json',
                                                 'Transfer-Encoding': 'chunked' }, JSON.stringify({ op: 'explode' }));
  check('a small chunked body is read: its edit is judged (400, unknown op)',
        chunked.status === 400 && /unknown op/.test(chunked.body.error), chunked.body.error);
  const rss0 = residentBytes();
  const gib = await hugeChunkedPost();
  const grown = residentBytes() - rss0;
  check('a chunked body of 1 GiB: refused (413 or closed) long before its end, memory within 100 MB',
        (gib.status === 413 || gib.status === 'closed') && gib.mib < 1024 && grown < 100e6,
        `${gib.status} after ${gib.mib} MiB sent, ${(grown / 1e6).toFixed(1)} MB more resident`);
  const garbage = await rawExchange('HELLO?\r\n\r\n');
  check('malformed HTTP: 400 naming the fault', /^HTTP\/1\.1 400/.test(garbage) && garbage.includes('malformed HTTP'),
        garbage.split('\r\n')[0]);
  const bigHeaders = await rawExchange(`GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:${port}\r\nX-Pad: ${'a'.repeat(20000)}\r\n\r\n`);
  check('headers over 16 KB: 431', /^HTTP\/1\.1 431/.test(bigHeaders), bigHeaders.split('\r\n')[0]);
  const badUtf8 = await rawRequest('POST', 'api/edit', { 'X-Editor-Token': editor.token, 'Content-Type': 'application/json' },
                                   Buffer.from([0x7b, 0x22, 0x6f, 0x70, 0x22, 0x3a, 0x22, 0xff, 0xfe, 0x22, 0x7d])); // {"op":"\xff\xfe"}
  check('invalid UTF-8 in a body: 400', badUtf8.status === 400, badUtf8.body.error);
  const wrongVerb = await rawRequest('GET', 'api/edit', { 'X-Editor-Token': editor.token });
  check('GET of a POST resource: 405', wrongVerb.status === 405, wrongVerb.body.error);

  // ---- 200 slow clients, each sending a header byte every 0.2 s, do not hold up the others
  const slowText = `GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:${port}\r\nX-Slow: ` + 'a'.repeat(200);
  const slow = [];
  for (let i = 0; i < 200; ++i) {
    const socket = connect(Number(port), '127.0.0.1');
    socket.on('error', () => {});
    socket.closedAt = null;
    socket.on('close', () => { socket.closedAt = performance.now(); });
    slow.push(socket);
  }
  let dripped = 0;
  const drip = setInterval(() => {
    for (const socket of slow) if (!socket.destroyed) socket.write(slowText[dripped % slowText.length]);
    ++dripped;
  }, 200);
  const slowStart = performance.now();
  await new Promise((r) => setTimeout(r, 1500));
  const asked = performance.now();
  const during = await get('api/state');
  const waited = performance.now() - asked;
  check('200 slow clients: a normal request is answered within 1 s', during.status === 200 && waited < 1000,
        `${waited.toFixed(0)} ms`);
  const page = await fetch(url);
  check('the page: served without a token, not to be framed',
        page.status === 200 && page.headers.get('x-frame-options') === 'DENY' &&
        page.headers.get('x-content-type-options') === 'nosniff');
  for (const [what, edit] of [['alpha 5e-324 (would not replay)', { op: 'alpha', value: 5e-324 }],
                              ['alpha 1e308 (an infinite cut cost)', { op: 'alpha', value: 1e308 }],
                              ['a sketch of 1001 points', { op: 'sketch', points: new Array(1001).fill([0, 0, 0]) }]]) {
    const r = await post('api/edit', edit);
    check(`refused with 400: ${what}`, r.status === 400, r.body.error);
  }

  // ---- queries
  const s0 = await state();
  check(`state: fandisk has ${ref.patches} patches at the defaults`, s0.patches === ref.patches, s0.patches);
  check('state: alpha 0.6, no edits, nothing to undo or redo',
        s0.alpha === 0.6 && s0.edits.length === 0 && !s0.can_undo && !s0.can_redo);
  const mesh = (await get('api/mesh')).body;
  check('mesh: 12946 triangles, 6475 vertices',
        mesh.triangles.length === 3 * 12946 && mesh.vertices.length === 3 * 6475 && s0.triangles === 12946);
  check('mesh: every corner is a vertex index', mesh.triangles.every((i) => i >= 0 && i < 6475));
  const l0 = await labels();
  check(`labels: one patch per triangle and vertex, numbered 0 .. ${ref.patches - 1}`,
        l0.face_patches.length === ref.faces && l0.vertex_patches.length === ref.vertices &&
        Math.max(...l0.face_patches) === ref.patches - 1 && Math.max(...l0.vertex_patches) === ref.patches - 1);
  // the binary forms the page loads: the same numbers (coordinates as float32)
  const bytes = async (path) => {
    const r = await fetch(url + path, { headers: auth });
    return { status: r.status, type: r.headers.get('content-type'), buffer: await r.arrayBuffer() };
  };
  const bm = await bytes('api/mesh?format=binary');
  const bmHeader = new DataView(bm.buffer);
  const bmVertices = bmHeader.getUint32(0, true), bmTriangles = bmHeader.getUint32(4, true);
  check('binary mesh: application/octet-stream, 16 + 12 V + 12 T bytes for 6475 vertices and 12946 triangles',
        bm.status === 200 && bm.type === 'application/octet-stream' && bmVertices === 6475 && bmTriangles === 12946 &&
        bm.buffer.byteLength === 16 + 12 * 6475 + 12 * 12946, `${bm.buffer.byteLength} bytes`);
  const bmXyz = new Float32Array(bm.buffer, 16, 3 * bmVertices);
  const bmTri = new Uint32Array(bm.buffer, 16 + 12 * bmVertices, 3 * bmTriangles);
  check('binary mesh: the diagonal, the coordinates (as float32) and the triangles of the JSON mesh',
        bmHeader.getFloat64(8, true) === mesh.diagonal && mesh.vertices.every((x, i) => bmXyz[i] === Math.fround(x)) &&
        mesh.triangles.every((t, i) => bmTri[i] === t));
  // the ids in the fewest bytes (1, 2 or 4) that hold the largest one
  const idWidth = (ids) => { const most = Math.max(0, ...ids); return most < 256 ? 1 : most < 65536 ? 2 : 4; };
  const idArray = { 1: Uint8Array, 2: Uint16Array, 4: Uint32Array };
  const bl = await bytes('api/labels?format=binary');
  const blHeader = new DataView(bl.buffer);
  const width = blHeader.getUint32(12, true);
  const expectedWidth = idWidth([...l0.face_patches, ...l0.vertex_patches]);
  check(`binary labels: ids of ${expectedWidth} byte(s), the fewest that hold the largest of the JSON labels`,
        width === expectedWidth, width);
  const Ids = idArray[width] || Uint8Array;
  const blFaces = new Ids(bl.buffer, 16, ref.faces), blVertices = new Ids(bl.buffer, 16 + width * ref.faces, ref.vertices);
  check('binary labels: patches, counts and every patch id of the JSON labels',
        bl.buffer.byteLength === 16 + width * (ref.faces + ref.vertices) && blHeader.getUint32(0, true) === ref.patches &&
        blHeader.getUint32(4, true) === ref.faces && blHeader.getUint32(8, true) === ref.vertices &&
        l0.face_patches.every((p, i) => blFaces[i] === p) && l0.vertex_patches.every((p, i) => blVertices[i] === p));
  const bf = await bytes('api/labels?format=binary&vertices=0');
  const bfHeader = new DataView(bf.buffer);
  const bfWidth = bfHeader.getUint32(12, true);
  check('binary labels with vertices=0: V = 0, the triangles\' id width, the same patch of every triangle, nothing after',
        bfWidth === idWidth(l0.face_patches) && bf.buffer.byteLength === 16 + bfWidth * ref.faces &&
        bfHeader.getUint32(0, true) === ref.patches && bfHeader.getUint32(4, true) === ref.faces &&
        bfHeader.getUint32(8, true) === 0 &&
        new (idArray[bfWidth] || Uint8Array)(bf.buffer, 16, ref.faces).every((p, i) => p === blFaces[i]),
        `${bf.buffer.byteLength} bytes`);
  // runs of triangles in one patch: ends increasing to T, no two neighbouring runs in one
  // patch, and every triangle's patch that of the binary labels
  const decodeRuns = (buffer, at) => {
    const h = new DataView(buffer, at, 16);
    const runs = h.getUint32(8, true), w = h.getUint32(12, true);
    const ends = new Uint32Array(buffer, at + 16, runs), ids = new (idArray[w] || Uint8Array)(buffer, at + 16 + 4 * runs, runs);
    const faces = [];
    let ordered = true;
    for (let r = 0, start = 0; r < runs; start = ends[r++]) {
      ordered &&= ends[r] > start && (r === 0 || ids[r] !== ids[r - 1]);
      for (let f = start; f < ends[r]; ++f) faces.push(ids[r]);
    }
    return { patches: h.getUint32(0, true), triangles: h.getUint32(4, true), runs, width: w, bytes: 16 + (4 + w) * runs,
             ordered: ordered && (runs === 0 || ends[runs - 1] === h.getUint32(4, true)), faces };
  };
  const br = await bytes('api/labels?format=runs');
  const runs0 = decodeRuns(br.buffer, 0);
  check(`labels?format=runs: ${runs0.runs} runs, ordered, of the JSON labels' id width, every triangle's patch`,
        br.type === 'application/octet-stream' && br.buffer.byteLength === runs0.bytes && runs0.ordered &&
        runs0.patches === ref.patches && runs0.triangles === ref.faces && runs0.width === idWidth(l0.face_patches) &&
        runs0.faces.length === ref.faces && l0.face_patches.every((p, i) => runs0.faces[i] === p),
        `${br.buffer.byteLength} bytes`);
  check('labels: format=runs with vertices is refused', (await get('api/labels?format=runs&vertices=0')).status === 400);
  check('labels: vertices=2, and vertices on JSON labels or on the mesh, are refused',
        (await get('api/labels?format=binary&vertices=2')).status === 400 &&
        (await get('api/labels?vertices=0')).status === 400 && (await get('api/mesh?format=binary&vertices=0')).status === 400);
  check('mesh: format=xml is refused', (await get('api/mesh?format=xml')).status === 400);
  const features = (await get('api/features')).body;
  check(`features: crease segments (6 numbers each) for the ${ref.crease_edges} crease edges`,
        features.creases.length === 6 * s0.crease_edges && s0.crease_edges === ref.crease_edges, s0.crease_edges);
  const smooth = (await get('api/boundaries?smooth=1')).body, raw = (await get('api/boundaries?smooth=0')).body;
  check('boundaries: the smoothing shortens them', smooth.curves.length > 0 && smooth.length < raw.length,
        `${raw.length.toFixed(4)} -> ${smooth.length.toFixed(4)}`);
  check('boundaries: smooth=2 is refused', (await get('api/boundaries?smooth=2')).status === 400);
  check('an unknown path is 404 with a JSON error', (await get('api/nothing')).status === 404);

  // ---- bad requests: 400 (or 413) and nothing changes
  const bad = [
    ['bad JSON', '{"op": "alpha", "value": }'],
    ['NaN', '{"op": "alpha", "value": NaN}'],
    ['an overflowing number', '{"op": "alpha", "value": 1e999}'],
    ['a string for a number', { op: 'alpha', value: 'high' }],
    ['no op', { value: 1 }],
    ['an unknown op', { op: 'explode' }],
    ['an unknown key', { op: 'alpha', value: 1, vaule: 2 }],
    ['a face index out of range', { op: 'merge', faces: [0, 12946] }],
    ['a negative face index', { op: 'refine', faces: [-1], amount: 0.2 }],
    ['a fractional face index', { op: 'refine', faces: [1.5], amount: 0.2 }],
    ['an empty region', { op: 'coarsen', faces: [], amount: 0.2 }],
    ['a negative scale factor', { op: 'scale', faces: [1], factor: -1 }],
    ['a sketch of one point', { op: 'sketch', points: [[0, 0, 0]] }],
    ['a sketch point of two numbers', { op: 'sketch', points: [[0, 0], [1, 1, 1]] }],
    ['a sketch alpha <= 1', { op: 'sketch', points: [[0, 0, 0], [0.1, 0, 0]], alpha: 1 }],
    ['undo with nothing to undo', { op: 'undo' }],
    ['redo with nothing to redo', { op: 'redo' }],
    ['an array instead of an object', [1, 2, 3]],
  ];
  for (const [what, body] of bad) {
    const r = await post('api/edit', body);
    check(`400 for ${what}`, r.status === 400 && typeof r.body.error === 'string' && r.body.error.length > 0,
          r.body.error);
  }
  const huge = await post('api/edit', JSON.stringify({ op: 'merge', faces: new Array(2_000_000).fill(12345) }));
  check('413 for a body over 8 MB', huge.status === 413, huge.body.error);
  const sBad = await state();
  check('the state after the bad requests is unchanged',
        sBad.patches === ref.patches && sBad.edits.length === 0 && sBad.cut_cost === s0.cut_cost);

  // ---- every verb
  const a = await post('api/edit', { op: 'alpha', value: 1.0 });
  check(`alpha 1.0: ${ref.set_alpha_1_with_crest_lines} patches, the segmentation's count`,
        a.status === 200 && a.body.patches === ref.set_alpha_1_with_crest_lines, a.body.patches);
  check('alpha: the answer is the new state with the edit listed and timed',
        a.body.alpha === 1 && a.body.edits[0] === 'alpha 1' && a.body.last_edit.op === 'alpha' &&
        a.body.last_edit.server_seconds > 0);
  const l1 = await labels();
  // two triangles of different patches: merging them removes exactly one patch
  const f1 = 0, f2 = l1.face_patches.findIndex((p) => p !== l1.face_patches[0]);
  const m = await post('api/edit', { op: 'merge', faces: [f1, f2] });
  check('merge of two triangles of two patches: one patch fewer', m.body.patches === a.body.patches - 1, m.body.patches);
  const l2 = await labels();
  check('merge: the two triangles now share a patch', l2.face_patches[f1] === l2.face_patches[f2]);
  const r = await post('api/edit', { op: 'refine', faces: [...Array(12946).keys()], amount: 0.3 });
  check('refine everywhere: at least as many patches', r.status === 200 && r.body.patches >= m.body.patches, r.body.patches);
  const c = await post('api/edit', { op: 'coarsen', faces: [...Array(12946).keys()], amount: 0.3 });
  check('coarsen by the same amount: back to the patches of the merge', c.body.patches === m.body.patches, c.body.patches);
  const answerBytes = JSON.stringify(c.body).length, fullLine = (await get(`api/history?from=${c.body.edit_count - 1}&count=1`)).body.edits[0];
  check('two edits of every triangle: the answer stays small (its lines cut), the history has them whole',
        answerBytes < 10000 && /^coarsen triangles 0 1 2 .* \.\.\. \(\d+ more\)$/.test(c.body.edits[c.body.edits.length - 1]) &&
        fullLine.split(' ').length === 12946 + 3, `${answerBytes} bytes`);
  const lc = await labels();
  const sc = await post('api/edit', { op: 'scale', faces: [...Array(12946).keys()], factor: 0 });
  check('scale by 0 everywhere: no feature reward left, fewer patches', sc.body.patches < c.body.patches, sc.body.patches);
  // a sketch between two points of the mesh: feature edges appear
  const p = (v) => mesh.vertices.slice(3 * v, 3 * v + 3);
  const t0 = mesh.triangles.slice(0, 3), far = mesh.triangles.slice(3 * 600, 3 * 600 + 3);
  const before = (await state()).feature_edges;
  const sk = await post('api/edit', { op: 'sketch', points: [p(t0[0]), p(far[0])] });
  check('sketch: accepted, feature edges added', sk.status === 200 && sk.body.feature_edges > before,
        `${before} -> ${sk.body.feature_edges}`);
  const u = await post('api/edit', { op: 'undo' });
  check('undo the sketch: its feature edges go', u.body.feature_edges === before && u.body.can_redo);
  const rd = await post('api/edit', { op: 'redo' });
  check('redo the sketch: they come back', rd.body.feature_edges === sk.body.feature_edges &&
        rd.body.cut_cost === sk.body.cut_cost && rd.body.patches === sk.body.patches);
  await post('api/edit', { op: 'undo' });
  await post('api/edit', { op: 'undo' });
  const back = await state();
  check('two undos: the state before the scale', back.patches === c.body.patches && back.cut_cost === c.body.cut_cost);
  check('after the undos, the labels are exactly those before the scale',
        JSON.stringify((await labels()).face_patches) === JSON.stringify(lc.face_patches));

  // ---- concurrent edits: one at a time, each answered
  const values = [0.7, 0.8, 0.9, 1.1, 1.2, 0.75, 0.85, 0.95];
  const answers = await Promise.all(values.map((v) => post('api/edit', { op: 'alpha', value: v })));
  const sc2 = await state();
  check('8 concurrent edits: all answered 200', answers.every((x) => x.status === 200));
  check('8 concurrent edits: all in the history, the state is the last one applied',
        sc2.edits.length === back.edits.length + 8 && sc2.edits[sc2.edits.length - 1] === `alpha ${sc2.alpha}`);

  // ---- an edit answered with its labels (what the page sends): the state and the
  // triangles' binary labels of that state, in one message
  const answer = await fetch(url + 'api/edit?labels=binary', { method: 'POST', body: JSON.stringify({ op: 'alpha', value: 0.65 }),
                                                             headers: { ...auth, 'Content-Type': 'application/json' } });
  const rb = await answer.arrayBuffer();
  const jsonBytes = new DataView(rb).getUint32(0, true);
  const edited = JSON.parse(new TextDecoder().decode(new Uint8Array(rb, 4, jsonBytes)));
  const afterEdit = await state();
  const labelsAfter = Buffer.from((await bytes('api/labels?format=binary&vertices=0')).buffer);
  check('edit?labels=binary: application/octet-stream, the JSON in a multiple of 4 bytes, the state of the edit',
        answer.status === 200 && answer.headers.get('content-type') === 'application/octet-stream' && jsonBytes % 4 === 0 &&
        edited.edit_count === afterEdit.edit_count && edited.patches === afterEdit.patches &&
        edited.cut_cost === afterEdit.cut_cost && edited.last_edit.op === 'alpha' && edited.alpha === 0.65, edited.edit_count);
  check('edit?labels=binary: then exactly the bytes of labels?format=binary&vertices=0 of that state',
        rb.byteLength === 4 + jsonBytes + labelsAfter.length &&
        Buffer.from(rb, 4 + jsonBytes).equals(labelsAfter), `${rb.byteLength} bytes`);
  const labelsJson = await post('api/edit?labels=json', { op: 'undo' });
  const refused = await fetch(url + 'api/edit?labels=binary', { method: 'POST', body: JSON.stringify({ op: 'jump' }),
                                                                headers: { ...auth, 'Content-Type': 'application/json' } });
  check('edit?labels=json and a refused edit with labels=binary: 400 in JSON, the state unchanged',
        labelsJson.status === 400 && refused.status === 400 && typeof (await refused.json()).error === 'string' &&
        (await state()).edit_count === afterEdit.edit_count);
  const runsAnswer = await fetch(url + 'api/edit?labels=runs', { method: 'POST', body: JSON.stringify({ op: 'alpha', value: 0.7 }),
                                                                headers: { ...auth, 'Content-Type': 'application/json' } });
  const ra = await runsAnswer.arrayBuffer();
  const raJson = new DataView(ra).getUint32(0, true);
  const raState = JSON.parse(new TextDecoder().decode(new Uint8Array(ra, 4, raJson)));
  const raRuns = decodeRuns(ra, 4 + raJson);
  const raLabels = (await labels()).face_patches;
  check('edit?labels=runs: the state of the edit, then its labels as labels?format=runs, every triangle\'s patch',
        runsAnswer.status === 200 && raJson % 4 === 0 && raState.alpha === 0.7 && ra.byteLength === 4 + raJson + raRuns.bytes &&
        raRuns.ordered && raRuns.patches === raState.patches && raLabels.every((p, i) => raRuns.faces[i] === p),
        `${raRuns.runs} runs`);
  await post('api/edit', { op: 'undo' });
  check('undo after it: back to the state of the concurrent edits',
        (await post('api/edit', { op: 'undo' })).body.cut_cost === sc2.cut_cost);

  // ---- save, then replay edits.txt with the batch program
  const saved = await post('api/save', {});
  check('save: 200 and the files listed', saved.status === 200 && saved.body.files.includes('edits.txt'));
  const out = editor.outputDir;
  const replay = out + '/replay';
  execFileSync(program, [fandisk, ...crestLines, '--edits', join(out, 'edits.txt'), '--output-dir', replay, '--quiet']);
  for (const f of ['face_patches.txt', 'vertex_patches.txt']) {
    const same = readFileSync(join(out, f), 'utf8') === readFileSync(join(replay, f), 'utf8');
    check(`replaying edits.txt gives the same ${f}`, same);
  }
  const s1 = JSON.parse(readFileSync(join(out, 'summary.json'), 'utf8'));
  const s2 = JSON.parse(readFileSync(join(replay, 'summary.json'), 'utf8'));
  check('replay: same patches and cut cost in summary.json',
        s1.segmentation.patches === s2.segmentation.patches && s1.segmentation.cut_cost === s2.segmentation.cut_cost &&
        s1.segmentation.cut_cost === sc2.cut_cost, `${s1.segmentation.patches} patches`);

  // ---- another crest-line scale (the authors' Q/W/E): recomputed, the history restarts
  const beforeRestart = await state();
  for (const [what, body] of [['no key', {}], ['a radius over 1', { radius: 2 }],
                              ['a negative threshold', { strength_threshold: -1 }], ['an unknown key', { rings: 3 }],
                              ['a string', { radius: 'wide' }]]) {
    const rr = await post('api/restart', body);
    check(`restart: 400 for ${what}`, rr.status === 400, rr.body.error);
  }
  check('restart: the refused requests changed nothing', (await state()).edit_count === beforeRestart.edit_count);
  const wide = await post('api/restart', { radius: 0.03 });
  check('restart at radius 0.03: the default 0.01 is gone, no edits, alpha back to 0.6',
        wide.status === 200 && wide.body.radius === 0.03 && wide.body.edits.length === 0 && wide.body.alpha === 0.6);
  check('restart at radius 0.03: other feature edges', wide.body.feature_edges !== s0.feature_edges,
        `${s0.feature_edges} -> ${wide.body.feature_edges}`);
  await post('api/edit', { op: 'alpha', value: 0.8 });
  await post('api/save', {});
  const header = readFileSync(join(out, 'edits.txt'), 'utf8').split('\n')[1];
  check('edits.txt names the options of its replay, the new radius among them', header.includes(' --radius 0.03 '), header);
  const flags = header.replace(/^# replay: feature_segmentation MESH /, '').replace(/ --edits edits.txt$/, '').split(' ');
  const replay2 = out + '/replay2';
  execFileSync(program, [fandisk, ...flags, '--edits', join(out, 'edits.txt'), '--output-dir', replay2, '--quiet']);
  check('replaying edits.txt with those options gives the same face_patches.txt',
        readFileSync(join(out, 'face_patches.txt'), 'utf8') === readFileSync(join(replay2, 'face_patches.txt'), 'utf8'));
  check('the server still answers after all of it', (await get('api/state')).status === 200);

  // ---- answers of bounded size: the state carries the last 50 edits, the history pages
  const n0 = (await state()).edit_count;
  for (let i = 0; i < 60; ++i) await post('api/edit', { op: 'alpha', value: Number((0.5 + 0.01 * i).toFixed(2)) });
  const long = await state();
  check('60 edits more: the state lists the last 50, and counts them all',
        long.edit_count === n0 + 60 && long.edits.length === 50 && long.edits_from === n0 + 10 &&
        long.edits[49] === 'alpha 1.09', `${long.edit_count} ${long.edits.length} ${long.edits[49]}`);
  const page1 = await get(`api/history?from=${n0}&count=10`);
  check('history from the first of them, 10 edits: the first ten', page1.status === 200 &&
        page1.body.edits.length === 10 && page1.body.edits[0] === 'alpha 0.5' && page1.body.edit_count === n0 + 60,
        page1.body.edits[0]);
  const tail = await get(`api/history?from=${n0 + 55}&count=1000`);
  check('history from the 56th: the last five', tail.body.edits.length === 5 && tail.body.edits[4] === 'alpha 1.09');
  for (const q of ['count=0', 'count=1001', 'from=-1', 'from=x']) {
    const r = await get('api/history?' + q);
    check(`history?${q}: 400`, r.status === 400, r.body.error);
  }
  // the slow clients' headers did not arrive within 10 s: the server closed them
  while (slow.some((x) => x.closedAt === null) && performance.now() - slowStart < 20000)
    await new Promise((r) => setTimeout(r, 200));
  clearInterval(drip);
  const closed = slow.filter((x) => x.closedAt !== null);
  const latest = Math.max(...closed.map((x) => x.closedAt - slowStart));
  check('the slow clients are closed once their 10 s for the headers are over',
        closed.length === 200 && latest >= 9000 && latest < 15000, `${closed.length} closed, the last at ${(latest / 1000).toFixed(1)} s`);
} finally {
  editor.stop();
}
process.exit(summary());
