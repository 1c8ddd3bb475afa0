// Browser tests of issue 6 "Export": a BVH (and CSV) downloaded from the page equals, byte for byte,
// the file `gaitlab run` writes for the same state — the human (engine ik), a PODA quadruped and a
// physics biped — and the BVH imports in an independent reader, three.js's BVHLoader
// (three/examples/jsm/loaders/BVHLoader.js, npm `three`), with the right bone and frame counts;
// "the last N seconds" gives the same file as `gaitlab run --last N`; and a WebM recording of 5 s of
// wall time in headless Chromium has bytes and a duration of about 5 s.
//
// The deterministic path: in the page pause, reset, start a take, step exactly K frames (the `step`
// command), save; the CLI runs the same preset / mode / method for K frames at the preset's fps.
// The CLI is run with `cargo run -q -p gaitlab-cli` from the repository root (the debug build
// `cargo test --workspace` makes; CARGO_TARGET_DIR is honoured when set).

import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { BVHLoader } from 'three/examples/jsm/loaders/BVHLoader.js';
import {
  command, launch, loadApp, repoRoot, saveArtifact, serveDist, state, withLoadedApp,
} from './harness.mjs';

const T = { timeout: 600_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

const withApp = (browser, fn) => withLoadedApp(browser, server.url, fn);

/** Sends `cmd` and resolves to the download it triggers (its name and bytes). */
async function downloadFrom(page, cmd, timeout = 60_000) {
  const pending = page.waitForEvent('download', { timeout });
  assert.equal(await command(page, cmd), 'ok', `command(${JSON.stringify(cmd)})`);
  const download = await pending;
  return { name: download.suggestedFilename(), bytes: readFileSync(await download.path()) };
}

const scratch = mkdtempSync(join(tmpdir(), 'gaitlab-export-'));

/** `gaitlab run ARGS --bvh F --csv F` through cargo; resolves to the two files' bytes. */
function cliFiles(tag, args) {
  const bvh = join(scratch, `${tag}.bvh`);
  const csv = join(scratch, `${tag}.csv`);
  const run = spawnSync('cargo', ['run', '-q', '-p', 'gaitlab-cli', '--', 'run', ...args, '--bvh', bvh, '--csv', csv],
    { cwd: repoRoot, encoding: 'utf8', timeout: 540_000 });
  assert.equal(run.status, 0, `gaitlab run ${args.join(' ')}: ${run.error ?? ''}${run.stderr}`);
  return { bvh: readFileSync(bvh), csv: readFileSync(csv) };
}

/** In the page: `setup`, then pause, reset, record, step exactly `frames` frames; the take's BVH and CSV. */
async function pageFiles(page, setup, frames, lastS = null) {
  assert.equal(await command(page, setup), 'ok', `setup ${JSON.stringify(setup)}`);
  assert.equal(await command(page, { paused: true, reset: true, record: true }), 'ok');
  for (let k = 0; k < frames; k++) assert.equal(await command(page, { step: true }), 'ok');
  await page.waitForFunction((n) => JSON.parse(window.gaitlab.state()).recording.frames >= n, frames,
    { timeout: 60_000, polling: 50 });
  const s = await state(page);
  assert.equal(s.recording.frames, frames, 'the take holds exactly the stepped frames');
  assert.equal(s.frame, frames, 'the animation advanced exactly the stepped frames');
  const bvh = await downloadFrom(page, { save: { format: 'bvh', last_s: lastS } });
  const csv = await downloadFrom(page, { save: { format: 'csv', last_s: lastS } });
  return { bvh: bvh.bytes, csv: csv.bytes, state: s };
}

/** Where two texts first differ, for a readable failure. */
function firstDifference(a, b) {
  const la = a.toString('utf8').split('\n');
  const lb = b.toString('utf8').split('\n');
  const line = la.findIndex((l, i) => l !== lb[i]);
  if (line < 0) return `same lines, ${a.length} vs ${b.length} bytes`;
  return `line ${line + 1} of ${la.length} vs ${lb.length}:\n  page ${la[line]?.slice(0, 200)}\n  cli  ${lb[line]?.slice(0, 200)}`;
}

/** The preset's animation rate, frames per second (the page steps at it; the CLI defaults to it). */
function presetFps(presetName) {
  return JSON.parse(readFileSync(join(repoRoot, 'presets', `${presetName}.json`), 'utf8')).scenario.fps;
}

/**
 * What three.js's BVHLoader should build from a preset's skeleton: one bone for the ROOT, one per
 * joint, and one per End Site (the writer gives every leaf joint an End Site).
 */
function expectedBones(presetName) {
  const preset = JSON.parse(readFileSync(join(repoRoot, 'presets', `${presetName}.json`), 'utf8'));
  const joints = preset.skeleton.joints;
  const parents = new Set(joints.map((j) => j.parent).filter((p) => p != null));
  const leaves = joints.filter((j) => !parents.has(j.name)).length;
  return { joints: joints.length, bones: 1 + joints.length + leaves, endSites: leaves };
}

const CASES = [
  { preset: 'human', engine: 'ik', setup: { preset: 'human', mode: 'run', method: 'dls' },
    args: ['human', '--mode', 'run', '--method', 'dls'], frames: 120 },
  { preset: 'poda-quadruped', engine: 'poda', setup: { preset: 'poda-quadruped' },
    args: ['poda-quadruped'], frames: 90 },
  { preset: 'raibert-biped', engine: 'physics', setup: { preset: 'raibert-biped' },
    args: ['raibert-biped'], frames: 90 },
];

describe('export: browser files equal the CLI files; three.js BVHLoader reads them (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  for (const c of CASES) {
    it(`${c.preset} (engine ${c.engine}): page BVH and CSV of ${c.frames} frames == gaitlab run's`, T, async () => {
      await withApp(browser, async ({ page }) => {
        const fromPage = await pageFiles(page, c.setup, c.frames);
        assert.equal(fromPage.state.engine, c.engine);
        const fps = presetFps(c.preset);
        const fromCli = cliFiles(c.preset, [...c.args, '--seconds', String(c.frames / fps)]);
        saveArtifact(`export-${c.preset}-page.bvh`, fromPage.bvh);
        saveArtifact(`export-${c.preset}-cli.bvh`, fromCli.bvh);
        assert.ok(fromPage.bvh.equals(fromCli.bvh), `BVH differs: ${firstDifference(fromPage.bvh, fromCli.bvh)}`);
        assert.ok(fromPage.csv.equals(fromCli.csv), `CSV differs: ${firstDifference(fromPage.csv, fromCli.csv)}`);

        // The independent reader: three.js's BVHLoader (not gaitlab's own parser).
        const parsed = new BVHLoader().parse(fromPage.bvh.toString('utf8'));
        const expected = expectedBones(c.preset);
        assert.equal(expected.joints, fromPage.state.joints, 'the preset file and the app agree on the joints');
        assert.equal(parsed.skeleton.bones.length, expected.bones,
          `BVHLoader bones: ROOT + ${expected.joints} joints + ${expected.endSites} End Sites`);
        assert.equal(parsed.skeleton.bones.filter((b) => b.name === 'ENDSITE').length, expected.endSites);
        // One position and one quaternion track per bone with channels (not the End Sites).
        assert.equal(parsed.clip.tracks.length, 2 * (1 + expected.joints));
        for (const track of parsed.clip.tracks) {
          assert.equal(track.times.length, c.frames, `${track.name}: one key per frame`);
        }
        assert.ok(Math.abs(parsed.clip.duration - (c.frames - 1) / fps) < 1e-4,
          `clip duration ${parsed.clip.duration} s`);
      });
    });
  }

  it('the last 0.5 s of a take == gaitlab run --last 0.5', T, async () => {
    await withApp(browser, async ({ page }) => {
      const fromPage = await pageFiles(page, { preset: 'human', mode: 'walk', method: 'sdls' }, 90, 0.5);
      const fromCli = cliFiles('human-last', ['human', '--mode', 'walk', '--method', 'sdls', '--seconds', '1.5',
        '--last', '0.5']);
      assert.match(fromPage.bvh.toString('utf8'), /\nFrames: 30\n/, '0.5 s at 60 fps');
      assert.ok(fromPage.bvh.equals(fromCli.bvh), `BVH differs: ${firstDifference(fromPage.bvh, fromCli.bvh)}`);
      assert.ok(fromPage.csv.equals(fromCli.csv), `CSV differs: ${firstDifference(fromPage.csv, fromCli.csv)}`);
      const parsed = new BVHLoader().parse(fromPage.bvh.toString('utf8'));
      assert.equal(parsed.clip.tracks[0].times.length, 30);
    });
  });
});

