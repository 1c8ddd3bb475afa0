#!/usr/bin/env python3
"""Writes crates/app/assets/symbols.ttf: the glyphs egui's bundled fonts lack
(Jᵀ, σᵢ⁻¹, ‖·‖, →, ⟨·,·⟩ …) cut from DejaVu Sans, the fallback font the
page draws them with (issue 43 item 5: formulas typeset with Unicode).

Needs Debian's fonts-dejavu-core and fontTools (pip install fonttools). The
characters are a fixed set of mathematical symbols plus every non-ASCII
character in crates/app/src; the app's test `every_character_the_app_writes_has_a_glyph`
fails when a new one is missing — run this again then.

    python3 tools/font_subset.py
"""
import pathlib
import sys

from fontTools import subset
from fontTools.ttLib import TTFont

ROOT = pathlib.Path(__file__).resolve().parent.parent
SOURCE = pathlib.Path("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")
OUT = ROOT / "crates/app/assets/symbols.ttf"
# Super- and subscripts, Greek, operators and arrows a formula may need.
FIXED = (
    "ᵀᵢⱼₖₙᵗ⁻⁺⁰¹²³⁴⁵⁶⁷⁸⁹ⁿ₀₁₂₃₄₅₆₇₈₉ₘₐₓ"
    "αβγδεζηθικλμνξπρστυφχψωΓΔΘΛΞΠΣΦΨΩ∂∇"
    "‖⟨⟩→←↑↓↔⇒≈≠≤≥±×·−√∞∑∏∫∈∉⊥′″°µ•…–—§é"
)


def main() -> int:
    chars = set(FIXED)
    for path in (ROOT / "crates/app/src").rglob("*.rs"):
        chars.update(c for c in path.read_text(encoding="utf-8") if ord(c) > 0x7F)
    font = TTFont(SOURCE)
    cmap = font.getBestCmap()
    wanted = sorted(ord(c) for c in chars if ord(c) in cmap)
    missing = sorted(c for c in chars if ord(c) not in cmap)
    options = subset.Options()
    options.hinting = False
    options.layout_features = []
    options.name_IDs = []
    options.notdef_outline = True
    subsetter = subset.Subsetter(options)
    subsetter.populate(unicodes=wanted)
    subsetter.subset(font)
    # The Bitstream Vera licence: a modified font takes a name without
    # "Bitstream" or "Vera".
    name = font["name"]
    for record_id, text in [(1, "gaitlab symbols"), (2, "Regular"), (4, "gaitlab symbols"),
                            (6, "gaitlab-symbols")]:
        name.setName(text, record_id, 3, 1, 0x409)
    OUT.parent.mkdir(parents=True, exist_ok=True)
    font.save(OUT)
    print(f"{OUT.relative_to(ROOT)}: {len(wanted)} characters, {OUT.stat().st_size} bytes")
    if missing:
        print("not in DejaVu Sans:", "".join(missing))
    return 0


if __name__ == "__main__":
    sys.exit(main())
