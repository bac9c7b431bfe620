// Browser side of bench/web_bench.sh: the page `spt export -o page.html` wrote, in headless
// Chromium, seeking frames in order and at random (the sequence play_bench.cpp uses), then
// playing the clip once at its fps to count the frames shown.
//   node bench/web_bench.mjs PAGE.html [passes] [--wasm OTHER.wasm]
//   prints {"in_order_ms": M, "random_ms": M, "frames": N, "played": P}
// Figures: median over passes of (wall time of the pass) / (frames drawn); a frame is the
// player's seek(): libspt decode + render in WebAssembly, RGBA, putImageData.
import fs from 'node:fs';
import { launch, openPlayer } from '../tests/web/chromium.mjs';

const args = process.argv.slice(2);
const wasmAt = args.indexOf('--wasm');
const wasm = wasmAt >= 0 ? args.splice(wasmAt, 2)[1] : null;
const [page_, passesArg] = args;
if (!page_) {
  console.error('usage: node web_bench.mjs PAGE.html [passes] [--wasm OTHER.wasm]');
  process.exit(2);
}
const passes = Number(passesArg ?? 5);
const { context, close } = await launch();
try {
  // --wasm: the page's player runs another build of spt_core.wasm (e.g. without -msimd128).
  if (wasm) {
    const b64 = fs.readFileSync(wasm).toString('base64');
    await context.addInitScript({ content: `globalThis.SPT_PLAYER_WASM = Uint8Array.from(atob('${b64}'), (c) => c.charCodeAt(0));` });
  }
  const { page } = await openPlayer(context, page_);
  const result = await page.evaluate(async (passes) => {
    const el = document.querySelector('spt-player');
    await el.ready;
    el.pause();
    const n = el.frameCount;
    const order = [];
    let x = 1;
    for (let i = 0; i < n; ++i) {
      x ^= x << 13; x >>>= 0;
      x ^= x >>> 17;
      x ^= x << 5; x >>>= 0;
      order.push(x % n);
    }
    const median = (v) => { v = [...v].sort((a, b) => a - b); const h = v.length >> 1; return v.length % 2 ? v[h] : (v[h - 1] + v[h]) / 2; };
    await el.seek(0);
    const inOrder = [], random = [];
    for (let p = 0; p < passes; ++p) {
      let t = performance.now();
      for (let i = 0; i < n; ++i) await el.seek(i);
      inOrder.push((performance.now() - t) / n);
      t = performance.now();
      for (const i of order) await el.seek(i);
      random.push((performance.now() - t) / order.length);
    }
    // Playback once from frame 0 without looping: which frames were drawn.
    await el.seek(0);
    el.loop = false;
    const shown = new Set([0]);
    const onFrame = (e) => shown.add(e.detail.frame);
    el.addEventListener('frame', onFrame);
    const seconds = n / el.fps;
    const ended = await new Promise((resolve) => {
      el.addEventListener('complete', () => resolve(true), { once: true });
      el.play();
      setTimeout(() => resolve(false), 4000 * seconds + 10000);
    });
    if (!ended) throw new Error(`playback did not complete (at frame ${el.frame}: ${el.errorMessage})`);
    el.removeEventListener('frame', onFrame);
    return { in_order_ms: median(inOrder), random_ms: median(random), frames: n, played: shown.size };
  }, passes);
  console.log(JSON.stringify(result));
} finally {
  await close();
}
