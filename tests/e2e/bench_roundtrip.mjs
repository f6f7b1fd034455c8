// The preview round trip of sandpic studio, measured in the page
// (performance.now() in headless Chromium): from a control change (an input
// event on colour C1, a new colour each time) to the new preview decoded and
// on screen (#preview's data-seq set once img.decode() resolved, then the
// next animation frame), on the default scene at full size. Twice: (a) idle,
// (b) while a final DEM render runs in the background (started from the page
// at --render-scale, large enough to run through the whole measurement; the
// studio is stopped afterwards, which ends it). Timings are printed, never
// asserted.
//
//   node tests/e2e/bench_roundtrip.mjs [--sandpic build/sandpic] [--n 20] [--render-scale 0.4] [--json FILE]
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ROOT, launchBrowser, parseArgs, startStudio, tempDir, waitForPreview } from './harness.mjs';

const args = parseArgs(process.argv.slice(2), {
  sandpic: path.join(ROOT, 'build/sandpic'),
  n: '20',
  warmup: '2',
  'render-scale': '0.4',
  json: '',
});
const N = Number(args.n), WARMUP = Number(args.warmup);
if (!(N >= 1) || !(WARMUP >= 0)) throw new Error('--n must be >= 1, --warmup >= 0');

// In the page before its scripts: the times of each /api/preview request
// (sent, answered) and the lattice time the server reports, and how many
// requests are in flight (a measurement starts with none).
function instrument() {
  window.__bench = { previews: [], inflight: 0 };
  const orig = window.fetch;
  window.fetch = async function (url, opts) {
    const b = window.__bench, isPreview = String(url).startsWith('/api/preview');
    const rec = isPreview ? { sent: performance.now() } : null;
    if (rec) b.previews.push(rec);
    b.inflight++;
    try {
      const res = await orig.call(this, url, opts);
      if (rec) {
        rec.answered = performance.now();
        rec.status = res.status;
        try { rec.lattice_ms = 1000 * JSON.parse(res.headers.get('X-Sandpic-Stats')).timing.total_s; } catch (_) { /* no stats */ }
      }
      // Counted out once the body is read: the page reads every answer.
      res.clone().arrayBuffer().finally(() => { b.inflight--; });
      return res;
    } catch (e) {
      b.inflight--;
      throw e;
    }
  };
}

// One change in the page, timed there: the input event to the frame after
// the new preview's decode().
async function once(page, colour) {
  await page.waitForFunction(() => window.__bench.inflight === 0, null, { polling: 20 });
  return page.evaluate(async (colour) => {
    const img = document.getElementById('preview');
    const input = document.querySelector('input[type=color][data-color="0"]');
    const before = Number(img.dataset.seq || 0), nPreviews = window.__bench.previews.length;
    const shown = new Promise((resolve) => {
      const mo = new MutationObserver(() => {
        const seq = Number(img.dataset.seq || 0);
        if (seq > before && seq === App.seq) { mo.disconnect(); resolve(performance.now()); }
      });
      mo.observe(img, { attributes: true, attributeFilter: ['data-seq'] });
    });
    const t0 = performance.now();
    input.value = colour;
    input.dispatchEvent(new Event('input', { bubbles: true }));
    const decoded = await shown;
    const painted = await new Promise((resolve) => requestAnimationFrame(() => resolve(performance.now())));
    const p = window.__bench.previews.slice(nPreviews).filter((r) => r.status === 200).pop() || {};
    return {
      total: painted - t0,          // change -> on screen
      debounce: p.sent - t0,        // the page's 150 ms wait for more changes
      request: p.answered - p.sent, // request sent -> answer's headers
      lattice: p.lattice_ms,        // the server's lattice run
      decode: decoded - p.answered, // body read, blob URL, decode
      paint: painted - decoded,
      previews: window.__bench.previews.length - nPreviews,
    };
  }, colour);
}

