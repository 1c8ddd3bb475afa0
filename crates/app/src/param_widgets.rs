//! The panels' controls drawn from the parameter table (docs/parameters.md;
//! issue 41 item 1): a slider, drag value or checkbox that sets a value of
//! the table finds its row by key ([`Param::new`], in core's static tables),
//! keeps its range within the row's domain ([`Param::band`]), shows the row's
//! unit ([`Param::text`]), says the row's reference and origin in its tooltip
//! after its own words (formatted only while hovered: [`Param::hover`]), and
//! carries a small "lab" tag ([`lab_mark`]) when the value is the lab's
//! addition.
//!
//! A physics controller's gains are rows of the run's table
//! (`scenario.physics.controller.NAME`), not of a static one: the engine
//! layer's table is read once per controller ([`controller_rows`]).

use std::hash::{Hash as _, Hasher as _};
use std::ops::RangeInclusive;
use std::sync::Arc;

use gaitlab_core::Creature;
use gaitlab_core::ik::IK_PARAMS;
use gaitlab_core::params::{Domain, Origin, ParamSpec, SCENARIO_PARAMS};
use gaitlab_core::preset::{PHYSICS_PARAMS, PODA_PARAMS, THESIS_PARAMS};
use gaitlab_engine::{AnyDriver, Parameter};

/// Every static table a panel's control may set, searched in this order
/// (no key is in two of them).
const TABLES: [&[ParamSpec]; 5] = [
    SCENARIO_PARAMS,
    IK_PARAMS,
    THESIS_PARAMS,
    PODA_PARAMS,
    PHYSICS_PARAMS,
];

