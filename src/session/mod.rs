//! One live pipeline: synthetic hands → contact image → vision → technique →
//! world → goal. `run`, `study`, `screenshot`, the demo, the benchmarks and
//! the tests all drive this same loop, so they cannot drift apart.

pub mod goal;
mod object_track;
mod report;
#[allow(clippy::module_inception)]
mod session;

pub use object_track::ObjectTrack;
pub use report::{ObjectReport, RunReport, StageMeans};
pub use session::{MOVING_SPEED, Session, SessionError, SessionOptions, StageTimes};
