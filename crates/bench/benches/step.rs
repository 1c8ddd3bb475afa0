//! Criterion benchmark of one physics integration step (Raibert & Hodgins
//! 1991: controller, actuators, ground contact, articulated-body dynamics and
//! the semi-implicit Euler update, at the preset's 0.4 ms step) of each
//! Raibert preset, from the running state [`step_bench::warmed_driver`]
//! reaches — the state `gaitlab bench` times from.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use gaitlab_bench::step::{self as step_bench, StepBenchOptions};
use gaitlab_core::preset::load_bundled;

/// The physics presets timed.
const PRESETS: [&str; 3] = ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"];

fn physics_step(c: &mut Criterion) {
    let warmup_s = StepBenchOptions::default().warmup_s;
    let mut group = c.benchmark_group("physics_step");
    for name in PRESETS {
        let preset = match load_bundled(name) {
            Some(Ok(preset)) => preset,
            other => panic!("bundled preset {name}: {other:?}"),
        };
        let mut driver = match step_bench::warmed_driver(&preset, warmup_s) {
            Ok(driver) => driver,
            Err(error) => panic!("{name}: {error}"),
        };
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| black_box(driver.run_steps(1)));
        });
    }
    group.finish();
}

criterion_group!(benches, physics_step);
criterion_main!(benches);
