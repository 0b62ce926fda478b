// Dev stand-in for `ergocell review`'s server: the same HTML shell, assets from dist/,
// api/review.json from a data file (default dev/sample.json, made by sample-data.mjs).
//
//   node dev/serve.mjs [data.json] [--port 8765]      (prints the URL; loopback only)
import { createServer } from 'node:http';
import { readFileSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const pi = args.indexOf('--port');
const port = pi >= 0 ? Number(args[pi + 1]) : 8765;
const dataPath = args.find((a, i) => !a.startsWith('--') && (pi < 0 || i !== pi + 1)) || join(here, 'sample.json');
if (!existsSync(dataPath)) {
  console.error(`no data file ${dataPath}; run: node dev/sample-data.mjs ${dataPath}`);
  process.exit(2);
}

export const shell = (title) =>
  `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>${title}</title>\n<link rel="stylesheet" href="assets/review.css">\n</head><body><div id="app"></div>\n<script src="assets/review.js"></script>\n</body></html>`;

const routes = {
  '/': ['text/html; charset=utf-8', () => shell('ergocell review')],
  '/assets/review.js': ['text/javascript; charset=utf-8', () => readFileSync(join(here, '../dist/review.js'))],
  '/assets/review.css': ['text/css; charset=utf-8', () => readFileSync(join(here, '../dist/review.css'))],
  '/api/review.json': ['application/json', () => readFileSync(dataPath)],
};

const server = createServer((req, res) => {
  const path = new URL(req.url, 'http://localhost').pathname;
  const r = routes[path];
  if (!r || req.method !== 'GET') {
    res.writeHead(404, { 'content-type': 'text/plain' });
    res.end('not found\n');
    return;
  }
  res.writeHead(200, {
    'content-type': r[0],
    'cache-control': 'no-store',
    'x-content-type-options': 'nosniff',
    // The policy `ergocell review` sends, so a violation shows up here too (as a console error).
    'content-security-policy':
      "default-src 'none'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; connect-src 'self'; frame-ancestors 'none'",
  });
  res.end(r[1]());
});
server.listen(port, '127.0.0.1', () => {
  console.log(`http://127.0.0.1:${server.address().port}/`);
});
