// SPDX-License-Identifier: GPL-3.0-or-later
// The editor's page in a real browser: Debian's Chromium, headless, driven by
// playwright-core (from npm, pinned by the editor's package-lock.json). Loads the page on
// fandisk, checks that the canvas draws the mesh, moves the alpha slider and sees the
// patch count change (data/fandisk.json: patches, then set_alpha_1_with_crest_lines at
// alpha 1), merges two patches
// with a Ctrl-drag stroke and sees the count drop, undoes; a page of another origin, open
// in the same browser (so with the editor's cookie), tries to read and drive the editor
// (a fetch, a no-cors fetch, a form) and cannot; then it saves a screenshot for
// the manual (FS_EDITOR_SCREENSHOT, default: the build folder). Exits 77 (skipped, with
// a message) only where no browser exists.
import { existsSync } from 'node:fs';
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { startEditor, check, summary, fandiskReference as ref } from './server.mjs';

const atAlpha1 = String(ref.set_alpha_1_with_crest_lines);

const browserPath = process.env.FS_CHROMIUM || '/usr/bin/chromium';
if (!existsSync(browserPath)) {
  console.log(`SKIPPED: no browser at ${browserPath} (install Debian's chromium, or set FS_CHROMIUM)`);
  process.exit(77);
}
const require = createRequire(join(process.env.FS_NODE_MODULES, 'index.js'));
const { chromium } = require('playwright-core');
const screenshot = process.env.FS_EDITOR_SCREENSHOT || join(process.env.FS_BINARY_DIR, 'editor_screenshot.png');

