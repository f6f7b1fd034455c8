// sandpic studio's page: controls bound to scene keys, a debounced lattice
// preview, flip, final DEM renders with progress, downloads, drag and drop.
'use strict';

const App = {
  scene: null,
  picture: null,     // the last preview's PNG (Blob)
  timer: 0,
  seq: 0,            // previews answered out of order are dropped

  async start() {
    this.scene = await (await api('GET', '/api/scene')).json();
    this.bind();
    Sketch.init(document.getElementById('sketch'), (kind, line) => this.addStroke(kind, line));
    this.dropTarget();
    this.show();
    this.changed(0);
  },

  bind() {
    for (const el of document.querySelectorAll('[data-key]')) {
      el.addEventListener('input', () => {
        const v = el.type === 'number' ? Number(el.value) : el.value;
        if (el.dataset.key === 'preset') return this.loadPreset(v);
        Scene.set(this.scene, el.dataset.key, v);
        this.changed();
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
      this.changed();
    });
    document.getElementById('show-units').addEventListener('change', () => Sketch.draw(this.scene));
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
    Sketch.draw(s);
  },

  reseed(key) {
    this.scene[key] = Math.floor(Math.random() * 2 ** 31);
    this.show();
    this.changed(0);
  },

  addStroke(kind, line) {
    if (kind !== 'ridges' && kind !== 'arcs') return;
    this.scene.segment.sketch[kind].push(line);
    this.scene.segment.method = 'sketch';  // a sketch drawn is a sketch used
    this.lastStroke = kind;
    this.show();
    this.changed(0);
  },

  undoStroke() {
    const sk = this.scene.segment.sketch, kind = this.lastStroke;
    if (kind && sk[kind].length) sk[kind].pop();
    else if (sk.arcs.length) sk.arcs.pop();
    else sk.ridges.pop();
    this.changed(0);
  },

  // A preview 150 ms after the last change: typing a number makes one request.
  changed(delay = 150) {
    clearTimeout(this.timer);
    Sketch.draw(this.scene);
    this.timer = setTimeout(() => this.preview(), delay);
  },

  async preview() {
    const seq = ++this.seq, t0 = performance.now();
    this.status('rendering preview...');
    try {
      const scene = { ...this.scene, mode: 'lattice' };
      const res = await api('POST', '/api/preview', scene);
      const blob = await res.blob();
      if (seq !== this.seq) return;
      this.clearErrors();
      this.picture = blob;
      const img = document.getElementById('preview');
      URL.revokeObjectURL(img.src);
      img.src = URL.createObjectURL(blob);
      // Tests and the benchmark wait on this: the preview numbered seq is decoded, on screen.
      img.decode().then(() => { img.dataset.seq = seq; }, () => {});
      const stats = JSON.parse(res.headers.get('X-Sandpic-Stats') || '{}');
      document.getElementById('stats').textContent =
        `${stats.grains?.total ?? '?'} grains, ${stats.units ?? '?'} units, ` +
        `lattice ${(stats.timing?.total_s ?? 0).toFixed(2)} s, round trip ${((performance.now() - t0) / 1000).toFixed(2)} s`;
      this.status('');
      this.units();
    } catch (e) {
      if (e.status === 409 || seq !== this.seq) return;  // superseded by a newer preview
      this.showError(e);
      this.status('');
    }
  },

  async units() {
    try {
      Sketch.units = await (await api('POST', '/api/units', this.scene)).json();
    } catch (_) {
      Sketch.units = { ellipses: [], cells: [] };
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
      if (file) this.loadText(await file.text());
    });
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
      this.poll(id, bar, label);
    } catch (e) {
      this.showError(e);
    }
  },

  // Once a second: the designer keeps working meanwhile.
  async poll(id, bar, label) {
    const st = await (await api('GET', `/api/render/${id}`)).json();
    bar.value = st.fraction;
    if (!st.done) return setTimeout(() => this.poll(id, bar, label), 1000);
    bar.hidden = true;
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
  showError(e) {
    this.clearErrors();
    const key = e.key || '';
    let slot = null;
    for (const el of document.querySelectorAll('[data-error-for]'))
      if (key && key.startsWith(el.dataset.errorFor) && (!slot || el.dataset.errorFor.length > slot.dataset.errorFor.length))
        slot = el;
    (slot || document.getElementById('general-error')).textContent = e.message;
    const control = document.querySelector(`[data-key="${key}"]`);
    if (control) control.classList.add('invalid');
  },
};

App.start().catch((e) => App.showError(e));
