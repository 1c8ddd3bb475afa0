//! Side-by-side comparison of IK methods (She 2006 §4.4: transpose, pinv,
//! DLS, SDLS; PODA eq. 6's null-space centering; CCD as a non-Jacobian
//! contrast): 2 or 4 views, each its own [`ThesisDriver`] with its own solver
//! configuration, on the same creature, mode and parameters, advanced in lock
//! step (same `dt`, same frame), so every view sees the same targets. Per view:
//! tracking error (She 2006 §5.3's `d`), wall time per IK iteration, joint
//! velocity jitter and limit hits. The "singularity" scenario pulls every limb
//! target to about its full reach ([`gaitlab_motion::stretch`]).
//!
//! # The `compare` command and state (DESIGN.md "Browser")
//! `{"compare": {"views": [NAME, …], "scenario": "script" | "singularity",
//! "options": [{"lambda", "gamma_max", "max_step", "rank_tolerance",
//! "null_space_gain"}, …]}}` starts (or reconfigures) a comparison; `views`
//! holds 2 or 4 of [`CompareMethod::ALL`]'s names, `scenario` and `options`
//! (one object per view, each key optional) may be left out. `{"compare":
//! false}` leaves it. `state().compare` is that same object plus a
//! `metrics` array (ignored by the command), so passing it back verbatim
//! restores the configuration; it is `null` when no comparison runs.

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::{Kinematics, Skeleton};
use gaitlab_motion::ThesisDriver;
use gaitlab_motion::stretch::StretchOptions;
use serde_json::{Map, Value, json};

use crate::history::History;
use crate::render::Scene;
use crate::view::ViewOptions;

/// Frames in the jitter window (4 s at 60 fps).
pub const JITTER_WINDOW_FRAMES: usize = 240;

/// A solver configuration a view can run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareMethod {
    /// Jacobian transpose (§4.4.1).
    Transpose,
    /// Pseudoinverse (§4.4.2).
    Pinv,
    /// Damped least squares (§4.4.3).
    Dls,
    /// Selectively damped least squares (§4.4.5).
    Sdls,
    /// Pseudoinverse with PODA's null-space centering (eq. 6).
    PinvCentering,
    /// DLS with PODA's null-space centering.
    DlsCentering,
    /// Cyclic coordinate descent.
    Ccd,
}

/// Which slider a method's card shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parameter {
    /// DLS damping λ, metres.
    Lambda,
    /// SDLS γmax, radians.
    GammaMax,
    /// Step clamp α, radians per iteration.
    MaxStep,
    /// Rank tolerance (relative to σmax).
    RankTolerance,
    /// Null-space gain k.
    NullSpaceGain,
}

impl CompareMethod {
    /// Every configuration.
    pub const ALL: [CompareMethod; 7] = [
        CompareMethod::Transpose,
        CompareMethod::Pinv,
        CompareMethod::Dls,
        CompareMethod::Sdls,
        CompareMethod::PinvCentering,
        CompareMethod::DlsCentering,
        CompareMethod::Ccd,
    ];

