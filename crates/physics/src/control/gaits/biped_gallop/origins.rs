//! Where the biped gallops' named parameters come from (Raibert & Hodgins
//! 1991, "Gaits", eqs. 1–5): their own rows, then the one-legged hopper's.

use gaitlab_core::params::Origin;

use crate::control::gaits::biped_gallop::BipedGallop;
use crate::control::gaits::biped_run::origins::HOPPER;
use crate::control::gaits::gait::Gait;
use crate::control::gaits::origins::{ControllerParam, GALLOP, LAB, concat, row};

/// The biped gallop's own rows, before the hopper's.
const GALLOP_OWN: [ControllerParam; 8] = [
    row(
        "trail_offset_m",
        "Trailing foot's extra forward placement",
        "m",
        LAB,
        Origin::Lab,
        "A term added to eq. 3's neutral point (0 by default: eq. 3 as printed)",
    ),
    row(
        "lead_offset_m",
        "Leading foot's extra forward placement",
        "m",
        LAB,
        Origin::Lab,
        "A term added to eq. 3's neutral point (0 by default: eq. 3 as printed)",
    ),
    row(
        "lead_retract_m",
        "Leading leg held short before the trailing touchdown",
        "m",
        GALLOP,
        Origin::Open,
        "The paper's gallop lands the legs apart in time without saying how: the lead 8 cm short",
    ),
    row(
        "lead_delay_s",
        "Delay before the leading leg lengthens for landing",
        "s",
        GALLOP,
        Origin::Open,
        "Spaces the two touchdowns in time, as the paper's gallop does; no value printed",
    ),
    row(
        "lead_extend_mps",
        "Leading leg's lengthening rate for landing",
        "m/s",
        LAB,
        Origin::Lab,
        "A rate of the lab's: Figure 4 lengthens the leg for landing without one",
    ),
    row(
        "trail_extend_mps",
        "Trailing leg's lengthening rate in flight",
        "m/s",
        LAB,
        Origin::Lab,
        "A rate of the lab's: Figure 4 lengthens the leg for landing without one",
    ),
    row(
        "trail_unload_mps",
        "Trailing leg's shortening rate in unloading",
        "m/s",
        LAB,
        Origin::Lab,
        "A rate of the lab's, handing the load to the leading leg; Figure 4 gives none",
    ),
    row(
        "pitch_feedforward",
        "Stance pitch feedforward against the flight's pitching",
        "",
        LAB,
        Origin::Lab,
        "A feedforward setting eq. 4's ϕ_d from the flight's pitching; the paper's ϕ_d is fixed",
    ),
];

const ROWS: [ControllerParam; 28] = concat(&GALLOP_OWN, &HOPPER);

/// [`BipedGallopParams`](crate::control::gaits::biped_gallop::params::BipedGallopParams)' parameters (both styles), in
/// [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES) order.
pub const ORIGINS: &[ControllerParam] = &ROWS;

impl Gait for BipedGallop {
    fn origins(&self) -> &'static [ControllerParam] {
        ORIGINS
    }
}
