//! The engines' catalogue: what a front end may ask about the engines without
//! reaching into a driver — Raibert & Hodgins 1991's gaits of each model
//! ("Gaits"), the speeds and scales each is tested at and Table 2 beside a
//! run; Girard & Maciejewski 1985's named gaits ("Gait Design in PODA"); She
//! 2006's parameter checks (§5.2, §6.2's workbench). Thin, documented
//! re-exposures of the engine crates' own functions, so the page's panels,
//! `state()` and the CLI ask one layer.

use gaitlab_core::preset::thesis::ThesisParams;
use gaitlab_physics::engine::metrics::GaitSummary;

use crate::metrics::Table2Entry;

/// Which of Raibert & Hodgins 1991's models a physics creature is (the
/// biped, the quadruped or the kangaroo): what [`physics_gaits`],
/// [`tested_speeds_mps`] and [`tested_scales`] are asked about.
pub use gaitlab_physics::Species;

/// The gaits of a physics model (Raibert & Hodgins 1991, "Gaits"), the
/// default first: what a gait menu lists.
#[must_use]
pub fn physics_gaits(species: Species) -> &'static [&'static str] {
    gaitlab_physics::control::gaits::table::gait_names(species)
}

/// The named PODA gaits for a creature of `leg_count` legs (Girard &
/// Maciejewski 1985, "Gait Design in PODA"), in table order.
#[must_use]
pub fn poda_gaits(leg_count: usize) -> Vec<&'static str> {
    gaitlab_motion::poda::gait_names(leg_count).collect()
}

/// The lowest and highest desired speed (m/s at scale 1) the 60-s sweep runs
/// `gait` of `species` at with no fall and the mean speed within 10 %
/// (docs/physics.md, "Gaits: a minute at several speeds"); `None` for a gait
/// the model does not have.
#[must_use]
pub fn tested_speeds_mps(species: Species, gait: &str) -> Option<(f64, f64)> {
    gaitlab_physics::control::gaits::table::tested_speeds_mps(species, gait)
}

/// The lowest and highest dynamic scale L (Table 1) `gait` of `species`
/// holds at, the middle of its tested speeds, by the same test
/// (`tools/physics_band_sweep.py`); `None` for a gait the model does not
/// have.
#[must_use]
pub fn tested_scales(species: Species, gait: &str) -> Option<(f64, f64)> {
    gaitlab_physics::control::gaits::table::tested_scales(species, gait)
}

/// Every row of Raibert & Hodgins 1991's Table 2 (the animation column) for
/// `gait` beside the run's figures in `summary` (`legs` names the
/// creature's legs, in leg order); empty for a gait the paper does not
/// tabulate. The comparison the page, `--json` and the docs print.
#[must_use]
pub fn table2(summary: &GaitSummary, gait: &str, legs: &[&str]) -> Vec<Table2Entry> {
    crate::metrics::table2_entries(summary, gait, legs)
}

/// Checks She 2006's motion parameters (§5.2's shapes, speeds and wounded
/// weights) before a front end hands them to the driver.
///
/// # Errors
/// The first bad value as `path: reason`.
pub fn check_thesis_params(params: &ThesisParams) -> Result<(), String> {
    gaitlab_motion::validate_params(params).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn physics_gaits_lead_with_the_default() {
        assert_eq!(physics_gaits(Species::Quadruped)[0], "trot");
        assert_eq!(physics_gaits(Species::Kangaroo), &["hop"]);
    }

    #[test]
    fn tested_bands_cover_only_the_models_gaits() {
        assert_eq!(
            tested_speeds_mps(Species::Kangaroo, "hop"),
            Some((2.0, 5.0))
        );
        assert_eq!(tested_speeds_mps(Species::Kangaroo, "trot"), None);
        assert_eq!(tested_scales(Species::Kangaroo, "trot"), None);
        assert!(tested_scales(Species::Biped, "run").is_some());
    }

    #[test]
    fn poda_gaits_fit_the_leg_count() {
        let six = poda_gaits(6);
        assert!(!six.is_empty());
        assert!(six.iter().all(|name| !name.is_empty()));
    }

    #[test]
    fn table2_has_a_row_per_paper_figure_and_none_for_an_untabulated_gait() {
        let summary = GaitSummary::default();
        let trot = table2(&summary, "trot", &["front_left", "front_right"]);
        assert!(!trot.is_empty());
        assert!(trot.iter().any(|row| row.input));
        assert!(table2(&summary, "no-such-gait", &[]).is_empty());
    }

    #[test]
    fn thesis_params_defaults_pass_the_check() {
        assert_eq!(check_thesis_params(&ThesisParams::default()), Ok(()));
    }
}
