//! One live pipeline: synthetic hands → contact image → vision → technique →
//! world → goal. `run`, `study`, `screenshot`, the demo, the benchmarks and
//! the tests all drive this same loop, so they cannot drift apart.

mod goal;
mod object_track;
mod report;
#[allow(clippy::module_inception)]
mod session;

pub use goal::{GoalTracker, Progress};
pub use object_track::ObjectTrack;
pub use report::{ObjectReport, RunReport, StageMeans};
pub use session::{MOVING_SPEED, Session, SessionError, SessionOptions, StageTimes};
