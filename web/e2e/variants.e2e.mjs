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
  ['legacy', ['--legacy']],
];

// The fields added to contract version 1 later: each side's 'uncertain' flag per frame and the
// angles' RULA score edges. Present in the sample (frames 165–179 uncertain on the right);
// older data without them must show neither.
async function newFields(b, name) {
  const { page } = b;
  const legacy = name === 'legacy';
  await page.evaluate(() => window.ergocellReview.seek(17.0));
  await page.waitForTimeout(100);
  const r = await page.evaluate(() => ({
    unc: [...document.querySelectorAll('#readout .gs.unc')].map((e) => `${e.textContent} (${e.title})`),
    readout: document.querySelector('#readout').textContent,
    legend: document.querySelector('#timeline .u-unc')?.textContent ?? null,
    key: document.querySelector('#angles .angle-legend')?.textContent ?? null,
    titles: [...document.querySelectorAll('#angles .hist')].map((e) => e.title).filter(Boolean),
    ramp: document.querySelector('.legend .ramp-note')?.textContent ?? '',
  }));
  if (!/per region/i.test(r.ramp)) fail(`${name}: the strain legend does not say the scale is per region ("${r.ramp}")`);
  if (legacy) {
    if (r.unc.length || r.legend || r.key || r.titles.length) fail(`${name}: data without the new fields shows them: ${JSON.stringify(r)}`);
    pass(`${name}: no uncertain marks or score edges without the fields (readout "${r.readout}")`);
    return;
  }
  if (r.unc.length !== 1 || !/^R \d\?/.test(r.unc[0])) fail(`${name}: at 17.0 s the readout should mark the right score uncertain, has ${JSON.stringify(r.unc)} ("${r.readout}")`);
  if (!r.legend || !/uncertain \(low-confidence landmarks\)R$/.test(r.legend)) fail(`${name}: the timeline legend's uncertain entry reads ${JSON.stringify(r.legend)} at 17.0 s`);
  if (!r.key || !/dotted: where the RULA score changes/.test(r.key)) fail(`${name}: no score-edge legend under "Joint angles" (${r.key})`);
  if (r.titles.length < 6 || !r.titles.some((t) => /90°/.test(t))) fail(`${name}: histograms without score edges: ${JSON.stringify(r.titles)}`);
  // And a frame where neither side is uncertain.
  await page.evaluate(() => window.ergocellReview.seek(5.0));
  await page.waitForTimeout(100);
  const clear = await page.evaluate(() => document.querySelectorAll('#readout .gs.unc').length);
  if (clear) fail(`${name}: at 5.0 s no side is uncertain, the readout marks ${clear}`);
  pass(`${name}: readout "${r.unc[0]}", timeline legend "${r.legend}", ${r.titles.length} histograms with score edges ("${r.titles[0]}")`);
}

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
      if (name === 'sample' || name === 'legacy') await newFields(b, name);
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
