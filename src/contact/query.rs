//! The contact query between two convex polygons: a separated pair is
//! settled by a separating axis and a short walk ([`super::separated`]),
//! an overlapping one by an expanding polytope and a shorter one
//! ([`super::overlapping`]); any other (touching, or too small for the
//! searches to pay) by the walk around the entrance block
//! ([`super::entrance_block`]).

use super::entrance_block::{pair_tolerance, walk_report};
use super::overlapping::overlapping_report;
use super::polygon::ConvexPolygon;
use super::report::ContactReport;
use super::separated::separated_report;

/// Distance or penetration depth of `a` and `b`, with witness points and
/// features: the same answers as `EntranceBlock::new(a, b).report()`,
/// without storing the block (worth building only to ask again).
pub fn contact_report(a: &ConvexPolygon, b: &ConvexPolygon) -> ContactReport {
    let tolerance = pair_tolerance(a, b);
    separated_report(a, b, tolerance)
        .or_else(|| overlapping_report(a, b, tolerance))
        .unwrap_or_else(|| walk_report(a, b, tolerance))
}
