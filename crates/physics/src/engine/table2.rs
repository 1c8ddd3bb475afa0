//! Raibert & Hodgins 1991, Table 2: the paper's figures for each gait (the
//! physical robot or animal, and the paper's animation), keyed to the
//! quantities [`crate::engine::metrics::GaitSummary`] measures, so the app, the CLI
//! and the docs can put ours beside theirs.

use crate::engine::metrics::GaitSummary;

/// Which measured quantity a row compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// Peak-to-peak trunk pitch per stride (deg).
    PitchDeg,
    /// Peak-to-peak trunk roll per stride (deg).
    RollDeg,
    /// Stride length (m).
    StrideLengthM,
    /// Stride duration (s).
    StrideDurationS,
    /// One step's length (m): the biped's Table-2 "stride" (flight + one
    /// stance), half of a full left–right cycle.
    StepLengthM,
    /// One step's duration (s), half of a full left–right cycle.
    StepDurationS,
    /// Mean flight duration (s).
    FlightS,
    /// Gathered flight (after the front legs lift off; bound) (s).
    GatheredFlightS,
    /// Extended flight (after the rear legs lift off; bound) (s).
    ExtendedFlightS,
    /// Mean stance duration (s).
    StanceS,
    /// Front legs' stance (s).
    StanceFrontS,
    /// Rear legs' stance (s).
    StanceRearS,
    /// Change of leg length during support (m).
    LegLengthChangeM,
    /// Mean running speed (m/s).
    SpeedMps,
    /// Peak vertical acceleration (g).
    PeakAccelG,
    /// Tail wag relative to the trunk, peak to peak (deg).
    TailWagDeg,
}

/// One row of Table 2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperRow {
    /// The quantity as the paper words it.
    pub label: &'static str,
    /// What it compares to.
    pub quantity: Quantity,
    /// The robot's or animal's figure.
    pub robot: f64,
    /// The paper's animation.
    pub animation: f64,
}

const fn row(label: &'static str, quantity: Quantity, robot: f64, animation: f64) -> PaperRow {
    PaperRow {
        label,
        quantity,
        robot,
        animation,
    }
}

const BOUND: [PaperRow; 9] = [
    row("pitch magnitude (deg)", Quantity::PitchDeg, 26.4, 25.8),
    row("stride length (m)", Quantity::StrideLengthM, 1.15, 1.22),
    row("stride duration (s)", Quantity::StrideDurationS, 0.37, 0.43),
    row("gathered flight (s)", Quantity::GatheredFlightS, 0.11, 0.22),
    row("extended flight (s)", Quantity::ExtendedFlightS, 0.04, 0.03),
    row("stance, front legs (s)", Quantity::StanceFrontS, 0.10, 0.10),
    row("stance, rear legs (s)", Quantity::StanceRearS, 0.12, 0.08),
    row(
        "change of leg length in support (m)",
        Quantity::LegLengthChangeM,
        0.085,
        0.092,
    ),
    row("running speed (m/s)", Quantity::SpeedMps, 2.9, 2.8),
];

const TROT: [PaperRow; 7] = [
    row("pitch magnitude (deg)", Quantity::PitchDeg, 2.2, 6.2),
    row("stride length (m)", Quantity::StrideLengthM, 1.84, 1.49),
    row("stride duration (s)", Quantity::StrideDurationS, 0.80, 0.54),
    row("flight duration (s)", Quantity::FlightS, 0.27, 0.18),
    row("stance duration (s)", Quantity::StanceS, 0.12, 0.09),
    row(
        "change of leg length in support (m)",
        Quantity::LegLengthChangeM,
        0.04,
        0.03,
    ),
    row("desired running speed (m/s)", Quantity::SpeedMps, 2.3, 2.3),
];

const BIPED_RUN: [PaperRow; 7] = [
    row("pitch magnitude (deg)", Quantity::PitchDeg, 2.0, 3.4),
    row("roll magnitude (deg)", Quantity::RollDeg, 6.7, 11.5),
    row(
        "stride length (m), one step",
        Quantity::StepLengthM,
        0.57,
        0.74,
    ),
    row(
        "stride duration (s), one step",
        Quantity::StepDurationS,
        0.36,
        0.47,
    ),
    row("flight duration (s)", Quantity::FlightS, 0.18, 0.29),
    row("stance duration (s)", Quantity::StanceS, 0.18, 0.18),
    row(
        "change of leg length in support (m)",
        Quantity::LegLengthChangeM,
        0.01,
        0.04,
    ),
];