    /// Short name used in commands and state.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            CompareMethod::Transpose => "transpose",
            CompareMethod::Pinv => "pinv",
            CompareMethod::Dls => "dls",
            CompareMethod::Sdls => "sdls",
            CompareMethod::PinvCentering => "pinv-ns",
            CompareMethod::DlsCentering => "dls-ns",
            CompareMethod::Ccd => "ccd",
        }
    }

    /// Parses [`CompareMethod::name`].
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Human label.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            CompareMethod::Transpose => "Jacobian transpose",
            CompareMethod::Pinv => "Pseudoinverse",
            CompareMethod::Dls => "Damped least squares",
            CompareMethod::Sdls => "Selectively damped LS",
            CompareMethod::PinvCentering => "Pseudoinverse + centering",
            CompareMethod::DlsCentering => "DLS + centering",
            CompareMethod::Ccd => "Cyclic coordinate descent",
        }
    }

    /// The method's update rule in Unicode text (`^T` transpose, `_i` subscript).
    #[must_use]
    pub fn formula(self) -> &'static str {
        // Only glyphs egui's bundled monospace font (Hack) has: no ᵀ or ᵢ.
        match self {
            CompareMethod::Transpose => "Δθ = α J^T e,  α = ⟨e, JJ^T e⟩ / ‖JJ^T e‖²",
            CompareMethod::Pinv => "Δθ = J⁺e = Σ σ_i⁻¹ v_i u_i^T e",
            CompareMethod::Dls => "Δθ = J^T (JJ^T + λ²I)⁻¹ e",
            CompareMethod::Sdls => "Δθ = ClampMaxAbs(Σ ClampMaxAbs(σ_i⁻¹ α_i v_i, γ_i), γmax)",
            CompareMethod::PinvCentering => "Δθ = J⁺e + (I − J⁺J)(−k∇H),  H = Σ α_j (θ_j − θc_j)²",
            CompareMethod::DlsCentering => "Δθ = Σ σ_i/(σ_i² + λ²) v_i u_i^T e + (I − J⁺J)(−k∇H)",
            CompareMethod::Ccd => "θ_j += atan2(Σ a·(u × v), Σ u·v),  j = leaf … root",
        }
    }

    /// One sentence on how the method behaves.
    #[must_use]
    pub fn behaviour(self) -> &'static str {
        match self {
            CompareMethod::Transpose => {
                "Cheap and never unstable, but slow to converge: errors stay largest."
            }
            CompareMethod::Pinv => {
                "Exact least-norm steps; near a singular (stretched) pose 1/σ explodes and the limb oscillates."
            }
            CompareMethod::Dls => {
                "Damping λ trades a little accuracy for smooth, bounded steps near singularities."
            }
            CompareMethod::Sdls => {
                "Damps each singular direction by how far it would move the effectors: accurate and smooth."
            }
            CompareMethod::PinvCentering => {
                "Pseudoinverse plus a pull of every joint toward its center angle in the null space."
            }
            CompareMethod::DlsCentering => {
                "Damped least squares plus PODA's null-space pull toward the center angles."
            }
            CompareMethod::Ccd => {
                "No Jacobian: turns one joint at a time toward the targets; robust but stiff-looking."
            }
        }
    }

    /// The sliders this method's card shows.
    #[must_use]
    pub fn parameters(self) -> &'static [Parameter] {
        match self {
            CompareMethod::Transpose | CompareMethod::Ccd => &[Parameter::MaxStep],
            CompareMethod::Pinv => &[Parameter::MaxStep, Parameter::RankTolerance],
            CompareMethod::Dls => &[Parameter::Lambda, Parameter::MaxStep],
            CompareMethod::Sdls => &[Parameter::GammaMax, Parameter::RankTolerance],
            CompareMethod::PinvCentering => &[
                Parameter::MaxStep,
                Parameter::RankTolerance,
                Parameter::NullSpaceGain,
            ],
            CompareMethod::DlsCentering => &[
                Parameter::Lambda,
                Parameter::MaxStep,
                Parameter::NullSpaceGain,
            ],
        }
    }

    /// The core method it runs.
    #[must_use]
    pub fn method(self) -> Method {
        match self {
            CompareMethod::Transpose => Method::Transpose,
            CompareMethod::Pinv | CompareMethod::PinvCentering => Method::Pinv,
            CompareMethod::Dls | CompareMethod::DlsCentering => Method::Dls,
            CompareMethod::Sdls => Method::Sdls,
            CompareMethod::Ccd => Method::Ccd,
        }
    }

    /// Whether PODA's null-space term is on.
    #[must_use]
    pub fn centering(self) -> bool {
        matches!(
            self,
            CompareMethod::PinvCentering | CompareMethod::DlsCentering
        )
    }

    /// Default options for this configuration, from the lab's `base` options.
    #[must_use]
    pub fn options(self, base: &IkOptions) -> IkOptions {
        IkOptions {
            method: self.method(),
            null_space_gain: if self.centering() {
                DEFAULT_NULL_SPACE_GAIN
            } else {
                0.0
            },
            ..base.clone()
        }
    }
}

