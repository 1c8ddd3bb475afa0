//! Round numbers for plot axes: steps of 1, 2 or 5 × 10ⁿ, the few ticks a
//! short plot can number, their labels, and the top of a y range several
//! plots share (issue 21 item 2, readable plots).

use egui_plot::{GridInput, GridMark, Plot};

/// Ticks for a short plot: three to five round values (1, 2 or 5 × 10ⁿ
/// apart) across the shown range, so a plot 100 px tall still numbers its
/// axis instead of showing only its 0.
pub fn few_round_marks(input: GridInput) -> Vec<GridMark> {
    let (low, high) = input.bounds;
    let span = high - low;
    if !(span.is_finite() && span > 0.0) {
        return Vec::new();
    }
    let step = round_step(span / 4.0);
    let first = (low / step).ceil();
    let last = (high / step).floor();
    if !(first.is_finite() && last.is_finite()) || last - first > 10.0 {
        return Vec::new();
    }
    let mut marks = Vec::with_capacity(8);
    let mut k = first;
    while k <= last {
        marks.push(GridMark {
            value: k * step,
            step_size: step,
        });
        k += 1.0;
    }
    marks
}

/// A tick's number with as many decimals as its step needs (0.5 → "0.5",
/// 20 → "20"), and no "-0".
pub fn tick_label(mark: GridMark) -> String {
    let decimals = (-mark.step_size.log10().floor()).clamp(0.0, 6.0);
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "clamped to 0–6 above"
    )]
    let decimals = decimals as usize;
    let value = if mark.value == 0.0 { 0.0 } else { mark.value };
    format!("{value:.decimals$}")
}

/// The smallest of 1, 2 or 5 × 10ⁿ at least `wanted` (> 0).
pub fn round_step(wanted: f64) -> f64 {
    let decade = 10f64.powf(wanted.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&step| step >= wanted)
        .unwrap_or(10.0 * decade)
}

/// A log₁₀ axis' tick label: `10^k` written out for whole k in −2..=3
/// (0.01 … 1000), `1ek` beyond, nothing between whole powers.
#[must_use]
pub fn power_of_ten_label(mark: egui_plot::GridMark) -> String {
    let k = mark.value.round();
    if (mark.value - k).abs() > 1e-6 {
        String::new()
    } else if (-2.0..=3.0).contains(&k) {
        format!("{}", 10f64.powf(k))
    } else {
        format!("1e{k}")
    }
}

/// A plot that shows figures and is not moved: no drag, zoom, scroll or box
/// zoom, so a touch on it scrolls the panel instead of panning the axes.
#[must_use]
pub fn still_plot<'a>(id: impl egui::AsIdSalt) -> Plot<'a> {
    Plot::new(id)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .allow_axis_zoom_drag(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_axis_gets_three_to_five_round_ticks() {
        for (low, high, step) in [
            (-63.0, 81.0, 50.0),
            (0.0, 1.0, 0.5),
            (0.0, 8.3, 5.0),
            (-0.2, 4.2, 2.0),
        ] {
            let marks = few_round_marks(GridInput {
                bounds: (low, high),
                base_step_size: 0.001,
            });
            assert!(
                (2..=5).contains(&marks.len()),
                "{low}..{high}: {} marks",
                marks.len()
            );
            for mark in &marks {
                assert!(mark.value >= low && mark.value <= high);
                assert!((mark.value / step - (mark.value / step).round()).abs() < 1e-9);
                assert_eq!(mark.step_size, step, "{low}..{high}");
            }
        }
        assert!(
            few_round_marks(GridInput {
                bounds: (1.0, 1.0),
                base_step_size: 1.0
            })
            .is_empty()
        );
    }

    #[test]
    fn tick_labels_carry_the_decimals_their_step_needs() {
        let label = |value, step_size| tick_label(GridMark { value, step_size });
        assert_eq!(label(0.5, 0.5), "0.5");
        assert_eq!(label(-0.0, 0.5), "0.0");
        assert_eq!(label(40.0, 20.0), "40");
        assert_eq!(label(0.02, 0.01), "0.02");
    }

    #[test]
    fn round_steps_are_one_two_or_five_times_a_power_of_ten() {
        assert_eq!(round_step(0.7), 1.0);
        assert_eq!(round_step(1.0), 1.0);
        assert_eq!(round_step(1.3), 2.0);
        assert_eq!(round_step(37.0), 50.0);
        assert!((round_step(0.0031) - 0.005).abs() < 1e-15);
    }
}
