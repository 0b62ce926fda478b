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
  ['sample', []],
  ['zero-frames', ['--frames', '0']],
  ['one-frame', ['--frames', '1']],
  ['null-strain', ['--null-strain']],
  ['no-robot', ['--no-robot']],
  ['compare-problems', ['--compare', '--problems']],
  ['no-sessions', ['--empty']],
];

async function interactions(b) {
  const { page } = b;
  const api = () => page.evaluate(() => ({ f: window.ergocellReview.frame(), p: window.ergocellReview.playing(), df: Number(document.querySelector('canvas.view3d').dataset.frame) }));
  await page.evaluate(() => window.ergocellReview.seek(0));
  await page.click('#step-forward');
  await page.click('#step-forward');
  let r = await api();
  if (r.f !== 2 || r.p) fail(`two clicks on #step-forward from frame 0 gave frame ${r.f} (playing ${r.p})`);
  await page.click('#step-back');
  // Focus is on a button now: space must toggle once (not also "click" the button).
  await page.keyboard.press('Space');
  r = await api();
  if (!r.p) fail('space did not start playback');
  await page.waitForTimeout(500);
  await page.keyboard.press('Space');
  r = await api();
  if (r.p) fail('a second space did not pause');
  const f0 = r.f;
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowLeft');
  await page.waitForTimeout(100);
  r = await api();
  if (r.f !== f0 + 1 || r.df !== r.f) fail(`arrows: expected frame ${f0 + 1}, got ${r.f} (canvas data-frame ${r.df})`);
  // The scrubber seeks.
  await page.$eval('#scrubber', (e) => {
    e.value = '150';
    e.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForTimeout(100);
  r = await api();
  if (r.f !== 150 || r.df !== 150) fail(`the scrubber set to 150 gave frame ${r.f} (data-frame ${r.df})`);
  // 4x plays about four times faster than 1x (10 Hz sample: ~40 frames a second).
  await page.selectOption('#speed', '4');
  await page.click('#play');
  await page.waitForTimeout(1000);
  await page.click('#play');
  r = await api();
  const adv = r.f - 150;
  if (adv < 20 || adv > 80) fail(`at 4x, 1 s of playback advanced ${adv} frames (expected ~40)`);
  await page.selectOption('#speed', '1');
  // Hovering a warning flag shows its message.
  const flag = await page.$('#timeline .wmark .flag');
  if (!flag) fail('no warning flag on the timeline');
  await flag.hover();
  const tip = await page.$eval('#timeline .wmark .tip', (e) => getComputedStyle(e).display !== 'none' && e.textContent);
  if (!tip || !/raised/.test(tip)) fail(`hovering the warning flag shows no message (${tip})`);
  pass(`step buttons, space, arrows, scrubber, 4x speed (${adv} frames in 1 s) and the warning tooltip ("${tip.slice(0, 50)}…") work`);
}

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
      if (name === 'sample') await interactions(b);
      if (name.startsWith('compare')) {
        await b.page.click('#session-select button[data-i="1"]');
        if ((await b.page.evaluate(() => window.ergocellReview.session())) !== 1) fail(`${name}: the session selector did not switch to B`);
        if (!(await b.page.$('.banner'))) fail(`${name}: no problems banner`);
        // A click on B's timeline shows B in 3D at that time; A's does the same for A.
        const overs = await b.page.$$('#timeline .u-over');
        if (overs.length !== 2) fail(`${name}: expected 2 timelines, found ${overs.length}`);
        await b.page.click('#session-select button[data-i="0"]');
        await overs[1].scrollIntoViewIfNeeded();
        const box = await overs[1].boundingBox();
        await b.page.mouse.click(box.x + box.width * 0.5, box.y + box.height * 0.5);
        const r = await b.page.evaluate(() => ({ s: window.ergocellReview.session(), t: window.ergocellReview.time() }));
        if (r.s !== 1 || Math.abs(r.t - 14.95) > 1.5) fail(`${name}: clicking B's timeline mid-way gave session ${r.s} at ${r.t} s`);
      }
      await b.page.waitForTimeout(200);
      assertClean(b, name);
      pass(`${name}: interacts without errors`);
    }
    if (shots) await b.page.screenshot({ path: join(shots, `${name}.png`), fullPage: true });
  }
  rmSync(tmp, { recursive: true, force: true });
});
