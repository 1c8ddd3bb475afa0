// The preset format's JSON Schema (docs/schema/preset.schema.json, generated from the Rust serde
// types) checked by an independent validator, ajv: every bundled preset validates, a "$schema"
// key is allowed, and a wrong type, a missing required field or an unknown key fail. No browser.
// Run: `cd tests/e2e && node --test schema.test.mjs`.

import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import Ajv from 'ajv';

const repoRoot = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const schema = JSON.parse(readFileSync(join(repoRoot, 'docs', 'schema', 'preset.schema.json'), 'utf8'));
const presetDir = join(repoRoot, 'presets');
const presetNames = readdirSync(presetDir).filter((f) => f.endsWith('.json')).sort();
const preset = (file) => JSON.parse(readFileSync(join(presetDir, file), 'utf8'));

// Strict mode, so a keyword ajv does not know is an error, not a silent pass. schemars writes
// `format` for Rust's number types (double, uint, uint32 …): annotations only, accepted as is.
const ajv = new Ajv({ allErrors: true, strict: true });
const formats = new Set(JSON.stringify(schema).match(/"format":"[^"]+"/g)?.map((f) => f.slice(10, -1)) ?? []);
for (const format of formats) ajv.addFormat(format, true);
const validate = ajv.compile(schema);

/** The errors ajv gives for `value`, as `instancePath message` lines ('' when valid). */
function errors(value) {
  return validate(value) ? '' : ajv.errorsText(validate.errors, { separator: '\n' });
}

/** A deep copy of the human preset changed by `change`. */
function humanWith(change) {
  const value = preset('human.json');
  change(value);
  return value;
}

describe('preset JSON Schema', () => {
  it('names itself', () => {
    assert.equal(schema.$schema, 'http://json-schema.org/draft-07/schema#');
    assert.match(schema.$id, /preset\.schema\.json$/);
    assert.match(schema.title, /gaitlab/);
  });

  it('accepts every bundled preset', () => {
    assert.ok(presetNames.length >= 9, `presets: ${presetNames}`);
    for (const file of presetNames) assert.equal(errors(preset(file)), '', file);
  });

  it('accepts a "$schema" key at the top level', () => {
    const value = humanWith((p) => { p.$schema = '../docs/schema/preset.schema.json'; });
    assert.equal(errors(value), '');
  });

  it('refuses a wrong type', () => {
    const cases = [
      [(p) => { p.scenario.fps = '60'; }, '/scenario/fps'],
      [(p) => { p.skeleton.joints[0].rest = 'zero'; }, '/skeleton/joints/0/rest'],
      [(p) => { p.skeleton.root.position = [0, 1]; }, '/skeleton/root/position'],
      [(p) => { p.scenario.engine = 'steam'; }, '/scenario/engine'],
      [(p) => { p.scenario.mode = 'wounded_walk'; }, '/scenario/mode'],
    ];
    for (const [change, path] of cases) {
      const text = errors(humanWith(change));
      assert.notEqual(text, '', `${path} accepted`);
      assert.ok(text.includes(path), `${path}: ${text}`);
    }
  });

  it('refuses a value outside its parameter-table range, as the parser does', () => {
    const cases = [
      [(p) => { p.scenario.ik = { lambda: 0 }; }, '/scenario/ik/lambda'],
      [(p) => { p.scenario.ik = { limit_passes: 17 }; }, '/scenario/ik/limit_passes'],
      [(p) => { p.scenario.thesis.slowdown = 0.5; }, '/scenario/thesis/slowdown'],
      [(p) => { p.scenario.fps = 0; }, '/scenario/fps'],
    ];
    for (const [change, path] of cases) {
      const text = errors(humanWith(change));
      assert.notEqual(text, '', `${path} accepted`);
      assert.ok(text.includes(path), `${path}: ${text}`);
    }
    assert.equal(errors(humanWith((p) => { p.scenario.ik = { lambda: 10, limit_passes: 16 }; })), '',
      'the ends of a closed range are accepted');
  });

  it('refuses a missing required field', () => {
    for (const [change, what] of [
      [(p) => { delete p.name; }, "must have required property 'name'"],
      [(p) => { delete p.scenario.engine; }, "must have required property 'engine'"],
      [(p) => { delete p.skeleton.joints[2].axis; }, "must have required property 'axis'"],
    ]) {
      const text = errors(humanWith(change));
      assert.ok(text.includes(what), `${what}: ${text || 'accepted'}`);
    }
  });

  it('refuses unknown keys, as the parser does', () => {
    for (const change of [
      (p) => { p.colour = 'red'; },
      (p) => { p.skeleton.joints[0].stiffness = 3; },
      (p) => { p.scenario.ik = { method: 'dls' }; },
    ]) {
      assert.match(errors(humanWith(change)), /must NOT have additional properties/);
    }
  });
});
