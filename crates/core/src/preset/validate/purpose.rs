//! What a preset is loaded for ([`Purpose`]): running its scenario or
//! tracking recorded targets, which decides whether the thesis roles apply.

/// What a preset is loaded for. A rule is checked where the loaded preset uses
/// what it checks: the thesis roles (`scenario.thesis.roles`) only where the
/// She 2006 target script will drive them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Purpose {
    /// Running the preset's scenario (the app, `gaitlab run`, `gaitlab validate`):
    /// every rule. The roles are checked when the engine is `ik` and the skeleton
    /// has at least [`THESIS_ROLE_COUNT`](crate::preset::THESIS_ROLE_COUNT) effectors, since every thesis mode
    /// (walk, run, wounded walk, wounded run) drives the four role effectors.
    #[default]
    Scenario,
    /// Following recorded effector targets with the skeleton (`gaitlab track`):
    /// the target script never runs, so the roles are not checked; every other
    /// rule is (tracking reads the skeleton, `scenario.ik`, `method`, `fps` and
    /// `thesis.iterations_per_frame`).
    Tracking,
}
