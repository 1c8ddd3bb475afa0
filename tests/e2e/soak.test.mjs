// The long run of issue 3's acceptance: for GAITLAB_SOAK_S seconds (default 120) the app cycles
// every IK preset × mode × method, then every PODA creature × gait, then every physics creature ×
// gait, while animating; it must stay silent on the console, keep animating, apply every switch, keep
// every effector error finite, keep PODA's planted feet from slipping and keep the simulated
// creatures finite and up.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { command, frameExceeds, launch, loadApp, saveArtifact, serveDist, state } from './harness.mjs';

const SOAK_S = Number(process.env.GAITLAB_SOAK_S ?? 120);
const PRESETS = ['human', 'ik-quadruped'];
const MODES = ['walk', 'run', 'wounded-walk', 'wounded-run'];
const METHODS = ['transpose', 'pinv', 'dls', 'sdls'];
const PODA_GAITS = {
  'poda-quadruped': ['walk', 'trot', 'pace', 'canter', 'transverse_gallop', 'rotary_gallop', 'bound', 'pronk'],
  'poda-biped': ['walk', 'run'],
  hexapod: ['tripod', 'ripple', 'wave'],
  'insect-14': ['wave'],
};
const PHYSICS_GAITS = {
  'raibert-biped': ['run', 'gallop', 'gallop_alternate'],
  'raibert-quadruped': ['trot', 'bound', 'gallop'],
  'raibert-kangaroo': ['hop'],
};

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

describe(`soak: ${SOAK_S} s cycling every preset, mode and method (WebGL2)`, () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('stays clean and keeps animating', { timeout: (SOAK_S + 180) * 1000 }, async () => {
    const p = await loadApp(browser, server.url);
    try {
      const combos = [
        ...PRESETS.flatMap((preset) => MODES.flatMap((mode) => METHODS.map((method) => ({ preset, mode, method })))),
        ...Object.entries(PODA_GAITS).flatMap(([preset, gaits]) => gaits.map((gait) => ({ preset, gait }))),
        ...Object.entries(PHYSICS_GAITS).flatMap(([preset, gaits]) => gaits.map((gait) => ({ preset, gait }))),
      ];
      const slotMs = (SOAK_S * 1000) / combos.length;
      const started = Date.now();
      const log = [];
      let preset = '';
      for (const [i, combo] of combos.entries()) {
        // Switching preset restarts the figure; mode, method and gait switch live, mid-stride.
        const { preset: _, ...live } = combo;
        // Physics creatures start each gait afresh (a live change is tested in lab_physics.rs).
        const change = combo.preset === preset && !combo.preset.startsWith('raibert-') ? live : combo;
        preset = combo.preset;
        const answer = await command(p.page, change);
        assert.equal(answer, 'ok', `command(${JSON.stringify(combo)}) → ${answer}`);
        const s0 = await state(p.page);
        const physics = combo.preset.startsWith('raibert-');
        if (combo.gait) assert.deepEqual([s0.engine, s0.preset, s0.gait], [physics ? 'physics' : 'poda', combo.preset, combo.gait]);
        else assert.deepEqual([s0.preset, s0.mode, s0.method], [combo.preset, combo.mode, combo.method]);
        assert.ok(await frameExceeds(p.page, s0.frame + 2, 30_000),
          `${JSON.stringify(combo)}: the animation advances (stuck at frame ${s0.frame})`);
        const until = started + (i + 1) * slotMs;
        while (Date.now() < until) await new Promise((ok) => setTimeout(ok, Math.min(500, until - Date.now())));
        const s = await state(p.page);
        assert.equal(s.last_error, null, `${JSON.stringify(combo)}: ${s.last_error}`);
        if (physics) {
          assert.ok(Number.isFinite(s.physics.height_m) && s.physics.height_m > 0.1, `${JSON.stringify(combo)}: trunk at ${s.physics.height_m} m`);
          assert.equal(s.physics.fell, false, `${JSON.stringify(combo)}: fell`);
          log.push({ ...combo, frame: s.frame, phase: s.physics.phase, fps: s.fps, sim_us_per_frame: s.sim_us_per_frame });
          continue;
        }
        const errors = s.views[0].effectors.map((e) => e.error_m);
        assert.ok(errors.every((e) => Number.isFinite(e)), `${JSON.stringify(combo)}: effector errors ${errors}`);
        if (combo.gait) {
          assert.ok(s.poda.foot_slip_max_m <= 0.001, `${JSON.stringify(combo)}: foot slip ${s.poda.foot_slip_max_m} m`);
        }
        log.push({ ...combo, frame: s.frame, foot_slip_max_m: s.poda?.foot_slip_max_m, fps: s.fps, sim_us_per_frame: s.sim_us_per_frame,
          max_error_mm: Math.max(...errors) * 1e3 });
      }
      const elapsed = (Date.now() - started) / 1000;
      saveArtifact('soak.json', Buffer.from(JSON.stringify({ seconds: elapsed, combos: log }, null, 1)));
      assert.ok(elapsed >= SOAK_S, `ran ${elapsed.toFixed(1)} s`);
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
