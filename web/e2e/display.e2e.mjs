// The operator display (`ergocell demo --display`) in headless Chromium:
//   node web/e2e/display.e2e.mjs <url> <screenshot.png> [restart [tasks]]
// Checks: the page connects and shows the session's state as it changes; a posture warning appears
// with its advice and the action level's colour, and the height class with its probability; after a reload the current state is back at once
// (the server sends its snapshot on connect); with `restart`, when the server goes away the page says
// so and, once a server is back on the same address, reconnects by itself. Prints the event-to-screen
// latency (server send time → after the next paint, same machine clock) of every update it rendered.
// With `tasks` (the restarted server runs the station's task mix), a warning is raised and then
// cleared on screen: the region's line appears and goes away again.
// Against docs/operator.md (read here, so the guide and the screen cannot drift apart): every top-bar
// text the page showed is one the guide explains (the hold reasons among them), every posture band
// reads as the guide's example does, in the colour the guide names for its action level, with the
// action level RULA gives its score, and no coloured band shows while the operator is asked to stand
// straight.
import { readFileSync } from 'node:fs';
import { main, pass, fail, screenshot, quantile, openDisplay } from './lib.mjs';

/** What docs/operator.md says the screen shows. */
function operatorGuide() {
  const md = readFileSync('docs/operator.md', 'utf8');
  const bands = {};
  for (const [, colour, label] of md.matchAll(/\*\*(Green|Yellow|Orange|Red)\*\*, "([^"]+)"/g)) bands[colour] = label.replace(/\.$/, '');
  const section = md.slice(md.indexOf('## What the top bar says'), md.indexOf('## Posture warnings'));
  // Each item's bold words (an item may name two: "**Height measured** and **Robot path locked…**").
  const states = section
    .split('\n')
    .filter((l) => l.startsWith('- **'))
    .flatMap((l) => [...l.matchAll(/\*\*([^*]+?)\.?\*\*/g)].map((m) => m[1].replace(/ — \(.*$/, '')));
  const holds = [...section.matchAll(/^ {2}- "([^"]+)"/gm)].map((m) => m[1]);
  const flat = md.replace(/\n\s*/g, ' ');
  const measuring = /it reads "(Posture: shown once your height is measured)"/.exec(flat)?.[1];
  const example = /e\.g\. "(Posture: [^"]+)"/.exec(flat)?.[1];
  return { bands, states, holds, measuring, example };
}

// RULA's action level for a grand score (McAtamney & Corlett 1993): 1–2 → 1, 3–4 → 2, 5–6 → 3, 7 → 4.
const actionLevel = (g) => (g <= 2 ? 1 : g <= 4 ? 2 : g <= 6 ? 3 : 4);
const COLOUR_OF_LEVEL = ['', 'Green', 'Yellow', 'Orange', 'Red'];

/** Whether an rgb() colour is the named one, by its hue. */
function looksLike(rgb, name) {
  const [r, g, b] = (rgb.match(/\d+/g) || []).map(Number);
  if (r == null) return false;
  const max = Math.max(r, g, b), min = Math.min(r, g, b);
  if (max - min < 40) return false;
  let h;
  if (max === r) h = (60 * ((g - b) / (max - min)) + 360) % 360;
  else if (max === g) h = 60 * ((b - r) / (max - min)) + 120;
  else h = 60 * ((r - g) / (max - min)) + 240;
  return { Green: h >= 90 && h <= 170, Yellow: h >= 45 && h < 70, Orange: h >= 20 && h < 45, Red: h < 20 || h >= 340 }[name];
}

