//! Study participants: a scripted, technique-agnostic participant that
//! drives synthetic hands in closed loop with a repertoire of manners and
//! learns which pays (`manner`, `learner`, `planner`), and replayed gesture
//! recordings (`runner`).

mod goals;
mod learner;
mod manner;
mod planner;
mod repertoire;
mod runner;
mod skill;
mod trial;
mod usage;

pub use learner::{EXPLORE_PRACTICE, Learner};
pub use manner::Manner;
pub use planner::{Planner, PlannerOptions};
pub use repertoire::{PRESETS, Repertoire, RepertoireError};
pub use runner::{ReplayRunner, ScriptedRunner, participant_skill};
pub use skill::{HandMode, Skill};
pub use trial::{FrameLog, MOVING_SPEED, ScriptedTrial, TrialStep, objects_moving, run_trial};
pub use usage::Usage;
