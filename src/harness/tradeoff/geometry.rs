//! The contact module's knobs: circle segment count against the analytic
//! circle, and the entrance block against the brute force and parry2d at
//! equal accuracy.

use super::row::Row;
use crate::contact::{self, CircleFit, ConvexPolygon, EntranceBlock, Vec2, discretize_circle};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query;
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::hint::black_box;
use std::time::Instant;

/// The segment count the report recommends for sphere and cylinder
/// footprints (3 cm radius: 0.14 mm error, inside the sensor's 1.6 mm pixel).
pub const DEFAULT_CIRCLE_SEGMENTS: usize = 32;

/// Median ns per call of `f`, over `batches` batches of `iters` calls.
fn time_ns(iters: usize, batches: usize, mut f: impl FnMut() -> f64) -> f64 {
    let mut samples: Vec<f64> = (0..batches)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..iters {
                black_box(f());
            }
            t.elapsed().as_secs_f64() * 1e9 / iters as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

/// A box footprint (6 × 6 cm) against a circle of radius 3 cm (a sphere's
/// footprint) discretised into N segments, at random placements with the
/// circle's centre outside the box: separated and overlapping. The exact
/// distance is |c − clamp(c, box)| − r.
pub fn circle_segments(quick: bool) -> Vec<Row> {
    let r = 0.03;
    let half = 0.03;
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let centers: Vec<Vec2> = (0..if quick { 300 } else { 2000 })
        .map(|_| {
            loop {
                let c = Vec2::new(rng.random_range(-0.1..0.1), rng.random_range(-0.1..0.1));
                let out = Vec2::new((c.x.abs() - half).max(0.0), (c.y.abs() - half).max(0.0));
                let d = (out.x * out.x + out.y * out.y).sqrt();
                if d > 0.001 && d < 0.06 {
                    break c;
                }
            }
        })
        .collect();
    let boxp = ConvexPolygon::from_xy(&[[-half, -half], [half, -half], [half, half], [-half, half]]).expect("box");
    let mut rows = Vec::new();
    for n in [6usize, 8, 12, 16, 24, 32, 48, 64, 128, 256] {
        let mut err = 0.0;
        let circles: Vec<ConvexPolygon> =
            centers.iter().map(|c| discretize_circle(*c, r, n, CircleFit::Inscribed, 0.0).expect("circle")).collect();
        for (c, poly) in centers.iter().zip(&circles) {
            let out = Vec2::new((c.x.abs() - half).max(0.0), (c.y.abs() - half).max(0.0));
            let exact = (out.x * out.x + out.y * out.y).sqrt() - r;
            err += (contact::contact_report(poly, &boxp).distance - exact).abs();
        }
        let mut k = 0;
        let ns = time_ns(if quick { 2000 } else { 20_000 }, 5, || {
            k = (k + 1) % circles.len();
            contact::contact_report(&circles[k], &boxp).distance
        });
        rows.push(Row::new(
            "circle_segments",
            n.to_string(),
            n == DEFAULT_CIRCLE_SEGMENTS,
            ns,
            "ns/query",
            err / centers.len() as f64 * 1000.0,
            "mm",
            "analytic circle",
        ));
    }
    rows
}

/// The entrance block (one-shot, and stored build + query), the O(m·n)
/// brute force and parry2d's GJK/EPA on the same overlapping n-gon pairs;
/// error is the distance's deviation from the brute force (the paper's
/// definition, exact up to rounding).
pub fn contact_methods(quick: bool) -> Vec<Row> {
    let sizes: &[usize] = if quick { &[8, 64] } else { &[8, 64, 256] };
    let mut rows = Vec::new();
    for &n in sizes {
        let a = discretize_circle(Vec2::ZERO, 1.0, n, CircleFit::Inscribed, 0.1).expect("n-gon");
        let b = discretize_circle(Vec2::new(0.6, 0.3), 1.0, n, CircleFit::Inscribed, 0.37).expect("n-gon");
        let reference = contact::brute_force_report(&a, &b).distance;
        let to_parry = |p: &ConvexPolygon| {
            let pts = p.vertices().iter().map(|v| Vector::new(v.x, v.y)).collect();
            ParryPolygon::from_convex_polyline_unmodified(pts)
        };
        let iters = if quick { 200 } else { 2000 } * 64 / n.max(8);
        let mut push = |method: &str, default: bool, ns: f64, d: f64| {
            rows.push(Row::new(
                "contact_method",
                format!("{method} n={n}"),
                default,
                ns,
                "ns/query",
                (d - reference).abs(),
                "m",
                "brute force",
            ));
        };
        let d = contact::contact_report(&a, &b).distance;
        push("entrance_block", true, time_ns(iters, 5, || contact::contact_report(&a, &b).distance), d);
        let d = EntranceBlock::new(&a, &b).report().distance;
        push("entrance_block_stored", false, time_ns(iters, 5, || EntranceBlock::new(&a, &b).report().distance), d);
        if n <= 256 {
            push(
                "brute_force",
                false,
                time_ns((iters / n).max(4), 5, || contact::brute_force_report(&a, &b).distance),
                reference,
            );
        }
        if let (Some(pa), Some(pb)) = (to_parry(&a), to_parry(&b)) {
            let id = Pose::identity();
            let run = || query::contact(&id, &pa, &id, &pb, 0.0).ok().flatten().map_or(f64::NAN, |c| c.dist);
            let d = run();
            push("parry2d", false, time_ns(iters, 5, run), d);
        }
    }
    rows
}
