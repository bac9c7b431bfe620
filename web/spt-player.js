// spt-player.js: the <spt-player> element, a .spt clip played in the browser by libspt
// compiled to WebAssembly (spt-core.js). See web/README.md.
//
//   <script type="module" src="spt-player.js"></script>
//   <spt-player src="clip.spt" autoplay loop></spt-player>
//
//   await el.seek(n)   resolves once frame n is drawn (rejects with libspt's message)
//   el.play(), el.pause(), el.frameCount, el.fps, el.frame, el.canvas, el.loop, el.speed
//   await el.load(urlOrBytes), await el.ready
//   events: load, frame (detail.frame), play, pause, complete, error and loaderror (detail.message)
import { loadSptCore, SptError } from './spt-core.js';

// Where the WebAssembly module comes from: globalThis.SPT_PLAYER_WASM (bytes or a URL) if a
// page sets it; else the element with id "spt-player-wasm" (the self-contained page of
// `spt export -o page.html`); else spt_core.wasm beside this file.
let inlineWasm = null;
function wasmSource() {
  if (globalThis.SPT_PLAYER_WASM) return Promise.resolve(globalThis.SPT_PLAYER_WASM);
  const inline = document.getElementById('spt-player-wasm');
  if (inline) return (inlineWasm ??= inlineBytes(inline));
  return Promise.resolve(new URL('spt_core.wasm', import.meta.url));
}

// src="#id": the clip is inside the element with that id (self-contained pages).
async function clipBytes(src) {
  if (src instanceof ArrayBuffer || ArrayBuffer.isView(src)) return src;
  src = String(src);
  if (src.startsWith('#')) {
    const holder = document.getElementById(src.slice(1));
    if (!holder) throw new SptError(`${src}: no element with that id holds the clip`, 'i/o error');
    return inlineBytes(holder);
  }
  const response = await fetch(src).catch((e) => { throw new SptError(`${src}: ${e.message}`, 'i/o error'); });
  if (!response.ok) throw new SptError(`${src}: ${response.status} ${response.statusText}`, 'i/o error');
  return response.arrayBuffer();
}

