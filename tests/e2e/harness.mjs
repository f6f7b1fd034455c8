// What the e2e test and the round-trip benchmark share: sandpic studio
// started on a free loopback port in a folder of its own, and Debian's
// Chromium driven headless by playwright-core (no browser is downloaded).
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const HERE = path.dirname(fileURLToPath(import.meta.url));
export const ROOT = path.resolve(HERE, '../..');
export const CHROMIUM = process.env.SANDPIC_CHROMIUM || '/usr/bin/chromium';
const SETUP_HINT = 'bash scripts/setup.sh --tests installs it';

// --name value pairs; every name must be known.
export function parseArgs(argv, defaults) {
  const out = { ...defaults };
  for (let i = 0; i < argv.length; i++) {
    const m = /^--([a-z-]+)$/.exec(argv[i]);
    if (!m || !(m[1] in defaults) || i + 1 >= argv.length) throw new Error(`bad argument ${argv[i]} (known: ${Object.keys(defaults).map((k) => '--' + k).join(' ')})`);
    out[m[1]] = argv[++i];
  }
  return out;
}

// playwright-core from tests/e2e/node_modules, and the browser it drives:
// a missing one is an error that says how to get it, never a skip.
export async function loadChromium() {
  let pw;
  try {
    pw = await import('playwright-core');
  } catch (e) {
    throw new Error(`playwright-core is not installed in ${HERE}/node_modules ` +
      `(cd tests/e2e && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci; ${SETUP_HINT}): ${e.message}`);
  }
  if (!fs.existsSync(CHROMIUM)) throw new Error(`no Chromium at ${CHROMIUM} (${SETUP_HINT}; SANDPIC_CHROMIUM names another)`);
  return pw.chromium;
}

export async function launchBrowser() {
  const chromium = await loadChromium();
  // A timeout of our own: a browser that cannot start fails the test.
  return chromium.launch({ executablePath: CHROMIUM, headless: true, timeout: 60_000 });
}

// `sandpic studio --port 0` in `dir` (final renders go to dir/studio-renders):
// resolves once it printed its address. stop() ends it and waits.
export function startStudio(bin, dir, extraArgs = []) {
  if (!fs.existsSync(bin)) throw new Error(`no sandpic binary at ${bin} (build first)`);
  fs.mkdirSync(dir, { recursive: true });
  const proc = spawn(bin, ['studio', '--port', '0', ...extraArgs], { cwd: dir, stdio: ['ignore', 'pipe', 'pipe'] });
  // However this process ends (an error, a signal, a closed pipe), the
  // studio ends with it.
  const end = () => { if (proc.exitCode === null && proc.signalCode === null) proc.kill('SIGKILL'); };
  process.on('exit', end);
  for (const sig of ['SIGINT', 'SIGTERM', 'SIGHUP']) process.once(sig, () => { end(); process.exit(128 + os.constants.signals[sig]); });
  let out = '', err = '';
  proc.stderr.on('data', (d) => { err += d; });
  const exited = new Promise((resolve) => proc.on('exit', (code, signal) => resolve({ code, signal })));
  const url = new Promise((resolve, reject) => {
    proc.stdout.on('data', (d) => {
      out += d;
      const m = /sandpic studio: (http:\/\/127\.0\.0\.1:\d+\/)/.exec(out);
      if (m) resolve(m[1]);
    });
    exited.then(({ code, signal }) => reject(new Error(`sandpic studio exited (${code ?? signal}) before printing its address: ${out}${err}`)));
    setTimeout(() => reject(new Error(`sandpic studio printed no address in 20 s: ${out}${err}`)), 20_000).unref();
  });
  return {
    url,
    stderr: () => err,
    running: () => proc.exitCode === null && proc.signalCode === null,
    async stop() {
      if (proc.exitCode === null && proc.signalCode === null) proc.kill('SIGTERM');
      return exited;
    },
  };
}

export function tempDir(prefix) {
  return fs.mkdtempSync(path.join(os.tmpdir(), prefix));
}

// Width and height from a PNG's IHDR; throws if it is no PNG.
export function pngSize(buf) {
  const sig = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  if (buf.length < 24 || !buf.subarray(0, 8).equals(sig) || buf.toString('latin1', 12, 16) !== 'IHDR')
    throw new Error(`not a PNG (${buf.length} bytes)`);
  return { width: buf.readUInt32BE(16), height: buf.readUInt32BE(20) };
}

// Resolves when the preview shown is the newest one the page asked for and
// it is newer than `after` (the page's hook: #preview's data-seq is set once
// a preview's picture is decoded, to the number App.preview gave it).
export async function waitForPreview(page, after, timeout = 60_000) {
  await page.waitForFunction((after) => {
    const seq = Number(document.getElementById('preview').dataset.seq || 0);
    return seq > after && seq === App.seq;
  }, after, { timeout, polling: 50 });
  return page.evaluate(() => App.seq);
}
