// The studio's preview while a slider is dragged, measured in the page
// (performance.now() in headless Chromium) on the default scene at full
// size. First single changes of the friction slider (each waits for its
// preview: the round trip from the input event to the preview on screen);
// then --drags drags of it, an input event every 1/--hz s as a hand moving
// it, one slider step (0.01) each: from 0.20 up to 1.20 and back to 0.45
// (176 events, 2.9 s at 60 Hz). For each drag: the previews shown per
// second while it lasts, the requests sent and those the studio answered 409
// (superseded), and the round trip of each preview shown (from the change
// whose scene it shows to its drawing and the next frame), with the
// server's lattice time per preview apart from it. Timings are printed,
// never asserted.
//
//   node tests/e2e/bench_drag.mjs [--sandpic build/sandpic] [--n 10] [--drags 3] [--hz 60] [--json FILE]
import fs from 'node:fs';
import path from 'node:path';
import { SERIES_HEADER, benchStudio, ms, once, printSeries, quantile } from './bench_common.mjs';
import { ROOT, parseArgs } from './harness.mjs';

const args = parseArgs(process.argv.slice(2), {
  sandpic: path.join(ROOT, 'build/sandpic'),
  n: '10',
  warmup: '2',
  drags: '3',
  hz: '60',
  json: '',
});
const N = Number(args.n), WARMUP = Number(args.warmup), DRAGS = Number(args.drags), HZ = Number(args.hz);
if (!(N >= 1) || !(WARMUP >= 0) || !(DRAGS >= 1) || !(HZ > 0)) throw new Error('--n, --drags must be >= 1, --warmup >= 0, --hz > 0');

const SLIDER = '#friction-slider';
// The drag's slider values, one step apart: up from 0.20 to 1.20, down to 0.45.
const steps = (a, b) => Array.from({ length: Math.round(Math.abs(b - a) * 100) }, (_, i) => (a + Math.sign(b - a) * (i + 1) / 100).toFixed(2));
const PATH = ['0.20', ...steps(0.2, 1.2), ...steps(1.2, 0.45)];

// One drag in the page: PATH's values at HZ, then the wait for the last
// one's preview. Returns the changes, the previews shown and the requests.
async function drag(page) {
  await page.waitForFunction(() => window.__bench.inflight === 0, null, { polling: 20 });
  return page.evaluate(async ({ selector, values, hz }) => {
    const b = window.__bench, img = document.getElementById('preview'), slider = document.querySelector(selector);
    const nPreviews = b.previews.length, shown = [];
    const mo = new MutationObserver(() => {
      const s = { seq: Number(img.dataset.seq || 0), decoded: performance.now() };
      shown.push(s);
      requestAnimationFrame(() => { s.painted = performance.now(); });
    });
    mo.observe(img, { attributes: true, attributeFilter: ['data-seq'] });
    const changes = [], t0 = performance.now();
    for (let i = 0; i < values.length; i++) {
      const wait = t0 + (i * 1000) / hz - performance.now();
      if (wait > 0) await new Promise((r) => setTimeout(r, wait));
      slider.value = values[i];
      changes.push(performance.now());
      slider.dispatchEvent(new Event('input', { bubbles: true }));
    }
    const end = performance.now();
    // The last change's preview, on screen.
    while (!(Number(img.dataset.seq || 0) === App.seq && b.inflight === 0 && shown.at(-1)?.painted))
      await new Promise((r) => setTimeout(r, 5));
    mo.disconnect();
    return { t0, end, changes, shown, requests: b.previews.slice(nPreviews), friction: App.scene.physics.friction };
  }, { selector: SLIDER, values: PATH, hz: HZ });
}

