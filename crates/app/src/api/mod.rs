//! The JS API's types (DESIGN.md "Browser", docs/app.md): the typed
//! [`Command`] that `command(json)` reads and the [`State`] that `state()`
//! writes, with the JSON Schemas generated from them (feature `schema`).

pub mod camera;
pub mod command;
mod error;
pub mod names;
#[cfg(feature = "schema")]
pub mod schema;
pub mod state;

pub use command::{Command, MAX_COMMAND_BYTES};
pub use state::State;
