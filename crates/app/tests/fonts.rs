//! Every character the app writes on screen has a glyph (issue 43 item 5:
//! formulas typeset with Unicode — Jᵀ, σᵢ⁻¹ — not drawn as empty boxes):
//! egui's bundled fonts plus the symbol font of `ui::fonts`.

use std::path::Path;

/// The non-ASCII characters of `dir`'s Rust sources outside comments, with
/// the file and line of their first use.
fn characters(dir: &Path, found: &mut Vec<(char, String)>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        panic!("cannot read {}", dir.display())
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            characters(&path, found);
            continue;
        }
        if path.extension().is_none_or(|e| e != "rs") {
            continue;
        }
        let Ok(text) = std::fs::read_to_string(&path) else {
            panic!("cannot read {}", path.display())
        };
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for c in code.chars().filter(|c| !c.is_ascii()) {
                if !found.iter().any(|(f, _)| *f == c) {
                    found.push((c, format!("{}:{}", path.display(), n + 1)));
                }
            }
        }
    }
}

#[test]
fn every_character_the_app_writes_has_a_glyph() {
    let ctx = egui::Context::default();
    // The fonts take effect from the frame after they are set.
    for _ in 0..2 {
        let mut output = ctx.run_ui(egui::RawInput::default(), |ui| {
            gaitlab_app::ui::fonts::ensure(ui.ctx());
        });
        output.textures_delta.clear();
    }
    let mut found = Vec::new();
    characters(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut found,
    );
    assert!(found.iter().any(|(c, _)| *c == 'ᵀ'), "the scan finds Jᵀ");
    let mut missing = Vec::new();
    for family in [egui::FontFamily::Proportional, egui::FontFamily::Monospace] {
        let font = egui::FontId::new(14.0, family);
        for (c, at) in &found {
            if !ctx.fonts_mut(|f| f.has_glyph(&font, *c)) {
                missing.push(format!("{c:?} ({:?}) at {at}", font.family));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "no glyph (run tools/font_subset.py): {missing:#?}"
    );
}
