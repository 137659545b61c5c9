//! The O(m·n) reference: every angle–edge and edge–angle pair is tested for
//! validity (the paper's formulas 5 and 6) and the valid covers, which are
//! exactly the pieces of the entrance block's boundary, are searched
//! directly. No walk, no ordering: this is what the O(m + n) walk is checked
//! against, and what it is timed against.

use super::entrance_block::{ContactEdge, CoverKind, PARALLEL, contact_at, nearest_on_boundary, pair_tolerance};
use super::polygon::ConvexPolygon;
use super::report::{ContactReport, Features, Relation};
use super::vec2::Vec2;

/// Every valid cover of A against B, in no particular order. O(m·n) tests,
/// about m + n covers kept.
///
/// An angle–edge pair (vertex `aᵢ`, edge `bⱼ → bⱼ₊₁`) is valid when, with
/// `aᵢ` placed on the edge, both of A's edges at `aᵢ` stay on the outer side
/// of the edge: `n · (aᵢ₋₁ − aᵢ) ≥ 0` and `n · (aᵢ₊₁ − aᵢ) ≥ 0`, `n` the
/// edge's outward normal. Edge–angle pairs are the same with A and B
/// swapped. Parallel neighbours make the product zero; a relative slack of
/// `PARALLEL` (1e-12) keeps such covers despite rounding (a cover accepted by the
/// slack lies inside the block by at most `1e-12 ×` an edge length).
pub fn valid_covers(a: &ConvexPolygon, b: &ConvexPolygon) -> Vec<ContactEdge> {
    let (av, bv) = (a.vertices(), b.vertices());
    let (n, m) = (av.len(), bv.len());
    let mut covers = Vec::with_capacity(2 * (n + m));
    let outside = |normal: Vec2, from: Vec2, to: Vec2| {
        let d = to - from;
        normal.dot(d) >= -PARALLEL * normal.length() * d.length()
    };
    for j in 0..m {
        let j1 = (j + 1) % m;
        let edge_b = bv[j1] - bv[j];
        let normal = edge_b.perp_cw();
        for i in 0..n {
            let (prev, next) = (av[(i + n - 1) % n], av[(i + 1) % n]);
            if outside(normal, av[i], prev) && outside(normal, av[i], next) {
                covers.push(ContactEdge {
                    start: bv[j] - av[i],
                    direction: edge_b,
                    normal: normal.normalized(),
                    kind: CoverKind::AngleEdge,
                    a: [a.source_index(i), a.source_index((i + 1) % n)],
                    b: [b.source_index(j), b.source_index(j1)],
                    a_point: av[i],
                    b_point: bv[j],
                    split: 1.0,
                });
            }
        }
    }
    for i in 0..n {
        let i1 = (i + 1) % n;
        let normal = (av[i1] - av[i]).perp_cw();
        for j in 0..m {
            let (prev, next) = (bv[(j + m - 1) % m], bv[(j + 1) % m]);
            if outside(normal, bv[j], prev) && outside(normal, bv[j], next) {
                let direction = av[i] - av[i1];
                covers.push(ContactEdge {
                    start: bv[j] - av[i],
                    direction,
                    normal: direction.perp_cw().normalized(),
                    kind: CoverKind::EdgeAngle,
                    a: [a.source_index(i), a.source_index(i1)],
                    b: [b.source_index(j), b.source_index((j + 1) % m)],
                    a_point: av[i],
                    b_point: bv[j],
                    split: 0.0,
                });
            }
        }
    }
    covers
}

/// The same answers as [`EntranceBlock::report`](super::entrance_block::EntranceBlock::report),
/// computed from every cover.
pub fn brute_force_report(a: &ConvexPolygon, b: &ConvexPolygon) -> ContactReport {
    brute_force_report_at(a, b, Vec2::ZERO)
}

/// [`brute_force_report`] with A moved by `translation`.
pub fn brute_force_report_at(a: &ConvexPolygon, b: &ConvexPolygon, translation: Vec2) -> ContactReport {
    let tolerance = pair_tolerance(a, b);
    let covers = valid_covers(a, b);
    let nearest = nearest_on_boundary(&covers, translation, tolerance);
    let (witness, _) = contact_at(&covers[nearest.edge], nearest.point, translation, tolerance);
    // Every cover through the contact point contributes its feature: that
    // is how the paper reads angle–angle contacts ("two contact edges at
    // once") and parallel overlaps.
    let mut features = Features::new();
    for cover in &covers {
        if (cover.closest_point(nearest.point) - nearest.point).length() <= tolerance {
            let (_, f) = contact_at(cover, nearest.point, translation, tolerance);
            for &feature in f.as_slice() {
                features.push(feature);
            }
        }
    }
    ContactReport {
        relation: Relation::from_signed_distance(nearest.signed_distance, tolerance),
        distance: nearest.signed_distance,
        exit: nearest.point - translation,
        witness,
        features,
        tolerance,
    }
}
