// Checks a self-contained report written by `ergocell report` (or dev/report.mjs), opened from file://:
//   node web/e2e/report.e2e.mjs <report.html> <screenshot.png>
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { existsSync } from 'node:fs';
import { main, loadChecks, screenshot, fail } from './lib.mjs';

const [file, shot] = process.argv.slice(2);
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
  await b.page.waitForTimeout(200);
  await screenshot(b, shot);
});
