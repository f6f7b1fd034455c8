// sandpic studio's page end to end, as a user drives it, in
// Debian's headless Chromium: the first preview; a colour, a flip, a sketch
// drawn with the mouse and a cell painted each redraw it; a final DEM render
// runs to the end and downloads as a PNG of the scaled size, and another is
// cancelled (a build without Bullet shows the mode key's error beside the
// control instead); the fall plays and downloads as MP4; the scene and the
// picture download; the friction slider dragged shows previews while it
// moves and ends on its final value's picture. No console error and no page
// error throughout.
// Screenshots of every step are kept in --artifacts.
//
//   node tests/e2e/studio.e2e.mjs [--sandpic build/sandpic] [--artifacts build/e2e-artifacts]
//        [--dem with-bullet|without-bullet|auto] [--render-scale 0.0845]
//
// Exit 0 passed, 1 failed (a missing browser or playwright-core is a failure).
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, launchBrowser, parseArgs, pngSize, startStudio, waitForPreview } from './harness.mjs';

const args = parseArgs(process.argv.slice(2), {
  sandpic: path.join(ROOT, 'build/sandpic'),
  artifacts: path.join(ROOT, 'build/e2e-artifacts'),
  dem: 'auto',
  // The smallest scale the default scene allows (row heights stay >= 1 px),
  // as tests/src/studio's DEM test: about 10-25 s with Bullet on two cores.
  'render-scale': '0.0845',
});
const ART = path.resolve(args.artifacts);
fs.rmSync(ART, { recursive: true, force: true });
fs.mkdirSync(ART, { recursive: true });

const t0 = Date.now();
const since = () => ((Date.now() - t0) / 1000).toFixed(1) + ' s';
let step = 0;
let lastPage = null;  // for a screenshot of a failure
function log(msg) { console.log(`[${since()}] ${msg}`); }

const problems = [];  // console errors, page errors, failed requests
const allowed = [{ path: /\/api\/preview$/, status: 409 }];  // error answers the step under way expects

