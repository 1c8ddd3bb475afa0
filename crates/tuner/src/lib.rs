//! gaitlab's gait tuner: the "tweaking" of Raibert & Hodgins 1991 §5 ("we
//! reduced the standing length… we adjusted the spring and damping
//! constants… until…") as a search. CMA-ES ([`cmaes`]) over a physics
//! gait's tunable gains ([`problem`]) against a named, weighted objective
//! ([`objective`]), the best candidate kept ([`tune()`]). Deterministic for a
//! seed: its random numbers ([`rng`]) and maths are portable, and runs are
//! handed to the caller's evaluator a generation at a time, so the CLI runs
//! them on every core and a page in Web Workers with the same result.

pub mod cmaes;
pub mod objective;
pub mod problem;
pub mod rng;
pub mod tune;

pub use objective::Objective;
pub use problem::{Evaluation, Problem};
pub use tune::{Generation, TuneOptions, Tuned, tune};