/// Null-space gain k of the centering configurations unless set.
pub const DEFAULT_NULL_SPACE_GAIN: f64 = 0.2;

impl Parameter {
    /// The key in the `options` objects of the command and state.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Parameter::Lambda => "lambda",
            Parameter::GammaMax => "gamma_max",
            Parameter::MaxStep => "max_step",
            Parameter::RankTolerance => "rank_tolerance",
            Parameter::NullSpaceGain => "null_space_gain",
        }
    }

    /// Accepted range (same units as the option).
    #[must_use]
    pub fn range(self) -> (f64, f64) {
        match self {
            Parameter::Lambda => (1e-4, 2.0),
            Parameter::GammaMax | Parameter::MaxStep => (1e-3, std::f64::consts::PI),
            Parameter::RankTolerance => (1e-12, 0.1),
            Parameter::NullSpaceGain => (0.0, 2.0),
        }
    }

    /// The option's value in `options`, mutably.
    pub fn slot(self, options: &mut IkOptions) -> &mut f64 {
        match self {
            Parameter::Lambda => &mut options.lambda,
            Parameter::GammaMax => &mut options.gamma_max,
            Parameter::MaxStep => &mut options.max_step,
            Parameter::RankTolerance => &mut options.rank_tolerance,
            Parameter::NullSpaceGain => &mut options.null_space_gain,
        }
    }

    /// Every parameter.
    pub const ALL: [Parameter; 5] = [
        Parameter::Lambda,
        Parameter::GammaMax,
        Parameter::MaxStep,
        Parameter::RankTolerance,
        Parameter::NullSpaceGain,
    ];
}

/// Where the targets come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CompareScenario {
    /// The thesis script of the lab's mode.
    #[default]
    Script,
    /// Every limb target pulled to about its full reach, swinging across it.
    Singularity,
}

impl CompareScenario {
    /// Name used in commands and state.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            CompareScenario::Script => "script",
            CompareScenario::Singularity => "singularity",
        }
    }

    /// Parses [`CompareScenario::name`].
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "script" => Some(CompareScenario::Script),
            "singularity" => Some(CompareScenario::Singularity),
            _ => None,
        }
    }
}

/// What a comparison runs: the views' configurations and options, and the scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareConfig {
    /// One configuration per view (2 or 4).
    pub views: Vec<CompareMethod>,
    /// Options per view (same length as `views`).
    pub options: Vec<IkOptions>,
    /// Target scenario.
    pub scenario: CompareScenario,
}

impl CompareConfig {
    /// `views` with their default options from `base`.
    #[must_use]
    pub fn new(views: &[CompareMethod], scenario: CompareScenario, base: &IkOptions) -> Self {
        Self {
            views: views.to_vec(),
            options: views.iter().map(|m| m.options(base)).collect(),
            scenario,
        }
    }

