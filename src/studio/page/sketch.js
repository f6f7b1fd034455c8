// The sketch canvas over the preview (paper §5.2): ridge lines and arcs
// drawn as polylines in window px, and the falling units the segmentation
// makes of them drawn on top. With the "paint cells" pen it shows the
// tessellation's cells instead, and a click picks one (paper §3).
'use strict';

const Sketch = {
  canvas: null,
  units: { ellipses: [], cells: [], tessellation: [] },
  stroke: null,  // the polyline being drawn
  onStroke: null,  // (kind, polyline) when a stroke ends
  onCell: null,  // (cell index) when a cell is clicked with the cells pen

  init(canvas, onStroke, onCell) {
    this.canvas = canvas;
    this.onStroke = onStroke;
    this.onCell = onCell;
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

  // The index of the tessellation cell at window px p, or -1.
  cellAt([x, y]) {
    return (this.units.tessellation || []).findIndex(([x0, y0, x1, y1]) => x >= x0 && x < x1 && y >= y0 && y < y1);
  },

  down(e) {
    if (this.pen() === 'off') return;
    if (this.pen() === 'cells') {
      const i = this.cellAt(this.point(e));
      if (i >= 0) this.onCell(i);
      return;
    }
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
    if (this.pen() === 'cells') this.drawCells(ctx, scene);
    else if (document.getElementById('show-units').checked) this.drawUnits(ctx);
    const sk = scene.segment.sketch;
    for (const r of sk.ridges) this.line(ctx, r, Scene.hex(sk.ridge_color));
    for (const a of sk.arcs) this.line(ctx, a, Scene.hex(sk.arc_color));
    if (this.stroke) this.line(ctx, this.stroke, this.pen() === 'arcs' ? Scene.hex(sk.arc_color) : Scene.hex(sk.ridge_color));
  },

  // Every cell filled with its dominant class's colour (the region as it
  // is before the fall: the picture shows it emptied), the ones edited by
  // hand outlined in red and marked with their classes.
  drawCells(ctx, scene) {
    const edited = new Map((scene.init.cell_overrides || []).map((o) => [o.cell, o]));
    const colors = scene.grains.colors.map((c) => Scene.hex(c));
    ctx.font = '11px system-ui, sans-serif';
    (this.units.tessellation || []).forEach(([x0, y0, x1, y1, dom], i) => {
      ctx.globalAlpha = 0.6;
      ctx.fillStyle = colors[dom - 1];
      ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
      ctx.globalAlpha = 1;
      const o = edited.get(i);
      ctx.strokeStyle = o ? 'rgba(220,30,30,0.95)' : 'rgba(0,0,0,0.35)';
      ctx.lineWidth = o ? 2.5 : 1;
      ctx.strokeRect(x0 + 0.5, y0 + 0.5, x1 - x0 - 1, y1 - y0 - 1);
      if (o && x1 - x0 > 30 && y1 - y0 > 14) {
        ctx.fillStyle = 'rgba(255,255,255,0.85)';
        ctx.fillRect(x0 + 2, y0 + 2, 38, 13);
        ctx.fillStyle = '#000';
        ctx.fillText(`S${o.dominant}/S${o.secondary}`, x0 + 4, y0 + 12);
      }
    });
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
