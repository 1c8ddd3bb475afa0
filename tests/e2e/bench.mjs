// Browser figures for `./build.sh bench --browser`: the time from navigation to the app's first
// painted frame on the local server, and window.gaitlab.bench() — the per-frame simulation + IK of
// the walking human with SDLS, the same routine `gaitlab bench` times natively. Prints one JSON
// object.
//
// Start-up is timed two ways: `--loads N` loads in one browser (the browser warm: its GPU process
// and WebGL already started; the first of them is cold and counted with the cold ones), and
// `--cold N` more browsers launched fresh for one load each (Chromium starts WebGL and asks for a
// WebGPU adapter for the first time, about 1 s more here).
// Usage: node bench.mjs [--loads N] [--cold N] [--frames N] [--repeats N] [--path webgl2|webgpu]

import { cliOption, launch, loadApp, serveDist } from './harness.mjs';

const loads = Number(cliOption('loads') ?? 11);
const cold = Number(cliOption('cold') ?? 4);
const frames = Number(cliOption('frames') ?? 600);
const repeats = Number(cliOption('repeats') ?? 15);
const path = cliOption('path') ?? 'webgl2';
if (!(loads >= 1) || !(cold >= 0)) {
  console.error('usage: node bench.mjs [--loads N>=1] [--cold N>=0] [--frames N] [--repeats N] [--path webgl2|webgpu]');
  process.exit(2);
}

const firstFrameMs = (p) => p.page.evaluate(() => window.__gaitlabFirstFrameMs);
const marksOf = (p) => p.page.evaluate(() => Object.fromEntries(
  performance.getEntriesByType('mark').map((m) => [m.name, Math.round(m.startTime)])));
const summary = (all) => {
  const sorted = [...all].sort((a, b) => a - b);
  return {
    median: sorted.length ? sorted[Math.floor(sorted.length / 2)] : null,
    max: sorted.at(-1) ?? null,
    within_2s: all.filter((ms) => ms <= 2000).length,
    all: all.map((ms) => Math.round(ms)),
  };
};

const server = await serveDist();
try {
  const coldMs = [];
  const coldMarks = [];
  for (let i = 0; i < cold; i++) {
    const browser = await launch(path);
    try {
      const p = await loadApp(browser, server.url);
      coldMs.push(await firstFrameMs(p));
      coldMarks.push(await marksOf(p));
      p.assertClean();
    } finally {
      await browser.close();
    }
  }

  const browser = await launch(path);
  try {
    const warmMs = [];
    let p;
    for (let i = 0; i < loads; i++) {
      if (p) await p.page.close();
      p = await loadApp(browser, server.url);
      (i === 0 ? coldMs : warmMs).push(await firstFrameMs(p));
    }
    const marks = await marksOf(p);
    await p.page.evaluate(() => window.gaitlab.command('{"paused": true}'));
    // A short first run lets V8 tier the wasm up before the timed one.
    await p.page.evaluate(() => window.gaitlab.bench('{"frames": 300, "repeats": 3}'));
    const wasm = JSON.parse(await p.page.evaluate((o) => window.gaitlab.bench(JSON.stringify(o)), { frames, repeats }));
    console.log(JSON.stringify({
      path,
      startup_marks_ms: { warm: marks, cold: coldMarks },
      first_frame_ms: { warm: summary(warmMs), cold: summary(coldMs) },
      wasm,
      user_agent: await p.page.evaluate(() => navigator.userAgent),
    }));
    p.assertClean();
    await p.page.close();
  } finally {
    await browser.close();
  }
} finally {
  await server.close();
}