// A drag's figures: each request carries the newest change made before it
// was sent; a preview shown is that request's answer.
function analyse(d) {
  const carried = (t) => { let i = -1; while (i + 1 < d.changes.length && d.changes[i + 1] <= t) i++; return i; };
  const bySeq = new Map(d.requests.map((r) => [r.seq, r]));
  const duringDrag = d.shown.filter((s) => s.decoded <= d.end);
  const trips = d.shown.map((s) => {
    const r = bySeq.get(s.seq), i = carried(r.sent);
    return { total: s.painted - d.changes[i], wait: r.sent - d.changes[i], request: r.answered - r.sent,
             lattice: r.lattice_ms, prepare: r.prepare_ms, simulate: r.simulate_ms, decode: s.decoded - r.answered,
             stale: carried(s.decoded) > i };
  });
  const seconds = (d.end - d.t0) / 1000;
  // While the drag lasts, the studio waits this long between an answer and
  // the next request (the page reading the answer and sending the scene).
  const gaps = d.requests.flatMap((r, i) => (i > 0 && r.sent <= d.end ? [r.sent - d.requests[i - 1].answered] : []));
  return {
    seconds,
    changes: d.changes.length,
    sent: d.requests.length,
    sentDuringDrag: d.requests.filter((r) => r.sent <= d.end).length,
    superseded: d.requests.filter((r) => r.status === 409).length,
    failed: d.requests.filter((r) => r.status !== 200 && r.status !== 409).length,
    shownDuringDrag: duringDrag.length,
    perSecond: duringDrag.length / seconds,
    staleShown: trips.filter((t) => t.stale).length,
    roundTrip: quantile(trips.map((t) => t.total), 0.5),
    roundTripP90: quantile(trips.map((t) => t.total), 0.9),
    parts: Object.fromEntries(['wait', 'request', 'lattice', 'prepare', 'simulate', 'decode'].map((k) => [k, quantile(trips.map((t) => t[k]), 0.5)])),
    gap: quantile(gaps, 0.5),
    settle: d.shown.at(-1).painted - d.changes.at(-1),
    finalFriction: d.friction,
    trips,
  };
}

await benchStudio(args.sandpic, `sandpic studio preview while dragging slider ${SLIDER} (physics.friction)`, async (page, problems) => {
  // Single changes: each waits for its preview.
  const singles = [];
  for (let i = 0; i < WARMUP + N; i++) {
    const s = await once(page, SLIDER, (0.3 + 0.07 * i).toFixed(2));  // a value not used before
    if (i >= WARMUP) singles.push(s);
  }
  console.log(`\nsingle changes of the slider (N=${N} after ${WARMUP} not counted), change -> preview on screen:`);
  console.log(SERIES_HEADER);
  const single = printSeries('single changes', singles);

  console.log(`\ndrags: ${PATH.length} input events at ${HZ} Hz (${PATH[0]} -> 1.20 -> ${PATH.at(-1)}), ` +
              `${(PATH.length / HZ).toFixed(1)} s each, ${DRAGS} drags`);
  console.log('drag  s    changes sent 409 shown/s(shown) stale | round trip median p90 | medians: wait request lattice prepare simulate decode | last change -> its preview');
  const drags = [];
  for (let k = 0; k < DRAGS; k++) {
    const a = analyse(await drag(page));
    drags.push(a);
    if (a.finalFriction !== Number(PATH.at(-1))) problems.push(`drag ${k + 1} ended at friction ${a.finalFriction}, not ${PATH.at(-1)}`);
    if (a.failed) problems.push(`drag ${k + 1}: ${a.failed} preview request(s) failed`);
    console.log(`${String(k + 1).padStart(4)} ${a.seconds.toFixed(1).padStart(4)} ${String(a.changes).padStart(7)} ${String(a.sent).padStart(4)} ` +
                `${String(a.superseded).padStart(3)} ${a.perSecond.toFixed(1).padStart(7)}(${String(a.shownDuringDrag).padStart(3)})  ` +
                `${String(a.staleShown).padStart(5)} |            ${ms(a.roundTrip)} ${ms(a.roundTripP90)} |  ` +
                `${ms(a.parts.wait)} ${ms(a.parts.request)} ${ms(a.parts.lattice)} ${ms(a.parts.prepare)} ${ms(a.parts.simulate)} ${ms(a.parts.decode)} | ${ms(a.settle)}`);
  }
  const med = (f) => quantile(drags.map(f), 0.5);
  const allTrips = drags.flatMap((d) => d.trips);
  console.log(`\nmedians: previews shown while dragging ${med((d) => d.perSecond).toFixed(1)}/s ` +
              `(requests sent ${med((d) => d.sent)} per drag of ${PATH.length} changes, ${med((d) => d.superseded)} answered 409); ` +
              `round trip while dragging ${ms(quantile(allTrips.map((t) => t.total), 0.5)).trim()} ms ` +
              `(of all ${allTrips.length} previews shown), single changes ${ms(single.median).trim()} ms; ` +
              `server lattice per preview ${ms(quantile(allTrips.map((t) => t.lattice), 0.5)).trim()} ms ` +
              `(the layout ${ms(quantile(allTrips.map((t) => t.prepare), 0.5)).trim()} ms, ` +
              `the fall ${ms(quantile(allTrips.map((t) => t.simulate), 0.5)).trim()} ms); ` +
              `the studio idle between an answer and the next request ${med((d) => d.gap).toFixed(1)} ms`);
  if (args.json) {
    fs.writeFileSync(args.json, JSON.stringify({ hz: HZ, path: PATH, single: { ...single, samples: singles }, drags }, null, 2));
    console.log(`samples in ${args.json}`);
  }
});
