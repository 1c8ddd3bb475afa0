//! The whole lab in a link (issue 6 item 2, DESIGN.md "Browser: URL"): what
//! "Copy link" writes and what opening the link restores.
//!
//! The link's `state` is a command object (keys of [`App::command`]) read out of
//! [`App::state_json`] through [`LINK_KEYS`]; restoring loads the preset and then
//! applies those keys one at a time in that order, each validated by the command
//! code, skipping values the lab already has. Adding a setting to links is one
//! line in [`LINK_KEYS`] (a command key and where `state()` shows its value, in
//! the shape the command accepts).

use serde_json::{Map, Value, json};

use crate::app::App;
use crate::link::{self, FullLink, LinkRequest};

/// `(command key, JSON pointer into state())` for every setting a link carries,
/// in the order a restore applies them. A key may appear twice (one pointer per
/// engine); the first pointer with a value wins.
///
/// The order matters where one edit derives another: the PODA speed keeps the
/// stroke and derives the period, so the speed goes before the duty factor and
/// the period (which keep the speed), leaving all three as written.
pub const LINK_KEYS: &[(&str, &str)] = &[
    ("mode", "/mode"),
    ("method", "/method"),
    ("gait", "/gait"),
    ("speed_mps", "/poda/speed_mps"),
    ("speed_mps", "/physics/speed_desired_mps"),
    ("duty_factor", "/poda/duty_factor"),
    ("period_s", "/poda/period_s"),
    ("phases", "/poda/phases"),
    ("step_height_m", "/poda/step_height_m"),
    ("transfer_keys", "/poda/transfer_keys"),
    ("path", "/poda/path"),
    ("hop_height_m", "/physics/hop_height_m"),
    ("gains", "/physics/gains"),
    ("lambda", "/ik/lambda"),
    ("gamma_max", "/ik/gamma_max"),
    ("max_step", "/ik/max_step"),
    ("clamp_every_method", "/ik/clamp_every_method"),
    ("target_clamp_m", "/ik/target_clamp_m"),
    ("transpose_alpha", "/ik/transpose_alpha"),
    ("null_space_gain", "/ik/null_space_gain"),
    ("enforce_limits", "/ik/enforce_limits"),
    ("limit_passes", "/ik/limit_passes"),
    ("jacobian_at", "/ik/jacobian_at"),
    ("heading_deg", "/heading_deg"),
    ("plots", "/plots"),
    ("plot_joints", "/plot_joints"),
    ("video_size", "/video/size"),
    ("views", "/view_options"),
    ("camera", "/camera"),
    ("compare", "/compare"),
    ("pinned_targets", "/pinned_targets"),
    ("paused", "/paused"),
    ("editor_open", "/editor/open"),
    ("lesson", "/lesson"),
];

/// The limit passes every link ran with before links carried them.
const LEGACY_LIMIT_PASSES: usize = 4;

/// The first non-null value `state` holds for command `key`.
fn current<'a>(state: &'a Value, key: &str) -> Option<&'a Value> {
    LINK_KEYS
        .iter()
        .filter(|(k, _)| *k == key)
        .find_map(|(_, pointer)| state.pointer(pointer).filter(|v| !v.is_null()))
}

impl App {
    fn state_value(&self) -> Value {
        serde_json::from_str(&self.state_json()).unwrap_or(Value::Null)
    }

    /// The lab's settings as the command object a link carries.
    #[must_use]
    pub fn link_state(&self) -> Map<String, Value> {
        let state = self.state_value();
        let mut out = Map::new();
        for (key, _) in LINK_KEYS {
            if !out.contains_key(*key)
                && let Some(value) = current(&state, key)
            {
                let mut value = value.clone();
                // The comparison's live figures are not settings.
                if *key == "compare"
                    && let Some(compare) = value.as_object_mut()
                {
                    compare.remove("metrics");
                    compare.remove("plot_error_max_mm");
                    compare.remove("notice");
                }
                out.insert((*key).to_owned(), value);
            }
        }
        out
    }

    /// The whole lab as a link carries it: the preset JSON, whether it is a
    /// bundled one unedited, and [`App::link_state`].
    #[must_use]
    pub fn full_link(&self) -> FullLink {
        FullLink {
            preset_json: self.preset_text(),
            bundled: self
                .session
                .custom_preset
                .is_none()
                .then(|| self.session.settings.preset.clone()),
            state: self.link_state(),
        }
    }

