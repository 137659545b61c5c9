//! The colours of the tasks' marks and of the techniques' feedback, as the
//! paper shows them: waypoints blue, targets and the finish red, feedback
//! red. The demo's scene view and the sample scenes of the golden-image tests
//! share them, so the tests picture what the app draws. Linear RGB, as every
//! [`Rgba`] of a draw list.

use crate::render::draw_list::Rgba;

pub const WAYPOINT_BLUE: Rgba = [0.15, 0.35, 0.95, 1.0];
pub const TARGET_RED: Rgba = [0.9, 0.12, 0.1, 1.0];
pub const FEEDBACK_RED: Rgba = [0.95, 0.05, 0.05, 1.0];
