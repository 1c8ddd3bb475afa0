// Browser test of ground that is not flat (issue 45 item 4), at 1440 × 900 and in the phone layout
// at 390 × 844: the Terrain panel's Stairs button (opened and clicked with the mouse, the panel
// scrolled into the window) builds a flight of stairs under the hexapod; the page draws it
// (state().terrain: stairs, its triangles drawn); the hexapod climbs it — the ground under its body
// rises to the top tread, its feet never slip and the camera keeps it framed — and a copied link
// reopens the same ground in a fresh browser. Screenshots: artifacts terrain-wide.png and
// terrain-phone.png. Run after ./build.sh: `cd tests/e2e && node --test terrain.test.mjs`.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  assertDrawn, command, launch, loadApp, serveDist, shootCanvas, sleep, state, until,
} from './harness.mjs';

const T = { timeout: 300_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

const centre = ([x, y, w, h]) => [x + w / 2, y + h / 2];

/** state() once two polls 300 ms apart agree on the widgets' places (a panel settles its layout). */
async function settled(page) {
  let s = await state(page);
  for (let k = 0; k < 10; k++) {
    await sleep(300);
    const again = await state(page);
    const same = JSON.stringify(again.layout.widgets_pt) === JSON.stringify(s.layout.widgets_pt);
    s = again;
    if (same) break;
  }
  return s;
}

/**
 * Clicks at `where(state())` until `pred(state())` holds, up to three times: on a starved machine
 * a click's press and release can fall in frames too far apart for egui to count it.
 */
async function clickUntil(page, where, pred, what) {
  for (let k = 1; ; k++) {
    const s = await settled(page);
    if (pred(s)) return s;
    await page.mouse.click(...where(s), { delay: 60 });
    try {
      return await until(page, pred, what, k < 3 ? 8_000 : 20_000, 150,
        (st) => JSON.stringify(st.layout.widgets_pt));
    } catch (e) {
      if (k >= 3) throw e;
    }
  }
}

/** Wheels the controls until rectangle `rectOf(state())` lies in the window. */
async function scrollTo(page, rectOf, what) {
  const height = await page.evaluate(() => innerHeight);
  let s = await settled(page);
  for (let k = 0; k < 30; k++) {
    const [x, y, w, h] = rectOf(s);
    if (w > 0 && y >= 0 && y + h <= height - 4) return s;
    // Over the controls (the header's own column), in the window.
    const [hx] = centre(s.layout.widgets_pt.terrain_header);
    await page.mouse.move(hx, Math.min(Math.max(y, 200), height - 80));
    await page.mouse.wheel(0, y < 0 ? -150 : 150);
    s = await settled(page);
  }
  throw new Error(`${what} never came into the window: ${JSON.stringify(rectOf(s))}`);
}

/** Opens the Terrain panel and clicks Stairs; returns the state with the stairs built. */
async function buildStairs(page, narrow) {
  let s = await settled(page);
  if (narrow) {
    assert.ok(s.layout.narrow, 'the phone layout');
    s = await clickUntil(page, (st) => centre(st.layout.controls_button_pt),
      (st) => st.layout.controls_open && st.layout.widgets_pt.terrain_header[2] > 0, 'the controls drawer');
  }
  assert.ok(s.layout.panels_shown.includes('Terrain'), JSON.stringify(s.layout.panels_shown));
  s = await scrollTo(page, (st) => st.layout.widgets_pt.terrain_header, 'the Terrain header');
  s = await clickUntil(page, (st) => centre(st.layout.widgets_pt.terrain_header),
    (st) => st.layout.widgets_pt.terrain_stairs[2] > 0, 'the Terrain panel to open');
  s = await scrollTo(page, (st) => st.layout.widgets_pt.terrain_stairs, 'the Stairs button');
  return clickUntil(page, (st) => centre(st.layout.widgets_pt.terrain_stairs),
    (st) => st.terrain.kind === 'stairs', 'stairs from the panel');
}

for (const [label, viewport, narrow] of [
  ['wide', { width: 1440, height: 900 }, false],
  ['phone', { width: 390, height: 844 }, true],
]) {
  describe(`terrain panel, ${viewport.width} × ${viewport.height} (WebGL2)`, () => {
    let browser;
    let second;
    before(async () => {
      browser = await launch('webgl2', { viewport });
      second = await launch('webgl2', { viewport });
    });
    after(async () => {
      await browser?.close();
      await second?.close();
    });

    it('builds stairs, the hexapod climbs them, a link reopens the same ground', T, async () => {
      const a = await loadApp(browser, `${server.url}?preset=hexapod`);
      let link;
      let spec;
      try {
        const { page } = a;
        let s = await buildStairs(page, narrow);
        spec = s.terrain.spec;
        console.log(`# ${label}: ${JSON.stringify(spec)}, ${s.terrain.triangles_drawn} triangles drawn`);
        // The panel's stairs: five 5 cm steps of 0.3 m treads toward +z, the first riser 0.5 m ahead.
        assert.deepEqual(spec, { kind: 'stairs', rise_m: 0.05, run_m: 0.3, count: 5, direction_deg: 90, start_m: 0.5 });
        assert.equal(s.terrain.triangles_drawn, 2 * (1 + 2 * 5), 'the floor, and a riser and a tread per step');
        assert.equal(s.custom_preset, true, 'the preset carries its ground');
        assert.equal(s.last_error, null);
        // Climb at twice real time; the top tread starts 1.7 m ahead.
        assert.equal(await command(page, { playback_rate: 2, paused: false }), 'ok');
        s = await until(page, (st) => st.terrain.ground_under_root_m >= 0.249, 'the hexapod on the top tread',
          150_000, 500, (st) => `t = ${st.time_s}, root ${st.terrain.root_m}, ground ${st.terrain.ground_under_root_m}`);
        console.log(`# ${label}: on the top tread at t = ${s.time_s.toFixed(1)} s, root ${s.terrain.root_m.map((v) => v.toFixed(3))}, `
          + `footholds moved ${s.terrain.footholds_moved}, slip ${(s.poda.foot_slip_max_m * 1e3).toFixed(2)} mm`);
        assert.ok(s.poda.foot_slip_max_m <= 0.001, `foot slip ${s.poda.foot_slip_max_m} m`);
        assert.ok(s.terrain.footholds_moved > 0, 'footholds moved off the risers\' edges');
        assert.ok(s.terrain.root_m[1] - s.terrain.ground_under_root_m > 0.05, 'the body stands above the tread');
        assert.equal(await command(page, { paused: true }), 'ok');
        if (narrow) {
          // Close the drawer: the view takes the screen again.
          await clickUntil(page, (st) => centre(st.layout.controls_button_pt),
            (st) => !st.layout.controls_open, 'the drawer to close');
        }
        await sleep(600);
        s = await state(page);
        // The camera kept the climbing hexapod in the view.
        assert.ok(s.layout.figure_pt, 'the figure is on screen');
        const [fx, fy, fw, fh] = s.layout.figure_pt;
        const [vx, vy, vw, vh] = s.layout.view_pt;
        assert.ok(fx >= vx - 1 && fy >= vy - 1 && fx + fw <= vx + vw + 1 && fy + fh <= vy + vh + 1,
          `the figure ${s.layout.figure_pt} inside the view ${s.layout.view_pt}`);
        // From the side and behind, the flight it came up shows.
        assert.equal(await command(page, { camera: { yaw_deg: 140, pitch_deg: 22 } }), 'ok');
        await sleep(800);
        assertDrawn(await shootCanvas(page, `terrain-${label}.png`), `${label} stairs`);
        link = await page.evaluate(() => window.gaitlab.link());
        a.assertClean();
      } finally {
        await a.page.close().catch(() => {});
      }

      const b = await loadApp(second, link);
      try {
        const s = await state(b.page);
        assert.equal(s.last_error, null);
        assert.deepEqual(s.terrain.spec, spec, 'the link reopens the same ground');
        assert.equal(s.terrain.triangles_drawn, 2 * (1 + 2 * 5));
        assert.equal(s.preset, 'hexapod');
        b.assertClean();
      } finally {
        await b.page.close().catch(() => {});
      }
    });
  });
}
