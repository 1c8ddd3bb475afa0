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
});
