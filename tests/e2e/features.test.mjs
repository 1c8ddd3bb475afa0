// Browser tests of the recording panel (motion take downloads, WebM video of the 3-D view), the
// in-page benchmark API, high-DPI and touch input. Same rules as app.test.mjs: every test fails on
// console errors/warnings, and pictures are checked by their pixels.

import { readFileSync } from 'node:fs';
import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  assertDrawn, command, frameExceeds, launch, saveArtifact, serveDist, shootCanvas, sleep, state,
  withLoadedApp,
} from './harness.mjs';

const T = { timeout: 240_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

const withApp = (browser, fn, query = '') => withLoadedApp(browser, server.url + query, fn);

/** Sends `cmd` and resolves to the download it triggers (its name and bytes). */
async function downloadFrom(page, cmd, timeout = 60_000) {
  const pending = page.waitForEvent('download', { timeout });
  assert.equal(await command(page, cmd), 'ok', `command(${JSON.stringify(cmd)})`);
  const download = await pending;
  const path = await download.path();
  return { name: download.suggestedFilename(), bytes: readFileSync(path) };
}

describe('recording panel and bench API (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('records a motion take and downloads it as BVH and CSV', T, async () => {
    await withApp(browser, async ({ page }) => {
      assert.equal(await command(page, { mode: 'wounded-walk', method: 'dls', record: true }), 'ok');
      const start = (await state(page)).frame;
      assert.ok(await frameExceeds(page, start + 30, 30_000), 'the animation advances while recording');
      assert.equal(await command(page, { record: false }), 'ok');
      const { recording } = await state(page);
      assert.equal(recording.active, false);
      assert.ok(recording.frames >= 30, `frames recorded: ${recording.frames}`);

      const bvh = await downloadFrom(page, { save: 'bvh' });
      assert.equal(bvh.name, 'gaitlab-human-wounded-walk-dls.bvh');
      const text = bvh.bytes.toString('utf8');
      saveArtifact('take.bvh', bvh.bytes);
      assert.ok(text.startsWith('HIERARCHY'), text.slice(0, 40));
      assert.match(text, new RegExp(`Frames: ${recording.frames}\\n`));
      assert.match(text, /Frame Time: 0\.016666/);
      const motion = text.slice(text.indexOf('Frame Time:')).split('\n').slice(1).filter((l) => l.trim());
      assert.equal(motion.length, recording.frames, 'one MOTION line per recorded frame');

      const csv = await downloadFrom(page, { save: 'csv' });
      const rows = csv.bytes.toString('utf8').trim().split('\n');
      assert.equal(rows.length, recording.frames + 1, 'header + one row per frame');
      assert.ok(rows[0].startsWith('t,root_x,root_y,root_z'), rows[0]);
      assert.ok(rows[0].includes('left_foot_target_x'), 'the CSV carries targets');
    });
  });

  it('records a WebM video of the 3-D view at the chosen frame size', T, async () => {
    await withApp(browser, async ({ page }) => {
      assert.equal(await command(page, { video_size: 'p360', record_video: true }), 'ok');
      // Software rendering on a loaded 2-core machine can drop to a frame or two per second.
      await page.waitForFunction(() => JSON.parse(window.gaitlab.state()).video.frames >= 10, null,
        { timeout: 120_000, polling: 200 });
      const video = await downloadFrom(page, { record_video: false });
      saveArtifact(video.name, video.bytes);
      assert.match(video.name, /^gaitlab-human-walk-sdls\.(webm|mp4)$/);
      assert.ok(video.bytes.length > 5_000, `video of ${video.bytes.length} bytes`);
      if (video.name.endsWith('.webm')) {
        assert.deepEqual([...video.bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML (WebM) header');
      }
      // Decode it in the page: the frame size is the one chosen, the header carries the duration
      // (WebCodecs + gaitlab's muxer; a MediaRecorder file has none), and the pictures at the
      // start, middle and end (reached by seeking, through the cues) are not blank.
      // A fresh page decodes: the app's page, busy rendering in software, can be handed no frame.
      const decoder = await page.context().newPage();
      const decoded = await decoder.evaluate(async ({ b64, type }) => {
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const el = document.createElement('video');
        el.muted = true;
        el.src = URL.createObjectURL(new Blob([bytes], { type }));
        await new Promise((ok, fail) => {
          el.onloadeddata = ok;
          el.onerror = () => fail(new Error(`video error ${el.error?.code}`));
        });
        const headerDuration = el.duration;
        const canvas = document.createElement('canvas');
        canvas.width = el.videoWidth;
        canvas.height = el.videoHeight;
        const ctx = canvas.getContext('2d', { willReadFrequently: true });
        const stddevs = [];
        for (const t of [0, headerDuration / 2, headerDuration - 0.05]) {
          el.currentTime = t;
          await new Promise((ok) => { el.onseeked = ok; });
          // Wait for the frame to reach the compositor (or 1 s, where there is no callback).
          await new Promise((ok) => {
            el.requestVideoFrameCallback?.(() => ok());
            setTimeout(ok, 1000);
          });
          ctx.drawImage(el, 0, 0);
          const { data } = ctx.getImageData(0, 0, canvas.width, canvas.height);
          let sum = 0;
          let sum2 = 0;
          const n = data.length / 4;
          for (let i = 0; i < data.length; i += 4) {
            const l = 0.2126 * data[i] + 0.7152 * data[i + 1] + 0.0722 * data[i + 2];
            sum += l;
            sum2 += l * l;
          }
          const mean = sum / n;
          stddevs.push(Math.sqrt(Math.max(0, sum2 / n - mean * mean)));
        }
        return { width: el.videoWidth, height: el.videoHeight, headerDuration, stddevs };
      }, { b64: video.bytes.toString('base64'), type: video.name.endsWith('.webm') ? 'video/webm' : 'video/mp4' });
      await decoder.close();
      const { encoder, seconds, frames, skipped } = (await state(page)).video;
      console.log(`# video (${encoder}): ${frames} frames, ${skipped} skipped; ${decoded.headerDuration.toFixed(3)} s in the header, ` +
        `${seconds.toFixed(3)} s recorded; luminance stddev ${decoded.stddevs.map((x) => x.toFixed(1)).join(', ')}`);
      assert.equal(encoder, 'webcodecs-vp9');
      assert.ok(Number.isFinite(decoded.headerDuration) && decoded.headerDuration >= seconds - 0.05,
        `header duration ${decoded.headerDuration} s for ${seconds} s recorded`);
      assert.deepEqual([decoded.width, decoded.height], [640, 360], 'frame size as chosen');
      for (const [i, sd] of decoded.stddevs.entries()) {
        assert.ok(sd > 8, `decoded frame ${i} (start, middle, end) is not blank (luminance stddev ${sd.toFixed(2)})`);
      }
    });
  });

  it('window.gaitlab.bench() times the per-frame simulation + IK in the page', T, async () => {
    await withApp(browser, async ({ page }) => {
      assert.equal(await command(page, { paused: true }), 'ok');
      const text = await page.evaluate(() => window.gaitlab.bench(JSON.stringify({ frames: 120, repeats: 3 })));
      const result = JSON.parse(text);
      assert.equal(result.error, undefined, text);
      assert.deepEqual([result.preset, result.mode, result.method], ['human', 'walk', 'sdls']);
      assert.ok(Number.isFinite(result.us_per_frame) && result.us_per_frame > 0, text);
      assert.ok(result.us_per_frame_best <= result.us_per_frame, text);
      saveArtifact('bench-wasm.json', Buffer.from(text));
      // Bad options are refused with the field named; the app keeps running.
      const refused = JSON.parse(await page.evaluate(() => window.gaitlab.bench('{"frames": 0}')));
      assert.match(refused.error, /^bench\.frames/);
      assert.equal(await command(page, { paused: false }), 'ok');
      assert.ok(await frameExceeds(page, (await state(page)).frame), 'still animating after the bench');
    });
  });
});