async function series(page, label) {
  const samples = [];
  for (let i = 0; i < WARMUP + N; i++) {
    // A colour not used before: every change is a real change.
    const c = '#' + [(37 * i + 80) % 256, (91 * i + 40) % 256, (53 * i + 160) % 256].map((v) => v.toString(16).padStart(2, '0')).join('');
    const s = await once(page, c);
    if (i >= WARMUP) samples.push(s);
  }
  return { label, samples };
}

const quantile = (xs, q) => {  // nearest rank
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))];
};
function summary(xs) {
  return { median: quantile(xs, 0.5), p90: quantile(xs, 0.9), min: Math.min(...xs), max: Math.max(...xs) };
}
const ms = (v) => (v === undefined || Number.isNaN(v) ? '   -' : v.toFixed(0).padStart(5));

function print(r) {
  const t = summary(r.samples.map((s) => s.total));
  const med = (k) => quantile(r.samples.map((s) => s[k]), 0.5);
  console.log(`${r.label.padEnd(22)} ${ms(t.median)} ${ms(t.p90)} ${ms(t.min)} ${ms(t.max)}   |  ` +
              `${ms(med('debounce'))} ${ms(med('request'))} ${ms(med('lattice'))} ${ms(med('decode'))} ${ms(med('paint'))}`);
  return t;
}

const dir = tempDir('sandpic-bench-');
const studio = startStudio(path.resolve(args.sandpic), dir);
let browser;
try {
  const url = await studio.url;
  browser = await launchBrowser();
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.addInitScript(instrument);
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  await page.goto(url);
  await waitForPreview(page, 0);
  const scene = await page.evaluate(() => App.scene);
  console.log(`sandpic studio preview round trip: ${url}, default scene ${scene.window.width}x${scene.window.height}, ` +
              `chromium ${browser.version()}, N=${N} changes of C1 (after ${WARMUP} not counted)`);
  const load = () => os.loadavg().map((v) => v.toFixed(2)).join(' ');
  console.log(`${os.cpus().length} cores, load average ${load()} (other work on the machine shows in the figures)`);

  const idle = await series(page, '(a) idle');

  // (b) A final render started from the page, running throughout.
  const scale = args['render-scale'];
  await page.fill('#render-scale', scale);
  await page.click('#final-render');
  await page.waitForFunction(() => /running/.test(document.getElementById('render-status').textContent));
  const renderId = Number(/render (\d+) running/.exec(await page.textContent('#render-status'))[1]);
  const busy = await series(page, `(b) DEM render ${scale}`);
  const st = await page.evaluate(async (id) => (await fetch(`/api/render/${id}`)).json(), renderId);
  const ranThrough = !st.done;

  console.log(`\nms                      median   p90   min   max   |  medians: debounce request lattice decode paint`);
  const a = print(idle), b = print(busy);
  console.log(`ratio (b)/(a): median ${(b.median / a.median).toFixed(2)}, p90 ${(b.p90 / a.p90).toFixed(2)}`);
  console.log(ranThrough
    ? `the DEM render (scale ${scale}) was still running at the end of (b) (${(100 * st.fraction).toFixed(1)}% done); the studio is stopped now, which ends it`
    : `WARNING: the DEM render at scale ${scale} ended during (b) (${st.error || 'done'}): use a larger --render-scale`);
  console.log(`load average at the end ${load()}`);
  if (problems.length) console.log(`page errors: ${problems.join('; ')}`);
  if (args.json) {
    fs.writeFileSync(args.json, JSON.stringify({ n: N, render_scale: Number(scale), ran_through: ranThrough, idle: { ...a, samples: idle.samples },
      during_render: { ...b, samples: busy.samples } }, null, 2));
    console.log(`samples in ${args.json}`);
  }
} finally {
  if (browser) await browser.close();
  await studio.stop();
  fs.rmSync(dir, { recursive: true, force: true });
}
