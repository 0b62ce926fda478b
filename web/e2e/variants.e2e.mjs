// Robustness of the page on edge-case data, with no server: builds file:// reports from
// dev/sample-data.mjs variants (zero frames, one frame, all-null strain, no robot, compare
// with problems, no sessions) and checks each loads cleanly.
//   node web/e2e/variants.e2e.mjs [screenshot-dir]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { main, loadChecks, fail, pass, assertClean } from './lib.mjs';

const web = join(dirname(fileURLToPath(import.meta.url)), '..');
const shots = process.argv[2];
const tmp = mkdtempSync(join(tmpdir(), 'ergocell-variants-'));
const variants = [
  ['zero-frames', ['--frames', '0']],
  ['one-frame', ['--frames', '1']],
  ['null-strain', ['--null-strain']],
  ['no-robot', ['--no-robot']],
  ['compare-problems', ['--compare', '--problems']],
  ['no-sessions', ['--empty']],
];

await main(async (b) => {
  for (const [name, args] of variants) {
    const json = join(tmp, `${name}.json`);
    const html = join(tmp, `${name}.html`);
    execFileSync('node', [join(web, 'dev/sample-data.mjs'), json, ...args]);
    execFileSync('node', [join(web, 'dev/report.mjs'), json, html]);
    const url = pathToFileURL(html).href;
    if (name === 'no-sessions') {
      await b.page.goto(url, { waitUntil: 'load' });
      const text = await b.page.textContent('#app');
      if (!/Nothing to review/.test(text)) fail(`${name}: expected a "Nothing to review" message, page says ${JSON.stringify(text.slice(0, 200))}`);
      assertClean(b, name);
      pass(`${name}: shows "${text.trim().slice(0, 60)}…"`);
    } else {
      const n = await loadChecks(b, url);
      if (n > 0) {
        await b.page.click('#play');
        await b.page.waitForTimeout(400);
        await b.page.click('#step-back');
        await b.page.keyboard.press('ArrowRight');
        await b.page.keyboard.press('Space');
        await b.page.waitForTimeout(200);
        await b.page.keyboard.press('Space');
      }
      if (name.startsWith('compare')) {
        await b.page.click('#session-select button[data-i="1"]');
        if ((await b.page.evaluate(() => window.ergocellReview.session())) !== 1) fail(`${name}: the session selector did not switch to B`);
        if (!(await b.page.$('.banner'))) fail(`${name}: no problems banner`);
      }
      await b.page.waitForTimeout(200);
      assertClean(b, name);
      pass(`${name}: interacts without errors`);
    }
    if (shots) await b.page.screenshot({ path: join(shots, `${name}.png`), fullPage: true });
  }
  rmSync(tmp, { recursive: true, force: true });
});
