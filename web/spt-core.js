// spt-core.js: libspt compiled to WebAssembly (spt_core.wasm, built from format/src by
// web/CMakeLists.txt), wrapped for JavaScript. No DOM: the player element, the tests and the
// benchmarks (in Node too) all use this.
//
//   const core = await loadSptCore(wasmBytesOrUrl);
//   const clip = core.open(fileBytes);          // throws SptError with libspt's message
//   clip.width, clip.height, clip.frameCount, clip.fps
//   const rgba = clip.render(n);                // Uint8ClampedArray, width * height * 4
//   clip.close();

export class SptError extends Error {
  constructor(message, code) {
    super(message);
    this.name = 'SptError';
    this.code = code;  // libspt's spt::Code name: "corrupt", "not an .spt file", ...
  }
}

const cores = new Map();

// Loads the module once per source. `source`: bytes (ArrayBuffer, typed array), a URL (string
// or URL) to fetch, or a compiled WebAssembly.Module.
export function loadSptCore(source) {
  const key = source instanceof URL ? source.href : source;
  if (!cores.has(key)) cores.set(key, instantiate(source));
  return cores.get(key);
}

async function instantiate(source) {
  let module;
  if (source instanceof WebAssembly.Module) module = source;
  else if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) module = await WebAssembly.compile(source);
  else {
    const response = await fetch(source);
    if (!response.ok) throw new SptError(`${source}: ${response.status} ${response.statusText}`, 'i/o error');
    module = await WebAssembly.compile(await response.arrayBuffer());
  }
  // STANDALONE_WASM with no stdio: libspt reports errors as values, so these two are all the
  // module imports (abort() ends in proc_exit).
  const imports = {
    env: { emscripten_notify_memory_growth() {} },
    wasi_snapshot_preview1: { proc_exit(code) { throw new SptError(`libspt stopped (exit ${code})`, 'bad state'); } },
  };
  const instance = await WebAssembly.instantiate(module, imports);
  instance.exports._initialize();
  return new SptCore(instance.exports);
}

class SptCore {
  constructor(x) { this.x = x; }

  string(ptr) {
    const bytes = new Uint8Array(this.x.memory.buffer, ptr);
    return new TextDecoder().decode(bytes.subarray(0, bytes.indexOf(0)));
  }

  error() {
    return new SptError(this.string(this.x.spt_error_message()), this.string(this.x.spt_code_name(this.x.spt_error_code())));
  }

  // Opens a .spt file from its bytes (copied into the module).
  open(bytes) {
    const data = bytes instanceof ArrayBuffer ? new Uint8Array(bytes) : new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const ptr = this.x.spt_alloc(data.length);
    new Uint8Array(this.x.memory.buffer, ptr, data.length).set(data);
    const handle = this.x.spt_open(ptr, data.length);
    this.x.spt_free(ptr);
    if (!handle) throw this.error();
    return new SptClip(this, handle);
  }
}

class SptClip {
  constructor(core, handle) {
    const x = core.x;
    this.core = core;
    this.handle = handle;
    this.width = x.spt_width(handle);
    this.height = x.spt_height(handle);
    this.frameCount = x.spt_frame_count(handle);
    this.fpsRational = [x.spt_fps_num(handle), x.spt_fps_den(handle)];
    this.fps = this.fpsRational[0] / this.fpsRational[1];
    // Format 1.3: an alpha canvas is transparent where nothing is painted; `background`
    // ('#rrggbb', sRGB) is what the file asks a viewer to show behind it.
    this.hasAlpha = x.spt_has_alpha(handle) !== 0;
    this.background = '#' + x.spt_background(handle).toString(16).padStart(6, '0');
    this.warnings = [];
    for (let i = 0; i < x.spt_warning_count(handle); ++i) this.warnings.push(core.string(x.spt_warning(handle, i)));
  }

  isKey(n) { return this.core.x.spt_is_key(this.handle, n) !== 0; }

  // Decodes and renders frame position n (0-based). The array views the module's memory:
  // copy it (or draw it) before the next call.
  render(n) {
    const x = this.core.x;
    if (!this.handle) throw new SptError('the clip is closed', 'bad state');
    if (x.spt_render(this.handle, n >>> 0) !== 0) throw this.core.error();
    return new Uint8ClampedArray(x.memory.buffer, x.spt_pixels(this.handle), this.width * this.height * 4);
  }

  close() {
    if (this.handle) this.core.x.spt_close(this.handle);
    this.handle = 0;
  }
}
