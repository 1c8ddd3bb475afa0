//! Presets: the JSON description of a creature and its default scenario,
//! parsed with serde and validated against DESIGN.md's input limits.

pub mod thesis;
