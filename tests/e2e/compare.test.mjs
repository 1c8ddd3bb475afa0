// Browser test of the side-by-side IK comparison (issue 6, item 1): four methods on the 63-joint
// ik-quadruped in the singularity scenario. The per-frame compute of all four views
// (state().sim_us_per_frame, measured by the app around every view's driver step) stays under
// 16 ms; the jitter metric ranks pinv worst; the canvas shows four labelled views, each with a
// figure drawn in it (screenshot saved as an artifact); the overlay draws the four figures in one
// view in four colours found in its pixels; a bad compare command is refused with the
// field named and leaves the comparison running.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { PNG } from 'pngjs';
import {
  assertDrawn, command, launch, loadApp, serveDist, shootCanvas, sleep, state,
} from './harness.mjs';

const T = { timeout: 300_000 };

/** Pixels in `rect` ([x, y, w, h], image pixels) whose colour is clearly saturated (figure, targets). */
function saturatedPixels(buf, [x0, y0, w, h]) {
  const { width, height, data } = PNG.sync.read(buf);
  let count = 0;
  for (let y = Math.max(0, Math.floor(y0)); y < Math.min(height, Math.ceil(y0 + h)); y++) {
    for (let x = Math.max(0, Math.floor(x0)); x < Math.min(width, Math.ceil(x0 + w)); x++) {
      const i = (y * width + x) * 4;
      const hi = Math.max(data[i], data[i + 1], data[i + 2]);
      const lo = Math.min(data[i], data[i + 1], data[i + 2]);
      if (hi - lo > 80) count++;
    }
  }
  return count;
}

/** Hue (degrees) and chroma (max − min, 0–255) of an sRGB pixel. */
function hueChroma(r, g, b) {
  const hi = Math.max(r, g, b);
  const lo = Math.min(r, g, b);
  const c = hi - lo;
  if (c === 0) return [0, 0];
  let h;
  if (hi === r) h = ((g - b) / c) % 6;
  else if (hi === g) h = (b - r) / c + 2;
  else h = (r - g) / c + 4;
  return [(h * 60 + 360) % 360, c];
}

/** The colours of transpose, pinv, DLS and SDLS (the app's compare::METHOD_COLOURS, Okabe–Ito). */
const VIEW_COLOURS = [[0xE6, 0x9F, 0x00], [0x56, 0xB4, 0xE9], [0x00, 0x9E, 0x73], [0xCC, 0x79, 0xA7]];

/** Pixels in `rect` of each view colour's hue (±10°, chroma over 60): lighting changes a colour's
 * brightness, not its hue. */
function pixelsPerViewColour(buf, [x0, y0, w, h]) {
  const { width, height, data } = PNG.sync.read(buf);
  const hues = VIEW_COLOURS.map(([r, g, b]) => hueChroma(r, g, b)[0]);
  const counts = hues.map(() => 0);
  for (let y = Math.max(0, Math.floor(y0)); y < Math.min(height, Math.ceil(y0 + h)); y++) {
    for (let x = Math.max(0, Math.floor(x0)); x < Math.min(width, Math.ceil(x0 + w)); x++) {
      const i = (y * width + x) * 4;
      const [hue, chroma] = hueChroma(data[i], data[i + 1], data[i + 2]);
      if (chroma <= 60) continue;
      hues.forEach((want, k) => {
        const d = Math.abs(hue - want);
        if (Math.min(d, 360 - d) <= 10) counts[k]++;
      });
    }
  }
  return counts;
}

/** The 2 × 2 panes of the view rectangle (as the app's viewport::split_rects, 2-px gap). */
function quadrants([x, y, w, h]) {
  const gap = 2;
  const pw = (w - gap) / 2;
  const ph = (h - gap) / 2;
  return [0, 1, 2, 3].map((i) => [x + (i % 2) * (pw + gap), y + Math.floor(i / 2) * (ph + gap), pw, ph]);
}

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

