// Shared by the e2e scripts: launch Debian's chromium through playwright-core, collect
// console errors / page errors / failed requests, fail with one clear message.
import { chromium } from 'playwright-core';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export const ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  // WebGL without a GPU: ANGLE on SwiftShader (CPU). Without these, headless chromium
  // refuses WebGL ("unsafe SwiftShader fallback") and three.js cannot create a context.
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
];

export class CheckFailed extends Error {}

export function fail(msg) {
  throw new CheckFailed(msg);
}

export function pass(msg) {
  console.log(`ok - ${msg}`);
}

/** Opens a browser page at 1400×900 and records every problem the page reports. */
export async function openBrowser() {
  const userDataDir = mkdtempSync(join(tmpdir(), 'ergocell-e2e-'));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ARGS,
    viewport: { width: 1400, height: 900 },
    deviceScaleFactor: 1,
  });
  const page = context.pages()[0] || (await context.newPage());
  const problems = [];
  const warnings = [];
  const driverNotes = [];
  page.on('console', (m) => {
    const where = m.location() && m.location().url ? ` (${m.location().url}:${m.location().lineNumber})` : '';
    if (m.type() === 'error') problems.push(`console error: ${m.text()}${where}`);
    else if (m.type() === 'warning') {
      // SwiftShader's performance note when headless chromium reads the frame back for
      // compositing; it comes from the GL driver, not from the page.
      if (/^\[\.WebGL-[^\]]*\]GL Driver Message .*GPU stall due to ReadPixels/.test(m.text())) driverNotes.push(m.text());
      else warnings.push(`console warning: ${m.text()}${where}`);
    }
  });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.method()} ${r.url()} (${r.failure() ? r.failure().errorText : '?'})`));
  page.on('response', (r) => {
    if (r.status() >= 400) problems.push(`HTTP ${r.status()} for ${r.request().method()} ${r.url()}`);
  });
  const close = async () => {
    await context.close().catch(() => {});
    rmSync(userDataDir, { recursive: true, force: true });
  };
  return { context, page, problems, warnings, driverNotes, close };
}

export function assertClean(b, when) {
  if (b.problems.length) fail(`${when}: ${b.problems.length} problem(s):\n  ${b.problems.join('\n  ')}`);
  if (b.warnings.length) fail(`${when}: ${b.warnings.length} console warning(s):\n  ${b.warnings.join('\n  ')}`);
}

export async function loadChecks(b, url) {
  const { page } = b;
  await page.goto(url, { waitUntil: 'load', timeout: 30000 });
  await page.waitForSelector('#frame-counter', { timeout: 15000 }).catch(async () => {
    const text = await page.evaluate(() => document.body.innerText).catch(() => '');
    fail(`#frame-counter did not appear; page says: ${JSON.stringify(text.slice(0, 300))}`);
  });
  await page.waitForFunction(() => window.ergocellReview && document.querySelector('canvas[data-frame]'), null, { timeout: 15000 }).catch(() => fail('window.ergocellReview or the 3D canvas did not appear'));
  // Give WebGL a couple of frames to render (context creation errors show up here).
  await page.waitForTimeout(500);
  const webgl = await page.evaluate(() => {
    const c = document.querySelector('canvas.view3d');
    return !!(c && (c.getContext('webgl2') || c.getContext('webgl')));
  });
  if (!webgl) fail('the 3D canvas has no WebGL context (is SwiftShader available?)');
  assertClean(b, 'loading the page');
  const counter = await page.textContent('#frame-counter');
  if (!/^frame \d+ \/ \d+ · \d+\.\d\d s$/.test(counter.trim())) fail(`#frame-counter text is ${JSON.stringify(counter)}`);
  const n = await page.evaluate(() => window.ergocellReview.frameCount());
  pass(`page loads, #frame-counter shows "${counter.trim()}", WebGL renders, no console errors, page errors or failed requests (${n} frames)`);
  return n;
}

export async function screenshot(b, path) {
  await b.page.screenshot({ path, fullPage: true });
  pass(`full-page screenshot written to ${path}`);
}

export async function main(fn) {
  let b;
  try {
    b = await openBrowser();
    await fn(b);
    assertClean(b, 'at the end');
    if (b.driverNotes.length) console.log(`note: ignored ${b.driverNotes.length} SwiftShader "GPU stall due to ReadPixels" driver message(s)`);
    await b.close();
    process.exit(0);
  } catch (e) {
    console.error(`FAIL: ${e instanceof CheckFailed ? e.message : e.stack || e}`);
    if (b) await b.close();
    process.exit(1);
  }
}
