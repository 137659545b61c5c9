//! The physics thresholds' table (`tests/common/thresholds.rs`) is
//! consistent: one entry a name, a reason for each, and every bound on the
//! safe side of the value this build measures, by a margin the reason states.

mod common;

use common::thresholds::{ALL, Side};

#[test]
fn every_threshold_has_a_name_a_reason_and_holds_its_measured_value() {
    for (i, t) in ALL.iter().enumerate() {
        assert!(!t.name.is_empty() && !t.reason.is_empty(), "threshold {i} has no name or reason");
        assert!(ALL[..i].iter().all(|o| o.name != t.name), "{}: two entries", t.name);
        assert!(t.bound.is_finite() && t.measured.is_finite(), "{}: bound and measured are numbers", t.name);
        assert!(t.holds(t.measured), "{}: the measured {} does not meet the bound {}", t.name, t.measured, t.bound);
        assert!(!t.holds(t.bound), "{}: a value at the bound itself fails", t.name);
        // A bound far from what the code measures cannot catch a change:
        // no more than three times the measured value away (upper bounds),
        // nor below a third of it (lower bounds).
        let loose = match t.side {
            Side::Below => t.bound > 3.0 * t.measured.max(1e-6),
            Side::Above => t.bound < t.measured / 3.0,
        };
        assert!(!loose, "{}: bound {} is loose against the measured {}", t.name, t.bound, t.measured);
    }
}
