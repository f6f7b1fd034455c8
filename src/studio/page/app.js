// sandpic studio's page: controls bound to scene keys, a lattice preview
// that follows a slider as it moves, the fall played as an animation, flip,
// cell colours painted by hand, final DEM renders with progress and cancel,
// downloads, drag and drop.
'use strict';

// A number typed key by key waits this long after its last keystroke: a
// half-typed "1." or the "3" of "350" is no value to show.
const TYPING_MS = 150;

const App = {
  scene: null,
  picture: null,     // the PNG of the preview shown (Blob)
  timer: 0,          // a typed change waiting for the next keystroke, 0 if none
  seq: 0,            // the number of the newest preview asked for
  shownSeq: 0,       // the number of the preview shown
  inflight: false,   // a preview request is out: at most one is
  dirty: false,      // the scene changed since the last preview request was sent
  fallSeq: 0,        // likewise animations: a newer one stops an older one playing
  renderId: 0,       // the final render running, 0 if none

  async start() {
    this.scene = await (await api('GET', '/api/scene')).json();
    this.controls(await (await api('GET', '/api/keys')).json());
    this.bind();
    Sketch.init(document.getElementById('sketch'), (kind, line) => this.addStroke(kind, line), (i) => this.paintCell(i));
    this.dropTarget();
    this.show();
    this.changed(0);
  },

  // Each control's choices, range and help from the key registry (/api/keys),
  // so a key's names and limits are declared once, in the tool.
  controls(keys) {
    const byKey = new Map(keys.map((k) => [k.key, k]));
    for (const el of document.querySelectorAll('[data-key]')) {
      const k = byKey.get(el.dataset.key);
      if (!k) continue;
      el.title = k.help;
      if (el.tagName === 'SELECT' && k.choices) {
        el.replaceChildren(...k.choices.map((c) => new Option(c === '' ? '(none)' : c, c)));
      } else if (el.type === 'number' && k.min !== undefined) {
        el.min = k.min;
        el.max = k.max;
      } else if (el.type === 'range' && k.min !== undefined) {
        // A slider spans the part of the key's range its page sets, within the range.
        el.min = Math.max(Number(el.min), k.min);
        el.max = Math.min(Number(el.max), k.max);
      }
    }
  },

  bind() {
    for (const el of document.querySelectorAll('[data-key]')) {
      el.addEventListener('input', (e) => {
        const key = el.dataset.key;
        const v = el.type === 'number' || el.type === 'range' ? Number(el.value) : el.value;
        if (key === 'preset') return this.loadPreset(v);
        Scene.set(this.scene, key, v);
        // The key's other control (a slider's number field) follows.
        for (const other of document.querySelectorAll(`[data-key="${key}"]`)) if (other !== el) other.value = el.value;
        // Keystrokes (an InputEvent with an inputType) wait for the next one;
        // a slider, a number field's arrows and a menu (a plain Event) go at once.
        this.changed(e.inputType ? TYPING_MS : 0);
      });
    }
    for (const el of document.querySelectorAll('[data-color]')) {
      el.addEventListener('input', () => {
        this.scene.grains.colors[Number(el.dataset.color)] = el.value;
        this.changed();
      });
    }
    const on = (id, f) => document.getElementById(id).addEventListener('click', f);
    on('flip', () => this.reseed('physics_seed'));
    on('new-layout', () => this.reseed('layout_seed'));
    on('undo-stroke', () => this.undoStroke());
    on('clear-sketch', () => {
      this.scene.segment.sketch.ridges = [];
      this.scene.segment.sketch.arcs = [];
      this.sketchRemoved();
    });
    document.getElementById('show-units').addEventListener('change', () => Sketch.draw(this.scene));
    for (const el of document.querySelectorAll('input[name=pen]'))
      el.addEventListener('change', () => Sketch.draw(this.scene));
    on('clear-cells', () => {
      this.scene.init.cell_overrides = [];
      this.show();
      this.changed(0);
    });
    on('play-fall', () => this.playFall());
    on('download-fall', () => this.downloadFall());
    on('cancel-render', () => this.cancelRender());
    on('final-render', () => this.finalRender());
    on('download-picture', () => this.picture && this.download(this.picture, 'sandpic.png'));
    on('download-scene', () =>
      this.download(new Blob([JSON.stringify(this.scene, null, 2)], { type: 'application/json' }), 'scene.json'));
  },

  // The controls from the scene.
  show() {
    for (const el of document.querySelectorAll('[data-key]')) {
      const v = Scene.get(this.scene, el.dataset.key);
      if (v !== undefined && v !== null) el.value = v;
    }
    for (const el of document.querySelectorAll('[data-color]'))
      el.value = Scene.hex(this.scene.grains.colors[Number(el.dataset.color)]);
    const s = this.scene;
    document.getElementById('seeds').textContent =
      `seed ${s.seed}, layout ${s.layout_seed ?? s.seed}, physics ${s.physics_seed ?? s.seed}`;
    const sk = s.segment.sketch, half = s.segment.method !== 'sketch' && (sk.ridges.length || sk.arcs.length);
    document.getElementById('sketch-hint').textContent = !half ? '' : sk.ridges.length
      ? 'now draw arc-like curves across the ridge line (pen: arc): the sketch is used once it has both'
      : 'now draw a ridge line for the arcs to cross (pen: ridge line): the sketch is used once it has both';
    document.getElementById('image-name').textContent =
      s.init.method === 'halftone' ? this.imageName || `halftoning ${s.init.image}` : '';
    const edits = (s.init.cell_overrides || []).length;
    document.getElementById('cell-count').textContent = edits ? `${edits} cell(s) edited` : '';
    Sketch.draw(s);
  },

  reseed(key) {
    this.scene[key] = Math.floor(Math.random() * 2 ** 31);
    // A new layout is new cells: the edits named the old ones by number.
    if (key === 'layout_seed') this.scene.init.cell_overrides = [];
    this.show();
    this.changed(0);
  },

  // paper §5.2: a sketch is ridge lines with arc-like curves across them;
  // half of one cannot segment. It is used (segment.method = sketch) once
  // it has both, and until then the page says what is missing and keeps
  // the picture of the method before.
  addStroke(kind, line) {
    if (kind !== 'ridges' && kind !== 'arcs') return;
    const seg = this.scene.segment;
    seg.sketch[kind].push(line);
    this.lastStroke = kind;
    if (seg.method !== 'sketch' && seg.sketch.ridges.length && seg.sketch.arcs.length) {
      this.methodBefore = seg.method;
      seg.method = 'sketch';
    }
    this.show();
    if (seg.method === 'sketch') this.changed(0);
  },

  // After a stroke is taken away: a sketch left without ridges or arcs
  // (and no sketch picture) goes back to the method before it.
  sketchRemoved() {
    const seg = this.scene.segment;
    if (seg.method === 'sketch' && !seg.sketch.image && !(seg.sketch.ridges.length && seg.sketch.arcs.length))
      seg.method = this.methodBefore || 'ellipses';
    this.show();
    this.changed(0);
  },

  // paper §3: the clicked cell takes the chosen dominant and secondary
  // classes (Algorithm 1 then fills it with them as with drawn ones).
  paintCell(i) {
    const dominant = Number(document.getElementById('cell-dominant').value);
    const secondary = Number(document.getElementById('cell-secondary').value);
    if (dominant === secondary) {
      this.showError(Object.assign(new Error('the dominant and secondary classes must differ'), { key: 'init.cell_overrides' }));
      return;
    }
    const list = (this.scene.init.cell_overrides || []).filter((o) => o.cell !== i);
    list.push({ cell: i, dominant, secondary });
    list.sort((a, b) => a.cell - b.cell);
    this.scene.init.cell_overrides = list;
    this.show();
    this.changed(0);
  },

  undoStroke() {
    const sk = this.scene.segment.sketch, kind = this.lastStroke;
    if (kind && sk[kind].length) sk[kind].pop();
    else if (sk.arcs.length) sk.arcs.pop();
    else sk.ridges.pop();
    this.sketchRemoved();
  },

  // Previews as fast as the studio answers them, one request in flight at
  // most: a change while one is out only marks the scene dirty, and the
  // answer sends the newest scene at once. While a slider is dragged the
  // preview follows it without a queue of stale scenes; a single change is
  // sent at once. `delay`: a typed change waits that long for the next
  // keystroke (TYPING_MS).
  changed(delay = 0) {
    clearTimeout(this.timer);
    this.timer = 0;
    this.dirty = true;
    Sketch.draw(this.scene);
    if (delay > 0) this.timer = setTimeout(() => { this.timer = 0; this.next(); }, delay);
    else this.next();
  },

  // The newest scene, if it has changed, unless a request is out or a typed
  // change waits for its next keystroke (each calls this again when done).
  next() {
    if (this.inflight || this.timer || !this.dirty) return;
    this.dirty = false;
    this.preview();
  },

  // Every answer is shown: answers come in the order sent (one at a time),
  // so one for a scene changed since is still the newest picture the page
  // has and nearer the scene than the one before. The next request goes as
  // soon as an answer's headers are in (the studio is done with it), while
  // its picture is read and decoded. The units and the fall's autoplay wait
  // for the answer of the scene as it is (at the end of a drag): mid-drag
  // they would be outdated at once and take the studio's time from the next
  // preview. An error for a changed scene is dropped: the newer scene's
  // answer follows at once.
  async preview() {
    const seq = ++this.seq, t0 = performance.now();
    this.inflight = true;
    this.status('rendering preview...');
    let res;
    try {
      res = await api('POST', '/api/preview', { ...this.scene, mode: 'lattice' });
    } catch (e) {
      this.inflight = false;
      this.status('');
      if (e.status === 409) {
        // Another page's newer preview took this one's place in the studio's
        // queue of one: this scene is asked for again shortly after.
        this.dirty = true;
        setTimeout(() => this.next(), 100);
        return;
      }
      if (!this.dirty && !this.timer) this.showError(e);
      this.next();
      return;
    }
    const current = !this.dirty && !this.timer;
    this.inflight = false;
    this.next();
    let blob;
    try {
      blob = await res.blob();
    } catch (e) {
      if (current) this.showError(e);
      return;
    }
    // Decoded off the main thread and drawn on a canvas: an <img> given a
    // blob URL took 20-25 ms longer to reach the screen in Chromium (the
    // default scene's 1000x700 preview).
    let bitmap;
    try {
      bitmap = await createImageBitmap(blob);
    } catch (e) {
      if (current) this.showError(e);
      return;
    }
    if (seq < this.shownSeq) { bitmap.close(); return; }  // a newer answer was drawn first
    this.shownSeq = seq;
    this.clearErrors();
    this.picture = blob;
    const canvas = document.getElementById('preview');
    if (canvas.width !== bitmap.width || canvas.height !== bitmap.height) {
      canvas.width = bitmap.width;
      canvas.height = bitmap.height;
    }
    canvas.getContext('2d').drawImage(bitmap, 0, 0);
    bitmap.close();
    // Tests and the benchmark wait on this: the preview numbered seq is drawn.
    canvas.dataset.seq = seq;
    const stats = JSON.parse(res.headers.get('X-Sandpic-Stats') || '{}');
    document.getElementById('stats').textContent =
      `${stats.grains?.total ?? '?'} grains, ${stats.units ?? '?'} units, ` +
      `lattice ${(stats.timing?.total_s ?? 0).toFixed(2)} s, round trip ${((performance.now() - t0) / 1000).toFixed(2)} s`;
    if (!this.inflight) this.status('');
    if (current) {
      this.units();
      if (document.getElementById('autoplay').checked) this.playFall();
    }
  },

  async units() {
    try {
      Sketch.units = await (await api('POST', '/api/units', this.scene)).json();
    } catch (_) {
      Sketch.units = { ellipses: [], cells: [], tessellation: [] };
    }
    Sketch.draw(this.scene);
  },

  // A preset is a base the scene's own keys override: start from the preset
  // alone, keeping the window, the region and the seed.
  async loadPreset(name) {
    const s = this.scene;
    const base = { preset: name, window: s.window, region: s.region, seed: s.seed };
    try {
      this.scene = await (await api('POST', '/api/scene', base)).json();
      this.show();
      this.changed(0);
    } catch (e) {
      this.showError(e);
    }
  },

  async loadText(text) {
    this.imageName = '';
    try {
      this.scene = await (await api('POST', '/api/scene', JSON.parse(text))).json();
      this.show();
      this.changed(0);
    } catch (e) {
      this.showError(e instanceof SyntaxError ? Object.assign(e, { key: '' }) : e);
    }
  },

  dropTarget() {
    const body = document.body;
    body.addEventListener('dragover', (e) => { e.preventDefault(); body.classList.add('dragging'); });
    body.addEventListener('dragleave', () => body.classList.remove('dragging'));
    body.addEventListener('drop', async (e) => {
      e.preventDefault();
      body.classList.remove('dragging');
      const file = e.dataTransfer.files[0];
      if (file) this.loadFile(file);
    });
    for (const id of ['scene-file', 'image-file'])
      document.getElementById(id).addEventListener('change', (e) => {
        const file = e.target.files[0];
        e.target.value = '';  // the same file chosen again is a change again
        if (file) this.loadFile(file);
      });
  },

  // A picture is halftoned into the region; anything else is read as a scene file.
  loadFile(file) {
    const picture = file.type.startsWith('image/') || /\.(png|jpe?g|bmp|tiff?|webp)$/i.test(file.name);
    return picture ? this.loadImage(file) : file.text().then((text) => this.loadText(text));
  },

  // paper §4.2: the picture goes to the studio's folder (studio-inputs/),
  // and the scene halftones it.
  async loadImage(file) {
    this.status('reading the picture...');
    try {
      const { path, width, height } = await (await api('POST', '/api/image', file)).json();
      this.scene.init.method = 'halftone';
      this.scene.init.image = path;
      this.imageName = `${file.name} (${width} x ${height}), halftoned into the region`;
      this.show();
      this.changed(0);
    } catch (e) {
      this.showError(e, 'init.image');
    }
    this.status('');
  },

  // The lattice's fall (paper Fig. 14c-d) over the preview, once, then the
  // preview again. The frames come as JPEGs back to back; all are decoded
  // before the first is shown, so it plays at its pace.
  async playFall() {
    const seq = ++this.fallSeq;
    const canvas = document.getElementById('fall');
    const frames = document.getElementById('fall-frames').value;
    this.status('rendering the fall...');
    try {
      const res = await api('POST', '/api/animation?frames=' + encodeURIComponent(frames), { ...this.scene, mode: 'lattice' });
      const buf = await res.arrayBuffer();
      const fps = Number(res.headers.get('X-Sandpic-Fps')) || 12;
      let at = 0;
      const urls = res.headers.get('X-Sandpic-Frame-Sizes').split(',').map((n) => {
        const url = URL.createObjectURL(new Blob([buf.slice(at, at + Number(n))], { type: 'image/jpeg' }));
        at += Number(n);
        return url;
      });
      const images = await Promise.all(urls.map(async (url) => {
        const im = new Image();
        im.src = url;
        await im.decode();
        return im;
      }));
      urls.forEach((url) => URL.revokeObjectURL(url));
      if (seq !== this.fallSeq) return;
      this.status('');
      canvas.width = images[0].naturalWidth;
      canvas.height = images[0].naturalHeight;
      canvas.hidden = false;
      const ctx = canvas.getContext('2d');
      for (const im of images) {
        if (seq !== this.fallSeq) return;
        ctx.drawImage(im, 0, 0);
        await new Promise((r) => setTimeout(r, 1000 / fps));
      }
      canvas.hidden = true;
      canvas.dataset.played = String(Number(canvas.dataset.played || 0) + 1);  // for tests
    } catch (e) {
      if (seq !== this.fallSeq) return;
      canvas.hidden = true;
      this.status('');
      this.showError(e, 'frames');
    }
  },

  async downloadFall() {
    const frames = document.getElementById('fall-frames').value;
    this.status('encoding the fall...');
    try {
      const res = await api('POST', `/api/animation?format=mp4&frames=${encodeURIComponent(frames)}`, { ...this.scene, mode: 'lattice' });
      this.download(await res.blob(), `sandpic-fall-seed-${this.scene.seed}.mp4`);
    } catch (e) {
      this.showError(e, 'frames');
    }
    this.status('');
  },

  async finalRender() {
    const scale = document.getElementById('render-scale').value;
    const bar = document.getElementById('render-progress');
    const label = document.getElementById('render-status');
    try {
      const res = await api('POST', '/api/render?scale=' + encodeURIComponent(scale), { ...this.scene, mode: 'dem' });
      const { id } = await res.json();
      bar.hidden = false;
      bar.value = 0;
      label.textContent = `render ${id} running`;
      this.renderId = id;
      document.getElementById('cancel-render').hidden = false;
      this.poll(id, bar, label);
    } catch (e) {
      this.showError(e, 'mode');
    }
  },

  async cancelRender() {
    if (!this.renderId) return;
    try {
      await api('POST', `/api/render/${this.renderId}/cancel`);
      document.getElementById('render-status').textContent = `render ${this.renderId} stopping...`;
    } catch (e) {
      this.showError(e, 'mode');
    }
  },

  // Once a second: the designer keeps working meanwhile.
  async poll(id, bar, label) {
    const st = await (await api('GET', `/api/render/${id}`)).json();
    bar.value = st.fraction;
    if (!st.done) return setTimeout(() => this.poll(id, bar, label), 1000);
    bar.hidden = true;
    this.renderId = 0;
    document.getElementById('cancel-render').hidden = true;
    if (st.cancelled) {
      label.textContent = `render ${id} cancelled`;
      return;
    }
    if (st.error) {
      label.textContent = `render ${id} failed: ${st.error}`;
      return;
    }
    label.textContent = `render ${id} done (kept in ${st.picture})`;
    const a = document.createElement('a');
    a.href = `/api/render/${id}/picture.png`;
    a.download = `sandpic-render-${id}.png`;
    a.innerHTML = `<img src="${a.href}" alt="render ${id}">`;
    document.getElementById('renders').prepend(a);
  },

  download(blob, name) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  },

  status(text) { document.getElementById('status').textContent = text; },

  clearErrors() {
    for (const el of document.querySelectorAll('.error')) el.textContent = '';
    for (const el of document.querySelectorAll('.invalid')) el.classList.remove('invalid');
  },

  // Beside the control whose key the message names (or its section: a
  // sketch's "segment.sketch.ridges[0]" goes to the sketch's), else on top.
  // `fallback`: the slot for a message that names no scene key (a query
  // parameter of the control's own request).
  showError(e, fallback = '') {
    this.clearErrors();
    const key = e.key || fallback;
    let slot = null;
    for (const el of document.querySelectorAll('[data-error-for]'))
      if (key && key.startsWith(el.dataset.errorFor) && (!slot || el.dataset.errorFor.length > slot.dataset.errorFor.length))
        slot = el;
    (slot || document.getElementById('general-error')).textContent = e.message;
    for (const control of document.querySelectorAll(`[data-key="${key}"]`)) control.classList.add('invalid');
  },
};

App.start().catch((e) => App.showError(e));
