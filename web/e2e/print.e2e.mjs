// Prints a report written by `ergocell report` to PDF in headless Chromium, as "Save as PDF" does:
//   node web/e2e/print.e2e.mjs <report.html> <out.pdf> <page1.png>
// Checks, with the print stylesheet applied at the width of an A4 page's text:
// - the findings come first and fit on page 1: the time at each action level (adding up to the
//   scored time), the worst moments each with a drawn still (front and right side), and a row per
//   body region with its verdict, a recommendation wherever the verdict asks for a change; every
//   badge readable on paper (contrast 4.5:1 or more);
// - the 3D view and the controls are left out, and no card, table or chart is wider than the page
//   or clips its content;
// - the PDF has a first page plus the session's pages (A4).
// Writes the PDF and a picture of page 1 (the print layout's first 1050 px) to look at.
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { existsSync, readFileSync } from 'node:fs';
import { main, loadChecks, fail, pass } from './lib.mjs';

const [file, pdf, shot] = process.argv.slice(2);
if (!file || !pdf || !shot) {
  console.error('usage: node print.e2e.mjs <report.html> <out.pdf> <page1.png>');
  process.exit(2);
}
if (!existsSync(file)) {
  console.error(`FAIL: no such file ${file}`);
  process.exit(1);
}

// A4 is 210 × 297 mm; the stylesheet's margins are 11 mm and 12 mm: 188 × 273 mm of text, in CSS
// pixels at 96 per inch.
const PX_PER_MM = 96 / 25.4;
const TEXT_W = Math.floor(188 * PX_PER_MM);
const TEXT_H = Math.floor(273 * PX_PER_MM);