    /// Parses the `compare` command's object (see the module docs), taking
    /// defaults from `base` and from `current` where its views match.
    ///
    /// # Errors
    /// `compare.…: reason` naming the bad field.
    pub fn from_json(
        value: &Value,
        base: &IkOptions,
        current: Option<&CompareConfig>,
    ) -> Result<Self, String> {
        let object: &Map<String, Value> = value
            .as_object()
            .ok_or("compare: expected an object or false")?;
        for key in object.keys() {
            if !["views", "scenario", "options", "metrics"].contains(&key.as_str()) {
                return Err(format!(
                    "compare.{key}: unknown key (views, scenario, options)"
                ));
            }
        }
        let views: Vec<CompareMethod> = match object.get("views") {
            Some(views) => {
                let list = views
                    .as_array()
                    .ok_or("compare.views: expected an array of method names")?;
                if list.len() != 2 && list.len() != 4 {
                    return Err(format!(
                        "compare.views: expected 2 or 4 views, got {}",
                        list.len()
                    ));
                }
                list.iter()
                    .enumerate()
                    .map(|(i, name)| {
                        let name = name
                            .as_str()
                            .ok_or_else(|| format!("compare.views[{i}]: expected a string"))?;
                        CompareMethod::parse(name).ok_or_else(|| {
                            format!(
                                "compare.views[{i}]: unknown method {name:?} ({})",
                                CompareMethod::ALL.map(CompareMethod::name).join(", ")
                            )
                        })
                    })
                    .collect::<Result<_, _>>()?
            }
            None => match current {
                Some(current) => current.views.clone(),
                None => DEFAULT_VIEWS.to_vec(),
            },
        };
        let scenario = match object.get("scenario") {
            Some(v) => {
                let name = v.as_str().ok_or("compare.scenario: expected a string")?;
                CompareScenario::parse(name).ok_or_else(|| {
                    format!("compare.scenario: unknown scenario {name:?} (script, singularity)")
                })?
            }
            None => current.map_or(CompareScenario::Script, |c| c.scenario),
        };
        let mut options: Vec<IkOptions> = views
            .iter()
            .enumerate()
            .map(|(i, m)| match current {
                Some(c) if c.views.get(i) == Some(m) => c.options[i].clone(),
                _ => m.options(base),
            })
            .collect();
        if let Some(v) = object.get("options") {
            let list = v
                .as_array()
                .ok_or("compare.options: expected an array of objects")?;
            if list.len() != views.len() {
                return Err(format!(
                    "compare.options: expected {} objects (one per view), got {}",
                    views.len(),
                    list.len()
                ));
            }
            for (i, (item, slot)) in list.iter().zip(options.iter_mut()).enumerate() {
                let item = item
                    .as_object()
                    .ok_or_else(|| format!("compare.options[{i}]: expected an object"))?;
                for (key, value) in item {
                    let parameter = Parameter::ALL
                        .into_iter()
                        .find(|p| p.key() == key)
                        .ok_or_else(|| format!("compare.options[{i}].{key}: unknown option"))?;
                    let x = value
                        .as_f64()
                        .ok_or_else(|| format!("compare.options[{i}].{key}: expected a number"))?;
                    let (lo, hi) = parameter.range();
                    if !(lo..=hi).contains(&x) {
                        return Err(format!(
                            "compare.options[{i}].{key}: {x} is outside [{lo}, {hi}]"
                        ));
                    }
                    *parameter.slot(slot) = x;
                }
            }
        }
        Ok(Self {
            views,
            options,
            scenario,
        })
    }

    /// The configuration as the command's object (without metrics).
    #[must_use]
    pub fn to_json(&self) -> Value {
        json!({
            "views": self.views.iter().map(|m| m.name()).collect::<Vec<_>>(),
            "scenario": self.scenario.name(),
            "options": self.options.iter().map(|o| json!({
                "lambda": o.lambda,
                "gamma_max": o.gamma_max,
                "max_step": o.max_step,
                "rank_tolerance": o.rank_tolerance,
                "null_space_gain": o.null_space_gain,
            })).collect::<Vec<_>>(),
        })
    }
}

/// The views a comparison starts with when none are named.
pub const DEFAULT_VIEWS: [CompareMethod; 4] = [
    CompareMethod::Transpose,
    CompareMethod::Pinv,
    CompareMethod::Dls,
    CompareMethod::Sdls,
];

/// One view's running figures. Allocation-free per frame.
#[derive(Clone, Debug, Default)]
pub struct ViewMetrics {
    /// Joint values one and two frames ago.
    previous: Vec<f64>,
    before_previous: Vec<f64>,
    /// Frames seen since the reset (the first two give no Δ²θ).
    frames: u64,
    /// mean_j |Δ²θⱼ| of the recent frames, rad per frame² (ring buffer).
    jitter: Vec<f64>,
    jitter_next: usize,
    /// Whether each joint sat on a limit last frame.
    at_limit: Vec<bool>,
    /// Times a joint arrived at one of its limits since the reset.
    pub limit_hits: u64,
    /// Wall time spent in this view's driver, µs.
    pub wall_us: f64,
    /// IK iterations run.
    pub iterations: u64,
}

