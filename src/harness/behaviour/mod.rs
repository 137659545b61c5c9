//! The paper's manipulations as a behaviour suite: a table of cases (a scene
//! file, a gesture file and physical checks) × techniques, measured through
//! the one frame loop ([`crate::session::Session`]).
//!
//! One definition serves `tests/behaviours.rs` (which asserts it),
//! `surfacelab behaviours` (which prints the table) and the demo (every case
//! is a file pair: `surfacelab demo --task SCENE --script GESTURE`).
//! Where the paper expects a manipulation to work, the check is the same for
//! every technique; where it names a technique's limit, that limit is
//! asserted instead and the paper's sentence is quoted beside it. Cells
//! that miss today are listed, with why, in `gaps.rs`.

mod case;
mod cases;
mod gaps;
mod measure;
mod table;

pub use case::{Axis, Case, Check, Expectation, Metric};
pub use cases::{cases, suite_kinds};
pub use gaps::{GAPS, Gap, known_gap};
pub use measure::{BehaviourError, Measurement, run_case, run_suite};
pub use table::{Cell, CellVerdict, cells, markdown};
