// The command API's JSON Schema (docs/schema/command.schema.json, generated from the Rust serde
// types of `gaitlab_app::api::Command`) checked by an independent validator, ajv: the command
// objects the browser tests send validate, and a wrong type or an unknown key (at the top or
// nested) fails. Also: the state schema compiles. No browser.
// Run: `cd tests/e2e && node --test command-schema.test.mjs`.

import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import Ajv from 'ajv';

const repoRoot = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const readSchema = (name) => JSON.parse(readFileSync(join(repoRoot, 'docs', 'schema', name), 'utf8'));
const schema = readSchema('command.schema.json');
const stateSchema = readSchema('state.schema.json');

// Strict mode, as schema.test.mjs; schemars' number `format`s are annotations, accepted as is.
function compile(s) {
  const ajv = new Ajv({ allErrors: true, strict: true });
  const formats = new Set(JSON.stringify(s).match(/"format":"[^"]+"/g)?.map((f) => f.slice(10, -1)) ?? []);
  for (const format of formats) ajv.addFormat(format, true);
  const validate = ajv.compile(s);
  return (value) => (validate(value) ? '' : ajv.errorsText(validate.errors, { separator: '\n' }));
}
const errors = compile(schema);

// What the browser tests send (app, comfort, compare, export, features, framing, link, physics,
// poda, soak tests), plus the keys they reach through links and the panels.
const sent = [
  { mode: 'run' },
  { method: 'dls' },
  { paused: true },
  { paused: false, plots: false },
  { method: 'sdls' },
  { theme: 'dark' },
  { preset: 'ik-quadruped' },
  { compare: { views: ['transpose', 'pinv', 'dls', 'sdls'], scenario: 'singularity' } },
  { compare: { views: ['pinv-ns', 'ccd'], scenario: 'script' } },
  { compare: { views: ['pinv', 'dls'], scenario: 'singularity', options: [{}, { lambda: 0.3 }] } },
  { compare: false },
  { compare: false, engine: 'poda' },
  { paused: true, reset: true, record: true },
  { step: true },
  { video_size: 'p360', record_video: true },
  { record_video: false },
  { mode: 'wounded-walk', method: 'dls', record: true },
  { record: false },
  { preset: 'hexapod', paused: true },
  { show_link: true },
  { show_link: false },
  { gain: { name: 'leg_stiffness', value: 1e9 } },
  { gains: { leg_stiffness: 5000, posture_kp: 100 } },
  { preset: 'raibert-kangaroo' },
  { engine: 'poda' },
  { preset: 'poda-quadruped', gait: 'trot' },
  { gait: 'transverse_gallop' },
  { speed_mps: 0.8, duty_factor: 0.6, period_s: 1.2, stroke_m: 0.3, hop_height_m: 0.1 },
  { phases: [0, 0.5, 0.25, 0.75], step_height_m: 0.08, transfer_keys: [[0.5, 1]] },
  { path: { kind: 'catmull_rom', points: [[0, 0], [0, 3], [2, 5]], closed: false } },
  { center: { joint: 'left_hind_knee_x', center: 1.2, gain: 1 } },
  { save: 'bvh' },
  { save: 'csv' },
  { save: { format: 'bvh', last_s: 0.5 } },
  { save: { format: 'csv', last_s: null } },
  { last_s: 5 },
  { editor_open: true, editor_text: '{}', editor_apply: true },
  { editor_revert: true, download_preset: true },
  { paper_alone: true },
  { views: { follow: false, grid: false, world_axes: true } },
  { camera: { yaw_deg: -35, pitch_deg: 20, distance_m: 4.25, target_m: [0.3, 0.5, 1.25] } },
  { camera: { yaw_rad: 0.5, pitch_rad: 0.2, follow_offset_m: [0, 0, 0], perspective: false } },
  { heading_deg: 15, plots: false },
  { lambda: 0.1, gamma_max: 0.7, max_step: 0.5, null_space_gain: 0.2, enforce_limits: true },
  { plot_joints: ['neck', 'left_elbow'] },
  { narrow: true },
  { narrow: null },
  { preset_json: '{"format":"gaitlab-preset/1"}' },
];

describe('command JSON Schema', () => {
  it('names itself', () => {
    assert.equal(schema.$schema, 'http://json-schema.org/draft-07/schema#');
    assert.match(schema.$id, /command\.schema\.json$/);
    assert.match(schema.title, /gaitlab/);
  });

  it('accepts every command the browser tests send', () => {
    assert.ok(sent.length >= 20);
    for (const command of sent) assert.equal(errors(command), '', JSON.stringify(command));
  });

  it('accepts a state().compare object sent back (metrics ignored)', () => {
    const saved = {
      views: ['pinv', 'dls'], scenario: 'script',
      options: [{ lambda: 0.1, gamma_max: 0.7, max_step: 0.5, rank_tolerance: 1e-6, null_space_gain: 0 },
        { lambda: 0.3, gamma_max: 0.7, max_step: 0.5, rank_tolerance: 1e-6, null_space_gain: 0 }],
      metrics: [{ mean_error_m: 0.01 }, { mean_error_m: 0.02 }],
    };
    assert.equal(errors({ compare: saved }), '');
  });

  it('rejects wrong types', () => {
    for (const bad of [
      { method: 7 },
      { paused: 'yes' },
      { speed_mps: 'fast' },
      { gain: { name: 'leg_stiffness', value: 'x' } },
      { camera: { target_m: [0, 1] } },
      { camera: [1, 2] },
      { compare: true },
      { save: 5 },
      { phases: [0.1, 'x'] },
      { theme: 'sepia' },
      { mode: 'fly' },
    ]) {
      assert.notEqual(errors(bad), '', JSON.stringify(bad));
    }
  });

  it('rejects unknown keys, at the top and nested', () => {
    for (const bad of [
      { launch: 'missiles' },
      { views: { sparkles: true } },
      { camera: { zoom: 2 } },
      { compare: { views: ['pinv', 'dls'], speed: 2 } },
      { save: { format: 'bvh', when: 'now' } },
      { gain: { name: 'leg_stiffness', value: 1, unit: 'N/m' } },
    ]) {
      assert.match(errors(bad), /must NOT have additional properties/, JSON.stringify(bad));
    }
  });

  it('requires the fields a nested object needs', () => {
    assert.match(errors({ gain: { value: 1 } }), /must have required property 'name'/);
    assert.match(errors({ center: { joint: 'left_hind_knee_x' } }), /must have required property 'center'/);
  });

  it('the state schema compiles and names itself', () => {
    assert.match(stateSchema.$id, /state\.schema\.json$/);
    assert.equal(typeof compile(stateSchema), 'function');
  });
});
