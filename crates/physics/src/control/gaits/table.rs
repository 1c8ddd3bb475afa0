//! The gait table: one row per (species, gait) of Raibert & Hodgins 1991's
//! models ("Gaits"), each with its controller's builder, the state it starts
//! from, its virtual legs, the speeds and dynamic scales it is tested at and
//! the lab's additions it offers. Adding a gait is a folder in
//! [`crate::control::gaits`] and a row in [`GAITS`].
//!
//! The tested speeds are those the speed sweep runs each gait at
//! (docs/physics.md, "Gaits: a minute at several speeds",
//! `tools/physics_speed_sweep.py`): 60 s at each, with the presets' own lab
//! additions, no fall and the mean speed within 10 %. The tested scales are
//! the dynamic scales L (Table 1) each holds at the middle of those speeds by
//! the same test (`tools/physics_band_sweep.py`, of L = 0.25, 0.5, 1, 2, 4).
//! The app draws both ranges as bands under their sliders and warns outside
//! them. The quadruped's gallop runs 11–12 % slow at 2 and 4: scaled by Table
//! 1 the motion is the same but for rounding, and the gallop does not yet
//! survive a perturbation that small (docs/physics.md, "Switching into the
//! bound").

use std::sync::OnceLock;

use crate::control::additions::Offered;
use crate::control::gaits::gait::{Build, Start};
use crate::control::gaits::{biped_gallop, biped_run, bound, kangaroo_hop, pace, trot};
use crate::creatures::Species;
use crate::creatures::Species::{Biped, Kangaroo, Quadruped};

/// One (species, gait) row of the table.
#[derive(Debug)]
pub struct GaitRow {
    /// The model.
    pub species: Species,
    /// The gait's name, as presets and links spell it.
    pub gait: &'static str,
    /// Builds its controller.
    pub build: Build,
    /// Its own start; `None`: the creature starts from the preset's rest pose.
    pub start: Option<Start>,
    /// The virtual legs whose legs it means to act together, as indices
    /// into the creature's legs, the leg meant to land first first: none for
    /// one-legged running and hopping.
    pub virtual_legs: &'static [[usize; 2]],
    /// The lowest and highest desired speed it is tested at (m/s at scale 1).
    pub tested_speeds_mps: (f64, f64),
    /// The lowest and highest dynamic scale L it is tested at.
    pub tested_scales: (f64, f64),
    /// The lab's additions it offers, each with its default.
    pub offers: Offered,
}

impl GaitRow {
    /// A row from its columns, in the table's order.
    #[allow(clippy::too_many_arguments)]
    const fn new(
        species: Species,
        gait: &'static str,
        build: Build,
        start: Option<Start>,
        virtual_legs: &'static [[usize; 2]],
        tested_speeds_mps: (f64, f64),
        tested_scales: (f64, f64),
        offers: Offered,
    ) -> Self {
        Self {
            species,
            gait,
            build,
            start,
            virtual_legs,
            tested_speeds_mps,
            tested_scales,
            offers,
        }
    }
}

/// Every gait of every model, each model's default gait first. Columns:
/// species, gait, builder, own start (`None`: the preset's rest pose),
/// virtual legs, tested speeds (m/s at scale 1), tested scales L, the lab's
/// additions offered.
#[rustfmt::skip]
pub static GAITS: &[GaitRow] = &[
    GaitRow::new(Biped, "run", biped_run::build::build, None, &[], (1.0, 2.5), (0.25, 4.0), Offered::BIPED_RUN),
    GaitRow::new(Biped, "gallop", biped_gallop::build::build::<false>, None, &[[0, 1]], (1.0, 2.0), (0.25, 4.0), Offered::BIPED_GALLOP),
    GaitRow::new(Biped, "gallop_alternate", biped_gallop::build::build::<true>, None, &[[0, 1]], (1.0, 2.0), (0.25, 4.0), Offered::BIPED_GALLOP),
    GaitRow::new(Quadruped, "trot", trot::build::build, Some(trot::start::start), &trot::TROT_PAIRS, (1.0, 2.3), (0.25, 4.0), Offered::TROT),
    GaitRow::new(Quadruped, "bound", bound::build::build::<false>, Some(bound::start::start), &bound::PAIRS, (1.5, 2.8), (0.25, 4.0), Offered::BOUND),
    GaitRow::new(Quadruped, "gallop", bound::build::build::<true>, Some(bound::start::start), &bound::PAIRS, (1.5, 2.8), (0.25, 1.0), Offered::BOUND),
    GaitRow::new(Quadruped, "pace", pace::build::build, Some(trot::start::start), &pace::PACE_PAIRS, (1.3, 2.0), (0.25, 4.0), Offered::TROT),
    GaitRow::new(Kangaroo, "hop", kangaroo_hop::build::build, Some(kangaroo_hop::start::start), &[], (2.0, 5.0), (0.25, 4.0), Offered::KANGAROO_HOP),
];