async function main() {
  const studio = startStudio(path.resolve(args.sandpic), path.join(ART, 'studio-folder'));
  let browser;
  try {
    const url = await studio.url;
    log(`studio at ${url}`);
    browser = await launchBrowser();
    log(`chromium ${browser.version()}`);
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true });
    const page = await context.newPage();
    lastPage = page;
    page.setDefaultTimeout(60_000);
    watch(page);
    const shot = async (name) => {
      const file = path.join(ART, `${String(++step).padStart(2, '0')}-${name}.png`);
      await page.screenshot({ path: file });
      log(`screenshot ${path.basename(file)}`);
    };
    // The bytes of the picture the preview shows (the PNG it was drawn from).
    const shown = () => page.evaluate(async () => {
      const buf = await App.picture.arrayBuffer();
      return Array.from(new Uint8Array(buf));
    }).then((a) => Buffer.from(a));
    const hash = (b) => createHash('sha256').update(b).digest('hex').slice(0, 16);

    // 1. The page loads, fills its controls from the scene, shows a preview.
    await page.goto(url);
    let seq = await waitForPreview(page, 0);
    const first = await shown();
    const scene0 = await page.evaluate(() => App.scene);
    const { width: W, height: H } = scene0.window;
    assert.deepEqual(pngSize(first), { width: scene0.window.width, height: scene0.window.height }, 'preview size = the scene window');
    assert.match(await page.textContent('#stats'), /grains, .* units/);
    assert.equal(await page.inputValue('[data-key="physics.friction"]'), String(scene0.physics.friction));
    // The controls' choices and ranges come from the key registry (/api/keys).
    const keys = await page.evaluate(async () => (await fetch('/api/keys')).json());
    const key = (k) => keys.find((x) => x.key === k);
    for (const k of ['preset', 'init.method', 'init.tessellation', 'segment.method'])
      assert.deepEqual(await page.$$eval(`[data-key="${k}"] option`, (os) => os.map((o) => o.value)), key(k).choices, `${k}'s options`);
    assert.equal(await page.getAttribute('[data-key="physics.friction"]', 'max'), String(key('physics.friction').max));
    assert.equal(await page.inputValue('[data-key="segment.method"]'), scene0.segment.method);
    log(`first preview: ${first.length} bytes, ${scene0.window.width}x${scene0.window.height}, ${hash(first)}`);
    await shot('loaded');

    // 2. C1 changes: the scene's first colour and the picture.
    const c1 = page.locator('input[type=color][data-color="0"]');
    const newColour = (await c1.inputValue()) === '#2f5d8a' ? '#8a2f5d' : '#2f5d8a';
    await c1.fill(newColour);
    seq = await waitForPreview(page, seq);
    const afterColour = await shown();
    assert.equal(Scene_hex(await page.evaluate(() => App.scene.grains.colors[0])), newColour);
    assert.notEqual(hash(afterColour), hash(first), 'a new C1 changes the preview');
    log(`C1 ${newColour}: preview ${hash(afterColour)}`);
    await shot('colour-c1');

    // 3. Flip: a new physics seed, the same layout falls again.
    const seeds = await page.textContent('#seeds');
    await page.click('#flip');
    seq = await waitForPreview(page, seq);
    const afterFlip = await shown();
    const seeds2 = await page.textContent('#seeds');
    assert.notEqual(seeds2, seeds, 'flip changes the seeds shown');
    assert.equal(seeds2.replace(/physics \d+/, ''), seeds.replace(/physics \d+/, ''), 'flip keeps the layout seed');
    assert.notEqual(hash(afterFlip), hash(afterColour), 'flip changes the preview');
    log(`flip: "${seeds}" -> "${seeds2}", preview ${hash(afterFlip)}`);
    await shot('flip');

    // 4. The final render of the scene so far, in the DEM (the segmentation
    // of ellipses: a few seconds; a sketch's few big piles take ten times
    // as long).
    const scale = Number(args['render-scale']);
    await page.fill('#render-scale', String(scale));
    const expected = { width: Math.max(1, Math.round(W * scale)), height: Math.max(1, Math.round(H * scale)) };
    let dem = args.dem;
    if (dem !== 'with-bullet') allowed.push({ path: /\/api\/render\?/, status: 400 });
    const started = Date.now();
    const answer = page.waitForResponse((r) => r.url().includes('/api/render?') && r.request().method() === 'POST');
    answer.catch(() => {});
    await page.click('#final-render');
    const status = (await answer).status();
    if (dem === 'auto') dem = status === 400 ? 'without-bullet' : 'with-bullet';
    if (dem === 'with-bullet') {
      assert.equal(status, 200, 'the final render starts');
      await page.waitForSelector('#render-progress:not([hidden])');
      await page.waitForFunction(() => /running/.test(document.getElementById('render-status').textContent));
      await shot('render-running');
      const link = page.locator('#renders a');
      await link.waitFor({ timeout: 300_000 });
      const secs = (Date.now() - started) / 1000;
      assert.match(await page.textContent('#render-status'), /done \(kept in .*render-.*\.png\)/);
      assert.equal(await page.isHidden('#render-progress'), true, 'the progress bar goes once done');
      await page.waitForFunction(() => {
        const img = document.querySelector('#renders a img');
        return img && img.complete && img.naturalWidth > 0;
      });
      await shot('render-done');
      const png = await download(page, '#renders a', 'render.png');
      assert.deepEqual(pngSize(png), expected, `the render is the window at scale ${scale}`);
      const kept = fs.readdirSync(path.join(ART, 'studio-folder/studio-renders')).filter((f) => f.endsWith('.png'));
      assert.equal(kept.length, 1, 'the render is kept in studio-renders/');
      log(`final render at scale ${scale}: ${secs.toFixed(1)} s, ${expected.width}x${expected.height} PNG downloaded`);
    } else {
      assert.equal(status, 400, 'a build without Bullet refuses the DEM');
      const slot = page.locator('[data-error-for="mode"]');
      await page.waitForFunction(() => document.querySelector('[data-error-for="mode"]').textContent !== '');
      assert.match(await slot.textContent(), /Bullet/);
      assert.equal(await slot.isVisible(), true, 'the error shows beside the final render control');
      assert.equal(await page.textContent('#general-error'), '', 'not on top: beside its control');
      assert.equal(await page.locator('#renders a').count(), 0);
      assert.equal(await page.isHidden('#render-progress'), true);
      await shot('render-refused');
      log(`final render refused beside its control: "${await slot.textContent()}"`);
    }

    // 5. A ridge drawn with the mouse on the sketch canvas (pen: ridge line),
    // a peak inside the region. A sketch needs arcs across its ridges
    // (paper §5.2): alone, the ridge is kept and drawn, the page says to draw
    // arcs, and the picture stays that of the method before (no request).
    await page.check('input[name=pen][value=ridges]');
    const RH = scene0.region.height;
    // Window px to page px; the page scrolled to its top first (checking a
    // radio button lower down scrolls it), the canvas whole in view.
    const pageAt = async () => {
      await page.evaluate(() => window.scrollTo(0, 0));
      const box = await page.locator('#sketch').boundingBox();
      return (x, y) => [box.x + (x * box.width) / W, box.y + (y * box.height) / H];
    };
    const stroke = async (points) => {
      const at = await pageAt();
      await page.mouse.move(...at(...points[0]));
      await page.mouse.down();
      for (const p of points.slice(1)) await page.mouse.move(...at(...p), { steps: 12 });
      await page.mouse.up();
    };
    const methodBefore = await page.evaluate(() => App.scene.segment.method);
    await stroke([[0.15 * W, 0.8 * RH], [0.5 * W, 0.25 * RH], [0.85 * W, 0.8 * RH]]);
    const hint = page.locator('#sketch-hint');
    await page.waitForFunction(() => document.getElementById('sketch-hint').textContent !== '');
    assert.match(await hint.textContent(), /arc/, 'the ridge alone: the page asks for arcs');
    assert.equal(await hint.isVisible(), true);
    assert.equal(await page.textContent('#general-error'), '');
    let sk = await page.evaluate(() => ({ ridges: App.scene.segment.sketch.ridges, method: App.scene.segment.method }));
    assert.equal(sk.ridges.length, 1, 'one ridge in the scene');
    assert.ok(sk.ridges[0].length >= 10, `the ridge has its points (${sk.ridges[0].length})`);
    assert.equal(sk.method, methodBefore, 'half a sketch is not used yet');
    assert.equal(await page.evaluate(() => App.seq), seq, 'and asks for no preview');
    assert.ok((await shown()).equals(afterFlip), 'the picture stays');
    log(`ridge of ${sk.ridges[0].length} points: "${await hint.textContent()}"`);
    await shot('ridge-alone');

    // Three arcs across it (pen: arc): the preview of the sketched scene.
    await page.check('input[name=pen][value=arcs]');
    // The units of the sketched scene (a request made after its preview).
    const units = page.waitForResponse((r) => r.url().endsWith('/api/units') &&
      JSON.parse(r.request().postData() || '{}').segment?.sketch?.arcs?.length === 3);
    units.catch(() => {});  // awaited below; a timeout must not end the process meanwhile
    for (const x of [0.3, 0.5, 0.7]) {
      const from = seq;
      await stroke([[(x - 0.04) * W, 0.1 * RH], [x * W, 0.5 * RH], [(x - 0.02) * W, 0.95 * RH]]);
      seq = await waitForPreview(page, from);
    }
    await (await units).finished();
    await page.evaluate(() => new Promise(requestAnimationFrame));  // the units drawn
    assert.equal(await hint.textContent(), '', 'the arcs answer the hint');
    assert.equal(await page.evaluate(() => App.scene.segment.method), 'sketch', 'a whole sketch is used');
    assert.equal(await page.inputValue('[data-key="segment.method"]'), 'sketch');
    const afterRidge = await shown();
    sk = await page.evaluate(() => App.scene.segment.sketch);
    assert.equal(sk.ridges.length, 1);
    assert.equal(sk.arcs.length, 3, 'three arcs in the scene');
    assert.notEqual(hash(afterRidge), hash(afterFlip), 'the sketch changes the preview');
    const nUnits = await page.evaluate(() => Sketch.units.ellipses.length);
    assert.ok(nUnits >= 3, `an ellipse under each crossing at least (${nUnits})`);
    log(`3 arcs across the ridge: preview ${hash(afterRidge)}, ${nUnits} ellipses drawn`);
    await shot('sketch');

    // 6. A cell painted (paper §3): the paint-cells pen shows the cells; a
    // click gives one the chosen classes; the picture changes.
    await page.check('input[name=pen][value=cells]');
    await page.selectOption('#cell-dominant', '4');
    await page.selectOption('#cell-secondary', '3');
    await page.waitForFunction(() => (Sketch.units.tessellation || []).length > 5);
    const cells = await page.evaluate(() => Sketch.units.tessellation);
    // The largest cell: the click lands inside it at any canvas scale.
    const big = cells.reduce((b, c, i) => ((c[2] - c[0]) * (c[3] - c[1]) > (b.c[2] - b.c[0]) * (b.c[3] - b.c[1]) ? { c, i } : b),
                             { c: cells[0], i: 0 });
    const wasSeq = seq;
    await page.mouse.click(...(await pageAt())((big.c[0] + big.c[2]) / 2, (big.c[1] + big.c[3]) / 2));
    seq = await waitForPreview(page, wasSeq);
    const overrides = await page.evaluate(() => App.scene.init.cell_overrides);
    assert.deepEqual(overrides, [{ cell: big.i, dominant: 4, secondary: 3 }], 'the cell clicked takes the classes chosen');
    const afterCell = await shown();
    assert.notEqual(hash(afterCell), hash(afterRidge), 'a painted cell changes the preview');
    await page.waitForFunction((i) => Sketch.units.tessellation[i][4] === 4, big.i);  // the units know it
    assert.match(await page.textContent('#cell-count'), /1 cell/);
    log(`cell ${big.i} painted S4/S3: preview ${hash(afterCell)}`);
    await shot('cell-painted');
    await page.check('input[name=pen][value=off]');

    // 7. The fall plays over the preview and ends on it; it downloads as MP4.
    await page.fill('#fall-frames', '12');
    await page.click('#play-fall');
    await page.waitForFunction(() => !document.getElementById('fall').hidden);
    await shot('fall-playing');
    await page.waitForFunction(() => document.getElementById('fall').dataset.played === '1');
    assert.equal(await page.isHidden('#fall'), true, 'the preview again after the fall');
    const mp4 = await download(page, '#download-fall', 'fall.mp4');
    assert.equal(mp4.toString('latin1', 4, 8), 'ftyp', 'the fall downloads as an MP4 file');
    log(`the fall: 12 frames played; MP4 of ${mp4.length} bytes`);

    // 8. The preview picture and the scene file download.
    const picture = await download(page, '#download-picture', 'picture.png');
    assert.ok(picture.equals(afterCell), 'the picture downloaded is the one shown');
    const sceneFile = JSON.parse((await download(page, '#download-scene', 'scene.json')).toString('utf8'));
    assert.equal(sceneFile.segment.method, 'sketch');
    assert.deepEqual(sceneFile.segment.sketch.ridges, sk.ridges, 'the scene file holds the ridge drawn');
    assert.deepEqual(sceneFile.segment.sketch.arcs, sk.arcs, 'and the arcs');
    assert.equal(Scene_hex(sceneFile.grains.colors[0]), newColour);
    assert.equal(`physics ${sceneFile.physics_seed}`, /physics \d+/.exec(seeds2)[0]);
    assert.deepEqual(sceneFile.init.cell_overrides, overrides, 'and the cell painted');
    log('downloads: picture.png (the preview shown), scene.json (the ridge, C1, the physics seed)');

    // 9. Drag and drop: a picture dropped on the page is halftoned into the
    // region (paper §4.2); the scene file downloaded, dropped back, gives
    // back the same picture (same scene, same seed, same bytes).
    const drop = (name, type, buf) => page.evaluate(({ name, type, data }) => {
      const bytes = Uint8Array.from(atob(data), (c) => c.charCodeAt(0));
      const dt = new DataTransfer();
      dt.items.add(new File([bytes], name, { type }));
      document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    }, { name, type, data: buf.toString('base64') });
    let from = seq;
    await drop('sunset.png', 'image/png', fs.readFileSync(path.join(ROOT, 'examples/inputs/fig15-sunset.png')));
    seq = await waitForPreview(page, from);
    const init = await page.evaluate(() => App.scene.init);
    assert.equal(init.method, 'halftone', 'a picture dropped: the region is its halftone');
    assert.match(init.image, /^studio-inputs\/image-[0-9a-f]{16}\.png$/);
    assert.ok(fs.existsSync(path.join(ART, 'studio-folder', init.image)), 'kept in the studio folder');
    assert.equal(await page.inputValue('[data-key="init.method"]'), 'halftone');
    assert.match(await page.textContent('#image-name'), /sunset\.png \(\d+ x \d+\)/);
    const afterPicture = await shown();
    assert.notEqual(hash(afterPicture), hash(afterCell), 'the halftoned picture falls');
    log(`picture dropped: ${init.image}, preview ${hash(afterPicture)}`);
    await shot('picture-dropped');
    from = seq;
    await drop('scene.json', 'application/json', fs.readFileSync(path.join(ART, 'scene.json')));
    seq = await waitForPreview(page, from);
    assert.equal(await page.evaluate(() => App.scene.init.method), 'tessellation');
    assert.ok((await shown()).equals(afterCell), 'the scene file dropped back: the same picture, byte for byte');
    log('scene.json dropped back: the same preview bytes as when it was downloaded');

    // 10. The friction slider dragged with the mouse: the preview follows
    // the hand (previews shown before the drag ends, each request sent once
    // the one before is answered: never two in flight), and the last one is
    // the picture of the final slider value. No timing is asserted: the drag
    // goes on (1-10 s) until two previews were shown during it.
    const slider = page.locator('#friction-slider');
    await slider.scrollIntoViewIfNeeded();
    const sbox = await slider.boundingBox();
    const frictionBefore = await page.evaluate(() => App.scene.physics.friction);
    await page.evaluate(async () => {
      const img = document.getElementById('preview'), t = (window.__drag = { shown: [], inflight: 0, maxInflight: 0, sent: [] });
      t.before = new Uint8Array(await App.picture.arrayBuffer());
      t.mo = new MutationObserver(() => t.shown.push(Number(img.dataset.seq)));
      t.mo.observe(img, { attributes: true, attributeFilter: ['data-seq'] });
      // Requests out: counted in when sent, out when the answer's headers are
      // in (the page sends the next preview no sooner).
      t.orig = window.fetch;
      t.fetch = t.orig.bind(window);
      window.fetch = async (url, opts) => {
        if (!String(url).startsWith('/api/preview')) return t.fetch(url, opts);
        t.sent.push(JSON.parse(opts.body).physics.friction);
        t.maxInflight = Math.max(t.maxInflight, ++t.inflight);
        try { return await t.fetch(url, opts); } finally { t.inflight--; }
      };
    });
    const y = sbox.y + sbox.height / 2, x0 = sbox.x + 4, x1 = sbox.x + sbox.width - 4;
    await page.mouse.move(x0 + 0.15 * (x1 - x0), y);
    await page.mouse.down();
    const dragStart = Date.now();
    let moves = 0, during = 0;
    // Back and forth over the middle of the slider (friction about 0.3 to
    // 1.7), a move every ~16 ms as a hand.
    while (Date.now() - dragStart < 1000 || (during < 2 && Date.now() - dragStart < 10_000)) {
      const f = 0.15 + 0.7 * (1 - Math.abs(((moves++ / 90) % 2) - 1));
      await page.mouse.move(x0 + f * (x1 - x0), y);
      await new Promise((r) => setTimeout(r, 16));
      during = await page.evaluate(() => window.__drag.shown.length);
    }
    await page.mouse.move(x0 + 0.62 * (x1 - x0), y);
    await page.mouse.up();
    const dragSeconds = (Date.now() - dragStart) / 1000;
    const drag = await page.evaluate(() => ({ shown: window.__drag.shown.length, value: document.getElementById('friction-slider').value }));
    seq = await waitForPreview(page, seq);
    const dragged = await page.evaluate(() => {
      const t = window.__drag;
      t.mo.disconnect();
      window.fetch = t.orig;
      return { maxInflight: t.maxInflight, sent: t.sent, friction: App.scene.physics.friction,
               field: document.querySelector('input[type=number][data-key="physics.friction"]').value };
    });
    assert.ok(drag.shown > 1, `previews shown while the slider moved (${drag.shown})`);
    assert.equal(dragged.maxInflight, 1, 'one preview request in flight at most');
    assert.equal(dragged.friction, Number(drag.value), 'the scene has the final slider value');
    assert.notEqual(dragged.friction, frictionBefore, 'the drag changed the friction');
    assert.equal(Number(dragged.field), dragged.friction, "the friction's number field follows the slider");
    assert.equal(dragged.sent.at(-1), dragged.friction, 'the last preview asked for is of the final value');
    // The picture shown against the studio's picture of the scene now (same
    // scene and seed, same bytes) and the one before the drag, in the page.
    const pictures = await page.evaluate(async () => {
      const bytes = async (res) => new Uint8Array(await res.arrayBuffer());
      const same = (a, b) => a.length === b.length && a.every((v, i) => v === b[i]);
      const now = await bytes(App.picture);
      const fresh = await bytes(await fetch('/api/preview', { method: 'POST', body: JSON.stringify({ ...App.scene, mode: 'lattice' }) }));
      return { fresh: same(now, fresh), before: same(now, window.__drag.before), size: now.length };
    });
    assert.ok(pictures.fresh, "the preview shown is the final value's picture, byte for byte");
    assert.ok(!pictures.before, 'the friction dragged changes the preview');
    log(`friction slider dragged ${dragSeconds.toFixed(1)} s (${moves} moves, ${dragged.sent.length} requests): ` +
        `${drag.shown} previews shown before the drag ended; final friction ${dragged.friction}, the final value's picture shown (${pictures.size} bytes)`);
    await shot('slider-dragged');

    // 11. A final render cancelled: it stops, says so, and keeps nothing.
    if (dem === 'with-bullet') {
      await page.fill('#render-scale', '0.3');  // half an hour if it ran
      await page.click('#final-render');
      await page.waitForSelector('#cancel-render:not([hidden])');
      await page.waitForFunction(() => /running/.test(document.getElementById('render-status').textContent));
      await page.click('#cancel-render');
      await page.waitForFunction(() => /cancelled/.test(document.getElementById('render-status').textContent));
      assert.equal(await page.isHidden('#cancel-render'), true);
      assert.equal(await page.locator('#renders a').count(), 1, 'no thumbnail for a cancelled render');
      const kept = fs.readdirSync(path.join(ART, 'studio-folder/studio-renders')).filter((f) => f.endsWith('.png'));
      assert.equal(kept.length, 1, 'nothing kept of the cancelled render');
      log(`render cancelled: "${await page.textContent('#render-status')}"`);
      await shot('render-cancelled');
    }

    // Nothing went wrong on the way, and the studio is still serving.
    assert.equal(await page.textContent('#general-error'), '', 'no error on top of the page');
    await page.evaluate(() => new Promise(requestAnimationFrame));
    assert.deepEqual(problems, [], 'no console errors, page errors or failed requests');
    assert.ok(studio.running(), 'the studio is still serving');
    await context.close();
  } catch (e) {
    if (lastPage && !lastPage.isClosed())
      await lastPage.screenshot({ path: path.join(ART, 'failed.png') }).catch(() => {});
    throw e;
  } finally {
    if (browser) await browser.close();
    await studio.stop();
    if (studio.stderr()) log(`studio stderr: ${studio.stderr()}`);
  }
}

