//! Task completion rules, shared by the demo, `run` and the study harness.
//!
//! A [`GoalTracker`] reads the world after every step and decides what the
//! scene's [`crate::scene::Goal`] says: objects placed, waypoints passed,
//! restarts, and whether the task is complete.

mod containment;
mod tracker;

pub use tracker::{GoalTracker, Progress};
