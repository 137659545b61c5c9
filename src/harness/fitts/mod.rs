//! A Fitts' law check of the simulated participants (`surfacelab
//! participants fitts`): do they drag like people?
//!
//! Each participant drags one puck from a start to a target over a grid of
//! distances and target widths, with the study's own planner restricted to
//! a one-finger drag, under one technique. A trial's movement time runs
//! from the finger's touch-down on the puck to its last lift, the span
//! Fitts' law models (the reach before it and the goal's dwell after it are
//! not part of the movement). Its end point is where the puck lay, along
//! the movement axis, when the finger lifted. [`fit`] turns the rows into
//! `a`, `b`, R² and ISO 9241-9 throughput; docs/design/participants.md
//! compares them with published finger-drag figures.

mod drags;
mod figure;
mod fit;

pub use drags::{
    FITTS_COLUMNS, FittsDesign, FittsError, FittsRow, MAX_DISTANCE_M, TIME_LIMIT_S, WIDTH_RANGE_M, run, write,
};
pub use fit::{FittsFit, WE_FACTOR, condition_means, fit, index_of_difficulty, linear_fit, throughput};
