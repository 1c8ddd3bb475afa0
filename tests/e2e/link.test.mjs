// Browser tests for full-state links and preset files (issue 6 items 2–3): "Copy link"
// (window.gaitlab.link()) opened in a fresh browser context gives the same state() field by field;
// broken links (flipped bytes, truncated, a 10 MB fragment) leave the app running with a message
// and the default preset; a preset file set on the file input and one dropped on the canvas load;
// a lesson link opens with its note and hidden panels; a target CSV dropped on the canvas is followed.
// Run after ./build.sh: `cd tests/e2e && node --test --test-concurrency=1 link.test.mjs`.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import {
  assertDrawn, command, frameExceeds, launch, loadApp, repoRoot, serveDist, shootCanvas, state,
} from './harness.mjs';

const T = { timeout: 240_000 };

/**
 * state() fields that are live counters, not settings, and so differ between two labs opened from
 * one link: the frame counter, simulated time, frame rate and timing, the wasm memory size and heap counts,
 * `views` (each effector's error at the current frame), the Jacobian panel's `jacobian` (this
 * iteration's singular values and gains), the history scrubber's `rewind` and the comparison's
 * live metrics and plot range.
 * Everything else must match exactly.
 */
const LIVE = ['frame', 'time_s', 'fps', 'sim_us_per_frame', 'views', 'jacobian', 'rewind', 'wasm_memory_bytes', 'wasm_heap_live_bytes', 'wasm_heap_peak_bytes'];

const presetJson = (name) => readFileSync(join(repoRoot, 'presets', `${name}.json`), 'utf8');

function settled(s) {
  const out = { ...s };
  for (const key of LIVE) delete out[key];
  // The ground is a setting; where the body stands on it and the footholds moved so far are live.
  if (out.terrain) out.terrain = { ...out.terrain, root_m: undefined, ground_under_root_m: undefined, footholds_moved: undefined };
  // The side-by-side comparison's live figures: its metrics and the plots' shared y-range, which
  // follows the errors measured so far (its configuration must match).
  // The notes' verdicts are computed from those figures too.
  if (out.compare) {
    out.compare = { ...out.compare, metrics: undefined, plot_error_max_mm: undefined, notice: undefined, claims: undefined };
  }
  return out;
}

/** Drops a file named `name` holding `text` on the canvas, as a person dragging it from a folder. */
async function dropFile(page, name, type, text) {
  await page.evaluate(([fileName, mime, body]) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([body], fileName, { type: mime }));
    const canvas = document.getElementById('gaitlab-canvas');
    for (const kind of ['dragenter', 'dragover', 'drop']) {
      canvas.dispatchEvent(new DragEvent(kind, { dataTransfer: transfer, bubbles: true, cancelable: true }));
    }
  }, [name, type, text]);
}

/** The app's last_error once it has one (links are read before the first frame). */
async function lastError(page) {
  return (await state(page)).last_error ?? '';
}

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

