// The performance budget's native vs wasm table (issue 7 item 4) for `./build.sh bench --suite`:
// runs window.gaitlab.bench('{"suite": true}') — the same gaitlab-bench suite `gaitlab bench --json`
// runs natively — in headless Chromium, and prints each case's median µs beside the native figure
// read from the file named by --native (the CLI's JSON), with the wasm/native ratio.
// Usage: node bench-suite.mjs --native native.json [--path webgl2|webgpu] [--json out.json]

import { readFileSync, writeFileSync } from 'node:fs';
import { cliOption as option, launch, loadApp, serveDist } from './harness.mjs';

const nativePath = option('native');
if (!nativePath) {
  console.error('usage: node bench-suite.mjs --native native.json [--path webgl2|webgpu] [--json out.json]');
  process.exit(2);
}
const native = JSON.parse(readFileSync(nativePath, 'utf8'));
const path = option('path') ?? 'webgl2';

const server = await serveDist();
const browser = await launch(path);
let wasm;
try {
  const p = await loadApp(browser, server.url);
  await p.page.evaluate(() => window.gaitlab.command('{"paused": true}'));
  // One untimed pass lets V8 tier the wasm up before the timed one.
  await p.page.evaluate(() => window.gaitlab.bench('{"suite": true, "repeats": 2}'));
  wasm = JSON.parse(await p.page.evaluate(() => window.gaitlab.bench('{"suite": true}')));
  p.assertClean();
  await p.page.close();
} finally {
  await browser.close();
  await server.close();
}

const rows = Object.keys(native.cases).sort().map((name) => {
  const n = native.cases[name];
  const w = wasm.cases?.[name];
  return { case: name, native_us: n, wasm_us: w ?? null, ratio: w === undefined ? null : w / n };
});
console.log('| case | native µs | wasm µs | wasm/native |');
console.log('| --- | --- | --- | --- |');
for (const r of rows) {
  const w = r.wasm_us === null ? 'missing' : r.wasm_us.toFixed(2);
  const ratio = r.ratio === null ? '' : `${r.ratio.toFixed(2)}×`;
  console.log(`| ${r.case} | ${r.native_us.toFixed(2)} | ${w} | ${ratio} |`);
}
const ratios = rows.filter((r) => r.ratio !== null).map((r) => r.ratio).sort((a, b) => a - b);
console.log(`median wasm/native ${ratios[Math.floor(ratios.length / 2)].toFixed(2)}×, `
  + `range ${ratios[0].toFixed(2)}–${ratios[ratios.length - 1].toFixed(2)}× over ${ratios.length} cases`);
const out = option('json');
if (out) writeFileSync(out, JSON.stringify({ native, wasm, rows }, null, 1));
if (rows.some((r) => r.wasm_us === null)) process.exit(1);
