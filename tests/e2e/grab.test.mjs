// Grab and pull (issue 44 item 1), with a real mouse at 1440 × 900 and a real finger at
// 390 × 844: a press on the left hand's target picks it and a drag moves it 0.3 m (the target
// stays under the pointer); pulled to a spot within reach and pinned, the hand has it within a
// second of SDLS (joint limits off there: the paper's clamp loses a reachable pin for part of
// each step); released, the script takes the target back without a jump beyond the
// script's own motion plus 5 mm a frame; a drag in empty space still turns the camera; and side
// by side all four views' targets move with the drag.
import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { command, launch, serveDist, sleep, state, until, withLoadedApp } from './harness.mjs';

const T = { timeout: 600_000 };
let server;
before(async () => { server = await serveDist(); });
after(async () => { await server?.close(); });

const effector = (s, name) => s.views[0].effectors.find((e) => e.name === name);
const sub = (a, b) => a.map((x, i) => x - b[i]);
const norm = (a) => Math.hypot(...a);
const dist = (a, b) => norm(sub(a, b));

/** A mouse or one finger, as the same four moves. */
async function hand(page, touch) {
  if (!touch) {
    return {
      down: async ([x, y]) => { await page.mouse.move(x, y); await page.mouse.down(); },
      move: ([x, y]) => page.mouse.move(x, y),
      up: () => page.mouse.up(),
    };
  }
  const cdp = await page.context().newCDPSession(page);
  const send = (type, points) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y]) => ({ x, y, id: 0 })),
  });
  return {
    down: (p) => send('touchStart', [p]),
    move: (p) => send('touchMove', [p]),
    up: () => send('touchEnd', []),
  };
}

/**
 * Moves the pointer to `p`, gives the app a few frames to take it, and returns the state once
 * the held target has stopped moving (a slow machine takes the move a frame or two late).
 */
async function moveTo(page, pointer, p) {
  await pointer.move(p);
  await sleep(250);
  let s = await state(page);
  for (let k = 0; k < 8; k++) {
    await sleep(100);
    const next = await state(page);
    const still = next.views[0].effectors.every((e, i) => dist(e.target_m, s.views[0].effectors[i].target_m) < 1e-6);
    s = next;
    if (still) break;
  }
  return s;
}

/**
 * With the pointer pressed at `from` on a pickable point of effector `name`, drags so that its
 * target moves `metres` from `start` along the screen direction `dir` (px, unit), refining the
 * length a few times (the drag plane maps screen to world projectively). Returns the last state.
 */
async function dragBy(page, pointer, from, dir, name, start, metres) {
  let k = 40;
  let s;
  for (let round = 0; round < 10; round++) {
    s = await moveTo(page, pointer, [from[0] + dir[0] * k, from[1] + dir[1] * k]);
    const moved = dist(effector(s, name).target_m, start);
    if (Math.abs(moved - metres) < 0.004) break;
    k *= metres / Math.max(moved, 1e-3);
  }
  return s;
}

/** Presses at `p`, nudges 10 px along `dir` to start the drag, and waits for the hold. */
async function grab(page, pointer, p, dir, name) {
  await pointer.down(p);
  await sleep(100);
  for (let k = 1; k <= 3; k++) {
    await moveTo(page, pointer, [p[0] + dir[0] * 4 * k, p[1] + dir[1] * 4 * k]);
  }
  try {
    return await until(page, (s) => effector(s, name).held, `${name} held`, 15_000);
  } catch (e) {
    // Say what the press took instead, if anything, and where the points were.
    const s = await state(page);
    const seen = s.views[0].effectors.map((x) => `${x.name}${x.held ? ' (held)' : ''} target ${x.target_pt?.map((v) => v.toFixed(0))} hand ${x.position_pt?.map((v) => v.toFixed(0))}`);
    throw new Error(`${e.message}; pressed at ${p.map((v) => v.toFixed(0))}; ${seen.join('; ')}`);
  }
}