// The bytes an inline element holds: its text in base64, gzipped first when it has
// data-encoding="gzip" (inflated by the browser's DecompressionStream).
async function inlineBytes(holder) {
  const bytes = base64Bytes(holder.textContent);
  if (holder.dataset.encoding !== 'gzip') return bytes;
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

export function base64Bytes(text) {
  const s = atob(text.replace(/\s+/g, ''));
  const out = new Uint8Array(s.length);
  for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
  return out;
}

const STYLE = `
:host { display: inline-block; position: relative; max-width: 100%; font: 13px system-ui, sans-serif;
        color: #eee; background: #222; outline: none; }
:host(:focus-visible) { box-shadow: 0 0 0 2px #58f; }
canvas { display: block; max-width: 100%; height: auto; background: #000; }
.bar { display: flex; align-items: center; gap: 8px; padding: 4px 8px; }
.bar[hidden] { display: none; }
button { font: inherit; color: inherit; background: #444; border: 0; border-radius: 3px;
         padding: 2px 10px; cursor: pointer; min-width: 4em; }
input[type=range] { flex: 1; min-width: 60px; }
.num { font-variant-numeric: tabular-nums; white-space: nowrap; }
.error { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
         padding: 16px; text-align: center; background: #300d; color: #fcc; white-space: pre-wrap; }
.error[hidden] { display: none; }
`;

export class SptPlayer extends HTMLElement {
  static get observedAttributes() { return ['src', 'loop', 'controls']; }

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML = `<style>${STYLE}</style><canvas width="0" height="0" part="canvas"></canvas>
      <div class="bar" part="controls"><button class="play" title="play/pause (space)">play</button>
      <input class="scrub" type="range" min="0" max="0" value="0" title="frame (arrows)">
      <span class="num">0 / 0</span><label><input class="loop" type="checkbox"> loop</label></div>
      <div class="error" role="alert" hidden></div>`;
    this._canvas = root.querySelector('canvas');
    this._context = this._canvas.getContext('2d', { willReadFrequently: true });
    this._bar = root.querySelector('.bar');
    this._button = root.querySelector('.play');
    this._scrub = root.querySelector('.scrub');
    this._num = root.querySelector('.num');
    this._loopBox = root.querySelector('.loop');
    this._error = root.querySelector('.error');
    this._clip = null;
    this._frame = -1;        // the frame on the canvas
    this._playing = false;
    this._speed = 1;
    this._generation = 0;    // bumped by each load, so a late load cannot overwrite a newer one
    this._ready = null;
    this._button.addEventListener('click', () => (this._playing ? this.pause() : this.play()));
    this._scrub.addEventListener('input', () => { this.pause(); this.seek(Number(this._scrub.value)).catch(() => {}); });
    this._loopBox.addEventListener('change', () => { this.loop = this._loopBox.checked; });
    this.addEventListener('keydown', (e) => this._key(e));
    this._tick = this._tick.bind(this);
  }

  connectedCallback() {
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    this._bar.hidden = this.getAttribute('controls') === 'false';
    if (!this._ready && this.hasAttribute('src')) this.load(this.getAttribute('src')).catch(() => {});
  }

  disconnectedCallback() { this.pause(); }

  attributeChangedCallback(name, old, value) {
    if (name === 'loop') this._loopBox.checked = value !== null;
    else if (name === 'controls') this._bar.hidden = value === 'false';
    else if (name === 'src' && this.isConnected && value !== null && old !== null && old !== value) this.load(value).catch(() => {});
  }

  get canvas() { return this._canvas; }
  get frameCount() { return this._clip ? this._clip.frameCount : 0; }
  get fps() { return this._clip ? this._clip.fps : 0; }
  get frame() { return this._frame; }
  get playing() { return this._playing; }
  get loop() { return this.hasAttribute('loop'); }
  set loop(v) { this.toggleAttribute('loop', !!v); }
  get speed() { return this._speed; }
  set speed(v) { this._speed = Number(v) > 0 ? Number(v) : 1; if (this._playing) this._restartClock(); }
  // Resolves once the clip is open (and frame 0 drawn); rejects with the load's error.
  get ready() { return this._ready ?? Promise.reject(new SptError('no clip: set src or call load()', 'bad state')); }

  // Opens a clip: a URL, "#id" of an element holding base64, or the file's bytes.
  load(src) {
    this.pause();
    const generation = ++this._generation;
    if (this._clip) this._clip.close();
    this._clip = null;
    this._frame = -1;
    this._showError(null);
    this._ready = (async () => {
      try {
        const [core, bytes] = await Promise.all([wasmSource().then(loadSptCore), clipBytes(src)]);
        if (generation !== this._generation) throw new SptError('superseded by a newer load', 'bad state');
        this._clip = core.open(bytes);
        this._canvas.width = this._clip.width;
        this._canvas.height = this._clip.height;
        // Alpha canvases are drawn over the file's background colour (not the player's black).
        this._canvas.style.background = this._clip.hasAlpha ? this._clip.background : '';
        this._scrub.max = String(this._clip.frameCount - 1);
        this._draw(0);
      } catch (e) {
        if (generation === this._generation) {
          this._fail(e);
          this.dispatchEvent(new CustomEvent('loaderror', { detail: { message: e.message, code: e.code } }));
        }
        throw e;
      }
      this.dispatchEvent(new CustomEvent('load', { detail: { frameCount: this.frameCount, fps: this.fps } }));
      if (this.hasAttribute('autoplay')) this.play();
    })();
    return this._ready;
  }

  // Resolves once frame n is on the canvas.
  async seek(n) {
    await this.ready;
    if (!Number.isInteger(n) || n < 0 || n >= this.frameCount)
      throw new SptError(`frame ${n} is outside the clip (0 to ${this.frameCount - 1})`, 'invalid argument');
    if (this._playing) this._restartClock(n);
    try {
      this._draw(n);
    } catch (e) {
      this._fail(e);
      throw e;
    }
  }

  play() {
    if (!this._clip || this._playing) return;
    if (this._frame >= this.frameCount - 1 && !this.loop) this._draw(0);
    this._playing = true;
    this._button.textContent = 'pause';
    this._restartClock();
    this._raf = requestAnimationFrame(this._tick);
    this.dispatchEvent(new CustomEvent('play'));
  }

  pause() {
    if (this._playing) this.dispatchEvent(new CustomEvent('pause'));
    this._playing = false;
    this._button.textContent = 'play';
    if (this._raf) cancelAnimationFrame(this._raf);
    this._raf = 0;
  }

  // Playback is timed by the clock, not by frames drawn: on a machine too slow for the file's
  // fps, the frames in between are skipped and the clip keeps its duration.
  _restartClock(from = this._frame) {
    this._t0 = performance.now() - (Math.max(0, from) * 1000) / (this.fps * this._speed);
  }

  _tick(now) {
    if (!this._playing) return;
    const n = this.frameCount;
    // now (the frame's start) can be a little before the clock was started in play().
    let target = Math.max(0, Math.floor(((now - this._t0) * this.fps * this._speed) / 1000));
    if (target >= n) {
      if (this.loop) {
        target %= n;
        this._t0 = now - (target * 1000) / (this.fps * this._speed);
      } else {
        if (this._frame !== n - 1) this._safeDraw(n - 1);
        this.pause();
        this.dispatchEvent(new CustomEvent('complete'));
        return;
      }
    }
    if (target !== this._frame) this._safeDraw(target);
    if (this._playing) this._raf = requestAnimationFrame(this._tick);
  }

  _safeDraw(n) {
    try { this._draw(n); } catch (e) { this._fail(e); }
  }

  _draw(n) {
    const rgba = this._clip.render(n);
    this._context.putImageData(new ImageData(rgba, this._clip.width, this._clip.height), 0, 0);
    this._frame = n;
    this._scrub.value = String(n);
    this._num.textContent = `${n} / ${this.frameCount - 1}`;
    this.dispatchEvent(new CustomEvent('frame', { detail: { frame: n } }));
  }

  _fail(e) {
    this.pause();
    this._showError(e.message);
    this.dispatchEvent(new CustomEvent('error', { detail: { message: e.message, code: e.code } }));
  }

  // The message shown over the canvas, or none; readable as el.errorMessage.
  _showError(message) {
    this._error.hidden = message === null;
    this._error.textContent = message ?? '';
  }
  get errorMessage() { return this._error.hidden ? null : this._error.textContent; }

  _key(e) {
    if (!this._clip) return;
    const step = e.shiftKey ? 10 : 1;
    const go = (n) => { this.pause(); this.seek(Math.min(this.frameCount - 1, Math.max(0, n))).catch(() => {}); };
    if (e.key === ' ' || e.key === 'k') this._playing ? this.pause() : this.play();
    else if (e.key === 'ArrowRight') go(this._frame + step);
    else if (e.key === 'ArrowLeft') go(this._frame - step);
    else if (e.key === 'Home') go(0);
    else if (e.key === 'End') go(this.frameCount - 1);
    else if (e.key === 'l') this.loop = !this.loop;
    else return;
    e.preventDefault();
  }
}

if (!customElements.get('spt-player')) customElements.define('spt-player', SptPlayer);