const KANGAROO_HOP: [PaperRow; 8] = [
    row(
        "peak vertical acceleration (g)",
        Quantity::PeakAccelG,
        5.0,
        4.6,
    ),
    row("pitch magnitude (deg)", Quantity::PitchDeg, 10.0, 12.0),
    row(
        "tail wag relative to trunk (deg)",
        Quantity::TailWagDeg,
        30.0,
        31.0,
    ),
    row("stride length (m)", Quantity::StrideLengthM, 2.2, 1.5),
    row("stride duration (s)", Quantity::StrideDurationS, 0.35, 0.35),
    row("flight duration (s)", Quantity::FlightS, 0.25, 0.24),
    row("stance duration (s)", Quantity::StanceS, 0.10, 0.11),
    row("running speed (m/s)", Quantity::SpeedMps, 6.2, 5.0),
];

/// Table 2's rows for a gait (`run` for the biped, `trot`, `bound`, `hop`);
/// empty for gaits the paper does not tabulate.
#[must_use]
pub fn paper_rows(gait: &str) -> &'static [PaperRow] {
    match gait {
        "run" => &BIPED_RUN,
        "trot" => &TROT,
        "bound" => &BOUND,
        "hop" => &KANGAROO_HOP,
        _ => &[],
    }
}

/// The speed at which the paper's animation ran each gait (m/s): what a
/// side-by-side comparison should ask for.
#[must_use]
pub fn paper_speed_mps(gait: &str) -> Option<f64> {
    match gait {
        "run" => Some(1.6),
        "trot" => Some(2.3),
        "bound" => Some(2.8),
        "hop" => Some(5.0),
        _ => None,
    }
}

/// Our measured value of a quantity; `None` when the run has no such figure
/// (no flights yet, or a quantity this creature lacks).
#[must_use]
pub fn measured(summary: &GaitSummary, quantity: Quantity, legs: &[&str]) -> Option<f64> {
    let positive = |x: f64| (x > 0.0 && x.is_finite()).then_some(x);
    let stance_of = |front: bool| {
        let (sum, n) = legs
            .iter()
            .zip(&summary.leg_stance_s)
            .filter(|(name, t)| name.starts_with("front") == front && **t > 0.0)
            .fold((0.0, 0), |(s, n), (_, t)| (s + t, n + 1));
        (n > 0).then(|| sum / f64::from(n))
    };
    let flight_after = |front: bool| {
        let (sum, n) = summary
            .flights
            .iter()
            .filter(|f| {
                legs.get(f.last_leg)
                    .is_some_and(|name| name.starts_with("front") == front)
            })
            .fold((0.0, 0), |(s, n), f| (s + f.end_s - f.start_s, n + 1));
        (n > 0).then(|| sum / f64::from(n))
    };
    match quantity {
        Quantity::PitchDeg => positive(summary.pitch_magnitude_deg),
        Quantity::RollDeg => positive(summary.roll_magnitude_deg),
        Quantity::StrideLengthM => positive(summary.stride_length_m),
        Quantity::StrideDurationS => positive(summary.stride_duration_s),
        Quantity::StepLengthM => positive(summary.stride_length_m / 2.0),
        Quantity::StepDurationS => positive(summary.stride_duration_s / 2.0),
        Quantity::FlightS => positive(summary.flight_duration_s),
        Quantity::GatheredFlightS => flight_after(true),
        Quantity::ExtendedFlightS => flight_after(false),
        Quantity::StanceS => positive(summary.stance_duration_s),
        Quantity::StanceFrontS => stance_of(true),
        Quantity::StanceRearS => stance_of(false),
        Quantity::LegLengthChangeM => positive(summary.leg_length_change_m),
        Quantity::SpeedMps => Some(summary.speed_mean_mps),
        Quantity::PeakAccelG => positive(summary.peak_vertical_accel_g),
        Quantity::TailWagDeg => summary.tail_wag_deg,
    }
}