/// Defines the table keys the panels look up, one constant each, and
/// [`key::ALL`] listing them for the test that every one is a row.
macro_rules! keys {
    ($($(#[$doc:meta])* $name:ident = $key:literal;)*) => {
        $($(#[$doc])* pub(crate) const $name: &str = $key;)*
        /// Every key the panels look up.
        #[cfg(test)]
        pub(crate) const ALL: &[&str] = &[$($name),*];
    };
}

/// The table keys of the values the panels set.
pub(crate) mod key {
    keys! {
        /// The figure's heading (View panel).
        HEADING = "heading_deg";
        /// DLS damping λ.
        LAMBDA = "scenario.ik.lambda";
        /// SDLS γmax.
        GAMMA_MAX = "scenario.ik.gamma_max";
        /// Pinv's step clamp.
        MAX_STEP = "scenario.ik.max_step";
        /// The lab's clamp on every method.
        CLAMP_EVERY_METHOD = "scenario.ik.clamp_every_method";
        /// Buss's target clamp.
        TARGET_CLAMP = "scenario.ik.target_clamp_m";
        /// §4.4.1's α.
        TRANSPOSE_ALPHA = "scenario.ik.transpose_alpha";
        /// The rank tolerance (side-by-side cards).
        RANK_TOLERANCE = "scenario.ik.rank_tolerance";
        /// Eq. 6's null-space gain.
        NULL_SPACE_GAIN = "scenario.ik.null_space_gain";
        /// Joint limits on or off.
        ENFORCE_LIMITS = "scenario.ik.enforce_limits";
        /// Solves per iteration with limits.
        LIMIT_PASSES = "scenario.ik.limit_passes";
        /// §3.2's control way.
        JACOBIAN_AT = "scenario.ik.jacobian_at";
        /// The target script.
        SCRIPT = "scenario.thesis.script";
        /// §5.2.2's listing.
        LISTING = "scenario.thesis.listing";
        /// The lab script's walking cycle.
        WALK = "scenario.thesis.walk";
        /// The lab script's running cycle.
        RUN = "scenario.thesis.run";
        /// Where the wounded weights act.
        WOUND_FORM = "scenario.thesis.wound_form";
        /// The wounded joints' weights.
        WOUNDED = "scenario.thesis.wounded";
        /// The slowdown factor.
        SLOWDOWN = "scenario.thesis.slowdown";
        /// Moving forward.
        MOVING_FORWARD = "scenario.thesis.moving_forward";
        /// The thesis' forward speed.
        THESIS_SPEED = "scenario.thesis.speed_mps";
        /// The lab's posture pull.
        POSTURE_GAIN = "scenario.thesis.posture_gain";
        /// PODA's period P.
        PERIOD = "scenario.poda.period_s";
        /// PODA's duty factor.
        DUTY_FACTOR = "scenario.poda.duty_factor";
        /// PODA's body speed.
        PODA_SPEED = "scenario.poda.speed_mps";
        /// PODA's stroke (a live value).
        STROKE = "stroke_m";
        /// PODA's leg force (a live value).
        LEG_FORCE = "leg_force_n";
        /// PODA's step height.
        STEP_HEIGHT = "scenario.poda.step_height_m";
        /// PODA's relative phases.
        PHASES = "scenario.poda.phases";
        /// PODA's transfer key positions.
        TRANSFER_KEYS = "scenario.poda.transfer_keys";
        /// A PODA joint's centre and gain (a live value).
        CENTER = "center";
        /// The physics creature's desired speed.
        PHYSICS_SPEED = "scenario.physics.speed_mps";
        /// The physics creature's hop height.
        HOP_HEIGHT = "scenario.physics.hop_height_m";
        /// Table 1's scale L.
        SCALE = "scenario.physics.scale";
    }
}

/// The row with `key` of whichever static table has it.
///
/// # Panics
/// When no table has it: the keys are constants ([`key`]), and a test looks
/// every one up.
fn spec(key: &str) -> &'static ParamSpec {
    match TABLES.iter().flat_map(|t| t.iter()).find(|p| p.key == key) {
        Some(p) => p,
        None => panic!("no parameter table has a row {key}"),
    }
}

/// A row of the table as one control shows it: the unit (degrees for an
/// angle shown so) and the band a slider covers.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Param {
    /// The table's row.
    spec: &'static ParamSpec,
    /// Shown in degrees (a row in radians is converted).
    degrees: bool,
    /// The band the control covers, in the unit shown, within the row's
    /// range; `None`: the row's whole range.
    band: Option<(f64, f64)>,
}

impl Param {
    /// The control of the row `key` (a [`key`] constant).
    ///
    /// # Panics
    /// When no table has the row (see [`spec`]).
    #[must_use]
    pub(crate) fn new(key: &str) -> Self {
        Self {
            spec: spec(key),
            degrees: false,
            band: None,
        }
    }

    /// The page's command key that sets the row (`period_s`), or its key
    /// where it has none.
    #[must_use]
    pub(crate) fn command(self) -> &'static str {
        self.spec.command.unwrap_or(self.spec.key)
    }

    /// Whether the row is the lab's addition (its control carries the tag).
    #[must_use]
    pub(crate) fn is_lab(self) -> bool {
        self.spec.origin == Origin::Lab
    }

    /// Shown in degrees: a row in radians is converted, one in degrees
    /// (`deg`) is written `°`.
    #[must_use]
    pub(crate) fn in_degrees(mut self) -> Self {
        self.degrees = true;
        self
    }

    /// The control covers only `band` (in the unit shown), cut to the row's
    /// range; the tooltip says the whole range.
    #[must_use]
    pub(crate) fn band(mut self, band: RangeInclusive<f64>) -> Self {
        let (mut lo, mut hi) = (*band.start(), *band.end());
        if let Some((min, max, min_open, max_open)) = self.table_range() {
            // An open end is refused: stay a hair inside it.
            let inside = (max - min) * 1e-12;
            if lo < min || (min_open && lo <= min) {
                lo = if min_open { min + inside } else { min };
            }
            if hi > max || (max_open && hi >= max) {
                hi = if max_open { max - inside } else { max };
            }
        }
        self.band = Some((lo, hi.max(lo)));
        self
    }

    /// Factor from the row's unit to the unit shown.
    fn factor(self) -> f64 {
        if self.degrees && self.spec.unit == "rad" {
            1.0_f64.to_degrees()
        } else {
            1.0
        }
    }

    /// The row's range in the unit shown, with its open ends; `None` for a
    /// row that is not a number.
    #[expect(
        clippy::cast_precision_loss,
        reason = "integer bounds are small (at most thousands)"
    )]
    fn table_range(self) -> Option<(f64, f64, bool, bool)> {
        let k = self.factor();
        match self.spec.domain {
            Domain::Real {
                min,
                max,
                min_open,
                max_open,
            } => Some((min * k, max * k, min_open, max_open)),
            Domain::Integer { min, max } => Some((min as f64, max as f64, false, false)),
            Domain::Bool | Domain::Choice { .. } | Domain::Structured { .. } => None,
        }
    }

    /// The slider's range, in the unit shown: its band, or else the row's
    /// whole range (an open end a hair inside).
    #[must_use]
    pub(crate) fn range(self) -> RangeInclusive<f64> {
        if let Some((lo, hi)) = self.band {
            return lo..=hi;
        }
        match self.table_range() {
            Some((min, max, ..)) => {
                let whole = self.band(min..=max);
                whole.range()
            }
            // A structured row's control gives its band.
            None => 0.0..=1.0,
        }
    }

    /// A whole-number row's range (its band, or the row's own).
    #[must_use]
    pub(crate) fn count_range(self) -> RangeInclusive<usize> {
        let range = self.range();
        let count = |x: f64| {
            // Whole numbers of a small range: exact.
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a rounded, non-negative bound of a small range"
            )]
            let n = x.round().max(0.0) as usize;
            n
        };
        count(*range.start())..=count(*range.end())
    }

    /// The unit shown: the row's, or `°` in degrees.
    #[must_use]
    pub(crate) fn unit(self) -> &'static str {
        if self.degrees { "°" } else { self.spec.unit }
    }

    /// The control's label: `name (unit)` with the unit shown, or `name`
    /// for a pure number.
    #[must_use]
    pub(crate) fn text(self, name: &str) -> String {
        match self.unit() {
            "" => name.to_owned(),
            unit => format!("{name} ({unit})"),
        }
    }

    /// `response` with the tooltip: `hint` (the control's own words) first,
    /// then the row's reference and origin, then its range and key.
    /// Formatted only while hovered.
    pub(crate) fn hover(self, response: egui::Response, hint: &str) -> egui::Response {
        response.on_hover_ui(|ui| self.tooltip(ui, hint))
    }

    /// The tooltip's lines (see [`Param::hover`]).
    pub(crate) fn tooltip(self, ui: &mut egui::Ui, hint: &str) {
        if !hint.is_empty() {
            ui.label(hint);
        }
        ui.label(source_line(
            self.spec.reference,
            self.spec.origin,
            self.spec.why,
        ));
        ui.weak(self.range_line());
    }

    /// `scenario.ik.lambda: in (0, 10] m · this control 0.001–1 m · command
    /// lambda`: the key, the row's range and unit, the control's band where
    /// narrower (without a unit for a structured row, whose parts differ)
    /// and the command.
    fn range_line(self) -> String {
        let spec = self.spec;
        let range = match spec.domain {
            Domain::Real { .. } | Domain::Integer { .. } if !spec.unit.is_empty() => {
                format!("in {} {}", spec.domain.describe(), spec.unit)
            }
            Domain::Real { .. } | Domain::Integer { .. } => {
                format!("in {}", spec.domain.describe())
            }
            Domain::Bool => "on or off".to_owned(),
            // A structured row's shape names its units.
            Domain::Choice { .. } | Domain::Structured { .. } => spec.domain.describe(),
        };
        let mut line = format!("{}: {range}", spec.key);
        if let Some((lo, hi)) = self.band {
            let table = self.table_range();
            let whole = table.is_some_and(|(min, max, ..)| close(lo, min) && close(hi, max));
            if !whole {
                let shown = match self.unit() {
                    _ if table.is_none() => String::new(),
                    "" => String::new(),
                    "°" => "°".to_owned(),
                    unit => format!(" {unit}"),
                };
                line.push_str(&format!(
                    " · this control {}–{}{shown}",
                    number(lo),
                    number(hi)
                ));
            }
        }
        if let Some(command) = spec.command {
            line.push_str(&format!(" · command {command}"));
        }
        line
    }
}