    /// The link "Copy link" copies: the page address then
    /// `#p=<base64url(deflate(envelope))>`.
    ///
    /// # Errors
    /// If the running preset cannot be written (it always parsed, so this
    /// does not happen in practice).
    pub fn share_link(&self) -> Result<String, String> {
        let payload = link::encode_full(&self.full_link())?;
        Ok(format!("{}#p={payload}", self.page_url))
    }

    /// Restores a full-state link: its preset (the bundled one when the
    /// text is that preset unedited), then its settings key by key.
    /// A preset that does not load leaves the default preset.
    ///
    /// Returns the problems met (`link: …`); the settings that were fine stay applied.
    pub fn apply_full_link(&mut self, full: &FullLink) -> Vec<String> {
        let mut errors = Vec::new();
        let bundled = full.bundled.as_deref().filter(|name| {
            gaitlab_core::preset::bundled_json(name)
                .is_some_and(|json| json.trim() == full.preset_json.trim())
        });
        let loaded = match bundled {
            Some(name) => self.set_preset(name),
            None => self.set_custom_preset(&full.preset_json),
        };
        if let Err(error) = loaded {
            errors.push(format!("link: {error}"));
            self.load_default_preset(&mut errors);
            return errors;
        }
        for key in full.state.keys() {
            if !LINK_KEYS.iter().any(|(k, _)| k == key) {
                errors.push(format!("link: state.{key}: not a setting links carry"));
            }
        }
        // Links made before `limit_passes` was a setting (2026-12-02) ran
        // with the re-solve's 4 passes whatever their preset said.
        if !full.state.is_empty() && !full.state.contains_key("limit_passes") {
            self.session.settings.ik.limit_passes = LEGACY_LIMIT_PASSES;
            self.apply_ik_options();
        }
        let mut done: Vec<&str> = Vec::with_capacity(LINK_KEYS.len());
        for (key, _) in LINK_KEYS {
            if done.contains(key) {
                continue;
            }
            done.push(key);
            let Some(value) = full.state.get(*key) else {
                continue;
            };
            if current(&self.state_value(), key) == Some(value) {
                continue;
            }
            let command = json!({ *key: value }).to_string();
            if let Err(error) = self.command(&command) {
                errors.push(format!("link: state.{error}"));
            }
        }
        errors
    }

    fn load_default_preset(&mut self, errors: &mut Vec<String>) {
        if let Err(error) = self.set_preset(gaitlab_core::preset::DEFAULT_PRESET) {
            errors.push(error);
        }
    }

    /// Applies a page's link (`?query` and `#fragment`): a full-state `#p=`,
    /// a bare-preset `#p=`, or `?preset=&mode=&method=`. A broken link shows
    /// its problem and loads the default preset; problems with single
    /// settings are shown and the rest applies. Never panics.
    pub fn open_link(&mut self, query: &str, fragment: &str) {
        let request: LinkRequest = link::parse(query, fragment);
        let mut errors = request.errors.clone();
        if let Some(full) = &request.full {
            errors.extend(self.apply_full_link(full));
        } else if let Some(json) = &request.custom_preset {
            if let Err(error) = self.set_custom_preset(json) {
                errors.push(format!("link: {error}"));
                self.load_default_preset(&mut errors);
            }
        } else if !errors.is_empty() && fragment.contains("p=") {
            // The #p= could not be read: start from the default preset.
            self.load_default_preset(&mut errors);
        } else if let Some(name) = &request.preset
            && name != &self.creature().name
            && let Err(error) = self.set_preset(name)
        {
            errors.push(format!("link: {error}"));
            self.load_default_preset(&mut errors);
        }
        if request.full.is_none() {
            for (key, value) in [("mode", &request.mode), ("method", &request.method)] {
                if let Some(value) = value {
                    let command = json!({ key: value }).to_string();
                    if let Err(error) = self.command(&command) {
                        errors.push(format!("link: {error}"));
                    }
                }
            }
        }
        if !errors.is_empty() {
            self.report_error(errors.join("; "));
        }
        // The link has been applied: the address bar already shows it.
        self.outbox.forget_link_changes();
    }
}