/** Checks everything the page showed (recorded by the observer below) against the guide. */
function checkAgainstGuide(seen, guide) {
  if (Object.keys(guide.bands).length !== 4 || !guide.states.length || !guide.holds.length || !guide.measuring || !guide.example) {
    fail(`docs/operator.md no longer reads as this check expects: ${JSON.stringify(guide)}`);
  }
  const band = /^(.+) \(RULA score (\d) of 7, action level (\d)\)$/;
  const ex = band.exec(guide.example);
  if (!ex || guide.bands[COLOUR_OF_LEVEL[Number(ex[3])]] !== ex[1]) fail(`the guide's own example "${guide.example}" does not match its colours`);
  if (!seen.length) fail('the page recorded no picture to check against the guide');
  const bandsSeen = new Set();
  const statesSeen = new Set();
  for (const o of seen) {
    const top = o.held ? o.stateText.replace(/^ROBOT HELD — /, '') : o.stateText.replace(/ — class c\d$/, ' — class c2');
    if (o.held) {
      if (!guide.holds.includes(top)) fail(`the hold "${o.stateText}" is not among the guide's reasons: ${JSON.stringify(guide.holds)}`);
    } else if (!guide.states.includes(top)) fail(`the top bar's "${o.stateText}" is not in the guide: ${JSON.stringify(guide.states)}`);
    statesSeen.add(o.held ? `ROBOT HELD — ${top}` : top);
    const level = Number(o.level);
    if (level === 0) {
      if (o.measuring && !o.warnings && o.bandText !== guide.measuring) fail(`while the operator is measured the band reads "${o.bandText}", not "${guide.measuring}"`);
      continue;
    }
    if (o.measuring && !o.warnings) fail(`a coloured band ("${o.bandText}") while the operator is asked to stand straight, with no warning up`);
    const m = band.exec(o.bandText);
    if (!m) fail(`the band "${o.bandText}" does not read as the guide's "${guide.example}"`);
    const [, label, score, al] = m;
    if (Number(al) !== level || actionLevel(Number(score)) !== level) fail(`the band "${o.bandText}": RULA score ${score} is action level ${actionLevel(Number(score))}, the band says ${al}, its colour is level ${level}`);
    const colour = COLOUR_OF_LEVEL[level];
    if (label !== guide.bands[colour]) fail(`action level ${level} reads "${label}", the guide says ${colour}, "${guide.bands[colour]}"`);
    if (!looksLike(o.bandColour, colour)) fail(`action level ${level} is drawn in ${o.bandColour}, which is not ${colour.toLowerCase()} as the guide says`);
    bandsSeen.add(`${colour}: ${o.bandText}`);
  }
  if (!bandsSeen.size) fail(`no posture band was shown in ${seen.length} pictures`);
  return { bandsSeen: [...bandsSeen], statesSeen: [...statesSeen] };
}

const [url, shot, restart, tasks] = process.argv.slice(2);
if (!url || !shot) {
  console.error('usage: node display.e2e.mjs <url> <screenshot.png> [restart]');
  process.exit(2);
}

const ACTIVE = ['measuring_height', 'class_decided', 'trajectory_locked', 'working', 'held'];

