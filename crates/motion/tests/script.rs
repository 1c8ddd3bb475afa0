//! The lab's target script (`ThesisParams::lab()`: cycle shapes after She
//! 2006 §5.2.2's walk and run) checked as a pure function:
//! period, left/right phase, hands against feet, foot lift, bounce, slowdown
//! and the stride-matched speed.

use gaitlab_core::preset::thesis::{ThesisMode, ThesisParams};
use gaitlab_motion::{Limb, ThesisScript};
use glam::DVec3;

const MIRROR: DVec3 = DVec3::new(-1.0, 1.0, 1.0);

fn close(a: DVec3, b: DVec3, tolerance: f64) -> bool {
    (a - b).abs().max_element() <= tolerance
}

#[test]
fn targets_repeat_after_one_period() {
    let params = ThesisParams::lab();
    for mode in ThesisMode::ALL {
        let script = ThesisScript::new(&params, mode);
        let period = 1.0 / script.shape().frequency_hz;
        assert!((script.period_s() - period).abs() < 1e-12);
        for i in 0..50 {
            let t = 0.037 * f64::from(i);
            let (a, b) = (script.at_time(t), script.at_time(t + period));
            for limb in Limb::ALL {
                assert!(
                    close(a.target(limb), b.target(limb), 1e-9),
                    "{mode:?} {limb:?} at t={t}: {} vs {}",
                    a.target(limb),
                    b.target(limb)
                );
            }
            assert!((a.root_height_m - b.root_height_m).abs() < 1e-9);
            // Half a period is not a repeat: the feet swap.
            let half = script.at_time(t + 0.5 * period);
            assert!(!close(
                a.target(Limb::LeftFoot),
                half.target(Limb::LeftFoot),
                1e-3
            ));
        }
    }
}

#[test]
fn right_limbs_run_half_a_cycle_after_the_left_mirrored() {
    let params = ThesisParams::lab();
    for mode in ThesisMode::ALL {
        let script = ThesisScript::new(&params, mode);
        let half = 0.5 * script.period_s();
        for i in 0..40 {
            let t = 1.0 + 0.029 * f64::from(i);
            let now = script.at_time(t);
            let earlier = script.at_time(t - half);
            assert!(close(
                now.target(Limb::RightFoot),
                earlier.target(Limb::LeftFoot) * MIRROR,
                1e-9
            ));
            assert!(close(
                now.target(Limb::RightHand),
                earlier.target(Limb::LeftHand) * MIRROR,
                1e-9
            ));
            // The left and right limbs sit on their own sides.
            assert!(now.target(Limb::LeftFoot).x > 0.0 && now.target(Limb::RightFoot).x < 0.0);
            assert!(now.target(Limb::LeftHand).x > 0.0 && now.target(Limb::RightHand).x < 0.0);
        }
    }
}

#[test]
fn each_hand_swings_against_its_own_foot() {
    let params = ThesisParams::lab();
    for mode in ThesisMode::ALL {
        let script = ThesisScript::new(&params, mode);
        let shape = script.shape();
        let foot_mid = 0.5 * (shape.front_foot.z + shape.back_foot.z);
        let hand_mid = 0.5 * (shape.front_hand.z + shape.back_hand.z);
        let mut correlation = [0.0; 2];
        let mut foot_extremes = (f64::MAX, f64::MIN);
        for i in 0..200 {
            let sample = script.at_time(script.period_s() * f64::from(i) / 200.0);
            for (side, (foot, hand)) in [
                (Limb::LeftFoot, Limb::LeftHand),
                (Limb::RightFoot, Limb::RightHand),
            ]
            .into_iter()
            .enumerate()
            {
                let df = sample.target(foot).z - foot_mid;
                let dh = sample.target(hand).z - hand_mid;
                correlation[side] += df * dh;
                // Whenever the foot is forward of its mid-stroke, the hand is back (and vice versa).
                assert!(
                    df * dh <= 1e-12,
                    "{mode:?} {foot:?} and {hand:?} on the same side of mid-stroke"
                );
            }
            foot_extremes.0 = foot_extremes.0.min(sample.target(Limb::LeftFoot).z);
            foot_extremes.1 = foot_extremes.1.max(sample.target(Limb::LeftFoot).z);
        }
        assert!(
            correlation[0] < 0.0 && correlation[1] < 0.0,
            "{mode:?}: {correlation:?}"
        );
        // The foot reaches exactly the two extremes of its stroke.
        assert!((foot_extremes.0 - shape.back_foot.z).abs() < 1e-3);
        assert!((foot_extremes.1 - shape.front_foot.z).abs() < 1e-3);
    }
}

