// SPDX-License-Identifier: GPL-3.0-or-later
// Starts `feature_segmentation edit` on a free port for the editor's tests, and stops it.
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

export const program = join(process.env.FS_BINARY_DIR, 'demo/Feature_segmentation/feature_segmentation');
export const fandisk = join(process.env.FS_MESH_DIR, 'fandisk.off');
// fandisk's figures at the defaults: ../data/fandisk.json, the file the tests of every
// language read them from.
export const fandiskReference = JSON.parse(
  readFileSync(join(dirname(fileURLToPath(import.meta.url)), '..', 'data', 'fandisk.json'), 'utf8'));

// The paper's interactive editing moves the crest lines' alpha_e: on fandisk, a clean
// CAD tessellation whose feature lines are by default its creases alone, the tests ask
// for the crest lines too.
export const crestLines = ['--crest-lines-on-clean-tessellations'];

// Resolves to { url, token, page, outputDir, stop() } once the server prints its address
// (page: the printed address, url: the server's root without the token).
export function startEditor(mesh = fandisk, extra = crestLines) {
  const outputDir = mkdtempSync(join(tmpdir(), 'fs-editor-'));
  const child = spawn(program, ['edit', mesh, '--port', '0', '--quiet', '--output-dir', outputDir, ...extra],
                      { stdio: ['ignore', 'pipe', 'pipe'] });
  let stderr = '';
  child.stderr.on('data', (d) => { stderr += d; });
  return new Promise((resolve, reject) => {
    let stdout = '';
    const timer = setTimeout(() => reject(new Error('the editor did not start in 120 s: ' + stderr)), 120000);
    child.stdout.on('data', (d) => {
      stdout += d;
      const m = stdout.match(/editor: (http:\/\/\S+)/);
      if (m) {
        clearTimeout(timer);
        const page = new URL(m[1]);
        const token = page.searchParams.get('token') || '';
        resolve({ url: page.origin + '/', token, page: m[1], outputDir, child, stop: () => child.kill('SIGTERM') });
      }
    });
    child.on('exit', (code) => { clearTimeout(timer); reject(new Error(`the editor exited (${code}): ${stderr}`)); });
  });
}

// A small assertion counter: every check prints a line; the process fails if one failed.
let failures = 0, checks = 0;
export function check(what, ok, detail = '') {
  ++checks;
  if (!ok) ++failures;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? ' (' + detail + ')' : ''}`);
}
export function summary() {
  console.log(`${checks - failures} of ${checks} checks passed`);
  return failures === 0 ? 0 : 1;
}