/**
 * Turns the camera and waits until it has arrived (the view eases toward a new camera over
 * frames, slower on a loaded machine): the drawn points stop moving. Returns the state.
 */
async function turnCamera(page, camera) {
  assert.equal(await command(page, { camera }), 'ok');
  return settle(page);
}

/**
 * Waits until the drawn targets and effectors stop moving on screen; returns the state. A
 * paused page may not draw again until an input comes, and `state()` reports the points as
 * last drawn, so the mouse hovers over the page's corner (which holds nothing) to make it draw.
 */
async function settle(page) {
  await sleep(300);
  await page.mouse.move(2, 2);
  await sleep(200);
  await page.mouse.move(3, 3);
  await sleep(200);
  let s = await state(page);
  const points = (st) => st.views[0].effectors.flatMap((e) => [...(e.position_pt ?? []), ...(e.target_pt ?? [])]);
  for (let k = 0; k < 50; k++) {
    await page.mouse.move(2 + (k % 2), 2);
    await sleep(150);
    const next = await state(page);
    const [a, b] = [points(s), points(next)];
    s = next;
    if (a.length === b.length && a.every((v, i) => Math.abs(v - b[i]) < 0.05)) break;
  }
  return s;
}

/** Steps one frame while paused and returns the state after it. */
async function stepFrame(page) {
  const { frame } = await state(page);
  assert.equal(await command(page, { step: true }), 'ok');
  return until(page, (s) => s.frame > frame, 'a frame step', 15_000, 50);
}

