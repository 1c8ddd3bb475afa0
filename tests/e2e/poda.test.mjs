// Browser test of the PODA engine (Girard & Maciejewski 1985): switch to the PODA quadruped, trot,
// then gallop through window.gaitlab.command; state() reflects each step, the figure keeps walking
// without foot slip, the view is drawn, and nothing reaches the console.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  assertDrawn, command, frameExceeds, launch, loadApp, serveDist, shootCanvas, sleep, state,
} from './harness.mjs';

const T = { timeout: 240_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

describe('PODA engine (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('switches to the PODA quadruped, trots, then gallops', T, async () => {
    const p = await loadApp(browser, server.url);
    try {
      const { page } = p;
      assert.equal(await command(page, { engine: 'poda' }), 'ok');
      let s = await state(page);
      assert.equal(s.engine, 'poda');
      assert.equal(s.preset, 'poda-biped');
      assert.equal(await command(page, { preset: 'poda-quadruped', gait: 'trot' }), 'ok');
      s = await state(page);
      assert.equal(s.preset, 'poda-quadruped');
      assert.equal(s.engine, 'poda');
      assert.equal(s.gait, 'trot');
      assert.equal(s.joints, 63);
      assert.deepEqual(s.poda.legs, ['left_front', 'right_front', 'left_hind', 'right_hind']);
      assert.ok(await frameExceeds(page, s.frame + 30, 60_000), 'the trot animates');

      assert.equal(await command(page, { gait: 'transverse_gallop' }), 'ok');
      s = await state(page);
      assert.equal(s.gait, 'transverse_gallop');
      assert.ok(await frameExceeds(page, s.frame + 60, 90_000), 'the gallop animates');
      s = await state(page);
      assert.equal(s.engine, 'poda');
      assert.ok(s.poda.foot_slip_max_m <= 0.001, `foot slip ${s.poda.foot_slip_max_m} m`);
      assert.ok(Math.abs(s.poda.support_s - s.poda.duty_factor * s.poda.period_s) < 1e-9, 'duty = support / P');
      assert.equal(s.last_error, null);

      // A gait the creature does not have is refused with the key named.
      assert.match(await command(page, { gait: 'tripod' }), /^gait: /);
      assert.equal((await state(page)).gait, 'transverse_gallop');

      // The 63-joint animal's frame (gait + IK of every leg) through the JS API.
      const bench = JSON.parse(await page.evaluate(() => window.gaitlab.bench(JSON.stringify(
        { preset: 'poda-quadruped', frames: 300, repeats: 3 }))));
      assert.equal(bench.engine, 'poda');
      assert.ok(bench.us_per_frame > 0 && bench.us_per_frame < 16_000, `µs per frame ${bench.us_per_frame}`);
      console.log(`# PODA quadruped in the browser: ${bench.us_per_frame.toFixed(1)} µs per frame (best ${bench.us_per_frame_best.toFixed(1)})`);

      await command(page, { paused: true });
      await sleep(500);
      assertDrawn(await shootCanvas(page, 'poda-quadruped-gallop.png'), 'PODA quadruped');
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
