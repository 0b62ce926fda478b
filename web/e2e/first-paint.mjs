// Measures how soon the review page shows a recording: headless Chromium opens the URL and reports
// the browser's first contentful paint and the time until the app has drawn the recording (the
// frame counter and the timeline are on the page). A measurement, not a test: it prints the times.
//
//   node e2e/first-paint.mjs http://127.0.0.1:8765/
import { openBrowser, assertClean } from './lib.mjs';

const url = process.argv[2];
if (!url) {
  console.error('usage: node e2e/first-paint.mjs <url of ergocell review or of a report file>');
  process.exit(2);
}
const b = await openBrowser();
try {
  const start = Date.now();
  await b.page.goto(url, { waitUntil: 'commit', timeout: 120000 });
  await b.page.waitForSelector('#frame-counter', { timeout: 120000 });
  await b.page.waitForSelector('#timeline .uplot', { timeout: 120000 });
  const shown = Date.now() - start;
  const fcp = await b.page.evaluate(() => {
    const e = performance.getEntriesByName('first-contentful-paint')[0];
    return e ? e.startTime : null;
  });
  const counter = await b.page.textContent('#frame-counter');
  assertClean(b, 'first paint');
  console.log(`first contentful paint ${fcp === null ? '?' : `${(fcp / 1000).toFixed(2)} s`}; recording shown (frame counter and timeline drawn) after ${(shown / 1000).toFixed(2)} s; counter: ${counter.trim()}`);
} finally {
  await b.close();
}