await main(async (b) => {
  const { page } = b;
  const guide = operatorGuide();
  // Every picture the page shows, as it changes: recorded in the page, checked at the end.
  await page.addInitScript(() => {
    window.__seen = [];
    const record = () => {
      const st = document.getElementById('state');
      const lv = document.getElementById('level');
      if (!st || !lv || !st.dataset.state) return;
      const o = {
        state: st.dataset.state,
        held: st.dataset.state === 'held',
        measuring: ['waiting_for_operator', 'measuring_height'].includes(st.dataset.state),
        stateText: st.textContent,
        level: lv.dataset.level,
        bandText: lv.textContent,
        bandColour: getComputedStyle(lv).backgroundColor,
        warnings: document.querySelectorAll('#warnings li').length,
      };
      const last = window.__seen[window.__seen.length - 1];
      if (!last || JSON.stringify(last) !== JSON.stringify(o)) window.__seen.push(o);
    };
    document.addEventListener('DOMContentLoaded', () => {
      new MutationObserver(record).observe(document.body, { subtree: true, childList: true, characterData: true, attributes: true });
    });
  });
  await openDisplay(page, url);
  pass('the page connects to the event stream');
  await page.waitForFunction((active) => active.includes(document.getElementById('state').dataset.state), ACTIVE, { timeout: 60000 })
    .catch(async () => fail(`no session state shown; #state says ${JSON.stringify(await page.textContent('#state'))}`));
  pass(`the session state is shown: "${(await page.textContent('#state')).trim()}"`);
  await page.waitForSelector('#warnings li', { timeout: 120000 })
    .catch(() => fail('no posture warning appeared within 120 s'));
  const w = await page.evaluate(() => {
    const li = document.querySelector('#warnings li');
    const level = document.getElementById('level');
    return { text: li.textContent, level: li.dataset.level, colour: getComputedStyle(level).backgroundColor, al: level.dataset.level };
  });
  if (!/—/.test(w.text)) fail(`the warning has no advice: ${JSON.stringify(w.text)}`);
  if (!(Number(w.al) >= 2)) fail(`a warning is shown but the action level is ${w.al}`);
  pass(`a warning is on screen: "${w.text}" (action level ${w.al}, colour ${w.colour})`);
  // The class the cell decided, with the decision's probability (the demo's operator stands 1 cm
  // above the c1/c2 boundary: served across it).
  const cls = (await page.textContent('#class')).trim();
  if (!/^height class c[123] \(probability (0\.\d\d|1\.00)(, near a class boundary)?\)$/.test(cls)) {
    fail(`the height class and its probability are not shown: ${JSON.stringify(cls)}`);
  }
  pass(`the height class is shown with its probability: "${cls}"`);
  const seenSoFar = await page.evaluate(() => window.__seen);
  const matched = checkAgainstGuide(seenSoFar, guide);
  pass(`${seenSoFar.length} pictures match docs/operator.md: top bar ${JSON.stringify(matched.statesSeen)}; bands ${JSON.stringify(matched.bandsSeen)}`);
  await screenshot(b, shot);
  const before = await page.evaluate(() => window.__latencies.slice());

  // A reload: the snapshot on connect puts the current picture back at once.
  await page.reload({ waitUntil: 'load' });
  const t0 = Date.now();
  await page.waitForFunction((active) => active.includes(document.getElementById('state').dataset.state) || document.getElementById('state').dataset.state === 'session_ended', ACTIVE, { timeout: 5000 })
    .catch(() => fail('after a reload the state did not come back within 5 s'));
  pass(`after a reload the state is back in ${Date.now() - t0} ms: "${(await page.textContent('#state')).trim()}"`);
  await page.waitForTimeout(3000);
  const latencies = before.concat(await page.evaluate(() => window.__latencies.slice())).sort((a, b) => a - b);
  if (latencies.length < 10) fail(`only ${latencies.length} updates rendered`);
  console.log(`latency: ${latencies.length} updates, event to screen p50 ${quantile(latencies, 0.5).toFixed(1)} ms, ` +
    `p99 ${quantile(latencies, 0.99).toFixed(1)} ms, max ${latencies[latencies.length - 1].toFixed(1)} ms`);

  if (restart === 'restart') {
    await page.waitForFunction(() => document.getElementById('conn').className === 'lost', null, { timeout: 180000 })
      .catch(() => fail('the page never noticed the server going away'));
    pass(`the server went away and the page says so: "${await page.textContent('#conn')}"`);
    await page.waitForFunction(() => document.getElementById('conn').textContent === 'live' && window.__snapshots > 0, null, { timeout: 120000 })
      .catch(() => fail('the page did not reconnect to the restarted server'));
    await page.waitForFunction(() => /^update \d+$/.test(document.getElementById('seq').textContent), null, { timeout: 10000 });
    pass(`the page reconnected by itself to the restarted server (${await page.textContent('#seq')})`);
    // the refused reconnection attempts while the server was down are expected
    b.problems.splice(0, b.problems.length, ...b.problems.filter((p) => !/\/events/.test(p)));
    if (tasks === 'tasks') {
      // the task mix's postures: a warning raised, then cleared (its line goes away)
      const shown = await page.waitForFunction(() => {
        const li = document.querySelector('#warnings li');
        return li ? { region: li.dataset.region, text: li.textContent, near: li.dataset.near === 'true' } : null;
      }, null, { timeout: 180000, polling: 50 })
        .then((h) => h.jsonValue())
        .catch(() => fail('under the task mix no warning was raised on screen within 180 s'));
      pass(`under the task mix a warning is raised on screen: "${shown.text}"${shown.near ? ' (near the limit)' : ''}`);
      await page.waitForFunction((region) => !document.querySelector(`#warnings li[data-region="${region}"]`), shown.region, { timeout: 180000, polling: 50 })
        .catch(() => fail(`the ${shown.region} warning was never cleared on screen within 180 s`));
      pass(`and cleared: the ${shown.region} line went away`);
    }
  }
  // Since the reload (the restarted server's session with it): the same against the guide.
  const after = await page.evaluate(() => window.__seen);
  const more = checkAgainstGuide(after, guide);
  pass(`after the reload, ${after.length} more pictures match docs/operator.md: top bar ${JSON.stringify(more.statesSeen)}; bands ${JSON.stringify(more.bandsSeen)}`);
});
