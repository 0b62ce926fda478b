// End-to-end check of the review page served by `ergocell review` (or dev/serve.mjs):
//   node web/e2e/review.e2e.mjs <url> <screenshot.png>
// Uses Debian's chromium (/usr/bin/chromium, or $CHROMIUM). Exits non-zero on the first failure.
import { main, loadChecks, screenshot, fail, pass, robotStripChecks } from './lib.mjs';

const [url, shot] = process.argv.slice(2);
if (!url || !shot) {
  console.error('usage: node review.e2e.mjs <url> <screenshot.png>');
  process.exit(2);
}

await main(async (b) => {
  const { page } = b;
  const n = await loadChecks(b, url);
  if (n < 2) fail(`the recording has ${n} frame(s); play and timeline checks need at least 2`);

  // 2. play advances the counter; pause stops it.
  const counter = () => page.textContent('#frame-counter');
  const before = await counter();
  await page.click('#play');
  await page
    .waitForFunction((b0) => document.querySelector('#frame-counter').textContent !== b0, before, { timeout: 2500 })
    .catch(() => fail(`pressing play did not advance the frame counter within 2 s (still "${before}")`));
  await page.waitForTimeout(300);
  const during = await counter();
  await page.click('#play');
  if (await page.evaluate(() => window.ergocellReview.playing())) fail('clicking #play a second time did not pause');
  const paused = await counter();
  await page.waitForTimeout(1000);
  const later = await counter();
  if (later !== paused) fail(`after pause the counter still moved: "${paused}" -> "${later}"`);
  pass(`play advances the counter ("${before}" -> "${during}"); pause stops it ("${paused}" unchanged over 1 s)`);

  // 3. a click at 70 % of the timeline's plotting area moves the 3D view there.
  const over = await page.$('#timeline .u-over');
  if (!over) fail('no timeline plot (#timeline .u-over) on the page');
  await over.scrollIntoViewIfNeeded();
  const box = await over.boundingBox();
  const frameBefore = await page.evaluate(() => window.ergocellReview.frame());
  await page.mouse.click(box.x + box.width * 0.7, box.y + box.height * 0.5);
  await page.waitForTimeout(300);
  const r = await page.evaluate(() => {
    const api = window.ergocellReview;
    const frame = Number(document.querySelector('canvas.view3d').getAttribute('data-frame'));
    return { frame, api: api.frame(), t: api.timeOf(frame), t0: api.timeOf(0), t1: api.timeOf(api.frameCount() - 1) };
  });
  if (r.frame !== r.api) fail(`canvas data-frame ${r.frame} differs from ergocellReview.frame() ${r.api}`);
  if (r.frame === frameBefore) fail(`the timeline click left the 3D view at frame ${r.frame}`);
  const share = (r.t - r.t0) / (r.t1 - r.t0);
  if (!(Math.abs(share - 0.7) <= 0.1)) fail(`clicking the timeline at 70 % went to frame ${r.frame} at ${r.t.toFixed(2)} s, ${(share * 100).toFixed(1)} % of the duration (expected 60–80 %)`);
  pass(`timeline click at 70 % moves the 3D view (canvas data-frame) from frame ${frameBefore} to ${r.frame} (${r.t.toFixed(2)} s, ${(share * 100).toFixed(1)} % of ${(r.t1 - r.t0).toFixed(2)} s)`);

  const text = await counter();
  if (!text.startsWith(`frame ${r.frame + 1} / ${n}`)) fail(`the counter reads "${text}" after the timeline click (expected frame ${r.frame + 1} / ${n})`);
  const scrub = await page.$eval('#scrubber', (e) => Number(e.value));
  if (scrub !== r.frame) fail(`the scrubber is at ${scrub}, not at frame ${r.frame}`);
  pass(`counter ("${text}") and scrubber follow the timeline click`);

  // 4. the robot's legs on the timeline's strip (the demo sends at least the leg to the handover).
  await robotStripChecks(b, 'the recording');
  const card = await page.textContent('#robot');
  if (!/home → handover/.test(card)) fail(`the robot card lists no leg home → handover: ${JSON.stringify(card.slice(0, 200))}`);

  // 5. REBA beside RULA, the task segments and ISO 11226's static postures (#20).
  const rows = await page.$$eval('#regions tbody th', (ths) => ths.map((t) => t.textContent));
  if (!rows.some((r) => /REBA score/.test(r))) fail(`the body regions table has no REBA row: ${JSON.stringify(rows)}`);
  if (!rows.some((r) => /Action level/.test(r))) fail(`the body regions table has no action level row: ${JSON.stringify(rows)}`);
  const phases = await page.$$eval('#segments tr[data-phase]', (trs) => trs.map((t) => t.getAttribute('data-phase')));
  for (const want of ['walking', 'floor pick', 'handover']) {
    if (!phases.includes(want)) fail(`the task segments table has no "${want}" row: ${JSON.stringify(phases)}`);
  }
  // the posture cost beside RULA: a number of RULA points per segment, the floor pick's above the
  // handover's (a bent trunk against a hand at elbow height)
  const costs = Object.fromEntries(await page.$$eval('#segments tr[data-phase]', (trs) =>
    trs.map((t) => [t.getAttribute('data-phase'), Number(t.querySelector('td.posture-cost')?.textContent)])));
  for (const want of ['walking', 'floor pick', 'handover']) {
    if (!(costs[want] >= 1 && costs[want] < 8)) fail(`the ${want} row's posture cost is not a RULA-points number: ${JSON.stringify(costs)}`);
  }
  if (!(costs['floor pick'] > costs.handover)) fail(`the floor pick's posture cost is not above the handover's: ${JSON.stringify(costs)}`);
  const parts = await page.$$eval('#segments tr[data-part]', (trs) => trs.map((t) => t.getAttribute('data-part')));
  if (parts.join() !== 'trunk,neck,left_upper_arm,right_upper_arm') fail(`the static postures table lists ${JSON.stringify(parts)}, not trunk, neck and both upper arms`);
  pass(`REBA and action level rows in the regions table; task segments ${phases.join(', ')} (posture cost ${JSON.stringify(costs)}); static postures of ${parts.join(', ')}`);

  // 6. the height class with the decision's probability, expected RULA cost and basis (the demo's
  // operator stands 1 cm above the c1/c2 boundary).
  const facts = await page.textContent('#facts');
  if (!/Height class\s*c[123]\s*probability (0\.\d\d|1\.00), expected RULA cost [+-]\d\.\d\d/.test(facts)) {
    fail(`the session facts lack the class decision's probability and cost: ${JSON.stringify(facts.slice(0, 300))}`);
  }
  pass(`the class decision is in the session facts: ${JSON.stringify(facts.match(/Height class.*?(boundary[^A-Z]*|class)(?=[A-Z])/s)?.[0] ?? '')}`);

  // 7. how sure each score is: every warning says how sure its band was, and the frame's readout
  // names its least sure region with its probability.
  const sure = await page.$$eval('#warnings ol.events li:not(.muted)', (lis) => lis.map((li) => li.querySelector('.sure')?.textContent ?? null));
  if (!sure.length) fail('the recording has no posture warning to check');
  if (sure.some((t) => t === null)) fail(`a warning does not say how sure it is: ${JSON.stringify(sure)}`);
  if (!sure.some((t) => /\d+ % sure/.test(t))) fail(`no warning states its band's probability: ${JSON.stringify(sure)}`);
  const readoutSure = await page.textContent('#readout .sure').catch(() => null);
  if (!readoutSure || !/^[a-z ]+ \d+ % sure$/.test(readoutSure)) fail(`the frame readout does not say how sure its scores are: ${JSON.stringify(readoutSure)}`);
  pass(`each of the ${sure.length} warnings says how sure it is (e.g. "${sure.find((t) => /%/.test(t)).trim()}"); the frame readout: "${readoutSure}"`);

  // 8. the screenshot.
  await page.mouse.move(5, 5);
  await page.waitForTimeout(200);
  await screenshot(b, shot);
});