describe('side-by-side IK comparison (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('runs four methods on the 63-joint animal under 16 ms a frame and ranks pinv jitter worst', T, async () => {
    const p = await loadApp(browser, server.url);
    try {
      const { page } = p;
      assert.equal(await command(page, { preset: 'ik-quadruped' }), 'ok');
      const views = ['transpose', 'pinv', 'dls', 'sdls'];
      assert.equal(await command(page, { compare: { views, scenario: 'singularity' } }), 'ok');
      let s = await state(page);
      assert.equal(s.joints, 63);
      assert.deepEqual(s.compare.views, views);
      assert.deepEqual(s.methods, views);
      assert.equal(s.compare.scenario, 'singularity');

      // 10 s of simulated time (the jitter window is the last 4 s).
      await page.waitForFunction(() => JSON.parse(window.gaitlab.state()).compare.metrics[0].frame >= 600,
        null, { timeout: 240_000, polling: 250 });
      s = await state(page);
      const frames = s.compare.metrics.map((m) => m.frame);
      assert.ok(frames.every((f) => f === frames[0]), `lock step: ${frames}`);
      const times = s.compare.metrics.map((m) => m.time_s);
      assert.ok(times.every((t) => t === times[0]), `same time: ${times}`);

      const ms = s.sim_us_per_frame / 1000;
      console.log(`# 4-view comparison on ik-quadruped in the browser: ${ms.toFixed(2)} ms of compute per frame`
        + ` (${s.compare.metrics.map((m) => `${m.method} ${m.us_per_iteration.toFixed(1)} µs/iter`).join(', ')})`);
      assert.ok(s.sim_us_per_frame > 0 && ms < 16, `compute per frame ${ms} ms`);

      for (const m of s.compare.metrics) {
        console.log(`# singularity ${m.method}: jitter ${m.jitter_rad.toExponential(3)} rad/frame², `
          + `mean error ${(m.mean_error_m * 1e3).toFixed(1)} mm, max ${(m.max_error_m * 1e3).toFixed(1)} mm, `
          + `limit hits ${m.limit_hits}`);
      }
      // The cards' error plots share one y-range: 0 to a round top above every view's largest
      // error in the plots' 10-s window (here the whole run since the reset).
      const largestMm = Math.max(...s.compare.metrics.map((m) => m.max_error_m * 1e3));
      const top = s.compare.plot_error_max_mm;
      console.log(`# cards' shared y-range: 0 to ${top} mm (largest error ${largestMm.toFixed(1)} mm)`);
      // Past 600 frames the largest error may have left the plots' window: then only half of it.
      const within = s.compare.metrics[0].frame <= 600 ? largestMm : 0.5 * largestMm;
      assert.ok(top >= within && top <= 2.5 * Math.max(largestMm, 1), `shared top ${top} mm for ${largestMm} mm`);
      const mantissa = top / 10 ** Math.floor(Math.log10(top));
      assert.ok([1, 2, 5, 10].some((m) => Math.abs(mantissa - m) < 1e-9), `${top} is 1, 2 or 5 × 10ⁿ`);
      const pinv = s.compare.metrics.find((m) => m.method === 'pinv');
      for (const m of s.compare.metrics) {
        if (m.method !== 'pinv') {
          assert.ok(pinv.jitter_rad > 5 * m.jitter_rad, `pinv jitter ${pinv.jitter_rad} vs ${m.method} ${m.jitter_rad}`);
        }
      }

      // Four panes, each with a figure in it.
      assert.equal(await command(page, { paused: true }), 'ok');
      const shot = await shootCanvas(page, 'compare-4-views.png');
      assertDrawn(shot, 'compare');
      s = await state(page);
      const rect = s.view_rect_px;
      assert.ok(rect[2] > 100 && rect[3] > 100, `view rect ${rect}`);
      const counts = quadrants(rect).map((q) => saturatedPixels(shot.png, q));
      console.log(`# coloured pixels per pane: ${counts.join(', ')} (see ${shot.file})`);
      assert.ok(counts.every((c) => c > 100), `every pane draws a figure: ${counts}`);

      // The overlay: the four figures in one view, each in its card's colour, the run carried on.
      const frameBefore = s.compare.metrics[0].frame;
      assert.equal(await command(page, { compare: { overlay: true } }), 'ok');
      await sleep(300);
      const overlaid = await shootCanvas(page, 'compare-overlay.png');
      assertDrawn(overlaid, 'overlay');
      s = await state(page);
      assert.equal(s.compare.overlay, true);
      assert.equal(s.compare.metrics[0].frame, frameBefore, 'the same run, still paused');
      const perColour = pixelsPerViewColour(overlaid.png, s.view_rect_px);
      console.log(`# overlay pixels per view colour (orange, sky blue, green, purple): ${perColour.join(', ')}`
        + ` (see ${overlaid.file})`);
      assert.ok(perColour.every((c) => c > 50), `four distinct colours drawn: ${perColour}`);
      assert.equal(await command(page, { compare: { overlay: false } }), 'ok');

      // The history scrubber: one second forward a frame at a time (each frame's pose digest
      // noted), one second back, then forward again: the stored poses come back, and simulating
      // again reproduces each frame bit for bit.
      const stepOnce = async () => {
        const before = (await state(page)).frame;
        assert.equal(await command(page, { step: true }), 'ok');
        await page.waitForFunction((f) => JSON.parse(window.gaitlab.state()).frame > f, before,
          { timeout: 10_000, polling: 20 });
        const r = (await state(page)).rewind;
        return r;
      };
      const start = (await state(page)).rewind;
      const digests = new Map([[start.frame, start.pose_digest]]);
      for (let k = 0; k < 60; k++) {
        const r = await stepOnce();
        digests.set(r.frame, r.pose_digest);
      }
      const end = (await state(page)).rewind.frame;
      assert.equal(await command(page, { step_back_s: 1 }), 'ok');
      let r = (await state(page)).rewind;
      assert.equal(r.frame, end - 60, 'one second back');
      assert.equal(r.newest_frame, end);
      assert.equal(r.pose_digest, digests.get(end - 60), `stored pose at frame ${r.frame}`);
      let replayed = 0;
      for (let k = 0; k < 60; k++) {
        r = await stepOnce();
        assert.equal(r.pose_digest, digests.get(r.frame), `frame ${r.frame} simulated again`);
        assert.equal(r.pose_matches_stored, true, `frame ${r.frame}`);
        replayed++;
      }
      console.log(`# history: stepped back 1 s from frame ${end}, ${replayed} frames simulated again, all bit-identical`);
      s = await state(page);

      // A bad compare command names the field and leaves the comparison as it was.
      assert.match(await command(page, { compare: { views: ['pinv', 'warp'] } }), /^compare\.views\[1\]/);
      assert.match(await command(page, { compare: { views: ['pinv'] } }), /^compare\.views/);
      s = await state(page);
      assert.deepEqual(s.compare.views, views);

      // Replaying the state's compare object restores the configuration; false leaves.
      const saved = s.compare;
      assert.equal(await command(page, { compare: false }), 'ok');
      assert.equal((await state(page)).compare, null);
      assert.equal(await command(page, { compare: saved }), 'ok');
      s = await state(page);
      for (const key of ['views', 'scenario', 'options']) assert.deepEqual(s.compare[key], saved[key], key);

      // Engines without IK methods refuse.
      assert.equal(await command(page, { compare: false, engine: 'poda' }), 'ok');
      assert.match(await command(page, { compare: { views: ['pinv', 'dls'] } }), /^compare: engine poda/);
      assert.deepEqual(p.problems, [], 'no console problems');
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