/** The duration a <video> element finds for `bytes` (seeking far past the end makes Chromium scan a
 * MediaRecorder WebM, whose header carries no duration). */
async function videoDuration(page, bytes, type) {
  return page.evaluate(async ({ b64, type }) => {
    const data = Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0));
    const el = document.createElement('video');
    el.muted = true;
    el.preload = 'auto';
    el.src = URL.createObjectURL(new Blob([data], { type }));
    await new Promise((ok, fail) => {
      el.onloadedmetadata = ok;
      el.onerror = () => fail(new Error(`video error ${el.error?.code}`));
    });
    if (!Number.isFinite(el.duration)) {
      await new Promise((ok) => {
        el.ondurationchange = () => { if (Number.isFinite(el.duration)) ok(); };
        el.currentTime = 1e101;
      });
    }
    return el.duration;
  }, { b64: bytes.toString('base64'), type });
}

/**
 * Records the 3-D view at 640 × 360 until the app has recorded `seconds` (its clock starts at the
 * first recorded frame), stops, and resolves to the app's recorded time, the seconds from the stop
 * command to the download, the download and its bytes.
 */
async function recordTake(page, seconds) {
  assert.equal(await command(page, { plots: false }), 'ok');
  assert.equal(await command(page, { video_size: 'p360', record_video: true }), 'ok');
  await page.waitForFunction((s) => JSON.parse(window.gaitlab.state()).video.seconds >= s, seconds,
    { timeout: 120_000, polling: 20 });
  const recordedS = (await state(page)).video.seconds;
  const stopping = Date.now();
  const pending = page.waitForEvent('download', { timeout: 60_000 });
  assert.equal(await command(page, { record_video: false }), 'ok');
  const download = await pending;
  const stopWallS = (Date.now() - stopping) / 1e3;
  return { recordedS, stopWallS, download, bytes: readFileSync(await download.path()) };
}

