// Browser tests of first impressions (issue 17 item 6): the camera frames every bundled preset,
// whole, right after loading, after 10 s of simulated time at its default gait and speed (stepped
// at once, so the camera has to catch up), and while it then runs in real time (the follow camera
// keeps a moving creature in view), on a 1280 × 800 screen and a 390 × 844 phone; and the side
// panel keeps its width while the Share row's link field is shown.
// The creature's box is state().views[0].creature_box_px (every bone and sphere with its radius,
// projected through the view's camera), the view is state().view_rect_px, both in physical pixels.
// Run after ./build.sh: `cd tests/e2e && node --test --test-concurrency=1 framing.test.mjs`.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import {
  animationFrames, command, launch, loadApp, pngDiff, repoRoot, serveDist, shootCanvas, sleep, state,
} from './harness.mjs';

const T = { timeout: 300_000 };

/** The bundled presets, by file name (each file's `name`). */
const PRESETS = readdirSync(join(repoRoot, 'presets'))
  .filter((f) => f.endsWith('.json'))
  .map((f) => f.slice(0, -'.json'.length))
  .sort();

/** Simulated seconds each preset runs before the second look. */
const RUN_S = 10;
/** Real seconds each preset then runs, unpaused, before the third look. */
const LIVE_S = 2;

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

/** How far (pixels) the box stays inside the view on each side: [left, top, right, bottom]. */
function margins(box, view) {
  const [bx, by, bw, bh] = box;
  const [vx, vy, vw, vh] = view;
  return [bx - vx, by - vy, vx + vw - (bx + bw), vy + vh - (by + bh)];
}

/** The creature's box and the view once the app has drawn a couple of frames. */
async function look(page) {
  await animationFrames(page, 3);
  // Paused, the app draws (and the camera moves) until the camera has caught up with the
  // creature: wait until it stays put over a few displayed frames (egui draws inside them).
  let target = JSON.stringify((await state(page)).camera.target_m);
  for (const end = Date.now() + 15_000; Date.now() < end;) {
    await animationFrames(page, 4);
    const now = JSON.stringify((await state(page)).camera.target_m);
    if (now === target) break;
    target = now;
  }
  const s = await state(page);
  return { s, box: s.views[0].creature_box_px, view: s.view_rect_px };
}

function assertInside({ s, box, view }, label) {
  assert.ok(Array.isArray(box) && box.length === 4, `${label}: no creature box in state() (${JSON.stringify(box)})`);
  const m = margins(box, view);
  const fmt = (a) => a.map((x) => x.toFixed(0)).join(', ');
  assert.ok(m.every((x) => x >= 0),
    `${label}: the creature's box [${fmt(box)}] leaves the view [${fmt(view)}] (margins ${fmt(m)}; camera ${JSON.stringify(s.camera)})`);
  return m;
}

/** Advances the paused lab by `seconds` of simulated time in single steps (up to 600 a frame). */
async function run(page, seconds) {
  const start = (await state(page)).time_s;
  for (let guard = 0; guard < 20; guard++) {
    const now = (await state(page)).time_s;
    if (now >= start + seconds - 1e-6) return now - start;
    // One rendered frame takes at most 600 pending steps.
    await page.evaluate(() => {
      for (let i = 0; i < 600; i++) window.gaitlab.command('{"step": true}');
    });
    await page.waitForFunction((t) => JSON.parse(window.gaitlab.state()).time_s > t, now,
      { timeout: 60_000, polling: 50 });
  }
  throw new Error(`simulated time did not reach ${seconds} s`);
}

for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
  const size = `${viewport.width}x${viewport.height}`;
  describe(`camera framing (WebGL2, ${size})`, () => {
    let browser;
    before(async () => { browser = await launch('webgl2', { viewport }); });
    after(async () => { await browser?.close(); });

    it(`frames every bundled preset whole, after loading and after ${RUN_S} s`, T, async () => {
      const app = await loadApp(browser, server.url);
      const { page } = app;
      const failures = [];
      try {
        for (const preset of PRESETS) {
          assert.equal(await command(page, { preset, paused: true }), 'ok', preset);
          assert.equal((await state(page)).preset, preset);
          const loaded = await look(page);
          const ran = await run(page, RUN_S);
          const later = await look(page);
          const shot = await shootCanvas(page, `framing-${size}-${preset}.png`);
          assert.equal(await command(page, { paused: false }), 'ok');
          await sleep(LIVE_S * 1000);
          const live = { s: await state(page) };
          Object.assign(live, { box: live.s.views[0].creature_box_px, view: live.s.view_rect_px });
          await shootCanvas(page, `framing-${size}-${preset}-running.png`);
          assert.equal(await command(page, { paused: true }), 'ok');
          const fmt = (seen) => `[${margins(seen.box ?? [0, 0, 0, 0], seen.view).map((x) => x.toFixed(0))}]`;
          console.log(`# ${size} ${preset}: margins (left, top, right, bottom) px after loading ${fmt(loaded)}, `
            + `after ${ran.toFixed(1)} s ${fmt(later)}, running ${fmt(live)} (${live.s.fps?.toFixed?.(0)} fps); ${shot.file}`);
          for (const [when, seen] of [['after loading', loaded], [`after ${RUN_S} s`, later], ['running', live]]) {
            try {
              assertInside(seen, `${size} ${preset} ${when}`);
            } catch (e) {
              failures.push(e.message);
            }
          }
        }
        assert.deepEqual(failures, [], failures.join('\n'));
        app.assertClean();
      } finally {
        await page.close().catch(() => {});
      }
    });
  });
}

describe('side panel width with the link field shown (WebGL2, 1280x800)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('keeps its width for 60 s after Copy link, and after the field is closed', T, async () => {
    const app = await loadApp(browser, server.url);
    const { page } = app;
    try {
      // The view starts where the side panel ends.
      const edge = async () => (await state(page)).view_rect_px[0];
      assert.equal(await command(page, { paused: true }), 'ok');
      await animationFrames(page, 3);
      const before = await edge();
      const plain = await shootCanvas(page, 'panel-without-link.png');
      assert.equal(await command(page, { show_link: true }), 'ok');
      await animationFrames(page, 3);
      const shown = await shootCanvas(page, 'panel-with-link.png');
      const panel = { x0: 0, y0: 0, x1: before / 1280, y1: 1 };
      const changed = pngDiff(plain.png, shown.png, panel);
      assert.ok(changed > 0.002, `the link field shows in the side panel (${(100 * changed).toFixed(2)} % of its pixels changed); see ${shown.file}`);

      // Running (a repaint every frame) for 60 s.
      assert.equal(await command(page, { paused: false }), 'ok');
      const widths = [await edge()];
      const start = Date.now();
      while (Date.now() - start < 60_000) {
        await sleep(10_000);
        widths.push(await edge());
      }
      const frames = (await state(page)).frame;
      console.log(`# side panel's right edge over 60 s with the link shown (px): ${widths.map((w) => w.toFixed(1)).join(', ')} (before: ${before.toFixed(1)}; ${frames} frames)`);
      await shootCanvas(page, 'panel-with-link-60s.png');
      for (const w of widths) assert.ok(Math.abs(w - before) <= 1, `the side panel's edge moved from ${before} to ${w} px: ${widths.join(', ')}`);

      assert.equal(await command(page, { show_link: false }), 'ok');
      await animationFrames(page, 3);
      const closed = await edge();
      assert.ok(Math.abs(closed - before) <= 1, `after closing the field the edge is ${closed} px, was ${before}`);
      app.assertClean();
    } finally {
      await page.close().catch(() => {});
    }
  });
});
