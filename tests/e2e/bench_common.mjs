// What the studio's browser benchmarks share (bench_roundtrip.mjs,
// bench_drag.mjs): the page's /api/preview requests timed in the page, one
// control change timed from its input event to the preview on screen, and
// the summaries printed. Timings are printed, never asserted.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser, startStudio, tempDir, waitForPreview } from './harness.mjs';

// In the page before its scripts: each /api/preview request (sent and
// answered, its status, the preview number App gave it and the lattice
// timing the server reports in X-Sandpic-Stats, in ms) and how many requests
// are in flight (a measurement starts with none).
export function instrument() {
  window.__bench = { previews: [], inflight: 0 };
  const orig = window.fetch;
  window.fetch = async function (url, opts) {
    const b = window.__bench, isPreview = String(url).startsWith('/api/preview');
    // App.seq is this request's number: App.preview numbers it just before sending.
    const rec = isPreview ? { sent: performance.now(), seq: typeof App === 'undefined' ? 0 : App.seq } : null;
    if (rec) b.previews.push(rec);
    b.inflight++;
    try {
      const res = await orig.call(this, url, opts);
      if (rec) {
        rec.answered = performance.now();
        rec.status = res.status;
        try {
          const t = JSON.parse(res.headers.get('X-Sandpic-Stats')).timing;
          rec.lattice_ms = 1000 * t.total_s;
          // The layout made before the fall (init, segment, order; 0 when reused) and the fall.
          rec.prepare_ms = 1000 * (t.init_s + t.segment_s + t.order_s);
          rec.simulate_ms = 1000 * t.simulate_s;
        } catch (_) { /* no stats */ }
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

// One change in the page, timed there: `value` set on the control `selector`
// and its input event (a plain Event, as a colour picker or a slider sends;
// not a keystroke), to the frame after the new preview is drawn.
export async function once(page, selector, value) {
  await page.waitForFunction(() => window.__bench.inflight === 0, null, { polling: 20 });
  return page.evaluate(async ({ selector, value }) => {
    const img = document.getElementById('preview');
    const input = document.querySelector(selector);
    const before = Number(img.dataset.seq || 0), nPreviews = window.__bench.previews.length;
    const shown = new Promise((resolve) => {
      const mo = new MutationObserver(() => {
        const seq = Number(img.dataset.seq || 0);
        if (seq > before && seq === App.seq) { mo.disconnect(); resolve(performance.now()); }
      });
      mo.observe(img, { attributes: true, attributeFilter: ['data-seq'] });
    });
    const t0 = performance.now();
    input.value = value;
    input.dispatchEvent(new Event('input', { bubbles: true }));
    const decoded = await shown;
    const painted = await new Promise((resolve) => requestAnimationFrame(() => resolve(performance.now())));
    const p = window.__bench.previews.slice(nPreviews).filter((r) => r.status === 200).pop() || {};
    return {
      total: painted - t0,          // change -> on screen
      wait: p.sent - t0,            // the page's wait before sending
      request: p.answered - p.sent, // request sent -> answer's headers
      lattice: p.lattice_ms,        // the server's lattice run, of it:
      prepare: p.prepare_ms,        // the layout (init, segment, falling order)
      simulate: p.simulate_ms,      // the fall
      decode: decoded - p.answered, // body read, decoded, drawn
      paint: painted - decoded,
      previews: window.__bench.previews.length - nPreviews,
    };
  }, { selector, value });
}

export const quantile = (xs, q) => {  // nearest rank
  const s = xs.filter((x) => x !== undefined && !Number.isNaN(x)).sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))] : NaN;
};

export function summary(xs) {
  return { median: quantile(xs, 0.5), p90: quantile(xs, 0.9), min: Math.min(...xs), max: Math.max(...xs) };
}

export const ms = (v) => (v === undefined || Number.isNaN(v) ? '   -' : v.toFixed(0).padStart(5));

export const loadAverage = () => os.loadavg().map((v) => v.toFixed(2)).join(' ');

// One line of a series of once() samples: the round trip's median, p90, min
// and max, then the medians of its parts.
export const SERIES_HEADER = 'ms                      median   p90   min   max   |  medians: wait request lattice prepare simulate decode paint';
export function printSeries(label, samples) {
  const t = summary(samples.map((s) => s.total));
  const med = (k) => quantile(samples.map((s) => s[k]), 0.5);
  console.log(`${label.padEnd(22)} ${ms(t.median)} ${ms(t.p90)} ${ms(t.min)} ${ms(t.max)}   |  ` +
              `${ms(med('wait'))} ${ms(med('request'))} ${ms(med('lattice'))} ${ms(med('prepare'))} ${ms(med('simulate'))} ${ms(med('decode'))} ${ms(med('paint'))}`);
  return t;
}

// `sandpic studio` in a folder of its own and a page of it with the
// requests instrumented, its first preview on screen; two lines say what
// is measured and the machine's load, then body(page, problems, scene)
// measures; the load at the end and any page errors or problems body
// noted are printed. The studio, the browser and the folder go afterwards.
export async function benchStudio(sandpic, title, body) {
  const dir = tempDir('sandpic-bench-');
  const studio = startStudio(path.resolve(sandpic), dir);
  let browser;
  try {
    const url = await studio.url;
    browser = await launchBrowser();
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.addInitScript(instrument);
    const problems = [];
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    await page.goto(url);
    await waitForPreview(page, 0);
    const scene = await page.evaluate(() => App.scene);
    console.log(`${title}: ${url}, default scene ${scene.window.width}x${scene.window.height}, chromium ${browser.version()}`);
    console.log(`${os.cpus().length} cores, load average ${loadAverage()} (other work on the machine shows in the figures)`);
    await body(page, problems, scene);
    console.log(`load average at the end ${loadAverage()}`);
    if (problems.length) console.log(`problems: ${problems.join('; ')}`);
  } finally {
    if (browser) await browser.close();
    await studio.stop();
    fs.rmSync(dir, { recursive: true, force: true });
  }
}
