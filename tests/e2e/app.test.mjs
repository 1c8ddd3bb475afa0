// Browser tests for the gaitlab web app (DESIGN.md "Contracts": window.gaitlab.state()/command(),
// URL parameters, first-frame signal from index.html). Run through ./build.sh test, or after
// ./build.sh: `cd tests/e2e && npm test -- *.test.mjs`.
//
// Each test fails on any console error/warning or page error that is not known noise, and every
// rendering test checks pixels, not only state: a wrong GPU setup can run without drawing.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  VIEW_REGION, animationFrames, assertDrawn, backendOf, canvasContextKind, command, frameExceeds, lastErrorOf,
  launch, loadApp, methodOf, pngDiff, saveReadmeScreenshot, serveDist, shootCanvas, sleep, state, waitReady,
} from './harness.mjs';

const T = { timeout: 120_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

/** Loads the app at `query` in a fresh page and waits for its first frame. */
const load = (browser, query = '', opts = {}) => loadApp(browser, server.url + query, opts);

/** Loads the app at `query`, runs `fn(p)`, and always closes the page (open pages compete for CPU). */
async function withApp(browser, query, opts, fn) {
  const p = await load(browser, query, opts);
  try {
    await fn(p);
    p.assertClean();
  } finally {
    await p.page.close().catch(() => {});
  }
}

describe('WebGL2 path (SwiftShader, no WebGPU adapter)', () => {
  let browser;
  let app; // one page shared by the tests that drive it through commands
  let defaults; // state of an app loaded without parameters

  before(async () => { browser = await launch('webgl2'); });
  after(async () => {
    await app?.page.close().catch(() => {});
    await browser?.close();
  });

  it('starts, reports its first frame and a JSON state for the default preset', T, async () => {
    app = await load(browser);
    const { page } = app;
    const firstFrame = await page.evaluate(() => window.__gaitlabFirstFrameMs);
    assert.equal(typeof firstFrame, 'number', 'window.__gaitlabFirstFrameMs is set');
    assert.ok(firstFrame > 0, `first frame at ${firstFrame} ms`);
    const s = await state(page);
    defaults = s;
    assert.equal(s.preset, 'human');
    for (const key of ['engine', 'mode', 'paused', 'frame']) assert.ok(key in s, `state has "${key}": ${JSON.stringify(s)}`);
    assert.equal(typeof methodOf(s), 'string', `state names a method: ${JSON.stringify(s)}`);
    assert.equal(s.paused, false);
    assert.equal(lastErrorOf(s), '', 'no error on a plain load');
    const hasAdapter = await page.evaluate(async () => !!(navigator.gpu && await navigator.gpu.requestAdapter()));
    assert.equal(hasAdapter, false, 'this launch must not offer a WebGPU adapter (it tests the WebGL2 fallback)');
    assert.equal(await canvasContextKind(page), 'webgl2', 'the canvas renders through WebGL2');
    const backend = backendOf(s);
    assert.match(backend ?? '', /^webgl2/, `state().backend on this path: ${backend}`);
    app.assertClean();
  });

  it('applies mode and method commands and rejects bad ones', T, async () => {
    assert.ok(app, 'needs the app page from the first test');
    const { page } = app;
    app.problems.length = 0;
    assert.equal(await command(page, '{"mode":"run"}'), 'ok');
    assert.equal((await state(page)).mode, 'run');
    assert.equal(await command(page, '{"method":"dls"}'), 'ok');
    let s = await state(page);
    assert.equal(methodOf(s), 'dls');
    assert.equal(s.mode, 'run', 'a method change keeps the mode');
    // Bad input answers with an error text and changes nothing.
    for (const bad of ['{"mode":"fly"}', '{"method":"magic"}', 'not json']) {
      const answer = await command(page, bad);
      assert.equal(typeof answer, 'string');
      assert.notEqual(answer, 'ok', `command(${bad}) must be refused`);
      assert.ok(answer.length > 0, `command(${bad}) explains the refusal`);
    }
    s = await state(page);
    assert.equal(s.mode, 'run');
    assert.equal(methodOf(s), 'dls');
    // Refused commands may warn about the bad value; anything else is a problem.
    app.problems.splice(0, app.problems.length,
      ...app.problems.filter((p) => !(p.startsWith('console.warning') && /fly|magic|not json|json/i.test(p))));
    app.assertClean();
  });

  it('draws the 3-D view (canvas pixels are far from blank)', T, async () => {
    assert.ok(app, 'needs the app page from the first test');
    const { page } = app;
    // Back to the defaults from the start, for a representative picture (also the README's).
    const reset = { mode: defaults?.mode ?? 'walk', method: methodOf(defaults ?? {}) ?? 'sdls', reset: true };
    assert.equal(await command(page, reset), 'ok', `command(${JSON.stringify(reset)})`);
    await sleep(2000); // mid-stride rather than the first pose
    const shot = await shootCanvas(page, 'webgl2.png');
    assertDrawn(shot, 'WebGL2');
    // The figure moves: a later frame differs inside the 3-D view.
    let changed = 0;
    let later;
    const until = Date.now() + 10_000;
    while (changed <= 0.0005 && Date.now() < until) {
      await animationFrames(page, 5);
      later = await shootCanvas(page, 'webgl2-later.png');
      changed = pngDiff(shot.png, later.png, VIEW_REGION);
    }
    assert.ok(changed > 0.0005,
      `WebGL2: the 3-D view does not animate (${(changed * 100).toFixed(3)}% of its pixels changed); see ${later.file}`);
    saveReadmeScreenshot(shot.png);
    app.assertClean();
  });

  it('pause freezes the frame counter and unpause resumes it', T, async () => {
    assert.ok(app, 'needs the app page from the first test');
    const { page } = app;
    // Software rendering on a busy machine can be slow: wait for progress instead of fixed sleeps.
    const f0 = (await state(page)).frame;
    assert.ok(await frameExceeds(page, f0), `frames advance while running (stuck at ${f0})`);

    assert.equal(await command(page, '{"pause":true}'), 'ok');
    assert.equal((await state(page)).paused, true);
    await animationFrames(page, 2);
    const fa = (await state(page)).frame;
    await animationFrames(page, 8);
    await sleep(300);
    const fb = (await state(page)).frame;
    assert.equal(fb, fa, `paused: the frame counter stays (${fa} → ${fb} over 8 display frames)`);

    assert.equal(await command(page, '{"pause":false}'), 'ok');
    assert.equal((await state(page)).paused, false);
    assert.ok(await frameExceeds(page, fb), `unpaused: frames advance again (stuck at ${fb})`);
    app.assertClean();
  });

  it('applies ?preset=human&mode=run&method=dls', T, async () => {
    await app?.page.close().catch(() => {}); // done with the shared page
    await withApp(browser, '?preset=human&mode=run&method=dls', {}, async (p) => {
      const s = await state(p.page);
      assert.equal(s.preset, 'human');
      assert.equal(s.mode, 'run');
      assert.equal(methodOf(s), 'dls');
      assert.equal(lastErrorOf(s), '', 'a good link raises no error');
    });
  });

  it('a bad query (?preset=nope&mode=fly) shows a message and falls back to the defaults', T, async () => {
    // The app may warn about the bad link on the console; errors still fail the test.
    await withApp(browser, '?preset=nope&mode=fly', { allow: [/nope|fly/i] }, async (p) => {
      const s = await state(p.page);
      assert.ok(lastErrorOf(s).length > 0, `state carries the error: ${JSON.stringify(s)}`);
      assert.equal(s.preset, defaults?.preset ?? 'human', 'falls back to the default preset');
      assert.notEqual(s.mode, 'fly');
      if (defaults) assert.equal(s.mode, defaults.mode, 'falls back to the default mode');
      // Still alive: it keeps animating.
      assert.ok(await frameExceeds(p.page, s.frame), 'the app keeps running after a bad link');
    });
  });

  it('a garbled #p= preset link shows a message and falls back to the default preset', T, async () => {
    await withApp(browser, '#p=%%%not-base64%%%', { allow: [/preset|base64|link|deflate|#p/i] }, async (p) => {
      const s = await state(p.page);
      assert.ok(lastErrorOf(s).length > 0, `state carries the error: ${JSON.stringify(s)}`);
      assert.equal(s.preset, defaults?.preset ?? 'human');
    });
  });
});

describe('page shell (index.html)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  /** Opens the page with `prepare(page)` applied first; resolves to the error box text. */
  async function failedStart(prepare) {
    const p = await browser.open();
    try {
      await prepare(p.page);
      await p.page.goto(server.url, { waitUntil: 'load' });
      await p.page.waitForFunction(() => document.body.dataset.failed === '1', null, { timeout: 30_000 });
      const shown = await p.page.evaluate(() => ({
        loading: !!document.getElementById('loading'),
        error: document.getElementById('error').hidden ? '' : document.getElementById('error').innerText,
      }));
      assert.equal(shown.loading, false, 'the loader is replaced by the message');
      p.assertClean();
      return shown.error;
    } finally {
      await p.page.close().catch(() => {});
    }
  }

  it('says so when the WebAssembly module cannot start', T, async () => {
    const text = await failedStart((page) => page.route('**/*.wasm', (route) => route.fulfill({
      status: 200, contentType: 'application/wasm', body: Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0, 1, 0x7f]),
    })));
    assert.match(text, /failed to load or start/);
    assert.match(text, /CompileError|WebAssembly/, `the message includes the cause: ${text}`);
  });

  it('the loader counts the download, then says the graphics are starting, and never animates', T, async () => {
    // Every text the loader shows, with the page's running animations at that moment. A spinning
    // loader made a software compositor busy enough to slow WebGL2 start-up 2.6-fold.
    const watch = () => {
      window.__loaderNews = [];
      addEventListener('DOMContentLoaded', () => {
        const line = document.getElementById('loading-text');
        const note = () => window.__loaderNews.push({
          text: line.textContent, animations: document.getAnimations().length,
          bar: document.getElementById('loading-bar').style.width,
        });
        note();
        new MutationObserver(note).observe(line, { childList: true, characterData: true, subtree: true });
      });
    };
    const p = await loadApp(browser, server.url, { init: watch });
    try {
      const news = await p.page.evaluate(() => window.__loaderNews);
      const wasmBytes = Number((await p.page.request.head(`${server.url}pkg/gaitlab_app_bg.wasm`))
        .headers()['content-length']);
      const total = (wasmBytes / 1048576).toFixed(1);
      const texts = news.map((n) => n.text);
      assert.equal(texts[0], 'Loading gaitlab…', texts.join(' | '));
      const downloads = news.filter((n) => n.text.startsWith('Downloading gaitlab… '));
      assert.ok(downloads.length >= 1, `download progress shown: ${texts.join(' | ')}`);
      for (const d of downloads) {
        const m = d.text.match(/^Downloading gaitlab… (\d+\.\d) of (\d+\.\d) MB$/);
        assert.ok(m, d.text);
        assert.equal(m[2], total, 'the total is the module size');
        assert.ok(Number(m[1]) <= Number(m[2]), d.text);
        // The bar counts bytes, the text tenths of a MB: they agree within a rounding or two.
        assert.ok(Math.abs(parseFloat(d.bar) - 100 * Number(m[1]) / Number(m[2])) <= 1.5, `${d.text}: bar ${d.bar}`);
      }
      assert.equal(texts.at(-1), 'Starting graphics…');
      assert.equal(news.at(-1).bar, '100%');
      assert.deepEqual(news.map((n) => n.animations), news.map(() => 0), 'no animation runs while loading');
      assert.equal(await p.page.evaluate(() => document.getElementById('loading')), null, 'loader gone');
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });

  it('says so when the browser has no WebAssembly', T, async () => {
    const text = await failedStart((page) => page.addInitScript(() => { delete globalThis.WebAssembly; }));
    assert.match(text, /does not support WebAssembly/);
  });
});