await main(async (b) => {
  const { page } = b;
  await loadChecks(b, pathToFileURL(resolve(file)).href);
  await page.emulateMedia({ media: 'print' });
  await page.setViewportSize({ width: TEXT_W, height: TEXT_H });
  await page.waitForTimeout(300);

  const seen = await page.evaluate(() => {
    const box = (el) => el.getBoundingClientRect();
    const shown = (el) => el && getComputedStyle(el).display !== 'none' && box(el).height > 0;
    const f = document.getElementById('findings');
    const levels = [...document.querySelectorAll('#findings .f-levels tbody tr.al-row')].map((tr) => tr.querySelectorAll('td.num')[1]?.textContent ?? '');
    // Print colours: each verdict and action-level badge readable on paper (WCAG contrast ratio).
    const lum = (c) => {
      const [r, g, b] = (c.match(/[\d.]+/g) || []).slice(0, 3).map((v) => {
        const x = Number(v) / 255;
        return x <= 0.03928 ? x / 12.92 : ((x + 0.055) / 1.055) ** 2.4;
      });
      return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    };
    const contrast = [...document.querySelectorAll('#findings .badge')].map((el) => {
      const st = getComputedStyle(el);
      const [a, b] = [lum(st.color), lum(st.backgroundColor)].sort((x, y) => y - x);
      return { text: el.textContent, ratio: (a + 0.05) / (b + 0.05) };
    });
    const captions = [...document.querySelectorAll('#findings .still figcaption')].map((c) => c.textContent);
    const moments = [...document.querySelectorAll('#findings .moment')].map((m) => ({
      lines: m.querySelectorAll('.still svg line:not(.floor)').length,
      views: m.querySelectorAll('.still svg').length,
    }));
    const regions = [...document.querySelectorAll('#findings .f-regions tbody tr')].map((tr) => ({
      region: tr.dataset.region,
      side: tr.dataset.side,
      verdict: tr.querySelector('.badge')?.textContent ?? '',
      advice: tr.lastElementChild?.textContent ?? '',
    }));
    // Anything wider than the page, or clipping what it holds.
    const wide = [];
    for (const el of document.querySelectorAll('.card, table, .uplot, .moment, .still svg')) {
      if (!shown(el)) continue;
      const r = box(el);
      const clips = ['hidden', 'clip'].includes(getComputedStyle(el).overflowX) && el.scrollWidth > el.clientWidth + 1;
      if (r.right > window.innerWidth + 1 || clips) wide.push(`${el.tagName.toLowerCase()}#${el.id || ''}.${[...el.classList].join('.')}: right ${Math.round(r.right)} px, scroll ${el.scrollWidth} / ${el.clientWidth}`);
    }
    const first = document.querySelector('main.layout');
    return {
      findingsShown: shown(f),
      findingsTop: f ? box(f).top : null,
      findingsBottom: f ? box(f).bottom : null,
      breakAfter: f ? getComputedStyle(f).breakAfter : null,
      layoutTop: first ? box(first).top : null,
      title: f?.querySelector('h1')?.textContent ?? '',
      levels,
      contrast,
      captions,
      moments,
      regions,
      viewerShown: shown(document.querySelector('.viewer')),
      transportShown: shown(document.querySelector('.transport')),
      wide,
    };
  });

  if (!seen.findingsShown || !seen.title.startsWith('Ergonomic findings')) fail(`no findings in print (${JSON.stringify(seen.title)})`);
  if (seen.breakAfter !== 'page') fail(`the findings do not end their page (break-after: ${seen.breakAfter})`);
  if (!(seen.layoutTop >= seen.findingsBottom)) fail('the session is printed before the findings');
  if (seen.findingsBottom > TEXT_H) fail(`the findings do not fit on page 1: ${Math.round(seen.findingsBottom)} px of ${TEXT_H}`);
  if (seen.levels.length !== 4) fail(`the action-level table has ${seen.levels.length} rows, not 4`);
  // The four levels' shares of the scored time add up to all of it.
  const shares = seen.levels.map((x) => parseFloat(x));
  const total = shares.reduce((a, b) => a + b, 0);
  if (shares.some((x) => !Number.isFinite(x)) || Math.abs(total - 100) > 0.25) fail(`the action levels' shares add up to ${total.toFixed(2)} %, not 100 % (${seen.levels.join(', ')})`);
  const faint = seen.contrast.filter((c) => c.ratio < 4.5);
  if (!seen.contrast.length || faint.length) fail(`badges too faint to read on paper: ${JSON.stringify(faint)}`);
  if (new Set(seen.captions).size !== 2 || !seen.captions.includes('front') || !seen.captions.includes('right side')) fail(`the stills are not labelled front and right side: ${JSON.stringify([...new Set(seen.captions)])}`);
  if (!seen.moments.length) fail('no worst moment (the demo reaches action level 3)');
  for (const [i, m] of seen.moments.entries()) {
    if (m.views !== 2 || m.lines < 10) fail(`worst moment ${i + 1}: ${m.views} view(s), ${m.lines} bone(s) drawn`);
  }
  if (seen.regions.length !== 9) fail(`${seen.regions.length} region rows, not 9 (arms per side, neck, trunk, legs)`);
  const needs = seen.regions.filter((r) => r.verdict === 'Change' || r.verdict === 'Brief');
  if (!needs.length) fail('no region needs a change in a demo whose operator was warned');
  for (const r of needs) if (!r.advice || r.advice === '–') fail(`${r.side} ${r.region}: verdict ${r.verdict} without a recommendation`);
  for (const r of seen.regions.filter((x) => x.verdict === 'Acceptable')) if (r.advice !== '–') fail(`${r.side} ${r.region}: acceptable, yet advised "${r.advice}"`);
  if (seen.viewerShown || seen.transportShown) fail('the 3D view or the controls are printed');
  if (seen.wide.length) fail(`clipped or wider than the page:\n  ${seen.wide.join('\n  ')}`);
  pass(`findings on page 1 (${Math.round(seen.findingsBottom)} of ${TEXT_H} px): 4 action levels, ${seen.moments.length} worst moment(s) with front and side stills, ${seen.regions.length} regions, ${needs.length} with a recommendation; nothing wider than the page`);

  await page.screenshot({ path: shot, clip: { x: 0, y: 0, width: TEXT_W, height: TEXT_H } });
  await page.pdf({ path: pdf, format: 'A4', printBackground: true, preferCSSPageSize: true });
  const bytes = readFileSync(pdf);
  const pages = (bytes.toString('latin1').match(/\/Type\s*\/Page[^s]/g) || []).length;
  if (!bytes.subarray(0, 5).equals(Buffer.from('%PDF-')) || pages < 2) fail(`${pdf}: not a PDF of the findings and the session (${pages} page(s))`);
  pass(`printed to ${pdf}: ${pages} A4 pages; page 1 pictured in ${shot}`);
});
