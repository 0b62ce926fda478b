// Checks a self-contained report written by `ergocell report` (or dev/report.mjs), opened from file://:
//   node web/e2e/report.e2e.mjs <report.html> <screenshot.png> [--overview]
// --overview: the report is a long recording's overview, and says so above the 3D view.
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { existsSync } from 'node:fs';
import { main, loadChecks, screenshot, fail, pass } from './lib.mjs';

const [file, shot, mode] = process.argv.slice(2);
if (!file || !shot) {
  console.error('usage: node report.e2e.mjs <report.html> <screenshot.png>');
  process.exit(2);
}
if (!existsSync(file)) {
  console.error(`FAIL: no such file ${file}`);
  process.exit(1);
}

await main(async (b) => {
  const url = pathToFileURL(resolve(file)).href;
  // A report must not fetch anything: every request other than the file itself is a failure.
  const requests = [];
  b.page.on('request', (r) => {
    if (r.url() !== url && !r.url().startsWith('data:')) requests.push(r.url());
  });
  await loadChecks(b, url);
  if (requests.length) fail(`the report made ${requests.length} request(s): ${requests.join(', ')}`);
  const note = await b.page.$eval('#overview-note', (e) => e.textContent).catch(() => null);
  if (mode === '--overview') {
    if (!note || !/Overview of a long recording\. This page holds [\d,]+ of its [\d,]+ frames/.test(note)) fail(`no overview note: ${JSON.stringify(note)}`);
    pass(`the overview says what it holds: ${note.slice(0, 90)}…`);
  } else if (note) fail(`a report of every frame shows an overview note: ${note}`);
  await b.page.waitForTimeout(200);
  await screenshot(b, shot);
});