const editor = await startEditor();
const browser = await chromium.launch({
  executablePath: browserPath,
  // software WebGL: CI machines have no GPU
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});
try {
  const context = await browser.newContext({ viewport: { width: 1100, height: 700 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // WebGL's errors (a shader that does not compile) reach the console, not pageerror
  page.on('console', (m) => { if (m.type() === 'error' && /WebGL|Shader/.test(m.text())) errors.push(m.text().slice(0, 300)); });
  await page.goto(editor.page); // the printed address, with its token
  await page.waitForFunction(() => window.editor && window.editor.ready === true, null, { timeout: 60000 });
  const patches = async () => Number(await page.textContent('#patches'));

  // ---- a page of another origin (same host, another port: the editor's cookie goes along)
  const editCount = async () => (await (await fetch(editor.url + 'api/state', { headers: { 'X-Editor-Token': editor.token } })).json()).edit_count;
  const countBefore = await editCount();
  const attack = `<!doctype html><iframe name="sink"></iframe>
    <form id="f" method="POST" action="${editor.url}api/edit" enctype="text/plain" target="sink">
      <input name='{"op":"alpha","value":2,"x":"' value='"}'></form>
    <script>
      window.results = {};
      const api = ${JSON.stringify(editor.url)} + 'api/';
      const body = JSON.stringify({ op: 'alpha', value: 3 });
      (async () => {
        try { await (await fetch(api + 'state', { credentials: 'include' })).json(); window.results.read = 'read'; }
        catch (e) { window.results.read = 'blocked'; }
        try { await fetch(api + 'edit', { method: 'POST', credentials: 'include', headers: { 'Content-Type': 'application/json' }, body });
              window.results.json = 'sent'; }
        catch (e) { window.results.json = 'blocked'; }
        try { await fetch(api + 'edit', { method: 'POST', mode: 'no-cors', credentials: 'include', headers: { 'Content-Type': 'text/plain' }, body });
              window.results.noCors = 'sent'; }
        catch (e) { window.results.noCors = 'blocked'; }
        document.getElementById('f').submit();
        window.results.form = 'submitted';
      })();
    </script>`;
  const attacker = createServer((req, res) => { res.writeHead(200, { 'Content-Type': 'text/html' }); res.end(attack); });
  await new Promise((r) => attacker.listen(0, '127.0.0.1', r));
  const evil = await context.newPage();
  await evil.goto(`http://127.0.0.1:${attacker.address().port}/`);
  await evil.waitForFunction(() => window.results && window.results.form === 'submitted', null, { timeout: 30000 });
  await evil.waitForTimeout(1500); // the form's request
  const results = await evil.evaluate(() => window.results);
  check('a page of another origin cannot read the state', results.read === 'blocked', JSON.stringify(results));
  check('its JSON fetch is stopped by the refused preflight', results.json === 'blocked');
  check('its no-cors fetch and its text/plain form change nothing', (await editCount()) === countBefore,
        `${countBefore} edits before, ${await editCount()} after`);
  await evil.close();
  attacker.close();

  check(`the page loads and shows ${ref.patches} patches`, (await patches()) === ref.patches);

  // the canvas draws the mesh: many non-white pixels in many colours
  const drawn = await page.evaluate(() => {
    const src = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = src.width; c.height = src.height;
    const g = c.getContext('2d');
    g.drawImage(src, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let covered = 0;
    const colours = new Set();
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 250 || d[i + 1] < 250 || d[i + 2] < 250) ++covered;
      colours.add((d[i] >> 4) * 256 + (d[i + 1] >> 4) * 16 + (d[i + 2] >> 4));
    }
    return { share: covered / (d.length / 4), colours: colours.size };
  });
  check('the canvas draws the mesh (over 10% of it covered, over 20 colours)',
        drawn.share > 0.1 && drawn.colours > 20, `${(100 * drawn.share).toFixed(1)}%, ${drawn.colours} colours`);

  // alpha slider to 1.0
  await page.$eval('#alpha', (el) => { el.value = '1'; el.dispatchEvent(new Event('change')); });
  await page.waitForFunction((n) => document.querySelector('#patches').textContent === n, atAlpha1, { timeout: 30000 });
  check(`moving the alpha slider to 1 gives ${atAlpha1} patches`, (await patches()) === ref.set_alpha_1_with_crest_lines);
  const lastEdit = await page.textContent('#last-edit');
  check('the time of the last edit is shown', /^alpha: [0-9.]+ ms$/.test(lastEdit), lastEdit);

  // Ctrl-drag across the model: the patches the stroke touches merge
  const box = await page.locator('#view canvas').boundingBox();
  // a diagonal from the upper left to the lower right of the view, across several faces
  const at = (t) => [box.x + box.width * (0.3 + 0.4 * t), box.y + box.height * (0.3 + 0.4 * t)];
  await page.keyboard.down('Control');
  await page.mouse.move(...at(0));
  await page.mouse.down();
  for (let i = 1; i <= 30; ++i) await page.mouse.move(...at(i / 30));
  await page.mouse.up();
  await page.keyboard.up('Control');
  await page.waitForFunction((n) => document.querySelector('#patches').textContent !== n, atAlpha1, { timeout: 30000 });
  const merged = await patches();
  check('a Ctrl-drag stroke merges patches', merged < ref.set_alpha_1_with_crest_lines, `${merged} patches`);
  const state = await page.evaluate(() => window.editor.current);
  check('the stroke arrived as one merge edit', state.edits[state.edits.length - 1].startsWith('merge triangles '));

  // undo with the button
  await page.click('#undo');
  await page.waitForFunction((n) => document.querySelector('#patches').textContent === n, atAlpha1, { timeout: 30000 });
  await page.waitForFunction(() => window.editor.inflight === 0, null, { timeout: 30000 });
  check(`undo gives the ${atAlpha1} patches back`, (await patches()) === ref.set_alpha_1_with_crest_lines);

  // Shift-drag paints a region; Refine sends it as a local edit
  await page.keyboard.down('Shift');
  await page.mouse.move(...at(0.45));
  await page.mouse.down();
  for (let i = 1; i <= 10; ++i) await page.mouse.move(...at(0.45 + 0.01 * i));
  await page.mouse.up();
  await page.keyboard.up('Shift');
  const painted = Number(await page.textContent('#region-size'));
  check('a Shift-drag stroke paints a region', painted > 0, `${painted} faces`);
  await page.click('#refine');
  await page.waitForFunction(() => window.editor.current.edits.length === 4 && window.editor.inflight === 0, null,
                             { timeout: 30000 });
  const refined = (await (await fetch(editor.url + 'api/history?from=3&count=1',
                                      { headers: { 'X-Editor-Token': editor.token } })).json()).edits[0];
  check('Refine sends the painted faces as a local refinement', refined.startsWith('refine triangles ') &&
        refined.split(' ').length === painted + 3, refined.slice(0, 40) + '...');
  // the feature lines and boundaries are drawn after the colours: wait for them
  await page.waitForFunction(() => window.editor.overlaysPending === 0, null, { timeout: 30000 });
  check('no script or WebGL error on the page', errors.length === 0, errors.join('; '));
  await page.screenshot({ path: screenshot });
  console.log(`screenshot: ${screenshot}`);
} finally {
  await browser.close();
  editor.stop();
}
process.exit(summary());