impl ViewMetrics {
    fn new(joints: usize) -> Self {
        Self {
            previous: vec![0.0; joints],
            before_previous: vec![0.0; joints],
            jitter: Vec::with_capacity(JITTER_WINDOW_FRAMES),
            at_limit: vec![false; joints],
            ..Self::default()
        }
    }

    fn record(&mut self, skeleton: &Skeleton, values: &[f64]) {
        if self.frames >= 2 {
            let n = values.len().max(1) as f64;
            let sum: f64 = values
                .iter()
                .zip(&self.previous)
                .zip(&self.before_previous)
                .map(|((x, p), b)| (x - 2.0 * p + b).abs())
                .sum();
            let jitter = sum / n;
            if self.jitter.len() < JITTER_WINDOW_FRAMES {
                self.jitter.push(jitter);
            } else {
                self.jitter[self.jitter_next] = jitter;
            }
            self.jitter_next = (self.jitter_next + 1) % JITTER_WINDOW_FRAMES;
        }
        for ((value, joint), at) in values.iter().zip(skeleton.joints()).zip(&mut self.at_limit) {
            let now = joint
                .limits
                .is_some_and(|(lo, hi)| *value <= lo + 1e-9 || *value >= hi - 1e-9);
            if now && !*at && self.frames > 0 {
                self.limit_hits += 1;
            }
            *at = now;
        }
        self.before_previous.copy_from_slice(&self.previous);
        self.previous.copy_from_slice(values);
        self.frames += 1;
    }

    /// Mean |Δ²θ| over the joints and the last [`JITTER_WINDOW_FRAMES`]
    /// frames, radians per frame² (0 before three frames).
    #[must_use]
    pub fn jitter_rad(&self) -> f64 {
        if self.jitter.is_empty() {
            0.0
        } else {
            self.jitter.iter().sum::<f64>() / self.jitter.len() as f64
        }
    }

    /// Wall time per IK iteration, µs (0 without a clock).
    #[must_use]
    pub fn us_per_iteration(&self) -> f64 {
        if self.iterations == 0 {
            0.0
        } else {
            self.wall_us / self.iterations as f64
        }
    }
}

/// One view: its configuration, driver, figures, plot history and scene.
pub struct CompareView {
    /// The configuration.
    pub method: CompareMethod,
    pub(crate) driver: ThesisDriver,
    pub(crate) metrics: ViewMetrics,
    /// Largest effector error per frame (one series, metres).
    pub(crate) history: History,
    pub(crate) scene: Scene,
    kinematics: Kinematics,
}

impl CompareView {
    /// The view's driver.
    #[must_use]
    pub fn driver(&self) -> &ThesisDriver {
        &self.driver
    }

    /// The view's figures.
    #[must_use]
    pub fn metrics(&self) -> &ViewMetrics {
        &self.metrics
    }

    /// Mean over effectors of each effector's mean error since the reset, metres.
    #[must_use]
    pub fn mean_error_m(&self) -> f64 {
        let Some(m) = self.driver.ik_metrics() else {
            return 0.0;
        };
        let k = m.effector_count().max(1);
        (0..k).filter_map(|e| m.mean_error_m(e)).sum::<f64>() / k as f64
    }

    /// Largest effector error since the reset, metres.
    #[must_use]
    pub fn max_error_m(&self) -> f64 {
        let Some(m) = self.driver.ik_metrics() else {
            return 0.0;
        };
        (0..m.effector_count())
            .filter_map(|e| m.max_error_m(e))
            .fold(0.0, f64::max)
    }

    fn refresh_scene(&mut self, view: &ViewOptions) {
        let skeleton = self.driver.skeleton();
        let pose = self.driver.pose();
        self.kinematics.update(skeleton, &pose.root, &pose.joints);
        self.scene.fill(
            skeleton,
            &self.kinematics,
            pose.root.position,
            self.driver.targets(),
            view,
        );
    }
}

