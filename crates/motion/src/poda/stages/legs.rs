//! The leg-states stage (Girard & Maciejewski 1985, eq. 9 and "Vertical
//! Control"): each leg's state at this frame — eq. 9 on the gait's values
//! until the gait changes, from then the leg's own cycles
//! ([`crate::poda::leg_cycles`]), which take a change on at its mid-stance —
//! and the lift-off and touchdown it crossed since the last frame.
//!
//! Reads the gait and the legs' clock (brought to this frame by the body
//! stage); writes each leg's phase, support, lift-off and touchdown.

use crate::poda::model::PodaModel;
use crate::poda::state::PodaState;

/// Each leg's state at `t` and its crossings since `t_prev`.
pub fn advance(model: &PodaModel, state: &mut PodaState, t_prev: f64, t: f64) {
    for i in 0..model.legs.len() {
        let phase = state.clock.leg_phase(i, t, &state.gait);
        let run = &mut state.runs[i];
        run.phase = phase;
        run.liftoff_s = None;
        run.touchdown_s = None;
        let Some(phase) = phase else {
            continue;
        };
        // Lift-off: the leg state passed the support duration since the last
        // frame. While a gait blend shifts the phases, `last_liftoff_s` (under
        // the current phases) may lie before the previous frame: the crossing
        // still happened in this frame, so the state decides, not the time.
        if run.support && (!phase.support || phase.last_liftoff_s > t_prev) {
            run.liftoff_s = Some(phase.last_liftoff_s.clamp(t_prev, t));
            run.support = false;
        }
        if !run.support && phase.support {
            run.touchdown_s = Some(phase.last_touchdown_s.clamp(t_prev, t));
            run.support = true;
        }
    }
}
