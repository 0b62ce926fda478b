// From a camera frame's capture stamp to its posture warning on the operator display, in headless
// Chromium: `ergocell run --display ADDR` on live cameras, this page watching for SECONDS seconds.
//   node web/e2e/display-latency.mjs <url> <seconds> <fixed_lag_s>
// For every warning first shown, the time from the capture stamp of the frame that raised it to the
// screen (after the next paint; one machine, one clock). The designed part — the dwell — is before
// that frame; the fixed lag (the frame is released that long after its stamp) is subtracted, so what
// is printed is the part beyond the dwell and the lag: transport, fusion, scoring, the display's
// push and the browser's paint. Prints one line `warning latency: …` and the JSON of every sample;
// measured, never asserted.
import { main, pass, fail, quantile, openDisplay } from './lib.mjs';

const [url, seconds, lag] = process.argv.slice(2);
if (!url || !(Number(seconds) > 0) || !(Number(lag) >= 0)) {
  console.error('usage: node display-latency.mjs <url> <seconds> <fixed_lag_s>');
  process.exit(2);
}

await main(async (b) => {
  const { page } = b;
  await openDisplay(page, url);
  pass('the display page is live');
  await page.waitForTimeout(Number(seconds) * 1000);
  const samples = await page.evaluate(() => window.__warningLatencies.slice());
  if (!samples.length) fail(`no warning was shown in ${seconds} s`);
  const beyond = samples.map((s) => s.ms - Number(lag) * 1000).sort((a, b) => a - b);
  console.log(`warning latency: ${beyond.length} warnings, capture to screen beyond the dwell and the ${lag} s fixed lag: ` +
    `p50 ${quantile(beyond, 0.5).toFixed(1)} ms, p99 ${quantile(beyond, 0.99).toFixed(1)} ms, max ${beyond[beyond.length - 1].toFixed(1)} ms`);
  console.log(JSON.stringify(samples));
  // the server going away at the session's end is expected
  b.problems.splice(0, b.problems.length, ...b.problems.filter((p) => !/\/events/.test(p)));
});
