// Dev stand-in for `ergocell report`: one self-contained HTML file (CSS, data and JS inline).
//
//   node dev/report.mjs data.json out.html
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const [dataPath = join(here, 'sample.json'), out = 'report.html'] = process.argv.slice(2);
const css = readFileSync(join(here, '../dist/review.css'), 'utf8');
const js = readFileSync(join(here, '../dist/review.js'), 'utf8');
// JSON inside <script>: escape '<' so no "</script>" or "<!--" can end or confuse the element.
const data = JSON.stringify(JSON.parse(readFileSync(dataPath, 'utf8'))).replace(/</g, '\\u003c').replace(/\u2028/g, '\\u2028').replace(/\u2029/g, '\\u2029');
const html = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>ergocell report</title>\n<style>${css}</style>\n</head><body><div id="app"></div>\n<script>window.ERGOCELL_REVIEW_DATA = ${data};</script>\n<script>${js}</script>\n</body></html>`;
writeFileSync(out, html);
console.log(`wrote ${out} (${(html.length / 1024).toFixed(0)} KiB)`);