describe('full-state links (WebGL2 path)', () => {
  let first; // the browser that makes the link
  let second; // a fresh browser context (its own profile) that opens it
  before(async () => {
    first = await launch('webgl2');
    second = await launch('webgl2');
  });
  after(async () => {
    await first?.close();
    await second?.close();
  });

  it('a copied link restores state() field by field in a fresh context', T, async () => {
    const a = await loadApp(first, server.url);
    let original;
    let link;
    try {
      assert.equal(await command(a.page, { preset: 'hexapod' }), 'ok');
      assert.equal((await state(a.page)).preset, 'hexapod');
      // An edited preset through the editor: the IK quadruped renamed, one limb lengthened.
      const edited = presetJson('ik-quadruped').replace('"name": "ik-quadruped"', '"name": "quad-edited"');
      assert.notEqual(edited, presetJson('ik-quadruped'));
      assert.equal(await command(a.page, { editor_open: true, editor_text: edited, editor_apply: true }), 'ok');
      for (const c of [
        { mode: 'wounded-run', method: 'dls', lambda: 0.21, max_step: 0.15 },
        { views: { follow: false, grid: false, world_axes: true } },
        { camera: { yaw_deg: -35, pitch_deg: 20, distance_m: 4.25, target_m: [0.3, 0.5, 1.25] } },
        { heading_deg: 15, plots: false },
        { compare: { views: ['pinv', 'dls'], scenario: 'singularity', options: [{}, { lambda: 0.3 }] } },
      ]) assert.equal(await command(a.page, c), 'ok', JSON.stringify(c));
      assert.ok(await frameExceeds(a.page, 5), 'the app runs');
      assert.equal(await command(a.page, { paused: true }), 'ok');
      original = await state(a.page);
      assert.equal(original.preset, 'quad-edited');
      assert.equal(original.custom_preset, true);
      assert.equal(original.ik.lambda, 0.21);
      assert.equal(original.view_options.grid, false);
      assert.deepEqual(original.compare.views, ['pinv', 'dls']);
      assert.equal(original.compare.options[1].lambda, 0.3);
      link = await a.page.evaluate(() => window.gaitlab.link());
      assert.ok(link.startsWith(`${server.url}#p=`), link.slice(0, 80));
      console.log(`link: ${link.length} characters`);
      a.assertClean();
    } finally {
      await a.page.close().catch(() => {});
    }

    const b = await loadApp(second, link);
    try {
      const restored = await state(b.page);
      assert.equal(restored.last_error, null);
      const want = settled(original);
      const got = settled(restored);
      for (const key of Object.keys(want)) assert.deepEqual(got[key], want[key], `state().${key}`);
      assert.deepEqual(Object.keys(got).sort(), Object.keys(want).sort());
      // The same link again from the restored app.
      assert.equal(await b.page.evaluate(() => window.gaitlab.link()), link);
      assertDrawn(await shootCanvas(b.page, 'link-restored'), 'restored link');
      b.assertClean();
    } finally {
      await b.page.close().catch(() => {});
    }
  });

  it('a lesson link opens with its note first, its panels hidden, the Jacobian panel named and its pinned pose', T, async () => {
    const a = await loadApp(first, server.url);
    let link;
    const lesson = {
      note: 'Watch the hands: where a target is out of reach, which method shakes?',
      hide_panels: ['Method', 'Recording', 'View'],
      pin_plots: ['errors'],
      open_panels: ['Jacobian'],
    };
    const pins = { right_foot: [-0.1, -0.75, 0.25] };
    try {
      assert.equal(await command(a.page, {
        preset: 'she-2006', pinned_targets: pins, views: { reach_shells: true, ellipsoids: true }, lesson,
      }), 'ok');
      const s = await state(a.page);
      assert.deepEqual(s.lesson, lesson);
      assert.deepEqual(s.pinned_targets, pins);
      link = await a.page.evaluate(() => window.gaitlab.link());
      a.assertClean();
    } finally {
      await a.page.close().catch(() => {});
    }
    const b = await loadApp(second, link);
    try {
      assert.ok(await frameExceeds(b.page, 3), 'the app runs');
      const s = await state(b.page);
      assert.equal(s.last_error, null);
      assert.deepEqual(s.lesson, lesson);
      assert.deepEqual(s.pinned_targets, pins, 'the pinned pose');
      assert.equal(s.view_options.reach_shells, true);
      assert.equal(s.view_options.ellipsoids, true);
      assert.equal(s.layout.lesson_note_open, true, 'the note shows first');
      for (const title of lesson.hide_panels) assert.ok(!s.layout.panels_shown.includes(title), `${title} hidden`);
      for (const title of ['Motion', 'Lesson', 'Share']) assert.ok(s.layout.panels_shown.includes(title), `${title} shown`);
      const shot = await shootCanvas(b.page, 'lesson-link.png');
      assertDrawn(shot, 'lesson link');
      console.log(`# lesson link: ${link.length} characters; note open, panels shown: ${s.layout.panels_shown.join(', ')} (see ${shot.file})`);
      assert.equal(await command(b.page, { lesson_note_open: false }), 'ok');
      assert.equal((await state(b.page)).layout.lesson_note_open, false);
      b.assertClean();
    } finally {
      await b.page.close().catch(() => {});
    }
  });

  it('broken links leave the app running with a message and the default preset', T, async () => {
    const a = await loadApp(first, server.url);
    let payload;
    try {
      assert.equal(await command(a.page, { preset: 'hexapod', method: 'pinv' }), 'ok');
      const link = await a.page.evaluate(() => window.gaitlab.link());
      payload = link.slice(link.indexOf('#p=') + 3);
    } finally {
      await a.page.close().catch(() => {});
    }
    const flip = (text, at) => text.slice(0, at) + (text[at] === 'Q' ? 'w' : 'Q') + text.slice(at + 1);
    const cases = [
      ['flipped bytes', flip(flip(flip(payload, 4), 5), 6), /link: /],
      ['truncated', payload.slice(0, Math.floor(payload.length / 2)), /link: #p=/],
      ['10 MB', 'A'.repeat(10 * 1024 * 1024), /link: #p= is longer than 128 KiB/],
    ];
    for (const [what, broken, message] of cases) {
      const p = await second.open();
      try {
        if (broken.length > 1_000_000) {
          // Chromium refuses to navigate to URLs over 2 MB: load the app, then put the fragment in
          // the address bar as a script would (a same-document navigation the app follows).
          await p.page.goto(server.url, { waitUntil: 'load' });
          await p.page.waitForFunction(() => typeof window.gaitlab?.state === 'function', null, { timeout: 60_000 });
          assert.equal(await command(p.page, { preset: 'hexapod' }), 'ok');
          await p.page.evaluate((h) => { window.location.hash = h; }, `p=${broken}`);
          await p.page.waitForFunction(() => (JSON.parse(window.gaitlab.state()).last_error ?? '').includes('link'),
            null, { timeout: 30_000, polling: 100 });
        } else {
          await p.page.goto(`${server.url}#p=${broken}`, { waitUntil: 'load' });
          await p.page.waitForFunction(() => typeof window.gaitlab?.state === 'function', null, { timeout: 60_000 });
        }
        const error = await lastError(p.page);
        assert.match(error, message, `${what}: ${error}`);
        const s = await state(p.page);
        assert.equal(s.preset, 'human', `${what}: the default preset`);
        assert.ok(await frameExceeds(p.page, s.frame + 3), `${what}: the app keeps running`);
        console.log(`${what}: ${error}`);
        p.assertClean();
      } finally {
        await p.page.close().catch(() => {});
      }
    }
  });

  it('a preset file set on the file input and one dropped on the canvas both load', T, async () => {
    const p = await loadApp(first, server.url);
    try {
      assert.equal((await state(p.page)).preset, 'human');
      await p.page.setInputFiles('#gaitlab-preset-file', {
        name: 'hexapod.json', mimeType: 'application/json', buffer: Buffer.from(presetJson('hexapod')),
      });
      await p.page.waitForFunction(() => JSON.parse(window.gaitlab.state()).preset === 'hexapod',
        null, { timeout: 30_000, polling: 100 });
      assert.equal((await state(p.page)).custom_preset, true);

      const text = presetJson('ik-quadruped');
      await dropFile(p.page, 'quadruped.json', 'application/json', text);
      await p.page.waitForFunction(() => JSON.parse(window.gaitlab.state()).preset === 'ik-quadruped',
        null, { timeout: 30_000, polling: 100 });

      // A bad file: its problem names the JSON path and the creature stays.
      await p.page.setInputFiles('#gaitlab-preset-file', {
        name: 'bad.json', mimeType: 'application/json',
        buffer: Buffer.from(presetJson('human').replace('"axis": [1, 0, 0]', '"axis": [0, 0, 0]')),
      });
      await p.page.waitForFunction(() => (JSON.parse(window.gaitlab.state()).editor.error ?? '').includes('axis'),
        null, { timeout: 30_000, polling: 100 });
      const s = await state(p.page);
      assert.match(s.editor.error, /^file bad\.json: preset: skeleton\.joints\[0\]\.axis/);
      // As the editor shows it: the joint's name after its index, and its line.
      const root = JSON.parse(presetJson('human')).skeleton.joints[0].name;
      assert.equal(s.editor.message,
        `file bad.json: skeleton.joints[0] (${root}).axis: must be a non-zero vector`);
      const axisLine = presetJson('human').split('\n').findIndex((l) => l.includes('"axis": [1, 0, 0]')) + 1;
      assert.equal(s.editor.line, axisLine, 'the line of the bad axis');
      assert.equal(s.editor.open, true, 'the bad file opens in the editor');
      assert.equal(s.preset, 'ik-quadruped');
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });

  it('a target CSV dropped on the page is followed, alone and side by side', T, async () => {
    const p = await loadApp(first, server.url);
    try {
      assert.equal((await state(p.page)).preset, 'human');
      // The human runs She 2006's clamp-only joint limits (§6.1.1.1, `limit_passes: 1`): with them
      // the lifted foot below misses its target by up to ~67 mm in about a third of the frames (a
      // joint pinned at its limit, the others not solved again). This test is about the recording
      // being followed, not about the thesis' clamp, so it runs the lab's re-solve (clamp, then
      // solve again without the clamped joints), which reaches every target here after the first
      // frame, and keeps the tight 50 mm bound: a figure not following the recording (its own walk,
      // hands 0.8 m out to the sides) would be decimetres off the recording's targets.
      assert.equal(await command(p.page, { limit_passes: 4 }), 'ok');
      const resolve = await state(p.page);
      assert.equal(resolve.ik.limit_passes, 4);
      assert.ok(resolve.lab_additions.some((a) => a.name === 'limit_re_solve'),
        `the re-solve named as the lab's: ${JSON.stringify(resolve.lab_additions.map((a) => a.name))}`);
      // Two seconds: the feet stepping in place, the hands swinging in front (world metres).
      const rows = ['t,lf_x,lf_y,lf_z,rf_x,rf_y,rf_z,lh_x,lh_y,lh_z,rh_x,rh_y,rh_z'];
      for (let k = 0; k <= 60; k++) {
        const t = k / 30;
        const s = Math.sin(2 * Math.PI * t);
        rows.push([t, 0.1, 0.05 + 0.05 * Math.max(s, 0), 0, -0.1, 0.05 + 0.05 * Math.max(-s, 0), 0,
          0.25, 1.0, 0.15 + 0.1 * s, -0.25, 1.0, 0.15 - 0.1 * s].join(','));
      }
      const csv = rows.join('\n');
      await dropFile(p.page, 'steps.csv', 'text/csv', csv);
      await p.page.waitForFunction(() => JSON.parse(window.gaitlab.state()).track?.file === 'steps.csv',
        null, { timeout: 30_000, polling: 100 });
      let s = await state(p.page);
      assert.deepEqual(s.track, { file: 'steps.csv', rows: 61, effectors: 4, duration_s: 2 });
      assert.equal(s.last_error, null);
      await p.page.waitForFunction(() => JSON.parse(window.gaitlab.state()).time_s > 1,
        null, { timeout: 60_000, polling: 100 });
      s = await state(p.page);
      const errors = s.views[0].effectors.map((e) => e.error_m);
      console.log(`# steps.csv followed at t = ${s.time_s.toFixed(2)} s: errors ${errors.map((e) => (e * 1e3).toFixed(1)).join(', ')} mm`);
      assert.ok(errors.every((e) => Number.isFinite(e) && e < 0.05), `every target followed: ${errors}`);
      assert.ok(s.layout.panels_shown.includes('Recorded targets'), s.layout.panels_shown.join(', '));
      // Side by side on the same recording.
      assert.equal(await command(p.page, { compare: { views: ['pinv', 'dls'] } }), 'ok');
      await p.page.waitForFunction(() => JSON.parse(window.gaitlab.state()).compare.metrics[0].frame > 30,
        null, { timeout: 60_000, polling: 100 });
      s = await state(p.page);
      assert.ok(s.compare.notice[0].includes('recording'), s.compare.notice[0]);
      assert.equal(await command(p.page, { compare: false, track: false }), 'ok');
      assert.equal((await state(p.page)).track, null);
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
