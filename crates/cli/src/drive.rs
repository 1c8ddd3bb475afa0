//! Running any driver headless for a number of frames: timing it and
//! streaming its frames to `--bvh` / `--csv` through the engine layer's
//! [`FrameWriter`] (the same writer the page's take uses), and a simulation's
//! every step to `--trace` through its [`StepTrace`].

use std::time::Instant;

use clap::Args;

use gaitlab_core::driver::Driver;
use gaitlab_engine::metrics::pose_within_limits;
use gaitlab_engine::{AnyDriver, FrameWriter, StepTrace, Timing};

use crate::fail::Failure;
use crate::options::written_frames;
use crate::schedule::Schedule;
use crate::sink::FileSink;

/// Output options shared by `run` and `track`.
#[derive(Args, Debug, Default)]
pub struct Outputs {
    /// Write the motion as BVH to this file.
    #[arg(long)]
    pub bvh: Option<String>,
    /// Write per-frame joint values, effector positions and targets as CSV to this file.
    #[arg(long)]
    pub csv: Option<String>,
    /// Print one JSON object of metrics.
    #[arg(long)]
    pub json: bool,
    /// Write only the last S seconds of the motion to --bvh and --csv (the
    /// browser's "Save the last S s"; rounded to whole frames, at least one).
    #[arg(long, value_name = "S")]
    pub last: Option<f64>,
}

/// One output file and its writer.
struct Stream<'a> {
    sink: FileSink,
    writer: FrameWriter<'a>,
}

impl<'a> Stream<'a> {
    fn open(path: &str, mut writer: FrameWriter<'a>, frames: usize) -> Result<Self, Failure> {
        let mut sink = FileSink::create(path)?;
        writer.begin(&mut sink, frames).map_err(|e| sink.fail(e))?;
        Ok(Self { sink, writer })
    }

    fn finish(mut self) -> Result<(), Failure> {
        self.writer.finish().map_err(|e| self.sink.fail(e))?;
        self.sink.finish()
    }
}

/// Steps `driver` `frames` times at `1/fps`, applying the `schedule`'s live
/// changes as their times come, writing every frame to the requested outputs
/// (only the last `--last` seconds of them, if asked) and every simulation
/// step to the `trace` file, if any (the caller has checked that the engine
/// has one).
pub fn drive(
    driver: &mut AnyDriver,
    frames: usize,
    fps: f64,
    outputs: &Outputs,
    trace: Option<&str>,
    schedule: &mut Schedule,
) -> Result<Timing, Failure> {
    let dt = 1.0 / fps;
    let written = written_frames(outputs.last, frames, fps)?;
    let first_written = frames - written;
    let skeleton = driver.skeleton().clone();
    let mut streams = Vec::with_capacity(2);
    if let Some(path) = outputs.bvh.as_deref() {
        let writer = FrameWriter::bvh(&skeleton, fps).map_err(Failure::input)?;
        streams.push(Stream::open(path, writer, written)?);
    }
    if let Some(path) = outputs.csv.as_deref() {
        let writer = FrameWriter::csv(&skeleton, driver.targets().is_some());
        streams.push(Stream::open(path, writer, written)?);
    }
    let mut trace = match trace {
        None => None,
        Some(path) => {
            let mut sink = FileSink::create(path).map_err(|failure| Failure {
                message: format!("--trace {}", failure.message),
                code: failure.code,
            })?;
            match StepTrace::begin(driver, &mut sink) {
                Ok(writer) => Some((sink, writer)),
                Err(Some(error)) => return Err(sink.fail(error)),
                Err(None) => {
                    return Err(Failure::input(
                        "--trace: this engine has no simulation to trace",
                    ));
                }
            }
        }
    };
    let start = Instant::now();
    let mut step_seconds = 0.0;
    let mut within_limits = true;
    for frame in 0..frames {
        schedule.apply_due(driver, driver.time(), dt);
        let before = Instant::now();
        match &mut trace {
            None => driver.step(dt),
            Some((sink, writer)) => writer.step(driver, dt, sink).map_err(|e| sink.fail(e))?,
        }
        step_seconds += before.elapsed().as_secs_f64();
        let pose = driver.pose();
        within_limits &= pose_within_limits(&skeleton, pose);
        if frame < first_written {
            continue;
        }
        let targets = driver.targets().map_or(&[][..], |t| &t.position[..]);
        for stream in &mut streams {
            stream
                .writer
                .frame(
                    &mut stream.sink,
                    driver.time(),
                    pose,
                    driver.effector_positions(),
                    targets,
                )
                .map_err(|e| stream.sink.fail(e))?;
        }
    }
    for stream in streams {
        stream.finish()?;
    }
    if let Some((sink, _)) = trace {
        sink.finish()?;
    }
    Ok(Timing {
        frames,
        step_ms: step_seconds * 1e3,
        wall_ms: start.elapsed().as_secs_f64() * 1e3,
        within_limits,
    })
}
