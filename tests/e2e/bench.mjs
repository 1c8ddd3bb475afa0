// Browser figures for `./build.sh bench --browser`: the time from navigation to the app's first
// frame on the local server (first load and later loads), and window.gaitlab.bench() — the
// per-frame simulation + IK of the walking human with SDLS, the same routine `gaitlab bench` times
// natively. Prints one JSON object.
// Usage: node bench.mjs [--loads N] [--frames N] [--repeats N] [--path webgl2|webgpu]

import { launch, loadApp, serveDist } from './harness.mjs';

function option(name, fallback) {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 ? Number(process.argv[i + 1]) : fallback;
}

const loads = option('loads', 5);
const frames = option('frames', 600);
const repeats = option('repeats', 15);
const pathArg = process.argv.indexOf('--path');
const path = pathArg >= 0 ? process.argv[pathArg + 1] : 'webgl2';

const server = await serveDist();
const browser = await launch(path);
try {
  const firstFrameMs = [];
  for (let i = 0; i < loads; i++) {
    const p = await loadApp(browser, server.url);
    firstFrameMs.push(await p.page.evaluate(() => window.__gaitlabFirstFrameMs));
    if (i < loads - 1) await p.page.close();
    else {
      await p.page.evaluate(() => window.gaitlab.command('{"paused": true}'));
      // A short first run lets V8 tier the wasm up before the timed one.
      await p.page.evaluate(() => window.gaitlab.bench('{"frames": 300, "repeats": 3}'));
      const text = await p.page.evaluate((o) => window.gaitlab.bench(JSON.stringify(o)), { frames, repeats });
      const wasm = JSON.parse(text);
      const sorted = [...firstFrameMs].sort((a, b) => a - b);
      const marks = await p.page.evaluate(() => Object.fromEntries(
        performance.getEntriesByType('mark').map((m) => [m.name, Math.round(m.startTime)])));
      console.log(JSON.stringify({
        path,
        startup_marks_ms: marks,
        first_frame_ms: { first_load: firstFrameMs[0], median: sorted[Math.floor(sorted.length / 2)], all: firstFrameMs },
        wasm,
        user_agent: await p.page.evaluate(() => navigator.userAgent),
      }));
      p.assertClean();
      await p.page.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
}