for (const device of [
  { label: 'mouse, 1440 × 900', viewport: { width: 1440, height: 900 }, touch: false },
  { label: 'touch, 390 × 844', viewport: { width: 390, height: 844 }, touch: true },
]) {
  describe(`grab and pull (${device.label})`, () => {
    let browser;
    before(async () => { browser = await launch('webgl2', { viewport: device.viewport, hasTouch: device.touch }); });
    after(async () => { await browser?.close(); });

    it('pulls a target 0.3 m, the hand follows, release blends back, empty space orbits, four views chase', T, async () => {
      await withLoadedApp(browser, server.url, async ({ page }) => {
        assert.equal(await command(page, { preset: 'she-2006', method: 'sdls', plots: false }), 'ok');
        await until(page, (s) => s.time_s >= 1.0, '1 s of the walk');
        assert.equal(await command(page, { paused: true }), 'ok');
        await sleep(300);
        // The script's own largest move of the left hand's target in a frame, over 20 frames.
        let s = await state(page);
        let last = effector(s, 'left_hand').target_m;
        let scriptMove = 0;
        for (let k = 0; k < 20; k++) {
          s = await stepFrame(page);
          const now = effector(s, 'left_hand').target_m;
          scriptMove = Math.max(scriptMove, dist(now, last));
          last = now;
        }
        await sleep(300);
        s = await state(page);
        const pointer = await hand(page, device.touch);

        // 1. The target: picked where it is drawn, dragged up the screen 0.3 m.
        let lh = effector(s, 'left_hand');
        assert.ok(lh.target_pt, 'the left hand target is on screen');
        const start = lh.target_m;
        await grab(page, pointer, lh.target_pt, [0, -1], 'left_hand');
        s = await dragBy(page, pointer, lh.target_pt, [0, -1], 'left_hand', start, 0.3);
        lh = effector(s, 'left_hand');
        const moved = dist(lh.target_m, start);
        console.log(`# ${device.label}: target moved ${moved.toFixed(4)} m; on screen ${lh.target_pt.map((v) => v.toFixed(1))}`);
        assert.ok(Math.abs(moved - 0.3) <= 0.01, `the target moved ${moved} m`);
        await pointer.up();
        await sleep(400);
        // Released: the script takes it back, never faster than its own motion plus 5 mm a frame.
        s = await state(page);
        last = effector(s, 'left_hand').target_m;
        let worst = 0;
        for (let k = 0; k < 45; k++) {
          s = await stepFrame(page);
          const now = effector(s, 'left_hand').target_m;
          worst = Math.max(worst, dist(now, last));
          last = now;
        }
        console.log(`# ${device.label}: after release the target moved at most ${(worst * 1e3).toFixed(1)} mm a frame (the script alone ${(scriptMove * 1e3).toFixed(1)})`);
        assert.ok(worst <= scriptMove + 0.005, `a jump of ${worst} m in a frame`);

        // 2. The hand itself, pulled 0.3 m toward its limb's anchor (within reach), pinned. With
        // the preset's joint limits (She 2006 §6.1.1.1's clamp) the hand loses a reachable pinned
        // target for part of each step (docs/app.md "Grab and pull", the Rust test
        // `pinned_reachable`), so this part measures the drag and the follow with limits off.
        {
          assert.equal(await command(page, { enforce_limits: false }), 'ok');
          // One frame, so the figure has been solved without limits before the press.
          await stepFrame(page);
          // Seen from the side, so the drag plane is the body's own on both screens: from the
          // left hand's side (the eye at yaw 90° is on +x), so it is drawn in front of the right.
          const side = effector(s, 'left_hand').position_m[0] >= effector(s, 'right_hand').position_m[0] ? 90 : -90;
          s = await turnCamera(page, { yaw_deg: side, pitch_deg: 10 });
          lh = effector(s, 'left_hand');
          const from = lh.position_pt;
          assert.ok(from, 'the left hand is on screen');
          // The screen direction toward the anchor: the drag's world motion per pixel right (a)
          // and per pixel down (b), then the least-squares screen direction along the anchor.
          s = await grab(page, pointer, from, [1, 0], 'left_hand');
          const anchor = effector(s, 'left_hand').reach_anchor_m;
          const px = [from[0] + 12, from[1]];
          const w0 = effector(await moveTo(page, pointer, px), 'left_hand').target_m;
          const wA = effector(await moveTo(page, pointer, [px[0] + 20, px[1]]), 'left_hand').target_m;
          const wB = effector(await moveTo(page, pointer, [px[0] + 20, px[1] + 20]), 'left_hand').target_m;
          const a = sub(wA, w0).map((x) => x / 20);
          const b = sub(wB, wA).map((x) => x / 20);
          // Toward the limb's anchor, as near as the drag plane (the body's side plane) allows:
          // the hand rises and comes back along the body, inside its reach.
          const d = sub(anchor, w0).map((x, _, all) => x / norm(all));
          const dot = (x, y) => x.reduce((acc, v, i) => acc + v * y[i], 0);
          const [aa, ab, bb, ad, bd] = [dot(a, a), dot(a, b), dot(b, b), dot(a, d), dot(b, d)];
          const det = aa * bb - ab * ab;
          const u = (bb * ad - ab * bd) / det;
          const v = (aa * bd - ab * ad) / det;
          const dir = [u / Math.hypot(u, v), v / Math.hypot(u, v)];
          // Back to the grab point, then along `dir`.
          await moveTo(page, pointer, px);
          const grabbedAt = effector(await state(page), 'left_hand').target_m;
          s = await dragBy(page, pointer, px, dir, 'left_hand', grabbedAt, 0.3);
          lh = effector(s, 'left_hand');
          assert.ok(Math.abs(dist(lh.target_m, grabbedAt) - 0.3) <= 0.01, `pulled ${dist(lh.target_m, grabbedAt)} m`);
          assert.equal(await command(page, { drag_target: { name: 'left_hand', pin: true } }), 'ok');
          await pointer.up();
          await sleep(300);
          s = await state(page);
          assert.equal(effector(s, 'left_hand').pinned, true);
          assert.ok(effector(s, 'left_hand').out_of_reach_m < 0, `within reach: ${effector(s, 'left_hand').out_of_reach_m}`);
          // Playing, the pinned target rides with the body; SDLS has it within a second and
          // keeps it (sampled every 50 ms over that second of play).
          const t0 = s.time_s;
          assert.equal(await command(page, { paused: false }), 'ok');
          let reachedAt = null;
          let worstAfter = 0;
          s = await until(page, (st) => {
            const err = effector(st, 'left_hand').error_m;
            if (reachedAt === null && err < 0.01) reachedAt = st.time_s - t0;
            else if (reachedAt !== null) worstAfter = Math.max(worstAfter, err);
            return st.time_s >= t0 + 1.0;
          }, 'a second of play after the pull', 60_000, 50);
          console.log(`# ${device.label}: SDLS error under 1 cm at ${reachedAt?.toFixed(2)} s after the pull, then at most ${(worstAfter * 1e3).toFixed(1)} mm over ${(s.time_s - t0).toFixed(2)} s (limits off)`);
          assert.ok(reachedAt !== null && reachedAt <= 1.0, `the hand had not reached its pinned target 1 s after the pull: ${JSON.stringify(effector(s, 'left_hand'))}`);
          assert.ok(worstAfter < 0.01, `the hand lost its pinned target by ${worstAfter} m`);
          assert.equal(await command(page, { paused: true, enforce_limits: true, drag_target: { name: 'left_hand', pin: false, position: null } }), 'ok');
        }

        // 3. A drag in empty space turns the camera and holds nothing.
        s = await state(page);
        const [vx, vy, vw, vh] = s.layout.view_pt;
        const empty = [vx + vw * 0.08, vy + vh * 0.12];
        const yaw0 = s.camera.yaw_deg;
        await pointer.down(empty);
        for (let k = 1; k <= 6; k++) await moveTo(page, pointer, [empty[0] + 15 * k, empty[1]]);
        s = await state(page);
        await pointer.up();
        const turned = Math.abs(((s.camera.yaw_deg - yaw0 + 540) % 360) - 180);
        assert.ok(turned > 3, `empty space orbits: ${turned}°`);
        assert.ok(s.views[0].effectors.every((e) => !e.held), 'nothing held');

        // 4. Side by side, four views: the drag moves every view's target. Seen from the left
        // hand's side, so where the hands overlap on screen the press takes the left one.
        s = await state(page);
        const yaw = effector(s, 'left_hand').position_m[0] >= effector(s, 'right_hand').position_m[0] ? 55 : -55;
        await turnCamera(page, { yaw_deg: yaw, pitch_deg: 20 });
        assert.equal(await command(page, { compare: { views: ['transpose', 'pinv', 'dls', 'sdls'] } }), 'ok');
        assert.equal(await command(page, { paused: false }), 'ok');
        await until(page, (st) => st.time_s >= 1.0, '1 s side by side');
        assert.equal(await command(page, { paused: true }), 'ok');
        s = await settle(page);
        const k = s.views[0].effectors.findIndex((e) => e.name === 'left_hand');
        const targetPt = s.views[0].effectors[k].target_pt;
        assert.ok(targetPt, 'the first pane shows the target');
        const before = s.compare.metrics.map((m) => m.effectors[k].target_m);
        await grab(page, pointer, targetPt, [0, -1], 'left_hand');
        for (let j = 1; j <= 6; j++) await moveTo(page, pointer, [targetPt[0], targetPt[1] - 12 - 6 * j]);
        s = await state(page);
        await pointer.up();
        const after = s.compare.metrics.map((m) => m.effectors[k].target_m);
        const shifts = after.map((t, i) => dist(t, before[i]));
        console.log(`# ${device.label}: side by side the four targets moved ${shifts.map((x) => x.toFixed(3)).join(', ')} m`);
        assert.ok(shifts[0] > 0.02, `the drag moved the target ${shifts[0]} m`);
        for (const t of after) assert.ok(dist(t, after[0]) < 1e-9, 'every view holds the same target');
      });
    });
  });
}
