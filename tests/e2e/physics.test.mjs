// Browser test of the physics engine (Raibert & Hodgins 1991): a ?preset= link opens the simulated
// biped, which runs under its controller in real time; state() reports the controller's state and
// the running figures; the kangaroo hops; an absurd gain blows the simulation up, the page says why
// and keeps running; the wasm integration rate is measured through window.gaitlab.bench.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  assertDrawn, command, frameExceeds, launch, loadApp, serveDist, shootCanvas, sleep, state,
} from './harness.mjs';

const T = { timeout: 240_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

describe('physics engine (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('runs the biped from a link, hops the kangaroo and survives an absurd gain', T, async () => {
    const p = await loadApp(browser, `${server.url}?preset=raibert-biped`);
    try {
      const { page } = p;
      let s = await state(page);
      assert.equal(s.preset, 'raibert-biped');
      assert.equal(s.engine, 'physics');
      assert.equal(s.gait, 'run');
      assert.ok(await frameExceeds(page, s.frame + 120, 90_000), 'the biped runs');
      s = await state(page);
      assert.equal(s.physics.fell, false);
      assert.ok(s.physics.height_m > 0.5, `trunk at ${s.physics.height_m} m`);
      assert.ok(s.physics.steps > 1000, `${s.physics.steps} integration steps`);
      assert.ok(['flight', 'loading', 'compression', 'thrust', 'unloading'].includes(s.physics.phase), s.physics.phase);
      assert.equal(s.last_error, null);

      await command(page, { paused: true });
      await sleep(300);
      assertDrawn(await shootCanvas(page, 'physics-biped-run.png'), 'physics biped');
      await command(page, { paused: false });

      // Physics in the browser: integration steps per second of the biped with contact.
      const bench = JSON.parse(await page.evaluate(() => window.gaitlab.bench(JSON.stringify(
        { preset: 'raibert-biped', repeats: 5 }))));
      assert.equal(bench.engine, 'physics');
      assert.ok(bench.steps_per_second > 2500, `${bench.steps_per_second} steps/s cannot keep real time`);
      console.log(`# physics biped in the browser: ${Math.round(bench.steps_per_second)} steps/s (${bench.realtime_factor.toFixed(1)}× real time; best ${Math.round(bench.steps_per_second_best)})`);

      // An absurd gain: the guard catches the blow-up, the creature starts again, the page says why.
      assert.equal(await command(page, { gain: { name: 'leg_stiffness', value: 1e9 } }), 'ok');
      s = await state(page);
      assert.ok(await frameExceeds(page, s.frame + 60, 60_000), 'keeps animating');
      s = await state(page);
      assert.match(s.last_error ?? '', /blew up.*put back/);
      assert.equal(s.physics.resets, 1);
      assert.ok(Number.isFinite(s.physics.height_m));
      assert.match(await command(page, { gain: { name: 'leg_stiffness', value: -1 } }), /^gain\.leg_stiffness: /);

      // The kangaroo hops.
      assert.equal(await command(page, { preset: 'raibert-kangaroo' }), 'ok');
      s = await state(page);
      assert.equal(s.gait, 'hop');
      assert.ok(await frameExceeds(page, s.frame + 120, 90_000), 'the kangaroo hops');
      s = await state(page);
      assert.equal(s.physics.fell, false);
      await command(page, { paused: true });
      await sleep(300);
      assertDrawn(await shootCanvas(page, 'physics-kangaroo-hop.png'), 'physics kangaroo');
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });

  // The paper's inputs (Figure 2: "the path along which to travel, and any event information, such as
  // when and how high to jump"; Table 1's scale L), through the commands the panel's controls share.
  it('the kangaroo jumps a box put ahead, the biped follows waypoints, L = 2 slows its steps by √2', T, async () => {
    const p = await loadApp(browser, `${server.url}?preset=raibert-kangaroo`);
    try {
      const { page } = p;
      const phys = async () => (await state(page)).physics;
      // Waits until `test(physics, arg)` holds in the page (false after `timeout` ms).
      const until = (test, arg, timeout) => page.waitForFunction(test, arg, { timeout, polling: 50 })
        .then(() => true, () => false);

      // It starts on its hopping cycle at the preset's 5 m/s, where it does not jump a box; its
      // speed ramp brings it to 3 m/s at 0.25 m/s² (8 s). Then a box 3 m ahead: the kangaroo's
      // jump states run, and it lands beyond the box, still up.
      assert.equal(await command(page, { speed_mps: 3 }), 'ok');
      assert.ok(await until(() => JSON.parse(window.gaitlab.state()).physics.steps > 25_000, null, 120_000), 'slowed to 3 m/s');
      let s = await phys();
      const start = s.position_m[1];
      assert.equal(await command(page, { obstacle_ahead_m: 3 }), 'ok');
      assert.ok(await until(() => JSON.parse(window.gaitlab.state()).physics.phase.startsWith('jump'), null, 60_000), 'the jump states run');
      assert.ok(await until((a) => JSON.parse(window.gaitlab.state()).physics.position_m[1] > a, start + 3 + 0.3 + 1.0, 60_000), 'past the box');
      s = await phys();
      assert.equal(s.fell, false);
      assert.equal(s.resets, 0);
      assert.match(await command(page, { obstacle_ahead_m: 50 }), /^obstacle_ahead_m: /);

      // The biped at L = 1: its stride; then waypoints 8 m ahead and 8 m to the left of that.
      assert.equal(await command(page, { preset: 'raibert-biped' }), 'ok');
      assert.ok(await until((a) => { const s = JSON.parse(window.gaitlab.state()).physics; return s.stride_duration_s > 0 && s.steps > a; }, 6 * 2500, 60_000), 'strides at L = 1');
      const stride1 = (await phys()).stride_duration_s;
      assert.equal(await command(page, { waypoints: [[0, 8], [-8, 8]] }), 'ok');
      assert.ok(await until(() => JSON.parse(window.gaitlab.state()).physics.waypoint >= 1, null, 60_000), 'reached the first waypoint');
      assert.ok(await until(() => JSON.parse(window.gaitlab.state()).physics.waypoint >= 2, null, 60_000), 'reached the second waypoint');
      s = await phys();
      assert.ok(s.position_m[0] < -5, `turned left toward x = -8: at ${s.position_m}`);
      assert.equal(s.resets, 0);
      assert.match(await command(page, { waypoints: [[0, 1e6]] }), /^waypoints\[0\]: /);

      // L = 2 from the slider's command: the creature starts again twice as large; steps take √2 as long.
      assert.equal(await command(page, { physics_scale: 2 }), 'ok');
      s = await phys();
      assert.equal(s.scale, 2);
      assert.ok(await until((a) => { const s = JSON.parse(window.gaitlab.state()).physics; return s.stride_duration_s > 0 && s.steps > a; }, 10 * 1770, 90_000), 'strides at L = 2');
      const stride2 = (await phys()).stride_duration_s;
      const ratio = stride2 / stride1;
      console.log(`# biped stride ${stride1.toFixed(3)} s at L = 1, ${stride2.toFixed(3)} s at L = 2: × ${ratio.toFixed(3)} (√2 = 1.414)`);
      assert.ok(Math.abs(ratio / Math.SQRT2 - 1) < 0.05, `stride × ${ratio}`);
      assert.equal((await phys()).fell, false);
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
