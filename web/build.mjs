// Builds web/dist/review.js (one minified IIFE, no imports, no source map) and
// web/dist/review.css (uPlot's stylesheet + ours). Both are committed and embedded
// by the Rust binary (`ergocell review` serves them, `ergocell report` inlines them).
// Deterministic: the same sources and pinned packages give byte-identical output.
import { build } from 'esbuild';
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const dist = join(here, 'dist');
mkdirSync(dist, { recursive: true });

const threeLicense = readFileSync(join(here, 'node_modules/three/LICENSE'), 'utf8').trim();
const uplotLicense = readFileSync(join(here, 'node_modules/uplot/LICENSE'), 'utf8').trim();
const threeVersion = JSON.parse(readFileSync(join(here, 'node_modules/three/package.json'), 'utf8')).version;
const uplotVersion = JSON.parse(readFileSync(join(here, 'node_modules/uplot/package.json'), 'utf8')).version;

// The report HTML travels alone (mailed), so the MIT notices travel inside the bundle.
const banner = `/*! ergocell review page. Bundles three.js ${threeVersion} and uPlot ${uplotVersion}.\n\nthree.js:\n${threeLicense}\n\nuPlot:\n${uplotLicense}\n*/`;

const result = await build({
  entryPoints: [join(here, 'src/main.js')],
  bundle: true,
  format: 'iife',
  minify: true,
  sourcemap: false,
  legalComments: 'none',
  banner: { js: banner, css: `/*! ergocell review page; includes uPlot ${uplotVersion} CSS (MIT, (c) Leon Sorokin) */` },
  target: ['es2020'],
  charset: 'utf8',
  outdir: dist,
  entryNames: 'review',
  write: false,
  logLevel: 'warning',
});

for (const f of result.outputFiles) {
  let text = f.text;
  // Both files may be inlined into <script>/<style> by `ergocell report`.
  if (/<\/script/i.test(text) || /<\/style/i.test(text) || /<!--/.test(text)) {
    throw new Error(`${f.path} contains a sequence that would break inlining into HTML`);
  }
  if (/sourceMappingURL/.test(text)) throw new Error('unexpected source map reference');
  writeFileSync(f.path, text);
  console.log(`${f.path.slice(here.length + 1)}  ${(text.length / 1024).toFixed(1)} KiB`);
}

writeFileSync(
  join(dist, 'THIRD_PARTY_LICENSES.txt'),
  `review.js and review.css bundle the following third-party software.\n\n` +
    `== three.js ${threeVersion} (https://threejs.org) ==\n\n${threeLicense}\n\n` +
    `== uPlot ${uplotVersion} (https://github.com/leeoniya/uPlot) ==\n\n${uplotLicense}\n`,
);
