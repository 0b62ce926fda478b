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

/** The `q` quantile of ascending `sorted` by nearest rank. */
export function quantile(sorted, q) {
  return sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1))];
}

/** Opens the operator display at `url` and waits until its event stream is live. */
export async function openDisplay(page, url) {
  await page.goto(url, { waitUntil: 'load', timeout: 30000 });
  await page.waitForFunction(() => document.getElementById('conn').textContent === 'live', null, { timeout: 15000 })
    .catch(() => fail('the page never said "live": no event stream'));
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

/**
 * The robot strip on the (first) timeline: the widest visible leg is drawn in its colour (a canvas
 * pixel inside its band), the legend has a "robot leg" row, hovering the leg shows its tooltip and
 * names it in the legend, and (with `events`) hovering a controller-event / part-taken diamond shows
 * its tooltip. Returns what it saw.
 */
export async function robotStripChecks(b, what, { events = false } = {}) {
  const { page } = b;
  const over = await page.$('#timeline .u-over');
  if (!over) fail(`${what}: no timeline plot`);
  await over.scrollIntoViewIfNeeded();
  const seen = await page.evaluate(() => {
    const over = document.querySelector('#timeline .u-over');
    const legs = [...over.querySelectorAll('.rmark.leg')].filter((e) => !e.hidden);
    const widest = legs.reduce((a, e) => (!a || e.offsetWidth > a.offsetWidth ? e : a), null);
    const canvas = over.parentElement.querySelector('canvas');
    let pixel = null;
    if (widest && canvas) {
      const k = canvas.width / canvas.clientWidth;
      const x = Math.round((over.offsetLeft + widest.offsetLeft + 3) * k);
      const y = Math.round((over.offsetTop + widest.offsetTop + widest.offsetHeight / 2) * k);
      pixel = [...canvas.getContext('2d').getImageData(x, y, 1, 1).data].slice(0, 3);
      widest.dataset.e2e = 'widest';
    }
    const hex = widest ? widest.dataset.color : null;
    const color = hex ? [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16)) : null;
    return {
      legs: legs.length,
      width: widest ? widest.offsetWidth : 0,
      pixel,
      color,
      legend: document.querySelector('#timeline .u-robot')?.textContent ?? null,
      events: [...over.querySelectorAll('.rmark.ev')].filter((e) => !e.hidden).length,
    };
  });
  if (!seen.legs) fail(`${what}: no robot leg on the timeline's strip`);
  if (!seen.legend || !/^robot leg/.test(seen.legend)) fail(`${what}: no "robot leg" row in the timeline's legend (${JSON.stringify(seen.legend)})`);
  // A leg is coloured by its constant (leg_id), so a named leg is never drawn in the colour of an unknown one.
  if (!seen.color || seen.color.join() === [0x90, 0xa4, 0xae].join()) fail(`${what}: the widest leg is drawn as an unnamed leg (its leg_id not read)`);
  if (!seen.pixel || seen.pixel.some((v, i) => Math.abs(v - seen.color[i]) > 12)) fail(`${what}: the widest leg's band is not drawn in its colour: pixel ${JSON.stringify(seen.pixel)}, expected ${JSON.stringify(seen.color)}`);
  const leg = await page.$('#timeline .rmark.leg[data-e2e="widest"]');
  await leg.hover();
  await page.waitForTimeout(150);
  const tip = await leg.$eval('.tip', (e) => (getComputedStyle(e).display !== 'none' ? e.textContent : null));
  if (!tip || !/→|leg/.test(tip)) fail(`${what}: hovering a robot leg shows no tooltip (${JSON.stringify(tip)})`);
  // Off the plot, the legend reads out the current frame: in the leg's middle, its name.
  await page.mouse.move(5, 5);
  const mid = await leg.evaluate((e) => ({ t: (Number(e.dataset.t) + Number(e.dataset.tEnd)) / 2, leg: e.dataset.leg }));
  await page.evaluate((t) => window.ergocellReview.seek(t), mid.t);
  await page.waitForTimeout(100);
  const value = await page.$eval('#timeline .u-robot .u-value', (e) => e.textContent);
  if (value !== mid.leg || !tip.startsWith(mid.leg)) fail(`${what}: at ${mid.t.toFixed(2)} s, in the leg "${tip.slice(0, 40)}…", the legend's robot leg reads "${value}"`);
  pass(`${what}: ${seen.legs} robot leg(s) on the strip (the widest, ${seen.width} px, drawn in ${JSON.stringify(seen.color)}), legend "${seen.legend}", tooltip "${tip.slice(0, 60)}…"`);
  let eventTip = null;
  if (events) {
    if (!seen.events) fail(`${what}: no controller event or part-taken diamond on the strip`);
    const flag = await page.$('#timeline .rmark.ev:not([hidden]) .flag');
    await flag.hover();
    await page.waitForTimeout(150);
    eventTip = await page.$eval('#timeline .rmark.ev:hover .tip', (e) => (getComputedStyle(e).display !== 'none' ? e.textContent : null)).catch(() => null);
    if (!eventTip || !/\d\.\d\d s · /.test(eventTip)) fail(`${what}: hovering a controller event shows no tooltip (${JSON.stringify(eventTip)})`);
    pass(`${what}: ${seen.events} event diamond(s); the first's tooltip "${eventTip.slice(0, 60)}…"`);
  }
  await page.mouse.move(5, 5);
  return { ...seen, tip, eventTip };
}