describe('high-DPI and touch (WebGL2, device pixel ratio 2, touch screen)', () => {
  let browser;
  // A smaller window keeps software rendering of 2× the pixels affordable.
  before(async () => {
    browser = await launch('webgl2', { deviceScaleFactor: 2, hasTouch: true, viewport: { width: 720, height: 450 } });
  });
  after(async () => { await browser?.close(); });

  it('renders at device resolution and orbits and zooms by touch', T, async () => {
    await withApp(browser, async ({ page }) => {
      const size = await page.evaluate(() => {
        const c = document.getElementById('gaitlab-canvas');
        return { width: c.width, height: c.height, css: c.getBoundingClientRect(), dpr: devicePixelRatio };
      });
      assert.equal(size.dpr, 2);
      assert.ok(Math.abs(size.width - 2 * size.css.width) <= 2 && Math.abs(size.height - 2 * size.css.height) <= 2,
        `canvas backing store ${size.width}×${size.height} for ${size.css.width}×${size.css.height} CSS px`);
      // Paused, the app only repaints on input: the screenshot finds a still canvas and each
      // touch event is handled promptly even where software rendering is slow.
      // Without the plots the 3-D view fills the right of this small window.
      assert.equal(await command(page, { paused: true, plots: false }), 'ok');
      await sleep(500);
      assertDrawn(await shootCanvas(page, 'webgl2-dpr2.png'), 'WebGL2 at DPR 2');

      const cdp = await page.context().newCDPSession(page);
      const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', {
        type, touchPoints: points.map(([x, y], id) => ({ x, y, id })),
      });
      const settle = () => sleep(150);
      // The 3-D view sits right of the side panel: drag one finger across it.
      const x0 = size.css.x + size.css.width * 0.65;
      const y0 = size.css.y + size.css.height * 0.45;
      const before = (await state(page)).camera;
      await touch('touchStart', [[x0, y0]]);
      for (let k = 1; k <= 5; k++) {
        await touch('touchMove', [[x0 + 24 * k, y0]]);
        await settle();
      }
      // Read while the finger is still down (see the closing note of issue 3: a release after a
      // synthetic drag has been seen to count as a double tap, which re-frames the figure).
      const orbited = (await state(page)).camera;
      await touch('touchEnd', []);
      await settle();
      // Yaw is reported in [0°, 360°): compare the angle turned, the short way round.
      const turned = Math.abs(((orbited.yaw_deg - before.yaw_deg + 540) % 360) - 180);
      assert.ok(turned > 5,
        `a one-finger drag orbits: yaw ${before.yaw_deg.toFixed(1)}° → ${orbited.yaw_deg.toFixed(1)}°`);

      // Pinch: two fingers moving apart zoom in (the camera comes closer).
      await touch('touchStart', [[x0 - 20, y0], [x0 + 20, y0]]);
      for (let k = 1; k <= 5; k++) {
        await touch('touchMove', [[x0 - 20 - 16 * k, y0], [x0 + 20 + 16 * k, y0]]);
        await settle();
      }
      const pinched = (await state(page)).camera;
      await touch('touchEnd', []);
      assert.ok(pinched.distance_m < orbited.distance_m * 0.9,
        `a pinch zooms in: ${orbited.distance_m.toFixed(2)} m → ${pinched.distance_m.toFixed(2)} m`);
      // A long pinch stops with the eye outside the 1.8-m figure (issue 21 item 7): the camera
      // stays at least the figure box's half diagonal (about 0.9 m or more) from its target.
      for (let round = 0; round < 3; round++) {
        await touch('touchStart', [[x0 - 10, y0], [x0 + 10, y0]]);
        for (let k = 1; k <= 5; k++) {
          await touch('touchMove', [[x0 - 10 - 30 * k, y0], [x0 + 10 + 30 * k, y0]]);
          await settle();
        }
        await touch('touchEnd', []);
        await settle();
      }
      const deep = (await state(page)).camera;
      console.log(`# pinch: ${orbited.distance_m.toFixed(2)} m → ${pinched.distance_m.toFixed(2)} m → ${deep.distance_m.toFixed(2)} m after three long pinches`);
      assert.ok(deep.distance_m >= 0.85, `the eye stops outside the figure: ${deep.distance_m.toFixed(2)} m`);
    });
  });
});