/// A running comparison.
pub struct Comparison {
    /// What runs.
    pub config: CompareConfig,
    pub(crate) views: Vec<CompareView>,
}

impl Comparison {
    /// Builds one driver per view from `template` (the lab's thesis driver:
    /// its skeleton, parameters, mode and origin), reset to time 0.
    #[must_use]
    pub fn new(config: CompareConfig, template: &ThesisDriver, view: &ViewOptions) -> Self {
        let views = config
            .views
            .iter()
            .zip(&config.options)
            .map(|(&method, options)| {
                let mut driver = template.clone();
                driver.set_options(options.clone());
                driver.set_stretch(
                    (config.scenario == CompareScenario::Singularity).then(StretchOptions::default),
                );
                driver.reset();
                let skeleton = driver.skeleton();
                let mut view_state = CompareView {
                    method,
                    metrics: ViewMetrics::new(skeleton.joint_count()),
                    history: History::new(vec![format!("{} max error (mm)", method.name())]),
                    scene: Scene::default(),
                    kinematics: Kinematics::new(skeleton),
                    driver,
                };
                view_state.refresh_scene(view);
                view_state
            })
            .collect();
        Self { config, views }
    }

    /// The views.
    #[must_use]
    pub fn views(&self) -> &[CompareView] {
        &self.views
    }

    /// Sets view `index`'s options live (the configuration keeps them).
    pub fn set_options(&mut self, index: usize, options: IkOptions) {
        if let (Some(view), Some(slot)) = (
            self.views.get_mut(index),
            self.config.options.get_mut(index),
        ) {
            view.driver.set_options(options.clone());
            *slot = options;
        }
    }

    /// Advances every view one frame of `dt` seconds, timing each with `clock`
    /// (milliseconds) when there is one.
    pub fn step(&mut self, dt: f64, clock: Option<&dyn Fn() -> f64>) {
        for view in &mut self.views {
            let started = clock.map(|c| c());
            view.driver.step(dt);
            if let (Some(started), Some(clock)) = (started, clock) {
                view.metrics.wall_us += (clock() - started) * 1e3;
            }
            view.metrics.iterations += view.driver.ik_report().map_or(0, |r| r.iterations as u64);
            let skeleton = view.driver.skeleton();
            view.metrics.record(skeleton, &view.driver.pose().joints);
            let error = view.driver.ik_report().map_or(0.0, |r| r.max_error_m);
            view.history
                .push(view.driver.time(), std::iter::once(error));
        }
    }

    /// Back to time 0 with cleared figures.
    pub fn reset(&mut self) {
        for view in &mut self.views {
            view.driver.reset();
            view.metrics = ViewMetrics::new(view.driver.skeleton().joint_count());
            view.history.clear();
        }
    }

    /// Sets the thesis motion of every view.
    pub fn set_mode(&mut self, mode: gaitlab_core::preset::thesis::ThesisMode) {
        for view in &mut self.views {
            view.driver.set_mode(mode);
        }
    }

    /// Rebuilds every view's scene from its pose.
    pub fn refresh_scenes(&mut self, view: &ViewOptions) {
        for v in &mut self.views {
            v.refresh_scene(view);
        }
    }

    /// The state's `compare` object: the configuration plus per-view metrics.
    #[must_use]
    pub fn state(&self) -> Value {
        let mut value = self.config.to_json();
        let metrics: Vec<Value> = self
            .views
            .iter()
            .map(|v| {
                json!({
                    "method": v.method.name(),
                    "mean_error_m": v.mean_error_m(),
                    "max_error_m": v.max_error_m(),
                    "us_per_iteration": v.metrics.us_per_iteration(),
                    "jitter_rad": v.metrics.jitter_rad(),
                    "limit_hits": v.metrics.limit_hits,
                    "frame": v.metrics.frames,
                    "time_s": v.driver.time(),
                })
            })
            .collect();
        if let Some(object) = value.as_object_mut() {
            object.insert("metrics".to_owned(), Value::Array(metrics));
        }
        value
    }
}
