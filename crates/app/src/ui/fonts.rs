//! The page's fonts (issue 43 item 5, formulas typeset with Unicode): egui's
//! bundled ones, then `assets/symbols.ttf` — a subset of DejaVu Sans cut by
//! `tools/font_subset.py` (licence beside it) — as the fallback for what they
//! lack: Jᵀ, σᵢ⁻¹, ‖Δθ‖, ⟨e, JJᵀe⟩, →.

use std::sync::Arc;

/// The fallback font's name in egui's font definitions.
const SYMBOLS: &str = "gaitlab-symbols";

/// Adds the symbol font to `ctx`'s proportional and monospace families,
/// once per context (later calls cost one look-up).
pub fn ensure(ctx: &egui::Context) {
    let id = egui::Id::unique(SYMBOLS);
    if ctx.data(|d| d.get_temp::<bool>(id)).unwrap_or(false) {
        return;
    }
    ctx.data_mut(|d| d.insert_temp(id, true));
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert(
        SYMBOLS.to_owned(),
        Arc::new(egui::FontData::from_static(include_bytes!(
            "../../assets/symbols.ttf"
        ))),
    );
    for family in [egui::FontFamily::Proportional, egui::FontFamily::Monospace] {
        fonts
            .families
            .entry(family)
            .or_default()
            .push(SYMBOLS.to_owned());
    }
    ctx.set_fonts(fonts);
}
