//! Criterion benchmarks of one animation frame of each kinematic engine: the
//! thesis driver (She 2006 §5.2.2's target script plus the frame's IK
//! iterations) on the human and the 63-joint quadruped, and the PODA gait
//! engine (Girard & Maciejewski 1985: leg states, footholds, foot targets and
//! every leg's IK) on the PODA quadruped and the hexapod. The drivers are
//! built by [`frame_bench::frame_driver`], the construction `gaitlab bench`
//! and `window.gaitlab.bench()` time.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use gaitlab_bench::frame::{self as frame_bench, FrameBenchOptions};
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;

fn frame(c: &mut Criterion, group_name: &str, presets: &[&str]) {
    let options = FrameBenchOptions::default();
    let mut group = c.benchmark_group(group_name);
    for &name in presets {
        let creature = match load_bundled(name) {
            Some(Ok(creature)) => creature,
            other => panic!("bundled preset {name}: {other:?}"),
        };
        let (mut driver, _) = match frame_bench::frame_driver(&creature, &options) {
            Ok(built) => built,
            Err(error) => panic!("{name}: {error}"),
        };
        // Reach steady tracking first, as the shared frame benchmark does.
        for _ in 0..options.warmup_frames {
            driver.step(options.frame_s);
        }
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| driver.step(options.frame_s));
        });
    }
    group.finish();
}

fn thesis_frame(c: &mut Criterion) {
    frame(c, "thesis_frame_sdls", &["human", "ik-quadruped"]);
}

fn poda_frame(c: &mut Criterion) {
    frame(c, "poda_frame", &["poda-quadruped", "hexapod"]);
}

criterion_group!(benches, thesis_frame, poda_frame);
criterion_main!(benches);