// Console errors and warnings, uncaught page errors, failed requests and
// error answers, except the ones the page handles by design: a superseded
// preview's 409, and (without Bullet) the final render's 400.
function watch(page) {
  const expectedStatus = (url, status) => allowed.some((a) => a.status === status && a.path.test(url));
  page.on('console', (m) => {
    if (m.type() !== 'error' && m.type() !== 'warning') return;
    const s = /status of (\d+)/.exec(m.text());
    if (s && expectedStatus(m.location().url || '', Number(s[1]))) return;
    problems.push(`console ${m.type()}: ${m.text()} (${m.location().url || ''})`);
  });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.method()} ${r.url()} ${r.failure()?.errorText}`));
  page.on('response', (r) => {
    if (r.status() >= 400 && !expectedStatus(r.url(), r.status())) problems.push(`HTTP ${r.status()}: ${r.request().method()} ${r.url()}`);
  });
}

// Clicks `selector`, takes the download it starts, keeps it in the artifacts.
async function download(page, selector, name) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
  const file = path.join(ART, name);
  await dl.saveAs(file);
  assert.equal(await dl.failure(), null, `download ${name}`);
  return fs.readFileSync(file);
}

function Scene_hex(c) {
  return typeof c === 'string' ? c.toLowerCase() : '#' + c.map((v) => v.toString(16).padStart(2, '0')).join('');
}

try {
  await main();
  console.log(`studio e2e: passed in ${since()}; screenshots and downloads in ${ART}`);
} catch (e) {
  console.error(`studio e2e: FAILED after ${since()}: ${e.stack || e}`);
  if (problems.length) console.error('console/page/request problems:\n  ' + problems.join('\n  '));
  console.error(`screenshots so far in ${ART}`);
  process.exit(1);
}
