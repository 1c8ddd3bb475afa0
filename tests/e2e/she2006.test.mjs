// Browser test of She 2006 as written (issue 18): the she-2006 preset walking, the four thesis
// methods side by side. Each view carries the §5.3 measurements: per effector whether its target
// is within reach (feet yes, hands no, walking) and by how much it is out of reach live, and the
// oscillation and jitter of each limb. With the thesis' clamp-only joint limits (§6.1.1.1, the
// preset's `limit_passes: 1`) pinv oscillates on the unreachable hands: its figures are at least
// 1.5 × DLS's and SDLS's, and its card's oscillation figure is above theirs; with §4.4.1's α and no
// step clamp (§4.4.2 clamps pinv alone) so does the transpose's.
// Screenshots: the 4 views with their cards, and the single view whose readout names the
// out-of-reach targets.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { command, launch, loadApp, serveDist, shootCanvas, state } from './harness.mjs';

const T = { timeout: 300_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

const byName = (effectors) => Object.fromEntries(effectors.map((e) => [e.name, e]));

describe('she-2006 side by side (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('shows reachability and oscillation per method on the thesis walk', T, async () => {
    const p = await loadApp(browser, server.url);
    try {
      const { page } = p;
      assert.equal(await command(page, { preset: 'she-2006', mode: 'walk' }), 'ok');
      let s = await state(page);
      assert.equal(s.preset, 'she-2006');
      assert.equal(s.ik.limit_passes, 1, 'the thesis clamps joints at their limits');
      // The single view names the out-of-reach targets live: the hands, not the feet.
      await page.waitForFunction(() => JSON.parse(window.gaitlab.state()).frame >= 30, null, { timeout: 60_000 });
      s = await state(page);
      const single = byName(s.views[0].effectors);
      assert.ok(single.left_hand.out_of_reach_m > 0.05, `left hand beyond reach ${single.left_hand.out_of_reach_m} m`);
      assert.ok(single.right_hand.out_of_reach_m > 0.05, `right hand beyond reach ${single.right_hand.out_of_reach_m} m`);
      assert.ok(single.left_foot.out_of_reach_m < 0, `left foot inside reach ${single.left_foot.out_of_reach_m} m`);
      await shootCanvas(page, 'she-2006-walk-single.png');

      const views = ['transpose', 'pinv', 'dls', 'sdls'];
      assert.equal(await command(page, { compare: { views, scenario: 'script' } }), 'ok');
      // 10 s of simulated time.
      await page.waitForFunction(() => JSON.parse(window.gaitlab.state()).compare.metrics[0].frame >= 600,
        null, { timeout: 240_000, polling: 250 });
      s = await state(page);
      const metrics = Object.fromEntries(s.compare.metrics.map((m) => [m.method, m]));
      for (const method of views) {
        const m = metrics[method];
        const e = byName(m.effectors);
        console.log(`# she-2006 walk ${method}: oscillation ${m.oscillation_hz.toFixed(2)} Hz `
          + `(feet ${e.left_foot.oscillation_hz.toFixed(2)}, hands ${e.left_hand.oscillation_hz.toFixed(2)}), `
          + `hand jitter ${(e.left_hand.jitter_rad * 1e3).toFixed(3)} mrad/frame², `
          + `reachable feet ${(e.left_foot.reachable * 100).toFixed(0)} % hands ${(e.left_hand.reachable * 100).toFixed(0)} %, `
          + `error reachable ${(m.mean_error_reachable_m * 1e3).toFixed(2)} mm unreachable ${(m.mean_error_unreachable_m * 1e3).toFixed(1)} mm`);
        assert.ok(Number.isFinite(m.oscillation_hz) && m.oscillation_hz > 0, `${method} oscillation ${m.oscillation_hz}`);
        for (const foot of ['left_foot', 'right_foot']) {
          assert.equal(e[foot].reachable, 1, `${method} ${foot} reachable`);
          assert.ok(e[foot].out_of_reach_m < 0, `${method} ${foot} inside reach now`);
        }
        for (const hand of ['left_hand', 'right_hand']) {
          assert.equal(e[hand].reachable, 0, `${method} ${hand} reachable`);
          assert.ok(e[hand].out_of_reach_m > 0, `${method} ${hand} out of reach now`);
        }
      }
      // SDLS tracks the reachable feet best (§5.3).
      for (const method of ['transpose', 'pinv', 'dls']) {
        assert.ok(metrics.sdls.mean_error_reachable_m <= metrics[method].mean_error_reachable_m,
          `sdls ${metrics.sdls.mean_error_reachable_m} m vs ${method} ${metrics[method].mean_error_reachable_m} m`);
      }
      // pinv oscillates on the unreachable hands (§5.3): ≥ 1.5 × DLS's and SDLS's, in
      // oscillation and jitter; the card's figure (all four effectors) is above theirs.
      const hands = (method, key) => {
        const e = byName(metrics[method].effectors);
        return (e.left_hand[key] + e.right_hand[key]) / 2;
      };
      for (const other of ['dls', 'sdls']) {
        for (const key of ['oscillation_hz', 'jitter_rad']) {
          assert.ok(hands('pinv', key) >= 1.5 * hands(other, key),
            `pinv hands ${key} ${hands('pinv', key)} vs ${other} ${hands(other, key)}`);
        }
        assert.ok(metrics.pinv.oscillation_hz > metrics[other].oscillation_hz,
          `pinv card figure ${metrics.pinv.oscillation_hz} above ${other} ${metrics[other].oscillation_hz}`);
      }
      // The transpose with §4.4.1's α "looks jerky and oscillates" (§5.3) on the walking hands:
      // ≥ 1.5 × DLS's and SDLS's oscillation and jitter, with no step clamp (§4.4.2 clamps pinv alone).
      assert.equal(s.ik.clamp_every_method, false, 'the step clamp is pinv\'s alone');
      assert.equal(s.ik.transpose_alpha, 'thesis', '§4.4.1\'s α');
      for (const other of ['dls', 'sdls']) {
        for (const key of ['oscillation_hz', 'jitter_rad']) {
          assert.ok(hands('transpose', key) >= 1.5 * hands(other, key),
            `transpose hands ${key} ${hands('transpose', key)} vs ${other} ${hands(other, key)}`);
        }
      }
      assert.equal(await command(page, { paused: true }), 'ok');
      await shootCanvas(page, 'she-2006-walk-4-views.png');
      assert.deepEqual(p.problems, [], 'no console problems');
    } finally {
      await p.page.close().catch(() => {});
    }
  });

  it('names the lab\'s additions in force and runs the paper alone', T, async () => {
    const p = await loadApp(browser, server.url);
    try {
      const { page } = p;
      // The page opens human, a gaitlab-preset/2 file with none of the lab's additions: She 2006
      // §5.2.2's listing, §6.1.1.1's clamp-only limits (docs/parameters.md, "Both ways": none of
      // the additions rescues a claim the thesis makes for it). An empty list is what the readout
      // shows as "The paper alone: none of the lab's additions in force." (no "Run the paper
      // alone" button then).
      const names = (s) => s.lab_additions.map((a) => a.name);
      const opened = await state(page);
      assert.equal(opened.preset, 'human');
      assert.deepEqual(names(opened), [], 'the human runs the paper alone');
      assert.equal(opened.ik.limit_passes, 1, 'the thesis clamps joints at their limits');
      assert.equal(opened.custom_preset, false, 'as bundled');
      await shootCanvas(page, 'lab-additions-human.png');
      // ik-quadruped keeps the lab's script (the thesis' listing is a human's): it lists it, with
      // its reason, and "Run the paper alone" (the `paper_alone` command) clears it.
      assert.equal(await command(page, { preset: 'ik-quadruped' }), 'ok');
      const quadruped = await state(page);
      assert.equal(quadruped.preset, 'ik-quadruped');
      assert.deepEqual(names(quadruped), ['lab_script']);
      assert.ok(quadruped.lab_additions.every((a) => a.reason.length > 20), 'each with its reason');
      await shootCanvas(page, 'lab-additions-ik-quadruped.png');
      assert.equal(await command(page, { paper_alone: true }), 'ok');
      const alone = await state(page);
      assert.deepEqual(alone.lab_additions, [], 'the paper alone');
      assert.equal(alone.preset, 'ik-quadruped');
      assert.equal(alone.custom_preset, true, 'run as a custom preset');
      // The physics quadruped runs every gait by eq. 2 alone and changes
      // gait by the paper's take-over: none of the lab's additions.
      assert.equal(await command(page, { preset: 'raibert-quadruped' }), 'ok');
      assert.deepEqual(names(await state(page)), []);
      assert.equal(await command(page, { paper_alone: true }), 'ok');
      assert.deepEqual(names(await state(page)), []);
      p.assertClean();
    } finally {
      await p.page.close().catch(() => {});
    }
  });
});
