//! The commands a person gives a running gait (Raibert & Hodgins 1991,
//! "Control": the desired speed ẋ_d of eq. 3, the heading, the hop height of
//! eq. 2), declared once for the controllers whose parameters carry them
//! under the same names.

/// Declares `set_speed()` and `set_heading()` over `self.params.speed_mps`
/// (m/s at scale 1) and `self.params.heading` (rad about +y); with
/// `hop_height_m`, also `set_hop_height()` and `hop_height_m()` over
/// `self.params.hop_height_m` (m at scale 1).
#[macro_export]
#[doc(hidden)]
macro_rules! steering_commands {
    () => {
        fn set_speed(&mut self, speed_mps: f64) {
            self.params.speed_mps = speed_mps;
        }

        fn set_heading(&mut self, heading: f64) {
            self.params.heading = heading;
        }
    };
    (hop_height_m) => {
        $crate::steering_commands!();

        fn set_hop_height(&mut self, height_m: f64) {
            self.params.hop_height_m = height_m;
        }

        fn hop_height_m(&self) -> Option<f64> {
            Some(self.params.hop_height_m)
        }
    };
}