/// The row of `gait` of `species`; `None` for a gait the model does not have.
#[must_use]
pub fn row(species: Species, gait: &str) -> Option<&'static GaitRow> {
    GAITS
        .iter()
        .find(|r| r.species == species && r.gait == gait)
}

/// The gaits of `species` in table order, its default first (listed from
/// the table once; a menu asks every frame).
#[must_use]
pub fn gait_names(species: Species) -> &'static [&'static str] {
    static NAMES: OnceLock<[Vec<&'static str>; 3]> = OnceLock::new();
    let names = NAMES.get_or_init(|| {
        [Species::Biped, Species::Quadruped, Species::Kangaroo].map(|s| {
            GAITS
                .iter()
                .filter(|r| r.species == s)
                .map(|r| r.gait)
                .collect()
        })
    });
    let i = match species {
        Species::Biped => 0,
        Species::Quadruped => 1,
        Species::Kangaroo => 2,
    };
    &names[i]
}

/// The lowest and highest desired speed (m/s at scale 1) `gait` of
/// `species` is tested at; `None` for a gait the model does not have.
#[must_use]
pub fn tested_speeds_mps(species: Species, gait: &str) -> Option<(f64, f64)> {
    row(species, gait).map(|r| r.tested_speeds_mps)
}

/// The dynamic scales L `gait` of `species` is tested at; `None` for a
/// gait the model does not have.
#[must_use]
pub fn tested_scales(species: Species, gait: &str) -> Option<(f64, f64)> {
    row(species, gait).map(|r| r.tested_scales)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each row is one gait of one model, with ranges that make sense and
    /// virtual legs of legs the model has; the defaults lead each model's list.
    #[test]
    fn each_row_is_one_gait_of_one_model() {
        let mut seen = std::collections::HashSet::new();
        for r in GAITS {
            assert!(
                seen.insert(format!("{:?} {}", r.species, r.gait)),
                "{} twice",
                r.gait
            );
            let (low, high) = r.tested_speeds_mps;
            assert!(0.0 < low && low < high, "{}: speeds", r.gait);
            let (small, large) = r.tested_scales;
            assert!(
                0.0 < small && small <= 1.0 && 1.0 <= large,
                "{}: scales",
                r.gait
            );
            let legs = match r.species {
                Species::Biped => 2,
                Species::Quadruped => 4,
                Species::Kangaroo => 1,
            };
            for pair in r.virtual_legs {
                assert!(
                    pair[0] != pair[1] && pair.iter().all(|&i| i < legs),
                    "{}",
                    r.gait
                );
            }
            assert_eq!(row(r.species, r.gait).map(|found| found.gait), Some(r.gait));
        }
        assert_eq!(gait_names(Species::Biped)[0], "run");
        assert_eq!(gait_names(Species::Quadruped)[0], "trot");
        assert_eq!(gait_names(Species::Kangaroo), &["hop"]);
        assert!(row(Species::Kangaroo, "trot").is_none());
    }

    #[test]
    fn every_gait_of_every_model_has_a_tested_range() {
        for species in [Species::Biped, Species::Quadruped, Species::Kangaroo] {
            for gait in gait_names(species) {
                let (low, high) = tested_speeds_mps(species, gait).expect("a range");
                assert!(0.0 < low && low < high, "{gait}");
            }
        }
        assert_eq!(tested_speeds_mps(Species::Kangaroo, "trot"), None);
    }

    /// The ranges are the sweep's: the lowest and highest of the speeds
    /// `tools/physics_speed_sweep.py` runs each gait at.
    #[test]
    fn the_ranges_are_the_sweeps() {
        let tool = include_str!("../../../../../tools/physics_speed_sweep.py");
        let mut checked = 0;
        for line in tool.lines().map(str::trim) {
            let Some(rest) = line.strip_prefix("(\"raibert-") else {
                continue;
            };
            let fields: Vec<&str> = rest.split('"').collect();
            let (model, gait) = (fields[0], fields[2]);
            let speeds: Vec<f64> = rest[rest.find('[').expect("[") + 1..rest.find(']').expect("]")]
                .split(',')
                .map(|v| v.trim().parse().expect("a speed"))
                .collect();
            let species = match model {
                "biped" => Species::Biped,
                "quadruped" => Species::Quadruped,
                _ => Species::Kangaroo,
            };
            let low = speeds.iter().copied().fold(f64::INFINITY, f64::min);
            let high = speeds.iter().copied().fold(0.0, f64::max);
            assert_eq!(
                tested_speeds_mps(species, gait),
                Some((low, high)),
                "{model} {gait}"
            );
            checked += 1;
        }
        assert_eq!(
            checked,
            GAITS.len(),
            "every gait of the table is in the sweep"
        );
    }
}
