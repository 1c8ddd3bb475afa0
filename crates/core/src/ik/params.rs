//! The IK solver's rows of the parameter table (She 2006 §4.4): damping λ,
//! SDLS's γmax, pinv's step clamp and the lab's clamp on every method,
//! §4.4.1's α, the rank tolerance, PODA eq. 6's null-space gain, joint
//! limits and §3.2's control way; with the range checks presets and stored
//! settings share.

use std::f64::consts::PI;

use super::IkOptions;
use crate::params::{Domain, Origin, ParamSpec};
use crate::preset::PresetError;

/// `scenario.ik.*`.
pub const IK_PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "scenario.ik.lambda",
        command: Some("lambda"),
        label: "DLS damping λ",
        unit: "m",
        domain: Domain::above(0.0, 10.0),
        live: true,
        reference: "She 2006 §4.4.3",
        origin: Origin::Open,
        why: "the thesis names no λ (it \"must be chosen very carefully\"); 0.2 m is a measured sweep's pick (docs/she-2006.md, Choosing λ)",
    },
    ParamSpec {
        key: "scenario.ik.gamma_max",
        command: Some("gamma_max"),
        label: "SDLS largest joint change γmax",
        unit: "rad",
        domain: Domain::above(0.0, PI),
        live: true,
        reference: "She 2006 §4.4.5 (Buss & Kim 2005)",
        origin: Origin::Paper,
        why: "π/4, the thesis' value (printed 4/π)",
    },
    ParamSpec {
        key: "scenario.ik.max_step",
        command: Some("max_step"),
        label: "Pseudoinverse step clamp (largest joint change per iteration)",
        unit: "rad",
        domain: Domain::above(0.0, PI),
        live: true,
        reference: "She 2006 §4.4.2",
        origin: Origin::Open,
        why: "§4.4.2 clamps pinv's \"maximum rotation angle changed value\" without giving it; 0.2 rad is Buss's code's",
    },
    ParamSpec {
        key: "scenario.ik.clamp_every_method",
        command: Some("clamp_every_method"),
        label: "Step clamp on transpose and DLS too",
        unit: "",
        domain: Domain::Bool,
        live: true,
        reference: "docs/she-2006.md",
        origin: Origin::Lab,
        why: "§4.4.2 clamps pinv only; Buss's code clamps every method",
    },
    ParamSpec {
        key: "scenario.ik.target_clamp_m",
        command: Some("target_clamp_m"),
        label: "Target clamp (longest effector error a solve sees; 0 off)",
        unit: "m",
        domain: Domain::closed(0.0, 10.0),
        live: true,
        reference: "Buss's IK code (CalcdTClampedFromdS, BaseMaxTargetDist 0.4)",
        origin: Origin::Lab,
        why: "the thesis clamps no target; Buss's SDLS clamps each effector's error to 0.4 of his scene's units",
    },
    ParamSpec {
        key: "scenario.ik.transpose_alpha",
        command: Some("transpose_alpha"),
        label: "Transpose step α",
        unit: "",
        domain: Domain::Choice {
            options: &["thesis", "buss"],
        },
        live: true,
        reference: "She 2006 §4.4.1",
        origin: Origin::Paper,
        why: "\"thesis\" is §4.4.1's α = Δs·Δt / (2|Δt|²); \"buss\" (twice it) is Buss's",
    },
    ParamSpec {
        key: "scenario.ik.rank_tolerance",
        command: None,
        label: "Pseudoinverse rank tolerance (share of the largest singular value)",
        unit: "",
        domain: Domain::open(0.0, 1.0),
        live: false,
        reference: "She 2006 §4.4.2; Girard & Maciejewski 1985 eq. 4–5",
        origin: Origin::Open,
        why: "neither paper gives one; 1e-6 drops only numerically zero singular values",
    },
    ParamSpec {
        key: "scenario.ik.null_space_gain",
        command: Some("null_space_gain"),
        label: "Null-space gain k toward the centre angles (pinv and DLS)",
        unit: "",
        domain: Domain::closed(0.0, 10.0),
        live: true,
        reference: "Girard & Maciejewski 1985 eq. 6",
        origin: Origin::Paper,
        why: "PODA's null-space term; the thesis has none, so 0 (off) for the thesis' presets",
    },
    ParamSpec {
        key: "scenario.ik.enforce_limits",
        command: Some("enforce_limits"),
        label: "Keep joints within their limits (clamp and re-solve)",
        unit: "",
        domain: Domain::Bool,
        live: true,
        reference: "She 2006 §3.1",
        origin: Origin::Paper,
        why: "the thesis' joints have limits",
    },
    ParamSpec {
        key: "scenario.ik.limit_passes",
        command: Some("limit_passes"),
        label: "Solves per iteration while joints hit their limits",
        unit: "",
        domain: Domain::Integer { min: 1, max: 16 },
        live: true,
        reference: "She 2006 §6.1.1.1",
        origin: Origin::Lab,
        why: "1 clamps each joint to its limits, the thesis' way; more passes re-solve without the clamped joints, the lab's (the code's default 4)",
    },
    ParamSpec {
        key: "scenario.ik.jacobian_at",
        command: Some("jacobian_at"),
        label: "Jacobian at the end effectors or at the targets",
        unit: "",
        domain: Domain::Choice {
            options: &["effectors", "targets"],
        },
        live: true,
        reference: "She 2006 §3.2",
        origin: Origin::Paper,
        why: "§3.2's two control ways, read as Buss's Jend and Jtarget (docs/ik-control-ways.md)",
    },
];

/// IK options in range, by [`IK_PARAMS`]: λ in (0, 10] m, γmax and max_step
/// in (0, π], rank tolerance in (0, 1), null-space gain in [0, 10], the
/// target clamp in [0, 10] m, 1..=16
/// limit passes. Shared by presets and by settings restored from storage.
///
/// # Errors
/// A [`PresetError`] naming the first value out of range under `prefix`.
pub fn check_ik_options(prefix: &str, ik: &IkOptions) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    let spec = |field: &str| crate::params::row(IK_PARAMS, &format!("scenario.ik.{field}"));
    for (field, value) in [
        ("lambda", ik.lambda),
        ("gamma_max", ik.gamma_max),
        ("max_step", ik.max_step),
        ("rank_tolerance", ik.rank_tolerance),
        ("null_space_gain", ik.null_space_gain),
        ("target_clamp_m", ik.target_clamp_m),
    ] {
        spec(field).check_real(&at(field), value)?;
    }
    spec("limit_passes").check_integer(&at("limit_passes"), ik.limit_passes)
}
