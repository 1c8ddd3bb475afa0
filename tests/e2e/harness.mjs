// Shared helpers for the gaitlab browser tests: a static server for dist/, Chromium launchers for
// the WebGL2 and WebGPU paths (flags from ../shared/TOOLCHAIN.md), console capture, the app's JS
// API and PNG statistics. Used by *.test.mjs through node's built-in test runner.

import { existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';
import { serveDir } from './static-server.mjs';

const here = dirname(fileURLToPath(import.meta.url));
export const repoRoot = resolve(here, '..', '..');
export const distDir = resolve(process.env.GAITLAB_DIST ?? join(repoRoot, 'dist'));
export const artifactsDir = join(here, 'artifacts');
export const chromiumPath = process.env.GAITLAB_CHROMIUM ?? '/usr/bin/chromium';

/** How long the app may take from navigation to its first frame (software rendering, big wasm). */
export const READY_TIMEOUT_MS = 60_000;
export const VIEWPORT = { width: 1280, height: 800 };

/** Serves dist/ (or `root`) on a free loopback port. Resolves to { url, close() }. */
export function serveDist(root = distDir) {
  return serveDir(root, 0);
}

const BASE_FLAGS = [
  '--no-sandbox',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

// Playwright passes its own --enable-features list before ours and Chromium keeps only the last
// one, so ours repeats Playwright's (screenshots from a fresh compositor surface).
const PLAYWRIGHT_FEATURES = ['CDPScreenshotNewSurface', 'SkipListAccountsWithoutGaiaCookies'];

/** Chromium flags per rendering path (TOOLCHAIN.md "Serving and browser tests"). */
export const FLAGS = {
  // Software WebGL2 through SwiftShader; without --enable-unsafe-webgpu there is no WebGPU adapter,
  // so the app has to take its WebGL2 fallback.
  webgl2: [...BASE_FLAGS, '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    `--enable-features=${PLAYWRIGHT_FEATURES.join(',')}`],
  // Software WebGPU: every one of these is needed for pixels to reach the screenshot.
  webgpu: [...BASE_FLAGS, '--enable-unsafe-webgpu', '--enable-unsafe-swiftshader',
    `--enable-features=${[...PLAYWRIGHT_FEATURES, 'Vulkan'].join(',')}`,
    '--use-vulkan=swiftshader', '--use-angle=swiftshader'],
};

// Expected console output per path: on the WebGL2 path wgpu first asks for a WebGPU adapter and
// Chromium warns that there is none before the app falls back to WebGL2.
const PATH_NOISE = {
  webgl2: [/^No available adapters\.?$/],
  webgpu: [],
};

/**
 * Launches headless Chromium with a fresh profile for `path` ('webgl2' or 'webgpu'), optionally
 * with a high-DPI screen (`deviceScaleFactor`), a touch screen (`hasTouch`) and a window size
 * (`viewport`, CSS pixels).
 * Resolves to { context, open(opts), close() }; `open` is openPage with the path's expected noise.
 */
export async function launch(path, { deviceScaleFactor = 1, hasTouch = false, viewport = VIEWPORT } = {}) {
  // Playwright's emulated scale factor leaves ResizeObserver's devicePixelContentBoxSize (what
  // eframe sizes the canvas by) at CSS pixels; a real high-DPI screen needs Chromium's own flag
  // and no emulated viewport.
  const hiDpi = deviceScaleFactor !== 1;
  const args = hiDpi
    ? [...FLAGS[path], `--force-device-scale-factor=${deviceScaleFactor}`,
      `--window-size=${viewport.width},${viewport.height}`]
    : FLAGS[path];
  if (!existsSync(chromiumPath)) throw new Error(`${chromiumPath} is missing (apt-get install chromium)`);
  const userDataDir = mkdtempSync(join(tmpdir(), 'gaitlab-e2e-'));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: chromiumPath,
    headless: true,
    args,
    viewport: hiDpi ? null : viewport,
    ...(hiDpi ? {} : { deviceScaleFactor }),
    hasTouch,
    acceptDownloads: true,
    timeout: 60_000,
  });
  return {
    context,
    open: (opts = {}) => openPage(context, { ...opts, allow: [...PATH_NOISE[path], ...(opts.allow ?? [])] }),
    close: async () => {
      await context.close().catch(() => {});
      rmSync(userDataDir, { recursive: true, force: true });
    },
  };
}

// Console output that is not the app's fault (TOOLCHAIN.md "Harmless noise to filter").
const NOISE = [
  /favicon\.ico/i,
  /Software rasterizer detected/i, // egui-wgpu on SwiftShader: expected in these tests
  /GPU stall due to ReadPixels/i, // Chromium's WebGL driver message when a screenshot reads back
  /Automatic fallback to software WebGL has been deprecated/i,
  // Chromium's performance hint when eframe's Canvas-2D glyph fallback (eframe/src/web/
  // canvas_glyphs.rs) rasterizes characters egui's fonts lack, such as "⚠".
  /^Canvas2D: Multiple readback operations using getImageData are faster with the willReadFrequently attribute/,
];

/**
 * Opens a page that records every console error/warning and page error.
 * `allow` adds regexps for messages a particular test expects; `init` runs before the page's scripts.
 */
export async function openPage(context, { allow = [], keepStorage = false, init = null } = {}) {
  const page = await context.newPage();
  // A script run before the page's own (e.g. to take an API away and exercise a fallback).
  if (init) await page.addInitScript(init);
  // Pages of one test browser share localStorage, where the app persists its settings: start
  // each page from the defaults so one test's mode/method changes don't leak into the next.
  if (!keepStorage) await page.addInitScript(() => { try { localStorage.clear(); } catch { /* opaque origin */ } });
  const problems = [];
  const log = [];
  const ignored = [...NOISE, ...allow];
  page.on('console', (msg) => {
    const text = msg.text();
    log.push(`[${msg.type()}] ${text}`);
    if (msg.type() !== 'error' && msg.type() !== 'warning') return;
    if (ignored.some((re) => re.test(text))) return;
    problems.push(`console.${msg.type()}: ${text}`);
  });
  page.on('pageerror', (err) => problems.push(`pageerror: ${err.stack ?? err.message ?? err}`));
  page.on('crash', () => problems.push('page crashed'));
  page.on('requestfailed', (req) => {
    if (!/favicon/.test(req.url())) problems.push(`request failed: ${req.url()} ${req.failure()?.errorText}`);
  });
  page.on('response', (res) => {
    if (res.status() >= 400 && !/favicon/.test(res.url())) problems.push(`HTTP ${res.status()}: ${res.url()}`);
  });
  return {
    page,
    log,
    problems,
    /** Throws if anything unexpected reached the console. */
    assertClean() {
      if (problems.length) {
        throw new Error(`the page reported ${problems.length} problem(s):\n  ${problems.join('\n  ')}`);
      }
    },
  };
}

/**
 * Waits for the app's first frame (`document.body.dataset.ready === "1"`) and its JS API;
 * explains a timeout.
 */
export async function waitReady(page, timeout = READY_TIMEOUT_MS) {
  try {
    await page.waitForFunction(
      () => document.body.dataset.ready === '1' && typeof window.gaitlab?.state === 'function',
      null, { timeout, polling: 100 });
  } catch (e) {
    const shown = await page.evaluate(() => {
      const el = document.getElementById('error');
      return el && !el.hidden ? el.textContent.trim() : '';
    }).catch(() => '');
    throw new Error(`the app did not report its first frame within ${timeout} ms${shown ? `; page shows: ${shown}` : ''}`, { cause: e });
  }
  // The loader must be gone once the app has drawn.
  const loading = await page.evaluate(() => !!document.getElementById('loading'));
  if (loading) throw new Error('#loading is still in the document after the first frame');
}

/** `window.gaitlab.state()`, parsed. */
export async function state(page) {
  const text = await page.evaluate(() => window.gaitlab.state());
  if (typeof text !== 'string') throw new Error(`state() returned ${typeof text}, not a JSON string`);
  return JSON.parse(text);
}

/** `window.gaitlab.command(json)`; returns its answer ("ok" or an error text). */
export async function command(page, obj) {
  const json = typeof obj === 'string' ? obj : JSON.stringify(obj);
  return page.evaluate((j) => window.gaitlab.command(j), json);
}

/** The state's method: `method`, or the first of `methods` when each view has its own. */
export function methodOf(s) {
  if (typeof s.method === 'string') return s.method;
  if (Array.isArray(s.methods)) return s.methods[0];
  return undefined;
}

/** The state's last error message ('' when none). */
export function lastErrorOf(s) {
  const e = s.last_error ?? s.lastError ?? s.error ?? '';
  return e === null ? '' : String(e);
}

/** The renderer backend the app reports, if it reports one (e.g. "Gl", "BrowserWebGpu"). */
export function backendOf(s) {
  const b = s.backend ?? s.renderer ?? s.graphics;
  return b == null ? undefined : String(b);
}

/**
 * Which context the app's canvas holds: 'webgpu', 'webgl2' or 'none'. Asking a canvas for a
 * context of another kind than the one it has returns null, so this does not disturb the app.
 */
export function canvasContextKind(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById('gaitlab-canvas');
    if (canvas.getContext('webgpu')) return 'webgpu';
    if (canvas.getContext('webgl2')) return 'webgl2';
    return 'none';
  });
}

