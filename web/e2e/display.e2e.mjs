// The operator display (`ergocell demo --display`) in headless Chromium:
//   node web/e2e/display.e2e.mjs <url> <screenshot.png> [restart [tasks]]
// Checks: the page connects and shows the session's state as it changes; a posture warning appears
// with its advice and the action level's colour, and the height class with its probability; after a reload the current state is back at once
// (the server sends its snapshot on connect); with `restart`, when the server goes away the page says
// so and, once a server is back on the same address, reconnects by itself. Prints the event-to-screen
// latency (server send time → after the next paint, same machine clock) of every update it rendered.
// With `tasks` (the restarted server runs the station's task mix), a warning is raised and then
// cleared on screen: the region's line appears and goes away again.
import { main, pass, fail, screenshot, quantile, openDisplay } from './lib.mjs';

const [url, shot, restart, tasks] = process.argv.slice(2);
if (!url || !shot) {
  console.error('usage: node display.e2e.mjs <url> <screenshot.png> [restart]');
  process.exit(2);
}

const ACTIVE = ['measuring_height', 'class_decided', 'trajectory_locked', 'working', 'held'];

await main(async (b) => {
  const { page } = b;
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
});