#[test]
fn feet_lift_only_while_swinging_forward() {
    let params = ThesisParams::lab();
    for mode in [ThesisMode::Walk, ThesisMode::Run] {
        let script = ThesisScript::new(&params, mode);
        let shape = script.shape();
        let period = script.period_s();
        let n = 400;
        let mut highest: f64 = 0.0;
        for i in 0..n {
            let t = period * f64::from(i) / f64::from(n);
            let dt = 1e-5;
            let before = script.at_time(t - dt).target(Limb::LeftFoot);
            let after = script.at_time(t + dt).target(Limb::LeftFoot);
            let here = script.at_time(t).target(Limb::LeftFoot);
            // Height of the plain sinusoid between the two extremes, without lift.
            let s = (here.z - 0.5 * (shape.front_foot.z + shape.back_foot.z))
                / (0.5 * (shape.front_foot.z - shape.back_foot.z));
            let base = 0.5 * (shape.front_foot.y + shape.back_foot.y)
                + 0.5 * (shape.front_foot.y - shape.back_foot.y) * s;
            let lift = here.y - base;
            highest = highest.max(lift);
            if after.z < before.z {
                assert!(
                    lift.abs() < 1e-9,
                    "{mode:?}: lifted by {lift} while moving back at t={t}"
                );
            }
            assert!(lift >= -1e-9);
        }
        assert!(
            (highest - shape.step_height_m).abs() < 1e-4,
            "{mode:?}: lift {highest}"
        );
    }
}

#[test]
fn walk_root_peaks_at_mid_stance_run_root_peaks_between_stances() {
    let params = ThesisParams::lab();
    for mode in [ThesisMode::Walk, ThesisMode::Run] {
        let script = ThesisScript::new(&params, mode);
        let shape = script.shape();
        let period = script.period_s();
        // Mid-stance of the right foot: left foot at mid-swing, phase 0.
        let mid_stance = script.at_time(0.0);
        // Left foot at the front, right at the back: between stances.
        let between = script.at_time(0.25 * period);
        assert!(
            (mid_stance.target(Limb::LeftFoot).z - 0.5 * (shape.front_foot.z + shape.back_foot.z))
                .abs()
                < 1e-9
        );
        assert!((between.target(Limb::LeftFoot).z - shape.front_foot.z).abs() < 1e-9);
        let rise = mid_stance.root_height_m - between.root_height_m;
        assert!(
            (rise.abs() - shape.bounce_m).abs() < 1e-9,
            "{mode:?}: bounce {rise}"
        );
        if mode.running() {
            assert!(rise < 0.0, "run: the root must be highest between stances");
        } else {
            assert!(rise > 0.0, "walk: the root must be highest at mid-stance");
        }
    }
}

#[test]
fn slowdown_two_halves_the_frequency_and_speed() {
    let params = ThesisParams::lab();
    let slow = ThesisParams {
        slowdown: 2.0,
        ..ThesisParams::lab()
    };
    for mode in ThesisMode::ALL {
        let (a, b) = (
            ThesisScript::new(&params, mode),
            ThesisScript::new(&slow, mode),
        );
        assert!((b.frequency_hz() - 0.5 * a.frequency_hz()).abs() < 1e-12);
        assert!((b.angular_frequency() - 0.5 * a.angular_frequency()).abs() < 1e-12);
        assert!((b.speed_mps() - 0.5 * a.speed_mps()).abs() < 1e-12);
        for i in 0..30 {
            let t = 0.05 * f64::from(i);
            for limb in Limb::ALL {
                assert!(close(
                    a.at_time(t).target(limb),
                    b.at_time(2.0 * t).target(limb),
                    1e-9
                ));
            }
        }
    }
}

#[test]
fn stride_matched_speed_holds_the_planted_foot_still_at_mid_stance() {
    let params = ThesisParams::lab();
    for mode in [ThesisMode::Walk, ThesisMode::Run] {
        let script = ThesisScript::new(&params, mode);
        let shape = script.shape();
        let expected =
            std::f64::consts::PI * (shape.front_foot.z - shape.back_foot.z) * shape.frequency_hz;
        assert!((script.speed_mps() - expected).abs() < 1e-12);
        // World z of the left foot target = speed·t + body z. Mid-stance of the
        // left foot is phase π, half a period in.
        let world_z = |t: f64| script.speed_mps() * t + script.at_time(t).target(Limb::LeftFoot).z;
        let dt = 1.0 / 60.0;
        let mid = 0.5 * script.period_s();
        for k in [-1.0, 0.0, 1.0] {
            let t = mid + k * dt;
            let per_frame = (world_z(t + 0.5 * dt) - world_z(t - 0.5 * dt)).abs();
            assert!(
                per_frame < 2e-3,
                "{mode:?}: planted foot moves {per_frame} m per frame"
            );
        }
        // The swinging foot moves forward at twice the speed at mid-swing and the
        // planted foot never moves backward.
        for i in 0..200 {
            let t = script.period_s() * f64::from(i) / 200.0;
            assert!(world_z(t + 1e-4) - world_z(t) >= -1e-12);
        }
        let stopped = ThesisParams {
            moving_forward: false,
            ..ThesisParams::lab()
        };
        assert_eq!(ThesisScript::new(&stopped, mode).speed_mps(), 0.0);
        let fixed = ThesisParams {
            speed_mps: Some(0.7),
            ..ThesisParams::lab()
        };
        assert_eq!(ThesisScript::new(&fixed, mode).speed_mps(), 0.7);
    }
}
