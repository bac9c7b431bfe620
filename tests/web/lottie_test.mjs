// Lottie import fidelity: each Lottie file (the shared lottie-web test animations and the
// synthetic ones in tests/importers/lottie/) is imported with `spt import`, rendered with
// `spt render` (flattened on white), and compared with lottie-web's canvas renderer in headless
// Chromium at the same frames (also flattened on white): PSNR over R, G, B, averaged over the
// frames. Files whose features the format holds must reach MIN_DB; the others are measured and
// printed (the importers README's table), with their sizes: .spt against the JSON raw and gzip.
//   node lottie_test.mjs SPT_TOOL MEDIA_DIR SYNTHETIC_DIR WORK_DIR
// Exit 0 when every check passes; any failure (or anything missing) exits 1 naming it.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { createRequire } from 'node:module';
import { launch } from './chromium.mjs';

const [spt, media, synthetic, work] = process.argv.slice(2);
if (!spt || !media || !synthetic || !work) {
  console.error('usage: node lottie_test.mjs SPT_TOOL MEDIA_DIR SYNTHETIC_DIR WORK_DIR');
  process.exit(2);
}
const MIN_DB = 40;
// Lines are mostly edge: lottie-web's canvas (Skia) covers diagonal edges about 0.1 px wider
// than the exact geometry (an 8 px line at slope 25/40 covers 9.61 px of a pixel column in
// Chromium, 9.44 exactly; a filled parallelogram of that outline covers the same 9.61), and spt
// renders the exact outline, so the files of thin lines meet a lower floor (37.7 dB measured).
const FLOOR = { 'strokes.json': 36, 'dashes.json': 36 };  // dashes: 5 and 6 px lines, 36.8 dB measured
const MAX_FRAMES = 24;
const EXPORT_MIN_DB = 35;  // spt export --lottie played by lottie-web, against spt render  // frames compared per file, evenly spread
// Shared files whose features the format holds (the others use masks, mattes, expressions,
// text or images; their PSNR is printed, not asserted).
const HELD = new Set(['bacon.json']);
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
const require = createRequire(import.meta.url);
const lottiePath = require.resolve('lottie-web/build/player/lottie.min.js');

const shared = path.join(media, 'lottie');
if (!fs.existsSync(path.join(shared, 'bacon.json'))) throw new Error(`media missing: ${shared}/bacon.json`);
const only = process.env.LOTTIE_TEST_ONLY;  // one file's name, to debug it
const files = [
  ...fs.readdirSync(shared).filter((f) => f.endsWith('.json')).sort().map((f) => ({ file: path.join(shared, f), held: HELD.has(f) })),
  ...fs.readdirSync(synthetic).filter((f) => f.endsWith('.json') && !f.endsWith('.strokes.json')).sort().map((f) => ({ file: path.join(synthetic, f), held: true })),
];
if (only) files.splice(0, files.length, ...files.filter((f) => path.basename(f.file) === only || only.startsWith('export-')));
else if (files.length < 8) throw new Error(`expected the shared and synthetic Lottie files, found ${files.length}`);

function ppm(file) {
  const b = fs.readFileSync(file);
  let pos = 0;
  for (let lines = 0; lines < 3;) if (b[pos++] === 10) ++lines;
  return b.subarray(pos);
}

