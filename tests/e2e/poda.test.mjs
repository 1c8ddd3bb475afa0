// Browser test of the PODA engine (Girard & Maciejewski 1985): switch to the PODA quadruped, trot,
// then gallop through window.gaitlab.command; state() reflects each step, the figure keeps walking
// without foot slip, the view is drawn, and nothing reaches the console; a six-legged wave at duty
// 0.46 is flagged statically unstable and at 0.83 it is not (issue 21 item 3).

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

  it('warns when a six-legged wave at duty 0.46 is statically unstable, and not at 0.83', T, async () => {
    const p = await loadApp(browser, `${server.url}?preset=hexapod`);
    try {
      const { page } = p;
      // Paused, stepped by frames: the same motion however fast the machine is.
      const walk = async (duty) => {
        assert.equal(await command(page, { paused: true, gait: 'wave', duty_factor: duty }), 'ok');
        assert.equal(await command(page, { reset: true }), 'ok');
        // 8 s at 60 fps; the steps queue and run one a frame.
        for (let k = 0; k < 480; k++) assert.equal(await command(page, { step: true }), 'ok');
        await page.waitForFunction(() => JSON.parse(window.gaitlab.state()).frame >= 480, null,
          { timeout: 120_000, polling: 100 });
        return (await state(page)).poda;
      };
      const slow = await walk(0.83);
      assert.equal(slow.duty_factor, 0.83);
      assert.equal(slow.stability_warning, false, `no warning at 0.83: ${JSON.stringify(slow)}`);
      assert.equal(slow.unstable_share, 0);
      assert.ok(slow.feet_down >= 4, `feet down ${slow.feet_down}`);
      const fast = await walk(0.46);
      assert.equal(fast.stability_warning, true, `a warning at 0.46: unstable ${fast.unstable_share}`);
      assert.ok(fast.unstable_share > 0.2, `unstable share ${fast.unstable_share}`);
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
