// The exported page in headless Chromium draws every frame identically to `spt render`, and a
// damaged clip shows an error and rejects seek() with libspt's message.
//   node player_test.mjs SPT_TOOL MEDIA_DIR WORK_DIR
// Exit 0 when every check passes; any failure (or anything missing) exits 1 naming it.
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { launch, openPlayer } from './chromium.mjs';

const [spt, media, work] = process.argv.slice(2);
if (!spt || !media || !work) {
  console.error('usage: node player_test.mjs SPT_TOOL MEDIA_DIR WORK_DIR');
  process.exit(2);
}
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
const w = (name) => path.join(work, name);
const run = (...args) => execFileSync(spt, args, { stdio: ['ignore', 'pipe', 'pipe'] }).toString();

// A painted clip with two key frames (0 and 4) and inter frames after each.
const video = path.join(media, 'video', 'city.mpg');
if (!fs.existsSync(video)) throw new Error(`media missing: ${video}`);
run('paint', video, '-o', w('clip.spt'), '--frames', '0-7', '--keyframe-interval', '4', '--max-strokes', '3000',
    '--seed', '1', '--progress', 'none');
run('pack', w('clip.spt'), '-o', w('stored.spt'), '--stored');

// Frames in seek order: forwards over inter frames, back across a key frame, and single steps.
const FRAMES = [0, 2, 3, 5, 7, 1, 4, 6];

function ppm(file) {
  const b = fs.readFileSync(file);
  let pos = 0;
  for (let lines = 0; lines < 3;) if (b[pos++] === 10) ++lines;
  return b.subarray(pos);
}

// Frame n from the page's canvas (RGBA) against spt render's (RGB): every byte, alpha 255.
// `first`: the clip's source number of frame 0 (spt render takes source numbers, seek() indices).
async function checkFrames(page, clip, frames = FRAMES, tag = 'ref', first = 0) {
  for (const n of frames) run('render', clip, '-o', w(`${tag}.${n}.ppm`), '--frames', String(first + n));
  for (const n of frames) {
    const b64 = await page.evaluate(async (n) => {
      const el = document.querySelector('spt-player');
      el.pause();
      await el.seek(n);
      const c = el.canvas;
      const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let s = '';
      for (let i = 0; i < px.length; i += 0x8000) s += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
      return btoa(s);
    }, n);
    const got = Buffer.from(b64, 'base64');
    const want = ppm(w(`${tag}.${n}.ppm`));
    assert.equal(got.length / 4, want.length / 3, `frame ${n}: canvas size`);
    let bad = 0, first = -1;
    for (let i = 0, j = 0; j < want.length; i += 4, j += 3) {
      if (got[i] !== want[j] || got[i + 1] !== want[j + 1] || got[i + 2] !== want[j + 2] || got[i + 3] !== 255) {
        if (first < 0) first = j / 3;
        ++bad;
      }
    }
    assert.equal(bad, 0, `${path.basename(clip)} frame ${n}: ${bad} pixels differ from spt render (first at pixel ${first})`);
    console.log(`ok: ${path.basename(clip)} frame ${n} identical to spt render`);
  }
}

// libspt's message for `file`, as the native tool prints it.
function nativeError(file, frame) {
  const r = spawnSync(spt, ['render', file, '-o', w('x.ppm'), '--frames', String(frame)]);
  assert.notEqual(r.status, 0, `spt render of the damaged ${file} should fail`);
  return r.stderr.toString();
}

// The file with its HEAD chunk's major version set to `major`, the chunk's CRC made right
// again (CRC-32 of type and payload, SPEC.md), so that the version is what the reader meets.
function withMajorVersion(file, major) {
  const b = Buffer.from(file);
  const length = b.readUInt32LE(8);
  assert.equal(b.toString('latin1', 12, 16), 'HEAD');
  b.writeUInt16LE(major, 16);
  let c = 0xffffffff;
  for (const x of b.subarray(12, 16 + length)) {
    c ^= x;
    for (let k = 0; k < 8; ++k) c = (c >>> 1) ^ (0xedb88320 & -(c & 1));
  }
  b.writeUInt32LE((c ^ 0xffffffff) >>> 0, 16 + length);
  return b;
}