/** The value after `--name` on the command line of a script (bench.mjs, bench-suite.mjs), or undefined. */
export function cliOption(name) {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 ? process.argv[i + 1] : undefined;
}

export const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));

/**
 * Waits until `pred(state())` holds, polling every `every` ms; a timeout names `what` and what
 * `show(state)` says of the last state (its time by default).
 */
export async function until(page, pred, what, timeout = 30_000, every = 150, show = (s) => `t = ${s.time_s}`) {
  const end = Date.now() + timeout;
  for (;;) {
    const s = await state(page);
    if (pred(s)) return s;
    if (Date.now() > end) throw new Error(`timed out waiting for ${what} (${show(s)})`);
    await sleep(every);
  }
}

/**
 * Luminance statistics of a PNG over a region given in fractions of its size:
 * { mean, stddev, distinct (distinct RGB colours, capped), width, height }.
 */
export function pngStats(buf, region = { x0: 0, y0: 0, x1: 1, y1: 1 }) {
  const png = PNG.sync.read(buf);
  const { width, height, data } = png;
  const xa = Math.floor(region.x0 * width);
  const xb = Math.ceil(region.x1 * width);
  const ya = Math.floor(region.y0 * height);
  const yb = Math.ceil(region.y1 * height);
  let n = 0;
  let sum = 0;
  let sum2 = 0;
  const colours = new Set();
  for (let y = ya; y < yb; y++) {
    for (let x = xa; x < xb; x++) {
      const i = (y * width + x) * 4;
      const l = 0.2126 * data[i] + 0.7152 * data[i + 1] + 0.0722 * data[i + 2];
      sum += l;
      sum2 += l * l;
      n++;
      if (colours.size < 100_000) colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    }
  }
  const mean = sum / n;
  return { mean, stddev: Math.sqrt(Math.max(0, sum2 / n - mean * mean)), distinct: colours.size, width, height };
}

