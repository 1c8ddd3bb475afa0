//! The command API's named values (`mode`, `method`, `engine`, `theme`, …):
//! strings in JSON, the app's enums once read, and an `enum` list in the
//! schema. An unknown name reads `unknown mode "fly" (walk, run, …)`.

use gaitlab_core::ik::{JacobianAt, Method, TransposeAlpha};
use gaitlab_core::preset::Engine;
use gaitlab_core::preset::thesis::ThesisMode;

use crate::named::named;
use crate::settings::VideoSize;
use crate::theme::Theme;

/// A take's file format for `save`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SaveFormat {
    /// Biovision hierarchy.
    Bvh,
    /// Joint angles per frame.
    Csv,
}

impl SaveFormat {
    /// The format's name (`bvh`, `csv`), as [`crate::Lab::save_take`] takes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            SaveFormat::Bvh => "bvh",
            SaveFormat::Csv => "csv",
        }
    }

    fn parse(name: &str) -> Option<Self> {
        match name {
            "bvh" => Some(SaveFormat::Bvh),
            "csv" => Some(SaveFormat::Csv),
            _ => None,
        }
    }
}

named!(
    /// `engine`: which engine's creature to load.
    EngineName(Engine), "engine", Engine::parse, ["ik", "poda", "physics"]
);
named!(
    /// `mode`: the thesis script.
    ModeName(ThesisMode), "mode", ThesisMode::parse,
    ["walk", "run", "wounded-walk", "wounded-run"]
);
named!(
    /// `method`: the IK method.
    MethodName(Method), "method", Method::parse, ["transpose", "pinv", "dls", "sdls", "ccd"]
);
named!(
    /// `jacobian_at`: She 2006 §3.2's control way — the Jacobian at the end
    /// effectors (they move towards the targets) or at the targets.
    JacobianAtName(JacobianAt), "jacobian_at", JacobianAt::parse, ["effectors", "targets"]
);
named!(
    /// `transpose_alpha`: the transpose method's α — She 2006 §4.4.1's
    /// (`thesis`) or Buss's, twice it (`buss`).
    TransposeAlphaName(TransposeAlpha), "transpose_alpha", TransposeAlpha::parse, ["thesis", "buss"]
);
named!(
    /// `theme`: the colours.
    ThemeName(Theme), "theme", Theme::parse, ["system", "light", "dark"]
);
named!(
    /// `video_size`: the video recording's frame size.
    VideoSizeName(VideoSize), "size", VideoSize::parse, ["view", "p360", "p720", "p1080"]
);
named!(
    /// `save.format`: the take's file format.
    SaveFormatName(SaveFormat), "format", SaveFormat::parse, ["bvh", "csv"]
);
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_name_lists_are_the_enums_names() {
        for name in ["walk", "run", "wounded-walk", "wounded-run"] {
            assert!(ThesisMode::parse(name).is_some(), "{name}");
        }
        for name in ["transpose", "pinv", "dls", "sdls", "ccd"] {
            assert!(Method::parse(name).is_some(), "{name}");
        }
        for way in JacobianAt::ALL {
            assert!(serde_json::from_value::<JacobianAtName>(way.name().into()).is_ok());
        }
        for alpha in TransposeAlpha::ALL {
            assert!(serde_json::from_value::<TransposeAlphaName>(alpha.name().into()).is_ok());
        }
        for name in ["view", "p360", "p720", "p1080"] {
            assert!(VideoSize::parse(name).is_some(), "{name}");
        }
    }
}