const { context, close } = await launch();
try {
  for (const clip of ['clip.spt', 'stored.spt']) {
    const html = w(clip.replace('.spt', '.html'));
    run('export', w(clip), '-o', html);
    // The stored mode compresses well: its page carries it gzipped (inflated by the browser).
    if (clip === 'stored.spt') assert.match(fs.readFileSync(html, 'utf8'), /id="spt-clip" data-encoding="gzip"/);
    const { page, errors } = await openPlayer(context, html);
    const info = await page.evaluate(async () => {
      const el = document.querySelector('spt-player');
      await el.ready;
      return { frameCount: el.frameCount, fps: el.fps, w: el.canvas.width, h: el.canvas.height };
    });
    assert.deepEqual(info, { frameCount: 8, fps: 25, w: 720, h: 405 }, `${clip}: the player's clip info`);
    await checkFrames(page, w(clip));
    // play() from frame 0 runs to the last frame at the file's fps and stops there (no loop).
    const played = await page.evaluate(async () => {
      const el = document.querySelector('spt-player');
      el.loop = false;
      await el.seek(0);
      const shown = [];
      el.addEventListener('frame', (e) => shown.push(e.detail.frame));
      const t = performance.now();
      const done = await new Promise((resolve) => {
        el.addEventListener('complete', () => resolve(true), { once: true });
        el.play();
        setTimeout(() => resolve(false), 20000);
      });
      return { done, shown, ms: performance.now() - t, frame: el.frame, playing: el.playing, error: el.errorMessage };
    });
    assert.ok(played.done, `${clip}: playback did not complete: ${JSON.stringify(played)}`);
    assert.equal(played.frame, 7, `${clip}: playback ends on the last frame`);
    assert.equal(played.playing, false);
    assert.ok(played.shown.length >= 2 && played.shown.every((f, i) => i === 0 || f > played.shown[i - 1]),
              `${clip}: frames shown in order: ${played.shown}`);
    assert.ok(played.ms >= 7 * 40 - 20, `${clip}: 8 frames at 25 fps took ${played.ms} ms`);
    console.log(`ok: ${clip} played frames ${played.shown.join(' ')} in ${played.ms.toFixed(0)} ms`);
    // Keys: arrows step a frame, Shift+arrow ten (clamped), Home/End, space plays and pauses.
    await page.evaluate(() => document.querySelector('spt-player').seek(3));
    await page.focus('spt-player');
    const frameAfter = async (key) => {
      await page.keyboard.press(key);
      // A key's seek() is drawn within a few tasks; an animation frame later it has been.
      return page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => setTimeout(() =>
        resolve(document.querySelector('spt-player').frame), 0))));
    };
    assert.equal(await frameAfter('ArrowRight'), 4, 'ArrowRight steps one frame');
    assert.equal(await frameAfter('ArrowLeft'), 3, 'ArrowLeft steps back');
    assert.equal(await frameAfter('Shift+ArrowRight'), 7, 'Shift+ArrowRight steps ten, clamped to the last frame');
    assert.equal(await frameAfter('Home'), 0);
    assert.equal(await frameAfter('End'), 7);
    await page.keyboard.press('Home');
    await page.keyboard.press(' ');
    assert.equal(await page.evaluate(() => document.querySelector('spt-player').playing), true, 'space plays');
    await page.keyboard.press(' ');
    assert.equal(await page.evaluate(() => document.querySelector('spt-player').playing), false, 'space pauses');
    console.log(`ok: ${clip} keys (arrows, Shift+arrows, Home, End, space)`);
    assert.deepEqual(errors, [], `${clip}: errors on the page`);
    await page.close();
  }

  // A cartoon with lines (format 1.4: anti-aliased curves) and stamps replayed after its
  // polygons and lines (format 1.5, coding 2 with lead strokes) draws as spt render draws it.
  const butterfly = path.join(media, 'video', 'butterfly-cartoon.avi');
  if (!fs.existsSync(butterfly)) throw new Error(`media missing: ${butterfly}`);
  // Every colour that covers 1e-4 of the pixels: many lines (the sparser palette's trial would
  // leave fewer).
  run('paint', butterfly, '-o', w('toon.spt'), '--frames', '40-41', '--style', 'cartoon', '--target-psnr', '36',
      '--seed', '1', '--min-color-share', '0.0001', '--progress', 'none');
  const toon = JSON.parse(run('info', w('toon.spt'), '--json', '--frames'));
  const kinds = toon.strokes.kinds;
  assert.ok(kinds.curve > 20 && kinds.stamp > 100, `toon.spt holds lines and stamps: ${JSON.stringify(kinds)}`);
  assert.equal(toon.format_version, '1.5');
  assert.deepEqual(toon.frame_list.map((f) => f.coding), ['replay', 'replay']);
  run('export', w('toon.spt'), '-o', w('toon.html'));
  {
    const { page, errors } = await openPlayer(context, w('toon.html'));
    await page.evaluate(async () => { await document.querySelector('spt-player').ready; });
    await checkFrames(page, w('toon.spt'), [0, 1, 0], 'toon', 40);  // painted from the video's frames 40-41
    assert.deepEqual(errors, [], 'toon.html: errors on the page');
    await page.close();
  }

  // --web: the folder for a web server. Served from here, its index.html fetches the module
  // and the clip beside it and draws the same frames.
  run('export', w('clip.spt'), '-o', w('site'), '--web');
  for (const f of ['index.html', 'clip.spt', 'spt-player.js', 'spt-core.js', 'spt_core.wasm', 'spt_core.wasm.gz'])
    assert.ok(fs.existsSync(path.join(w('site'), f)), `--web wrote site/${f}`);
  assert.deepEqual(fs.readFileSync(path.join(w('site'), 'clip.spt')), fs.readFileSync(w('clip.spt')));
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.spt': 'application/octet-stream' };
  const server = http.createServer((req, res) => {
    const file = path.join(w('site'), path.normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)));
    if (!file.startsWith(w('site')) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': types[path.extname(file)] ?? 'application/octet-stream' }).end(fs.readFileSync(file));
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  try {
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${server.address().port}/index.html`);
    const b64 = await page.evaluate(async () => {
      await customElements.whenDefined('spt-player');
      const el = document.querySelector('spt-player');
      await el.ready;
      el.pause();
      await el.seek(5);
      const px = el.canvas.getContext('2d').getImageData(0, 0, el.canvas.width, el.canvas.height).data;
      let s = '';
      for (let i = 0; i < px.length; i += 0x8000) s += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
      return btoa(s);
    });
    const got = Buffer.from(b64, 'base64');
    const want = ppm(w('ref.5.ppm'));
    let bad = 0;
    for (let i = 0, j = 0; j < want.length; i += 4, j += 3) if (got[i] !== want[j] || got[i + 1] !== want[j + 1] || got[i + 2] !== want[j + 2]) ++bad;
    assert.equal(bad, 0, `served --web page, frame 5: ${bad} pixels differ from spt render`);
    console.log('ok: the --web folder, served over http, draws frame 5 identical to spt render');
    await page.close();
  } finally {
    server.close();
  }

  // A damaged inter frame (a byte of frame 2's payload flipped): spt export refuses the file;
  // a page holding it plays up to that frame, then shows libspt's message and rejects.
  const bytes = fs.readFileSync(w('clip.spt'));
  const frams = [];
  for (let i = bytes.indexOf('FRAM'); i >= 0; i = bytes.indexOf('FRAM', i + 4)) frams.push(i);
  assert.ok(frams.length >= 8, `clip.spt: ${frams.length} FRAM chunks found`);
  const damaged = Buffer.from(bytes);
  damaged[frams[2] + 40] ^= 0x55;
  fs.writeFileSync(w('damaged.spt'), damaged);
  const refused = spawnSync(spt, ['export', w('damaged.spt'), '-o', w('damaged.html')]);
  assert.equal(refused.status, 1, `spt export of a damaged file exits 1: ${refused.stderr}`);
  assert.ok(!fs.existsSync(w('damaged.html')), 'no page written for a damaged file');
  const native = nativeError(w('damaged.spt'), 2);
  const good = fs.readFileSync(w('clip.html'), 'utf8');
  const clipElement = /<script type="application\/octet-stream" id="spt-clip"[^>]*>[^<]*<\/script>/;
  assert.match(good, clipElement, 'clip.html holds the clip in a <script id="spt-clip">');
  fs.writeFileSync(w('damaged.html'), good
    .replace(clipElement, `<script type="application/octet-stream" id="spt-clip">${damaged.toString('base64')}</script>`)
    .replace(' autoplay loop>', '>'));
  {
    const { page } = await openPlayer(context, w('damaged.html'));
    const r = await page.evaluate(async () => {
      const el = document.querySelector('spt-player');
      await el.ready;
      await el.seek(1);
      try {
        await el.seek(2);
        return { resolved: true };
      } catch (e) {
        const box = el.shadowRoot.querySelector('.error');
        return { message: e.message, code: e.code, shown: !box.hidden && box.textContent, errorMessage: el.errorMessage };
      }
    });
    assert.ok(!r.resolved, 'seek(2) of the damaged clip resolved');
    assert.ok(r.message.length > 0 && native.includes(r.message),
              `the rejection "${r.message}" is libspt's message as spt render gives it: ${native}`);
    assert.equal(r.shown, r.message, 'the element shows the message');
    assert.equal(r.errorMessage, r.message);
    console.log(`ok: damaged frame 2 rejected with libspt's message: ${r.message} (${r.code})`);

    // Not a .spt file at all, and an unsupported version: load() rejects, the element shows it.
    for (const [name, data] of [['not-spt', Buffer.from('this is not a painting, just text\n'.repeat(4))],
                                ['version-9', withMajorVersion(bytes, 9)]]) {
      fs.writeFileSync(w(name + '.spt'), data);
      const want = spawnSync(spt, ['info', w(name + '.spt')]).stderr.toString();
      const m = await page.evaluate(async (b64) => {
        const el = document.querySelector('spt-player');
        let event = null;
        el.addEventListener('loaderror', (e) => { event = e.detail.message; }, { once: true });
        try { await el.load(Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))); return null; } catch (e) { return [e.message, el.errorMessage, event]; }
      }, data.toString('base64'));
      assert.ok(m, `${name}: load() resolved`);
      assert.ok(want.includes(m[0]), `${name}: the rejection "${m[0]}" is libspt's message: ${want}`);
      assert.equal(m[1], m[0], `${name}: the element shows the message`);
      assert.equal(m[2], m[0], `${name}: a loaderror event carries the message`);
      console.log(`ok: ${name} rejected with libspt's message: ${m[0]}`);
    }
    await page.close();
  }

  // Format 1.3 (made from JSON version 3 by spt import): a scene-linear clip shows the sRGB view
  // spt render writes, byte for byte; an alpha clip is transparent where nothing is painted,
  // over the file's background colour, and opaque pixels are spt render's.
  {
    const strokes = [];
    for (let i = 0; i < 60; ++i)
      strokes.push({ type: 'stamp', set: 0, template: i % 2, orient: i % 8, x: (i * 37) % 96 + 0.5, y: (i * 23) % 64 + 0.5,
                     linear: [(i % 7) * 0.9, 0.03 * (i % 5), 3.5 * (i % 3)] });
    const doc = (canvas) => JSON.stringify({ format: 'spt-strokes', version: 3, sets: [[12, 6]], strokes,
                                              canvas: { width: 96, height: 64, ...canvas } });
    fs.writeFileSync(w('lin.json'), doc({ color_encoding: 'linear-half', background: [14336, 0, 15360] }));
    fs.writeFileSync(w('alpha.json'), doc({ color_encoding: 'linear-half', alpha: true, background: [14336, 0, 15360] }));
    const { page, errors } = await openPlayer(context, w('clip.html'));
    for (const name of ['lin', 'alpha']) {
      run('import', w(`${name}.json`), '-o', w(`${name}.spt`), '--quiet');
      run('render', w(`${name}.spt`), '-o', w(`${name}.ppm`));
      const r = await page.evaluate(async (b64) => {
        const el = document.querySelector('spt-player');
        el.pause();
        await el.load(Uint8Array.from(atob(b64), (c) => c.charCodeAt(0)));
        await el.seek(0);
        const px = el.canvas.getContext('2d').getImageData(0, 0, el.canvas.width, el.canvas.height).data;
        let s = '';
        for (let i = 0; i < px.length; i += 0x8000) s += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
        return { px: btoa(s), background: el.canvas.style.background };
      }, fs.readFileSync(w(`${name}.spt`)).toString('base64'));
      const got = Buffer.from(r.px, 'base64');
      const want = ppm(w(`${name}.ppm`));
      assert.equal(got.length / 4, want.length / 3, `${name}: canvas size`);
      // The file's background 0.5, 0, 1.0 through the sRGB curve is #bc00ff.
      let bad = 0, clear = 0, first = -1;
      for (let i = 0, j = 0; j < want.length; i += 4, j += 3) {
        const a = got[i + 3];
        const same = got[i] === want[j] && got[i + 1] === want[j + 1] && got[i + 2] === want[j + 2];
        const ok = a === 255 ? same : name === 'alpha' && a === 0 && want[j] === 0xbc && want[j + 1] === 0 && want[j + 2] === 0xff;
        if (a === 0) ++clear;
        if (!ok && first < 0) first = j / 3;
        if (!ok) ++bad;
      }
      assert.equal(bad, 0, `${name}.spt: ${bad} pixels differ from spt render (first at pixel ${first})`);
      if (name === 'alpha') {
        assert.ok(clear > 100, `alpha.spt: ${clear} transparent pixels`);
        assert.equal(r.background, 'rgb(188, 0, 255)', 'alpha.spt: drawn over the file background');
      } else {
        assert.equal(clear, 0);
        assert.equal(r.background, '', 'lin.spt: no background behind an opaque canvas');
      }
      console.log(`ok: ${name}.spt (format 1.3) drawn as spt render shows it`);
    }
    assert.deepEqual(errors, [], 'format 1.3: errors on the page');
    await page.close();
  }
} finally {
  await close();
}
console.log('web player: all checks passed');
