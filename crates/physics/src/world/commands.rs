//! The commands a person gives a running creature (Raibert & Hodgins 1991,
//! "Control" and Figure 2's animator inputs): the desired forward speed ẋ_d
//! of eq. 3, the heading, and the hop height of eq. 2. They are an input the
//! controller reads every control interval, as MuJoCo's `ctrl` is, and live
//! only here while a creature runs; a gait's parameters hold its gains, not
//! its commands. Given at scale 1, they are scaled by Table 1 in one place,
//! [`Commands::at_scale`], when the loop hands them to the controller.

use crate::control::laws::scale::Scale;

/// The commands, at dynamic scale 1 as people give them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Commands {
    /// Desired forward speed ẋ_d of eq. 3 (m/s at scale 1).
    pub speed_mps: f64,
    /// Desired heading (rad about +y; 0 = +z).
    pub heading_rad: f64,
    /// Desired hop height (m at scale 1); `None`: the gait's own.
    pub hop_height_m: Option<f64>,
}

/// The commands at the creature's scale, as a controller reads them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ScaledCommands {
    /// Desired forward speed ẋ_d of eq. 3 (m/s, ×√L).
    pub speed_mps: f64,
    /// Desired heading (rad; angles do not scale).
    pub heading_rad: f64,
    /// Desired hop height (m, ×L); `None`: the gait's own.
    pub hop_height_m: Option<f64>,
}

impl Commands {
    /// These commands for a creature at dynamic scale `l` (Table 1: speeds
    /// ×√L, lengths ×L, angles unchanged).
    #[must_use]
    pub fn at_scale(&self, l: f64) -> ScaledCommands {
        let s = Scale::new(l);
        ScaledCommands {
            speed_mps: self.speed_mps * s.velocity(),
            heading_rad: self.heading_rad,
            hop_height_m: self.hop_height_m.map(|h| h * s.length()),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::world::commands::Commands;

    #[test]
    fn table_1_scales_speed_by_root_l_and_height_by_l() {
        let c = Commands {
            speed_mps: 2.0,
            heading_rad: 0.5,
            hop_height_m: Some(0.1),
        };
        let s = c.at_scale(4.0);
        assert!((s.speed_mps - 4.0).abs() < 1e-12);
        assert!((s.heading_rad - 0.5).abs() < 1e-12);
        assert!((s.hop_height_m.expect("a height") - 0.4).abs() < 1e-12);
        assert_eq!(Commands::default().at_scale(2.0).hop_height_m, None);
    }
}
