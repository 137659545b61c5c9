//! One measured setting of a knob: a row of `tradeoff.csv`.

use serde::Serialize;

/// One measured setting (a row of `tradeoff.csv`).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Row {
    pub knob: String,
    pub value: String,
    /// This is the shipped default.
    pub default: bool,
    pub time: f64,
    pub time_unit: String,
    pub error: f64,
    pub error_unit: String,
    /// What the error is measured against.
    pub reference: String,
    /// |completion time − reference| of a scripted positioning trial (s),
    /// for physics knobs in the full sweep.
    pub trial_time_diff_s: Option<f64>,
    /// On its knob's Pareto front (filled in after the sweep).
    pub on_front: bool,
}

impl Row {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        knob: &str,
        value: String,
        default: bool,
        time: f64,
        time_unit: &str,
        error: f64,
        error_unit: &str,
        reference: &str,
    ) -> Row {
        Row {
            knob: knob.to_string(),
            value,
            default,
            time,
            time_unit: time_unit.to_string(),
            error,
            error_unit: error_unit.to_string(),
            reference: reference.to_string(),
            trial_time_diff_s: None,
            on_front: false,
        }
    }
}