/** Fraction of pixels in `region` whose RGB differs between two PNGs of the same size. */
export function pngDiff(a, b, region = { x0: 0, y0: 0, x1: 1, y1: 1 }) {
  const pa = PNG.sync.read(a);
  const pb = PNG.sync.read(b);
  if (pa.width !== pb.width || pa.height !== pb.height) return 1;
  const { width, height } = pa;
  let n = 0;
  let changed = 0;
  for (let y = Math.floor(region.y0 * height); y < Math.ceil(region.y1 * height); y++) {
    for (let x = Math.floor(region.x0 * width); x < Math.ceil(region.x1 * width); x++) {
      const i = (y * width + x) * 4;
      n++;
      if (pa.data[i] !== pb.data[i] || pa.data[i + 1] !== pb.data[i + 1] || pa.data[i + 2] !== pb.data[i + 2]) changed++;
    }
  }
  return changed / n;
}

export function saveArtifact(name, buf) {
  mkdirSync(artifactsDir, { recursive: true });
  const file = join(artifactsDir, name);
  writeFileSync(file, buf);
  return file;
}

/**
 * The README screenshot: written when docs/screenshot.png is missing, or always when
 * GAITLAB_UPDATE_SCREENSHOT=1 (so ordinary test runs leave the committed file alone).
 */
