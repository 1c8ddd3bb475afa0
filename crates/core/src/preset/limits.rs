//! DESIGN.md's input limits on a preset: file size, joint, effector and limb counts, name length.

/// Largest accepted preset, bytes (DESIGN.md input limits: 256 KiB).
pub const MAX_PRESET_BYTES: usize = 256 * 1024;

/// Most joints in a preset, counting limb joints (DESIGN.md input limits).
pub const MAX_JOINTS: usize = 512;

/// Most end effectors in a preset, counting limb effectors (DESIGN.md input limits).
pub const MAX_EFFECTORS: usize = 32;

/// Most DH limbs in a preset (DESIGN.md: ≤ 32 legs).
pub const MAX_LIMBS: usize = 32;

/// Longest joint, effector, limb or preset name, characters.
pub const MAX_NAME_CHARS: usize = 64;
