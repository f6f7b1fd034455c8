// The preview round trip of sandpic studio, measured in the page
// (performance.now() in headless Chromium): from a control change (an input
// event on colour C1, a new colour each time) to the new preview decoded and
// on screen (#preview's data-seq set once it is drawn on its canvas, then the
// next animation frame), on the default scene at full size. Twice: (a) idle,
// (b) while a final DEM render runs in the background (started from the page
// at --render-scale, large enough to run through the whole measurement; the
// studio is stopped afterwards, which ends it). Timings are printed, never
// asserted.
//
//   node tests/e2e/bench_roundtrip.mjs [--sandpic build/sandpic] [--n 20] [--render-scale 0.4] [--json FILE]
import fs from 'node:fs';
import path from 'node:path';
import { SERIES_HEADER, benchStudio, once, printSeries } from './bench_common.mjs';
import { ROOT, parseArgs } from './harness.mjs';

const args = parseArgs(process.argv.slice(2), {
  sandpic: path.join(ROOT, 'build/sandpic'),
  n: '20',
  warmup: '2',
  'render-scale': '0.4',
  json: '',
});
const N = Number(args.n), WARMUP = Number(args.warmup);
if (!(N >= 1) || !(WARMUP >= 0)) throw new Error('--n must be >= 1, --warmup >= 0');

async function series(page, label) {
  const samples = [];
  for (let i = 0; i < WARMUP + N; i++) {
    // A colour not used before: every change is a real change.
    const c = '#' + [(37 * i + 80) % 256, (91 * i + 40) % 256, (53 * i + 160) % 256].map((v) => v.toString(16).padStart(2, '0')).join('');
    const s = await once(page, 'input[type=color][data-color="0"]', c);
    if (i >= WARMUP) samples.push(s);
  }
  return { label, samples };
}

await benchStudio(args.sandpic, `sandpic studio preview round trip, N=${N} changes of C1 (after ${WARMUP} not counted)`, async (page) => {
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

  console.log(`\n${SERIES_HEADER}`);
  const a = printSeries(idle.label, idle.samples), b = printSeries(busy.label, busy.samples);
  console.log(`ratio (b)/(a): median ${(b.median / a.median).toFixed(2)}, p90 ${(b.p90 / a.p90).toFixed(2)}`);
  console.log(ranThrough
    ? `the DEM render (scale ${scale}) was still running at the end of (b) (${(100 * st.fraction).toFixed(1)}% done); the studio is stopped now, which ends it`
    : `WARNING: the DEM render at scale ${scale} ended during (b) (${st.error || 'done'}): use a larger --render-scale`);
  if (args.json) {
    fs.writeFileSync(args.json, JSON.stringify({ n: N, render_scale: Number(scale), ran_through: ranThrough, idle: { ...a, samples: idle.samples },
      during_render: { ...b, samples: busy.samples } }, null, 2));
    console.log(`samples in ${args.json}`);
  }
});