describe('export: WebM video in headless Chromium (WebGL2, 640 × 400 window)', () => {
  let browser;
  // A small window keeps software rendering fast enough for a steady stream of frames: the
  // recording's duration runs from its first to its last copied frame.
  before(async () => { browser = await launch('webgl2', { viewport: { width: 640, height: 400 } }); });
  after(async () => { await browser?.close(); });

  it('records 5 s of the 3-D view: bytes > 0 and a duration of about 5 s', T, async () => {
    await withApp(browser, async ({ page }) => {
      const { recordedS, stopWallS, download, bytes } = await recordTake(page, 5);
      saveArtifact(`five-seconds.${download.suggestedFilename().split('.').pop()}`, bytes);
      assert.ok(bytes.length > 0, 'the video has bytes');
      const webm = download.suggestedFilename().endsWith('.webm');
      if (webm) assert.deepEqual([...bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML (WebM) header');
      const duration = await videoDuration(page, bytes, webm ? 'video/webm' : 'video/mp4');
      const { frames, encoder, skipped } = (await state(page)).video;
      console.log(`# WebM (${encoder}): ${bytes.length} bytes, ${frames} frames, ${skipped} skipped, ` +
        `duration ${duration.toFixed(3)} s; ${recordedS.toFixed(3)} s recorded when stopped, ` +
        `file ${stopWallS.toFixed(3)} s later`);
      // Nothing lost at either end: the file lasts at least the time recorded (a hold frame is
      // written on stopping, however few frames a starved machine rendered; CI once saw 12 frames
      // and a MediaRecorder file 1.5 s short), and at most that plus the time stopping took and
      // the last frame's 0.1 s.
      assert.equal(encoder, 'webcodecs-vp9', 'Chromium encodes through WebCodecs');
      assert.ok(duration >= recordedS - 0.05, `duration ${duration} s, shorter than the ${recordedS} s recorded`);
      assert.ok(duration <= recordedS + stopWallS + 0.15,
        `duration ${duration} s, longer than ${recordedS} s recorded + ${stopWallS} s stopping`);
    });
  });

  it('without WebCodecs, MediaRecorder records the view: a WebM that plays for about as long', T, async () => {
    const p = await loadApp(browser, server.url, { init: () => { delete window.VideoEncoder; } });
    try {
      const { page } = p;
      const { recordedS, stopWallS, download, bytes } = await recordTake(page, 3);
      assert.match(download.suggestedFilename(), /\.webm$/);
      assert.deepEqual([...bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML (WebM) header');
      const duration = await videoDuration(page, bytes, 'video/webm');
      const { encoder, frames } = (await state(page)).video;
      console.log(`# fallback (${encoder}): ${bytes.length} bytes, ${frames} frames, duration ` +
        `${duration.toFixed(3)} s; ${recordedS.toFixed(3)} s recorded, file ${stopWallS.toFixed(3)} s later`);
      assert.equal(encoder, 'mediarecorder');
      // MediaRecorder may drop frames while its encoder starts and when it stops; the file still
      // has to play for most of the take and not beyond it.
      assert.ok(duration > 1 && duration <= recordedS + stopWallS + 0.2,
        `duration ${duration} s for ${recordedS} s recorded`);
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