describe('WebGPU path (SwiftShader Vulkan)', () => {
  let browser;
  before(async () => { browser = await launch('webgpu'); });
  after(async () => { await browser?.close(); });

  it('renders through WebGPU', T, async (t) => {
    const p = await browser.open();
    try {
      await p.page.goto(server.url, { waitUntil: 'load' });
      await webgpuChecks(t, p);
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});

async function webgpuChecks(t, p) {
  const adapter = await p.page.evaluate(async () => {
    if (!navigator.gpu) return 'navigator.gpu is missing';
    const a = await navigator.gpu.requestAdapter();
    return a ? '' : 'requestAdapter() gave no adapter';
  });
  if (adapter) {
    t.skip(`no WebGPU in this Chromium: ${adapter}`);
    return;
  }
  try {
    await waitReady(p.page);
  } catch (e) {
    e.message += `\n--- page console ---\n${p.log.slice(-30).join('\n')}`;
    throw e;
  }
  const s = await state(p.page);
  assert.equal(s.preset, 'human');
  assert.equal(await canvasContextKind(p.page), 'webgpu', 'the canvas renders through WebGPU');
  const backend = backendOf(s);
  assert.match(backend ?? '', /^webgpu/, `state().backend on this path: ${backend}`);
  // Let it walk a moment, then hold still: on a loaded machine a constantly repainting canvas
  // can keep Playwright's element screenshot waiting for a stable frame.
  await frameExceeds(p.page, s.frame + 10, 30_000);
  assert.equal(await command(p.page, { paused: true }), 'ok');
  await sleep(500);
  assertDrawn(await shootCanvas(p.page, 'webgpu.png'), 'WebGPU');
  p.assertClean();
}