export function saveReadmeScreenshot(buf) {
  const file = join(repoRoot, 'docs', 'screenshot.png');
  if (existsSync(file) && process.env.GAITLAB_UPDATE_SCREENSHOT !== '1') return null;
  mkdirSync(dirname(file), { recursive: true });
  writeFileSync(file, buf);
  return file;
}

// Where the 3-D view is expected: right of the side panel, clear of top and bottom bars
// (fractions of the canvas).
export const VIEW_REGION = { x0: 0.4, y0: 0.2, x1: 0.95, y1: 0.8 };
// A blank or uniformly cleared view has stddev 0 and a handful of colours; a lit figure over a
// floor is far above both.
export const MIN_VIEW_STDDEV = 8;
export const MIN_VIEW_COLOURS = 64;

/** Waits (up to `timeout` ms) until state().frame > `frame`; false if it never does. */
export async function frameExceeds(page, frame, timeout = 15_000) {
  try {
    await page.waitForFunction((f) => JSON.parse(window.gaitlab.state()).frame > f, frame, { timeout, polling: 100 });
    return true;
  } catch {
    return false;
  }
}

/** Resolves after the page has displayed `n` more animation frames. */
export function animationFrames(page, n) {
  return page.evaluate((count) => new Promise((done) => {
    let left = count;
    const tick = () => (--left <= 0 ? done() : requestAnimationFrame(tick));
    requestAnimationFrame(tick);
  }), n);
}

/** Opens `url` in a fresh page of `browser` and waits for the app's first frame; a timeout carries the page's console. */
export async function loadApp(browser, url, opts = {}) {
  const p = await browser.open(opts);
  await p.page.goto(url, { waitUntil: 'load' });
  try {
    await waitReady(p.page);
  } catch (e) {
    e.message += `\n--- page console ---\n${p.log.slice(-30).join('\n')}\n--- problems ---\n${p.problems.join('\n')}`;
    throw e;
  }
  return p;
}

/**
 * Runs `fn(p)` on the app freshly loaded from `url`, fails on console problems, and always closes
 * the page.
 */
export async function withLoadedApp(browser, url, fn) {
  const p = await loadApp(browser, url);
  try {
    await fn(p);
    p.assertClean();
  } finally {
    await p.page.close().catch(() => {});
  }
}

/** Screenshot of the canvas, its statistics, and an artifact file. */
export async function shootCanvas(page, name) {
  const canvas = page.locator('#gaitlab-canvas');
  let png;
  try {
    png = await canvas.screenshot({ animations: 'allow', timeout: 30_000 });
  } catch (e) {
    // On a starved machine the element-stability wait (two equal animation frames) can run out;
    // a clip of the page at the canvas's box needs no such wait.
    if (e.name !== 'TimeoutError') throw e;
    const clip = await canvas.boundingBox();
    if (!clip) throw e;
    png = await page.screenshot({ clip, animations: 'allow', timeout: 60_000 });
  }
  const file = saveArtifact(name, png);
  return { png, file, whole: pngStats(png), view: pngStats(png, VIEW_REGION) };
}

export function assertDrawn(shot, label) {
  const { whole, view, file } = shot;
  const fmt = (s) => `stddev ${s.stddev.toFixed(2)}, ${s.distinct} colours`;
  assert.ok(whole.distinct > 1 && whole.stddev > 0.5, `${label}: the canvas is uniform (${fmt(whole)}); see ${file}`);
  assert.ok(view.stddev >= MIN_VIEW_STDDEV && view.distinct >= MIN_VIEW_COLOURS,
    `${label}: the 3-D view region looks blank (${fmt(view)}; want stddev >= ${MIN_VIEW_STDDEV} and >= ${MIN_VIEW_COLOURS} colours); see ${file}`);
}

