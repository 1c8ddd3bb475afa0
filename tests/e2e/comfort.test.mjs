// Browser tests of the comfort features (issue 6 item 5): the phone layout (a 390 × 844 touch
// screen: the 3-D view fills the width, a tap on "Controls" opens the drawer, the view keeps
// drawing; a tap on "Plots" opens the live plots, or side by side the comparison's cards, every
// interactive widget at least 44 px, issue 21 item 7) and the light/dark theme (the panels' pixels follow the setting). Touch orbit and
// pinch zoom are tested in features.test.mjs ("high-DPI and touch").

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  assertDrawn, command, launch, pngStats, serveDist, shootCanvas, sleep, state, until as waitFor, withLoadedApp,
} from './harness.mjs';

const T = { timeout: 240_000 };

let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

const withApp = (browser, fn) => withLoadedApp(browser, server.url, fn);

/** Waits until `pred(state())` holds, polling; a timeout shows the layout. */
const until = (page, pred, what, timeout = 20_000) =>
  waitFor(page, pred, what, timeout, 100, (s) => JSON.stringify(s.layout));

/**
 * A finger tap on the phone bar's button at `rect` (CSS pixels = egui points at DPR 1), repeated
 * up to three times until `pred(state())` holds: on a starved machine (about 1 fps in CI) a tap's
 * press and release can fall in frames too far apart for egui to count a click; a person would
 * tap again.
 */
async function tapUntil(page, rect, pred, what) {
  const [bx, by, bw, bh] = rect;
  const cdp = await page.context().newCDPSession(page);
  const at = [{ x: bx + bw / 2, y: by + bh / 2, id: 0 }];
  for (let tap = 1; ; tap++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at });
    await sleep(80);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    try {
      return await until(page, pred, what, tap < 3 ? 8_000 : 20_000);
    } catch (e) {
      if (tap >= 3) throw e;
      const s = await state(page);
      if (pred(s)) return s; // the tap landed just after the wait
    }
  }
}