const { context, close } = await launch();
let failed = 0;
const rows = [];
try {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.setContent('<!DOCTYPE html><html><body style="margin:0;background:#fff"><div id="c"></div></body></html>');
  await page.addScriptTag({ path: lottiePath });
  // Mean PSNR of lottie-web's frames of `data` against spt render's frames of `sptFile`.
  async function measure(name, data, sptFile) {
    const n = Math.round(data.op - data.ip);
    const stride = Math.max(1, Math.ceil(n / MAX_FRAMES));
    const frames = [];
    for (let f = 0; f < n; f += stride) frames.push(f);
    const dir = path.join(work, name + '.frames');
    fs.mkdirSync(dir);
    execFileSync(spt, ['render', sptFile, '-o', path.join(dir, 'f.####.ppm'), '--frames', `0-${n - 1}x${stride}`,
                       '--background', 'ffffff'], { stdio: ['ignore', 'pipe', 'inherit'] });
    await page.evaluate(({ data }) => {
      if (window.anim) window.anim.destroy();
      const c = document.getElementById('c');
      c.style.width = data.w + 'px';
      c.style.height = data.h + 'px';
      window.anim = lottie.loadAnimation({ container: c, renderer: 'canvas', loop: false, autoplay: false, animationData: data,
                                           rendererSettings: { clearCanvas: true, dpr: 1 } });
    }, { data });
    let sum = 0;
    let min = Infinity;
    let worst = 0;
    for (const f of frames) {
      const ref = await page.evaluate((f) => {
        window.anim.goToAndStop(f, true);
        const cv = document.querySelector('#c canvas');
        const px = cv.getContext('2d').getImageData(0, 0, cv.width, cv.height).data;
        // Raw RGBA as base64 (a JSON array of millions of numbers is far slower to hand over).
        let bin = '';
        for (let i = 0; i < px.length; i += 0x8000) bin += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
        return { w: cv.width, h: cv.height, rgba: btoa(bin) };
      }, f);
      const rgba = Buffer.from(ref.rgba, 'base64');
      ref.rgb = new Uint8Array((rgba.length / 4) * 3);
      for (let i = 0, j = 0; i < rgba.length; i += 4, j += 3) {
        const a = rgba[i + 3];  // straight alpha over white
        for (let k = 0; k < 3; ++k) ref.rgb[j + k] = Math.round((rgba[i + k] * a + 255 * (255 - a)) / 255);
      }
      const mine = ppm(path.join(dir, `f.${String(f).padStart(4, '0')}.ppm`));
      if (ref.w !== data.w || ref.h !== data.h || mine.length !== ref.rgb.length)
        throw new Error(`${name} frame ${f}: lottie-web canvas ${ref.w}x${ref.h}, spt ${mine.length / 3} pixels`);
      if (process.env.LOTTIE_TEST_DUMP)  // the reference frames beside spt's, to look at
        fs.writeFileSync(path.join(dir, `ref.${String(f).padStart(4, '0')}.ppm`),
                         Buffer.concat([Buffer.from(`P6\n${ref.w} ${ref.h}\n255\n`), Buffer.from(ref.rgb)]));
      let se = 0;
      for (let i = 0; i < mine.length; ++i) { const d = mine[i] - ref.rgb[i]; se += d * d; }
      const mse = se / mine.length;
      const db = mse === 0 ? 99 : Math.min(99, 10 * Math.log10(255 * 255 / mse));
      sum += db;
      if (db < min) { min = db; worst = f; }
    }
    return { frames: frames.length, mean: sum / frames.length, min, worst };
  }

  // Import: lottie-web's render of each Lottie file against spt render of its import.
  for (const { file, held } of files) {
    const name = path.basename(file);
    const data = JSON.parse(fs.readFileSync(file, 'utf8'));
    const out = path.join(work, name.replace(/\.json$/, '.spt'));
    execFileSync(spt, ['import', file, '-o', out, '--quiet'], { stdio: ['ignore', 'pipe', 'inherit'] });
    const { frames, mean, min, worst } = await measure(name, data, out);
    const raw = fs.statSync(file).size;
    const gz = zlib.gzipSync(fs.readFileSync(file), { level: 9 }).length;
    const bytes = fs.statSync(out).size;
    const floor = FLOOR[name] ?? MIN_DB;
    const ok = !held || mean >= floor;
    if (!ok) failed++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}: ${frames} frames, mean ${mean.toFixed(2)} dB (min ${min.toFixed(2)} at frame ${worst}),` +
                ` .spt ${bytes} B, JSON ${raw} B, gzip ${gz} B${held ? '' : ' (not asserted: features the format lacks)'}`);
  }

  // Export: `spt export --lottie` of .spt files (the synthetic imports: polygons and curves; an
  // SVG import: affine strokes; a stroke list of stamps) played by lottie-web against spt render.
  const exports = files.filter((f) => f.file.startsWith(synthetic)).map((f) => path.join(work, path.basename(f.file).replace(/\.json$/, '.spt')));
  const svg = path.join(media, 'foreign', 'coffee-primitive-ellipses.svg');
  if (!fs.existsSync(svg)) throw new Error(`media missing: ${svg}`);
  execFileSync(spt, ['import', svg, '-o', path.join(work, 'primitive.spt'), '--quiet']);
  exports.push(path.join(work, 'primitive.spt'));
  execFileSync(spt, ['import', path.join(synthetic, 'stamps.strokes.json'), '-o', path.join(work, 'stamps.spt'), '--quiet']);
  exports.push(path.join(work, 'stamps.spt'));
  for (const sptFile of exports.filter((e) => !only || only === 'export-' + path.basename(e, '.spt'))) {
    const name = 'export-' + path.basename(sptFile, '.spt');
    const json = path.join(work, name + '.json');
    execFileSync(spt, ['export', sptFile, '-o', json, '--lottie'], { stdio: ['ignore', 'pipe', 'inherit'] });
    const { frames, mean, min, worst } = await measure(name, JSON.parse(fs.readFileSync(json, 'utf8')), sptFile);
    const ok = mean >= EXPORT_MIN_DB;
    if (!ok) failed++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}: ${frames} frames, mean ${mean.toFixed(2)} dB (min ${min.toFixed(2)} at frame ${worst}),` +
                ` Lottie ${fs.statSync(json).size} B, .spt ${fs.statSync(sptFile).size} B`);
  }
  if (errors.length) { console.log(`FAIL page errors: ${errors.join('; ')}`); failed++; }
} finally {
  await close();
}
if (failed) { console.error(`${failed} Lottie fidelity check(s) failed`); process.exit(1); }
console.log('all Lottie fidelity checks passed');
