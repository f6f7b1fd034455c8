// The sketch canvas over the preview (paper §5.2): ridge lines and arcs
// drawn as polylines in window px, and the falling units the segmentation
// makes of them drawn on top.
'use strict';

const Sketch = {
  canvas: null,
  units: { ellipses: [], cells: [] },
  stroke: null,  // the polyline being drawn
  onStroke: null,  // (kind, polyline) when a stroke ends

  init(canvas, onStroke) {
    this.canvas = canvas;
    this.onStroke = onStroke;
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', () => this.up());
    canvas.addEventListener('pointercancel', () => { this.stroke = null; });
  },

  pen() { return document.querySelector('input[name=pen]:checked').value; },

  // Window px from a pointer event: the canvas is scaled with the preview.
  point(e) {
    const r = this.canvas.getBoundingClientRect();
    return [Math.round((e.clientX - r.left) * this.canvas.width / r.width),
            Math.round((e.clientY - r.top) * this.canvas.height / r.height)];
  },

  down(e) {
    if (this.pen() === 'off') return;
    this.canvas.setPointerCapture(e.pointerId);
    this.stroke = [this.point(e)];
  },

  move(e) {
    if (!this.stroke) return;
    const p = this.point(e), q = this.stroke[this.stroke.length - 1];
    // Points 4 px apart at least: a scene file stays small.
    if (Math.hypot(p[0] - q[0], p[1] - q[1]) >= 4) this.stroke.push(p);
    this.draw(App.scene);
  },

  up() {
    const s = this.stroke;
    this.stroke = null;
    if (s && s.length >= 2) this.onStroke(this.pen(), s);
  },

  line(ctx, pts, color) {
    ctx.strokeStyle = color;
    ctx.lineWidth = 3;
    ctx.beginPath();
    pts.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
    ctx.stroke();
  },

  draw(scene) {
    const c = this.canvas, ctx = c.getContext('2d');
    c.width = scene.window.width;
    c.height = scene.window.height;
    ctx.clearRect(0, 0, c.width, c.height);
    ctx.strokeStyle = 'rgba(0,0,0,0.4)';
    ctx.setLineDash([6, 4]);
    ctx.strokeRect(0.5, 0.5, c.width - 1, scene.region.height);
    ctx.setLineDash([]);
    if (document.getElementById('show-units').checked) this.drawUnits(ctx);
    const sk = scene.segment.sketch;
    for (const r of sk.ridges) this.line(ctx, r, Scene.hex(sk.ridge_color));
    for (const a of sk.arcs) this.line(ctx, a, Scene.hex(sk.arc_color));
    if (this.stroke) this.line(ctx, this.stroke, this.pen() === 'arcs' ? Scene.hex(sk.arc_color) : Scene.hex(sk.ridge_color));
  },

  drawUnits(ctx) {
    ctx.lineWidth = 1.5;
    ctx.strokeStyle = 'rgba(30,60,220,0.8)';
    for (const [x, y, a, b, t] of this.units.ellipses) {
      ctx.beginPath();
      ctx.ellipse(x, y, a, b, t, 0, 2 * Math.PI);
      ctx.stroke();
    }
    for (const [x0, y0, x1, y1] of this.units.cells) ctx.strokeRect(x0, y0, x1 - x0, y1 - y0);
  },
};