describe('phone layout (WebGL2, 390 × 844 touch screen)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2', { hasTouch: true, viewport: { width: 390, height: 844 } }); });
  after(async () => { await browser?.close(); });

  it('fills the width with the 3-D view and opens the controls drawer by a tap', T, async () => {
    await withApp(browser, async ({ page }) => {
      assert.equal(await command(page, { paused: true }), 'ok');
      let s = await until(page, (x) => x.layout.narrow && x.layout.controls_button_pt[2] > 0, 'the phone layout');
      assert.equal(s.layout.controls_open, false, 'the drawer starts closed');
      const [, , vw, vh] = s.view_rect_px;
      assert.ok(vw >= 0.95 * 390, `the 3-D view takes the width: ${vw} px of 390`);
      assert.ok(vh >= 0.8 * 844, `and most of the height: ${vh} px of 844`);
      assertDrawn(await shootCanvas(page, 'phone-closed.png'), 'phone layout');

      s = await tapUntil(page, s.layout.controls_button_pt, (x) => x.layout.controls_open, 'the drawer to open');
      const [, , vw2, vh2] = s.view_rect_px;
      assert.ok(vw2 >= 0.95 * 390, `the view keeps the width under the drawer: ${vw2}`);
      assert.ok(vh2 > 0.3 * 844 && vh2 < vh, `the drawer takes the lower part: view ${vh} → ${vh2} px`);
      const shot = await shootCanvas(page, 'phone-drawer.png');
      // The drawer's panels are in the lower part of the screen, the figure above them.
      const drawer = pngStats(shot.png, { x0: 0.05, y0: 0.7, x1: 0.95, y1: 0.95 });
      assert.ok(drawer.distinct > 8, `the drawer shows controls (${drawer.distinct} colours); see ${shot.file}`);
      const view = pngStats(shot.png, { x0: 0.1, y0: 0.1, x1: 0.9, y1: 0.4 });
      assert.ok(view.stddev > 5, `the view above the drawer still draws (stddev ${view.stddev.toFixed(1)})`);

      // Every interactive widget egui registered in the drawer is a 44-px touch target.
      console.log(`# phone drawer: ${s.layout.touch_targets_checked} touch targets, `
        + `${s.layout.small_touch_targets_pt.length} under 44 px`);
      assert.ok(s.layout.touch_targets_checked >= 15, `${s.layout.touch_targets_checked} targets measured`);
      assert.deepEqual(s.layout.small_touch_targets_pt, [], 'every target at least 44 × 44 px');
      // The help window too: fixed, no title bar, a full-size Close button.
      assert.equal(await command(page, { help: true }), 'ok');
      s = await until(page, (x) => x.layout.help_open && x.layout.touch_targets_checked > 0, 'the help window');
      await sleep(300);
      s = await state(page);
      assertDrawn(await shootCanvas(page, 'phone-help.png'), 'phone help');
      assert.deepEqual(s.layout.small_touch_targets_pt, [], 'help: every target at least 44 × 44 px');
      assert.equal(await command(page, { help: false }), 'ok');

      // The app keeps working in this layout: a method change reaches the state.
      assert.equal(await command(page, { method: 'sdls' }), 'ok');
      assert.equal((await state(page)).method, 'sdls');
    });
  });

  it('opens the live plots by a tap, in place of the controls', T, async () => {
    await withLoadedApp(browser, `${server.url}?preset=raibert-biped`, async ({ page }) => {
      let s = await until(page, (x) => x.layout.narrow && x.layout.plots_button_pt[2] > 0, 'the phone layout');
      assert.equal(s.layout.plots_open, false, 'the plots start closed');
      const [, , , vh] = s.view_rect_px;
      s = await tapUntil(page, s.layout.plots_button_pt, (x) => x.layout.plots_open, 'the plots to open');
      assert.equal(s.layout.controls_open, false, 'one drawer at a time');
      assert.ok(s.view_rect_px[3] < vh, `the plots take the lower part: view ${vh} → ${s.view_rect_px[3]} px`);
      // Let the running biped draw a second of its traces.
      await sleep(1500);
      const shot = await shootCanvas(page, 'phone-plots.png');
      const sheet = pngStats(shot.png, { x0: 0.05, y0: 0.6, x1: 0.95, y1: 0.95 });
      assert.ok(sheet.distinct > 8, `the drawer shows plots (${sheet.distinct} colours); see ${shot.file}`);
      s = await tapUntil(page, s.layout.controls_button_pt, (x) => x.layout.controls_open, 'the controls to open');
      assert.equal(s.layout.plots_open, false, 'opening the controls closes the plots');
    });
  });

  it('shows the comparison cards in the plots drawer, every target 44 px', T, async () => {
    await withApp(browser, async ({ page }) => {
      assert.equal(await command(page, { compare: { views: ['transpose', 'pinv', 'dls', 'sdls'], scenario: 'singularity' } }), 'ok');
      let s = await until(page, (x) => x.layout.narrow && x.layout.plots_button_pt[2] > 0, 'the phone layout');
      s = await tapUntil(page, s.layout.plots_button_pt, (x) => x.layout.plots_open, 'the cards to open');
      await sleep(1500);
      s = await until(page, (x) => x.layout.touch_targets_checked > 10, 'the cards laid out');
      const shot = await shootCanvas(page, 'phone-cards.png');
      const sheet = pngStats(shot.png, { x0: 0.05, y0: 0.6, x1: 0.95, y1: 0.95 });
      assert.ok(sheet.distinct > 8, `the drawer shows the cards (${sheet.distinct} colours); see ${shot.file}`);
      console.log(`# phone cards: ${s.layout.touch_targets_checked} touch targets (sliders of 4 cards), `
        + `${s.layout.small_touch_targets_pt.length} under 44 px`);
      assert.deepEqual(s.layout.small_touch_targets_pt, [], 'every target at least 44 × 44 px');
    });
  });
});

describe('light and dark theme (WebGL2)', () => {
  let browser;
  before(async () => { browser = await launch('webgl2'); });
  after(async () => { await browser?.close(); });

  it('paints the panels light or dark as set, and keeps the setting in state()', T, async () => {
    await withApp(browser, async ({ page }) => {
      assert.equal(await command(page, { paused: true }), 'ok');
      // The side panel's lower part: its background, few widgets.
      const panel = { x0: 0.005, y0: 0.75, x1: 0.2, y1: 0.78 };
      const looks = {};
      for (const theme of ['light', 'dark']) {
        assert.equal(await command(page, { theme }), 'ok');
        const s = await until(page, (x) => x.theme === theme && x.dark === (theme === 'dark'), `theme ${theme}`);
        assert.equal(s.theme, theme);
        await sleep(300);
        looks[theme] = pngStats((await shootCanvas(page, `theme-${theme}.png`)).png, panel).mean;
      }
      console.log(`# panel luminance: light ${looks.light.toFixed(0)}, dark ${looks.dark.toFixed(0)}`);
      assert.ok(looks.light > 180, `light panels are light: ${looks.light}`);
      assert.ok(looks.dark < 80, `dark panels are dark: ${looks.dark}`);
      assert.match(await command(page, { theme: 'sepia' }), /^theme: unknown theme "sepia"/);
      assert.equal((await state(page)).theme, 'dark', 'a bad theme changes nothing');
    });
  });
});
