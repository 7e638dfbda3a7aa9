// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's page on a large part, in a real browser (Debian's Chromium, headless, with
// software WebGL, driven by playwright-core from the editor's npm install). The part:
// CGAL's blade (16,222 faces) subdivided flat 3 times (each triangle into four by its
// edge midpoints): 1,038,208 faces, written as OFF in --work. `feature_segmentation edit`
// is started on it at its defaults; once it prints its address (the server is ready), the
// page is opened. Measured:
//   - load: from opening the page to the mesh drawn and coloured by patch (the page's
//     `editor.loadMs`: the binary mesh and labels; the feature lines and boundaries are
//     drawn when they arrive, after);
//   - alpha round trip: an alpha edit from the slider to the new colours drawn (the
//     page's `editor.lastRoundTripMs`: one request answered with the new state and the
//     binary labels, then colours and redraw), alternately 1.0 and 0.6, --repeat times,
//     each once the boundaries before it are drawn and two animation frames have passed
//     (the page idle, as between a user's moves); median and maximum, and the server's
//     own time of the edit.
// Prints a table and writes CSV and Markdown (--out, default editor_page.csv and .md).
//
// Usage: node bench_editor_page.mjs [--levels 3] [--repeat 9] [--work DIR] [--out FILE]
// Environment (the build's target bench_editor_page sets them): FS_BINARY_DIR (the build
// folder, with the program), FS_MESH_DIR (CGAL's meshes), FS_NODE_MODULES (playwright-core),
// FS_CHROMIUM (default /usr/bin/chromium).
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { cpus } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';

const { values: opt } = parseArgs({ options: {
  levels: { type: 'string', default: '3' }, repeat: { type: 'string', default: '9' },
  work: { type: 'string', default: 'bench_editor_page_work' }, out: { type: 'string', default: 'editor_page.csv' } } });
const levels = Number(opt.levels), repeat = Number(opt.repeat);
if (!(Number.isInteger(levels) && levels >= 0 && levels <= 4)) throw new Error('--levels must be in 0 .. 4');
if (!(Number.isInteger(repeat) && repeat >= 1 && repeat <= 100)) throw new Error('--repeat must be in 1 .. 100');
for (const name of ['FS_BINARY_DIR', 'FS_MESH_DIR', 'FS_NODE_MODULES'])
  if (!process.env[name]) throw new Error(`${name} is not set (run the build's target bench_editor_page)`);
const browserPath = process.env.FS_CHROMIUM || '/usr/bin/chromium';
if (!existsSync(browserPath)) throw new Error(`no browser at ${browserPath} (install Debian's chromium, or set FS_CHROMIUM)`);
const program = join(process.env.FS_BINARY_DIR, 'demo/Feature_segmentation/feature_segmentation');
const { chromium } = createRequire(join(process.env.FS_NODE_MODULES, 'index.js'))('playwright-core');

// ---- the part: blade, subdivided flat `levels` times
function readOff(path) {
  const words = readFileSync(path, 'utf8').split('\n').filter((l) => !l.startsWith('#')).join(' ').split(/\s+/).filter(Boolean);
  if (!words[0].endsWith('OFF')) throw new Error(`${path}: not an OFF file`);
  const nv = Number(words[1]), nf = Number(words[2]);
  let k = 4;
  const points = [];
  for (let i = 0; i < nv; ++i, k += 3) points.push([Number(words[k]), Number(words[k + 1]), Number(words[k + 2])]);
  const triangles = [];
  for (let f = 0; f < nf; ++f) {
    const n = Number(words[k]);
    if (n !== 3) throw new Error(`${path}: face ${f} is not a triangle`);
    triangles.push([Number(words[k + 1]), Number(words[k + 2]), Number(words[k + 3])]);
    k += 1 + n;
  }
  return { points, triangles };
}
function subdivide({ points, triangles }) {
  const midpoint = new Map();
  const mid = (a, b) => {
    const key = Math.min(a, b) * points.length + Math.max(a, b);
    let m = midpoint.get(key);
    if (m === undefined) {
      m = points.length + midpoint.size;
      midpoint.set(key, m);
      extra.push(points[a].map((x, c) => 0.5 * (x + points[b][c])));
    }
    return m;
  };
  const extra = [], out = [];
  for (const [a, b, c] of triangles) {
    const ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.push([a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]);
  }
  return { points: points.concat(extra), triangles: out };
}
mkdirSync(opt.work, { recursive: true });
let soup = readOff(join(process.env.FS_MESH_DIR, 'blade.off'));
for (let l = 0; l < levels; ++l) soup = subdivide(soup);
const meshPath = join(opt.work, `blade_x${4 ** levels}.off`);
writeFileSync(meshPath, `OFF\n${soup.points.length} ${soup.triangles.length} 0\n` +
  soup.points.map((p) => p.join(' ')).join('\n') + '\n' + soup.triangles.map((t) => '3 ' + t.join(' ')).join('\n') + '\n');
const faces = soup.triangles.length;
soup = null;