/// Whether `a` and `b` are the same bound, but for the hair an open end
/// moves it.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-5 * (a.abs().max(b.abs()).max(1.0))
}

/// A band's end as people write it: at most four decimals, no trailing zeros.
fn number(x: f64) -> String {
    let text = format!("{x:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// The origin in words for a tooltip.
fn origin_words(origin: Origin) -> &'static str {
    match origin {
        Origin::Paper => "the paper's",
        Origin::Open => "a value the paper leaves open",
        Origin::Lab => "the lab's addition",
    }
}

/// `— She 2006 §4.4.3 · a value the paper leaves open: why`.
pub(crate) fn source_line(reference: &str, origin: Origin, why: &str) -> String {
    format!("— {reference} · {}: {why}", origin_words(origin))
}

/// The lab tag's colour: a violet readable on light and dark panels.
#[must_use]
pub(crate) fn lab_colour(visuals: &egui::Visuals) -> egui::Color32 {
    if visuals.dark_mode {
        egui::Color32::from_rgb(196, 160, 255)
    } else {
        egui::Color32::from_rgb(112, 56, 184)
    }
}

/// The words of the lab tag (the label a test finds it by).
pub(crate) const LAB_MARK: &str = "lab";

/// A small framed "lab" tag: the value beside it is the lab's addition,
/// not the paper's. Not a touch target (it senses hover only).
pub(crate) fn lab_mark(ui: &mut egui::Ui) -> egui::Response {
    let colour = lab_colour(ui.visuals());
    egui::Frame::new()
        .stroke(egui::Stroke::new(1.0, colour))
        .corner_radius(3.0)
        .inner_margin(egui::Margin::symmetric(3, 0))
        .show(ui, |ui| {
            ui.add(
                egui::Label::new(egui::RichText::new(LAB_MARK).small().color(colour))
                    .selectable(false),
            )
        })
        .inner
        .on_hover_text(
            "The lab's addition: behaviour the paper does not have (docs/parameters.md, \
             origin \"lab\")",
        )
}

/// Adds a control with `add`, followed on its row by the lab tag when `lab`.
pub(crate) fn marked(
    ui: &mut egui::Ui,
    lab: bool,
    add: impl FnOnce(&mut egui::Ui) -> egui::Response,
) -> egui::Response {
    if lab {
        ui.horizontal(|ui| {
            let response = add(ui);
            lab_mark(ui);
            response
        })
        .inner
    } else {
        add(ui)
    }
}

/// Adds the control `add` makes for `param`: the lab tag beside it when the
/// row is the lab's, and the tooltip of [`Param::hover`].
pub(crate) fn control(
    ui: &mut egui::Ui,
    param: Param,
    hint: &str,
    add: impl FnOnce(&mut egui::Ui) -> egui::Response,
) -> egui::Response {
    param.hover(marked(ui, param.is_lab(), add), hint)
}

/// Adds `widget` for `param` (see [`control`]).
pub(crate) fn add(
    ui: &mut egui::Ui,
    param: Param,
    widget: impl egui::Widget,
    hint: &str,
) -> egui::Response {
    control(ui, param, hint, |ui| ui.add(widget))
}

/// The start of a physics controller row's key.
const CONTROLLER_PREFIX: &str = "scenario.physics.controller.";

/// The running physics controller's rows of the run's table
/// (`scenario.physics.controller.NAME`: reference, origin, why), read from
/// the engine layer once per controller (`names`: its gains, which tell the
/// controllers apart) and kept in egui's memory.
pub(crate) fn controller_rows(
    ui: &egui::Ui,
    creature: &Creature,
    driver: &AnyDriver,
    names: impl Iterator<Item = &'static str>,
) -> Arc<Vec<Parameter>> {
    let slot = egui::Id::unique("gaitlab-controller-rows");
    let mut hasher = std::hash::DefaultHasher::new();
    for name in names {
        name.hash(&mut hasher);
    }
    let which = hasher.finish();
    if let Some((seen, rows)) = ui.data(|d| d.get_temp::<(u64, Arc<Vec<Parameter>>)>(slot))
        && seen == which
    {
        return rows;
    }
    let rows: Arc<Vec<Parameter>> = Arc::new(
        gaitlab_engine::parameters(creature, driver)
            .into_iter()
            .filter(|p| p.key.starts_with(CONTROLLER_PREFIX))
            .collect(),
    );
    ui.data_mut(|d| d.insert_temp(slot, (which, Arc::clone(&rows))));
    rows
}

/// A controller gain's tooltip lines after its own: the row's reference and
/// origin, then its key, range and unit, the slider's band (0 to `hi`) and
/// its command.
pub(crate) fn controller_tooltip(ui: &mut egui::Ui, row: &Parameter, hi: f64) {
    ui.label(source_line(&row.reference, row.origin, &row.why));
    let unit = if row.unit.is_empty() {
        String::new()
    } else {
        format!(" {}", row.unit)
    };
    let command = row
        .command
        .as_deref()
        .map_or_else(String::new, |c| format!(" · command {c}"));
    ui.weak(format!(
        "{}: in {}{unit} · this control 0–{}{unit}{command}",
        row.key,
        row.range,
        number(hi)
    ));
}

/// The row of controller parameter `name` among `rows`.
#[must_use]
pub(crate) fn controller_row<'a>(rows: &'a [Parameter], name: &str) -> Option<&'a Parameter> {
    rows.iter()
        .find(|p| p.key.strip_prefix(CONTROLLER_PREFIX) == Some(name))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_the_panels_look_up_is_a_row_of_one_table() {
        for key in key::ALL {
            let found = TABLES
                .iter()
                .flat_map(|t| t.iter())
                .filter(|p| p.key == *key)
                .count();
            assert_eq!(found, 1, "{key}: in {found} rows");
            assert_eq!(Param::new(key).spec.key, *key);
        }
    }

    #[test]
    fn the_lab_tag_marks_lab_rows_only() {
        assert!(Param::new(key::CLAMP_EVERY_METHOD).is_lab());
        assert!(Param::new(key::POSTURE_GAIN).is_lab());
        assert!(Param::new(key::LIMIT_PASSES).is_lab());
        assert!(!Param::new(key::GAMMA_MAX).is_lab(), "the paper's");
        assert!(!Param::new(key::LAMBDA).is_lab(), "open, not the lab's");
    }

    #[test]
    fn a_band_stays_within_the_rows_range_and_says_it() {
        // λ is (0, 10] m: a band past both ends is cut, the open end a hair inside.
        let lambda = Param::new(key::LAMBDA).band(-1.0..=50.0);
        let range = lambda.range();
        assert!(*range.start() > 0.0 && *range.start() < 1e-9, "{range:?}");
        assert!((*range.end() - 10.0).abs() < 1e-12, "{range:?}");
        // A narrower band is kept, and the tooltip says both.
        let lambda = Param::new(key::LAMBDA).band(0.001..=1.0);
        assert_eq!(lambda.range(), 0.001..=1.0);
        assert_eq!(
            lambda.range_line(),
            "scenario.ik.lambda: in (0, 10] m · this control 0.001–1 m · command lambda"
        );
        // γmax is (0, π] rad, shown in degrees: 1°–180°.
        let gamma = Param::new(key::GAMMA_MAX).in_degrees().band(1.0..=400.0);
        let range = gamma.range();
        assert!((*range.end() - 180.0).abs() < 1e-9, "{range:?}");
        assert_eq!(gamma.text("SDLS γmax"), "SDLS γmax (°)");
        assert_eq!(
            gamma.range_line(),
            "scenario.ik.gamma_max: in (0, π] rad · this control 1–180° · command gamma_max"
        );
        // A whole-number row without a band: the row's range.
        assert_eq!(Param::new(key::LIMIT_PASSES).count_range(), 1..=16);
        assert_eq!(Param::new(key::DUTY_FACTOR).range(), 0.05..=0.95);
        assert_eq!(Param::new(key::PERIOD).text("Period P"), "Period P (s)");
        assert_eq!(
            Param::new(key::HEADING).in_degrees().text("Heading"),
            "Heading (°)"
        );
    }

    #[test]
    fn the_source_line_names_reference_and_origin() {
        assert_eq!(
            source_line("She 2006 §4.4.3", Origin::Open, "why"),
            "— She 2006 §4.4.3 · a value the paper leaves open: why"
        );
        assert_eq!(
            source_line("docs/she-2006.md", Origin::Lab, "why"),
            "— docs/she-2006.md · the lab's addition: why"
        );
    }

    #[test]
    fn every_physics_gain_finds_its_controller_row_read_once() {
        for preset in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
            let creature = gaitlab_core::preset::load_bundled(preset)
                .expect("bundled")
                .expect("valid");
            let driver =
                gaitlab_engine::driver_for(&creature, &gaitlab_engine::Overrides::default())
                    .expect("a driver");
            let gains = driver.physics_readout().expect("physics").gains;
            let ctx = egui::Context::default();
            let mut output = ctx.run_ui(egui::RawInput::default(), |ui| {
                let rows = controller_rows(ui, &creature, &driver, gains.iter().map(|g| g.name));
                for gain in &gains {
                    let row = controller_row(&rows, gain.name);
                    assert!(row.is_some(), "{preset}: no row for {}", gain.name);
                }
                let again = controller_rows(ui, &creature, &driver, gains.iter().map(|g| g.name));
                assert!(Arc::ptr_eq(&rows, &again), "{preset}: read once");
            });
            output.textures_delta.clear();
        }
    }

    #[test]
    fn a_band_end_is_written_plainly() {
        assert_eq!(number(0.001), "0.001");
        assert_eq!(number(180.0), "180");
        assert_eq!(number(-1.0), "-1");
        assert_eq!(number(0.25), "0.25");
    }
}
