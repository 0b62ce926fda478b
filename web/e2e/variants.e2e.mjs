// Robustness of the page on edge-case data, with no server: builds file:// reports from
// dev/sample-data.mjs variants (zero frames, one frame, all-null strain, no robot, compare
// with problems, no sessions) and checks each loads cleanly.
//   node web/e2e/variants.e2e.mjs [screenshot-dir]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { main, loadChecks, fail, pass, assertClean, robotStripChecks } from './lib.mjs';

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
    swatches: [...document.querySelectorAll('.legend .score-ramp span')].map((e) => [e.textContent, getComputedStyle(e).backgroundColor]),
  }));
  // The legend: the seven RULA scores, each its own colour, and one scale for every region.
  const labels = r.swatches.map(([k]) => k).join(' ');
  const colours = new Set(r.swatches.map(([, c]) => c));
  if (labels !== '1 2 3 4 5 6 7' || colours.size !== 7) fail(`${name}: the colour legend should show scores 1 … 7 in seven colours, shows "${labels}" in ${colours.size}`);
  if (!/the same in every region/i.test(r.ramp)) fail(`${name}: the legend does not say one colour is one score in every region ("${r.ramp}")`);
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

// The cell's cycle (added later too): the robot's legs, holds and controller events on the
// timeline's strip, the robot card, the parts taken. The sample: six legs (3.0 s home → handover
// … 27.0 s handover → home, its end only planned), holds at 18.0 and 25.3 s, three parts taken.
async function robotFields(b, name) {
  const { page } = b;
  const legacy = name === 'legacy';
  const card = () => page.evaluate(() => ({
    text: document.querySelector('#robot').textContent,
    legs: [...document.querySelectorAll('#robot .leg-name')].map((e) => e.textContent),
    parts: [...document.querySelectorAll('#facts dt')].find((e) => e.textContent === 'Parts taken')?.nextElementSibling?.textContent ?? null,
    marks: document.querySelectorAll('#timeline .rmark').length,
    legend: document.querySelector('#timeline .u-robot')?.textContent ?? null,
  }));
  const r = await card();
  if (legacy) {
    if (r.marks || r.legend || r.legs.length || !/no robot commands recorded/.test(r.text) || r.parts !== 'not recorded') fail(`${name}: data without the robot fields shows them: ${JSON.stringify(r)}`);
    pass(`${name}: no robot strip, legend row or legs without the fields; robot card "${r.text.slice(0, 60)}…", parts taken "${r.parts}"`);
    return;
  }
  const HO = 'home → handover', HH = 'handover → home';
  if (JSON.stringify(r.legs) !== JSON.stringify([HO, HH, HO, HH, HO, HH])) fail(`${name}: the robot card lists the legs ${JSON.stringify(r.legs)}`);
  if (!/6 legs · 3 parts taken · 2 holds/.test(r.text)) fail(`${name}: the robot card's summary reads ${JSON.stringify(r.text.slice(0, 120))}`);
  if (!/aborted/.test(r.text) || !/sent · end planned/.test(r.text) || /feedback #/.test(r.text)) fail(`${name}: the robot card's outcomes: ${JSON.stringify(r.text)}`);
  if (r.parts !== '3') fail(`${name}: the facts count ${JSON.stringify(r.parts)} parts taken`);
  // Feedback is folded into its leg: no marker of its own (the sample has none either; the count is in the tooltip).
  const seen = await robotStripChecks(b, name, { events: true });
  if (!/feedback messages · largest joint error 0\.\d{4} rad/.test(seen.tip)) fail(`${name}: the leg's tooltip has no feedback summary: ${JSON.stringify(seen.tip)}`);
  // The planned-only last leg and the holds: drawn; the readout names the leg under way.
  await page.evaluate(() => window.ergocellReview.seek(4.0));
  await page.waitForTimeout(100);
  const rl = await page.$eval('#readout', (e) => e.querySelector('.rl')?.textContent ?? null);
  if (rl !== `robot ${HO}`) fail(`${name}: at 4.0 s the readout's robot leg reads ${JSON.stringify(rl)}`);
  await page.evaluate(() => window.ergocellReview.seek(11.0));
  await page.waitForTimeout(100);
  if (await page.$('#readout .rl')) fail(`${name}: at 11.0 s no leg is under way, yet the readout names one`);
  // A leg in the card seeks to its start.
  const btn = await page.$$('#robot button[data-t]');
  const legBtn = [];
  for (const x of btn) if (await x.$('.leg-name')) legBtn.push(x);
  await legBtn[2].click();
  const t = await page.evaluate(() => window.ergocellReview.time());
  if (Math.abs(t - 13.0) > 0.051) fail(`${name}: the third leg in the robot card seeks to ${t} s, not 13.0 s`);
  pass(`${name}: robot card lists 6 alternating legs, 3 parts taken, 2 holds; readout "${rl}" at 4.0 s; a leg in the card seeks to ${t.toFixed(2)} s`);
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
      if (name === 'sample' || name === 'legacy') {
        await newFields(b, name);
        await robotFields(b, name);
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