// ---- the server, then the page
const serverStart = performance.now();
const child = spawn(program, ['edit', meshPath, '--port', '0', '--quiet', '--output-dir', join(opt.work, 'out')],
                    { stdio: ['ignore', 'pipe', 'pipe'] });
let stderr = '';
child.stderr.on('data', (d) => { stderr += d; });
const address = await new Promise((resolve, reject) => {
  let stdout = '';
  child.stdout.on('data', (d) => {
    stdout += d;
    const m = stdout.match(/editor: (http:\/\/\S+)/);
    if (m) resolve(m[1]);
  });
  child.on('exit', (code) => reject(new Error(`the editor exited (${code}): ${stderr}`)));
});
const serverSeconds = (performance.now() - serverStart) / 1000;
const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const browser = await chromium.launch({ executablePath: browserPath,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'] });
let row;
try {
  const page = await (await browser.newContext({ viewport: { width: 1100, height: 700 } })).newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(address);
  await page.waitForFunction(() => window.editor && window.editor.ready === true, null, { timeout: 300000 });
  const loadMs = await page.evaluate(() => window.editor.loadMs);
  const patchesAtStart = Number(await page.textContent('#patches'));
  // the feature lines and boundaries the page fetches after showing the part
  await page.waitForFunction(() => window.editor.overlaysPending === 0, null, { timeout: 300000 });
  const trips = [], server = [], splits = { edit: [], draw: [] };
  for (let i = 0; i < repeat; ++i) {
    const value = i % 2 === 0 ? '1' : '0.6';
    await page.evaluate((v) => {
      window.editor.lastRoundTripMs = null;
      const slider = document.getElementById('alpha');
      slider.value = v;
      slider.dispatchEvent(new Event('change'));
    }, value);
    await page.waitForFunction(() => window.editor.lastRoundTripMs !== null && window.editor.inflight === 0, null, { timeout: 120000 });
    trips.push(await page.evaluate(() => window.editor.lastRoundTripMs));
    // the feature lines and boundaries the page fetches next, before the next edit
    await page.waitForFunction(() => window.editor.overlaysPending === 0, null, { timeout: 120000 });
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    server.push(1000 * await page.evaluate(() => window.editor.current.last_edit.server_seconds));
    const split = await page.evaluate(() => window.editor.lastSplitMs);
    for (const k of Object.keys(splits)) splits[k].push(split[k]);
  }
  if (errors.length) throw new Error('the page reported: ' + errors.join('; '));
  row = { mesh: `blade x${4 ** levels}`, faces, server_ready_s: serverSeconds, patches: patchesAtStart, load_ms: loadMs,
          alpha_round_trip_ms_median: median(trips), alpha_round_trip_ms_max: Math.max(...trips),
          alpha_server_ms_median: median(server), alpha_edit_request_ms_median: median(splits.edit),
          alpha_draw_ms_median: median(splits.draw) };
} finally {
  await browser.close();
  child.kill('SIGTERM');
}

const cpu = (cpus()[0] || { model: 'unknown' }).model.trim();
const keys = Object.keys(row);
writeFileSync(opt.out, keys.join(',') + '\n' + keys.map((k) => typeof row[k] === 'number' ? +row[k].toFixed(3) : `"${row[k]}"`).join(',') + '\n');
const md = `The editor's page at a million faces (\`bench_editor_page\`, ${cpu}, ${cpus().length} cores; headless Chromium, ` +
  `software WebGL): ${row.mesh}, ${faces} faces, the program at its defaults.\n\n` +
  '| mesh | faces | server ready s | patches | page load ms | alpha round trip ms (median / max) | of which: edit request with labels (server) | colours and redraw |\n' +
  '|---|---:|---:|---:|---:|---:|---:|---:|\n' +
  `| ${row.mesh} | ${faces} | ${row.server_ready_s.toFixed(1)} | ${row.patches} | ${row.load_ms.toFixed(0)} | ` +
  `${row.alpha_round_trip_ms_median.toFixed(0)} / ${row.alpha_round_trip_ms_max.toFixed(0)} | ` +
  `${row.alpha_edit_request_ms_median.toFixed(0)} (${row.alpha_server_ms_median.toFixed(0)}) | ` +
  `${row.alpha_draw_ms_median.toFixed(0)} |\n\n` +
  `${row.load_ms <= 5000 ? 'PASS' : 'MISS'}  the page shows the part within 5 s of the server being ready\n` +
  `${row.alpha_round_trip_ms_median <= 100 ? 'PASS' : 'MISS'}  an alpha edit's round trip within 100 ms (median of ${repeat})\n`;
writeFileSync(opt.out.replace(/\.csv$/, '') + '.md', md);
// the provenance the manual prints under the table (as provenance.h writes it)
const today = new Date().toISOString().slice(0, 10);
writeFileSync(opt.out.replace(/\.csv$/, '') + '.provenance.txt', `program: bench_editor_page\narguments: ${process.argv.slice(2).join(' ')}\n` +
  `machine: ${cpu}, ${cpus().length} cores\ndate: ${today}\n`);
console.log(md);
console.log(`Written: ${opt.out}`);
