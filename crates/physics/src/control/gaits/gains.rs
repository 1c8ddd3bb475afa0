//! The gains a person may tune while a controller runs (the app's sliders and
//! the `gain` command): each names a field of the controller's parameters, at
//! scale 1 in the paper's units. Nothing limits a gain beyond being finite and
//! non-negative — absurd gains are allowed, and the simulation's blow-up
//! guard ([`crate::world::sim`]) catches what they do. Each is a
//! [`Gain`](crate::world::sim::Gain), part of the controller interface the
//! loop calls; the macro here declares a controller's.

/// A tunable gain's name in words, with the paper's symbol and equation
/// where it has one; the wire key itself for a name not listed.
#[must_use]
pub fn words(name: &'static str) -> &'static str {
    match name {
        "leg_stiffness" => "Leg spring stiffness k (eq. 1)",
        "leg_damping" => "Leg spring damping b (eq. 1)",
        "placement_gain_s" => "Foot placement gain k_ẋ (eq. 3)",
        "posture_kp" => "Posture stiffness k_p (eq. 4)",
        "posture_kv" => "Posture damping k_v (eq. 4)",
        "pitch_kp" => "Pitch stiffness k_p (eq. 4)",
        "pitch_kv" => "Pitch damping k_v (eq. 4)",
        "roll_kp" => "Roll stiffness (eq. 4)",
        "roll_kv" => "Roll damping (eq. 4)",
        "swing_kp" => "Swing hip stiffness (eq. 5)",
        "swing_kv" => "Swing hip damping (eq. 5)",
        "ankle_stiffness" => "Ankle spring stiffness (eq. 1)",
        "ankle_damping" => "Ankle spring damping (eq. 1)",
        "tail_stiffness" => "Tail spring stiffness",
        "tail_damping" => "Tail spring damping",
        other => other,
    }
}

/// Declares `gains()` and `set_gain()` over named fields of `self.params`
/// (given as `field => unit`), with `Default` supplying the defaults; or,
/// as `params.sub = DEFAULT; …`, over the fields of `self.params.sub` with
/// their defaults in `DEFAULT`. Also `parameter()` and `parameter_names()`
/// over every named parameter of `self.params`
/// ([`NamedParameters`](crate::control::gaits::parameters::NamedParameters)).
#[macro_export]
#[doc(hidden)]
macro_rules! tunable_gains {
    ($($path:ident).+ = $default:expr; $($field:ident => $unit:literal),* $(,)?) => {
        fn gains(&self) -> Vec<$crate::world::sim::Gain> {
            let d = $default;
            let now = &self.$($path).+;
            vec![$($crate::world::sim::Gain::new(
                stringify!($field),
                $crate::control::gaits::gains::words(stringify!($field)),
                $unit,
                now.$field,
                d.$field,
            )),*]
        }

        fn set_gain(&mut self, name: &str, value: f64) -> bool {
            if !(value.is_finite() && value >= 0.0) {
                return false;
            }
            let now = &mut self.$($path).+;
            match name {
                $(stringify!($field) => now.$field = value,)*
                _ => return false,
            }
            true
        }

        fn parameter(&self, name: &str) -> Option<f64> {
            $crate::control::gaits::parameters::NamedParameters::parameter(&self.params, name)
        }

        fn parameter_names(&self) -> &'static [&'static str] {
            $crate::control::gaits::parameters::names_of(&self.params)
        }
    };
    ($params:ty; $($field:ident => $unit:literal),* $(,)?) => {
        $crate::tunable_gains!(params = <$params>::default(); $($field => $unit),*);
    };
}

/// A family's tunable gains over its gaits' parameters: `biped P` — the run's
/// and both gallops' leg spring, eq. 4's posture servo, eq. 3's gain and the
/// swing servo, in `P`'s `hopper`, and the gait's own hop height, `P`'s
/// `hop_height_m`; `quadruped …` — the trot's, bound's and
/// gallop's leg spring, eq. 3's gain and eq. 4's pitch and roll servos, over
/// the parameters `tunable_gains!` is given.
#[macro_export]
#[doc(hidden)]
macro_rules! family_gains {
    (biped $params:ty) => {
        $crate::tunable_gains!(params.hopper = <$params>::default().hopper;
            leg_stiffness => "N/m", leg_damping => "N·s/m", posture_kp => "N·m/rad",
            posture_kv => "N·m·s/rad", placement_gain_s => "s", swing_kp => "N·m/rad",
            swing_kv => "N·m·s/rad");

        fn hop_height_m(&self) -> Option<f64> {
            Some(self.params.hop_height_m)
        }
    };
    (quadruped $($params:tt)*) => {
        $crate::tunable_gains!($($params)*;
            leg_stiffness => "N/m", leg_damping => "N·s/m", placement_gain_s => "s",
            pitch_kp => "N·m/rad", pitch_kv => "N·m·s/rad", roll_kp => "N·m/rad",
            roll_kv => "N·m·s/rad");
    };
}
