//! Contact geometry timings against vertex count: the O(m + n) entrance
//! block (build, query, both), the one-shot walk that answers without
//! storing the block, the O(m·n) brute force, the cached block's point
//! queries and parry2d's GJK/EPA `contact`, on overlapping pairs of n-gons
//! (n = 8 … 4096), and the cached block against parry on random
//! translations round random overlapping pairs (n = 64, 256, 1024). After
//! criterion's own report a summary prints the median per size, the
//! log-log slopes and the ratios against their targets:
//!
//! ```text
//! cargo bench --bench contact                  # full run, ~2 minutes on 2 cores
//! cargo bench --bench contact -- build         # criterion filter, summary of what ran
//! cargo bench --bench contact -- translations  # the random-translation table only
//! ```

use std::collections::BTreeMap;
use std::hint::black_box;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query;
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surfacelab::contact::{
    CachedBlock, CircleFit, ConvexPolygon, EntranceBlock, Relation, Vec2, brute_force_report, contact_report,
    discretize_circle, log_log_slope, random_ellipse,
};

const SIZES: [usize; 10] = [8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096];
/// The brute force is quadratic: at 4096 vertices a call takes far too long to sample.
const BRUTE_MAX: usize = 1024;

/// Nanoseconds per call of every timing criterion made, by method and size,
/// in order: its warm-up's first, then the [`SAMPLE_SIZE`] samples it
/// measures. The summary takes the median of those last ones.
static SAMPLES: Mutex<BTreeMap<(&'static str, usize), Vec<f64>>> = Mutex::new(BTreeMap::new());

fn record(method: &'static str, n: usize, ns: f64) {
    if let Ok(mut samples) = SAMPLES.lock() {
        samples.entry((method, n)).or_default().push(ns);
    }
}

/// Two overlapping n-gons whose edges are never parallel.
fn pair(n: usize) -> (ConvexPolygon, ConvexPolygon) {
    let a = discretize_circle(Vec2::ZERO, 1.0, n, CircleFit::Inscribed, 0.1).expect("n-gon");
    let b = discretize_circle(Vec2::new(0.6, 0.3), 1.0, n, CircleFit::Inscribed, 0.37).expect("n-gon");
    (a, b)
}

/// Sizes of the random-pair comparison with parry.
const RANDOM_SIZES: [usize; 8] = [8, 16, 32, 64, 128, 256, 512, 1024];
/// Random pairs per size; each call takes the next, so no one pair's
/// geometry decides a timing.
const RANDOM_PAIRS: usize = 32;

/// Random convex pairs of `n` vertices each: overlapping (centres 0.5
/// apart) or separated (4 apart, beyond the largest axes), as raw points.
fn random_pairs(n: usize, separated: bool) -> Vec<(Vec<Vec2>, Vec<Vec2>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(20 + n as u64 + u64::from(separated));
    let d = if separated { 4.0 } else { 0.5 };
    (0..RANDOM_PAIRS)
        .map(|_| {
            let dir: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            (
                random_ellipse(&mut rng, n, Vec2::ZERO),
                random_ellipse(&mut rng, n, Vec2::new(d * dir.cos(), d * dir.sin())),
            )
        })
        .collect()
}

fn built(pairs: &[(Vec<Vec2>, Vec<Vec2>)]) -> Vec<(ConvexPolygon, ConvexPolygon)> {
    pairs
        .iter()
        .map(|(a, b)| (ConvexPolygon::new(a).expect("convex"), ConvexPolygon::new(b).expect("convex")))
        .collect()
}

fn parry(p: &ConvexPolygon) -> ParryPolygon {
    let pts = p.vertices().iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("convex")
}

fn bench(
    c: &mut Criterion,
    method: &'static str,
    sizes: &[usize],
    mut make: impl FnMut(usize) -> Box<dyn FnMut() -> f64>,
) {
    let mut group = c.benchmark_group(format!("contact/{method}"));
    for &n in sizes {
        let mut f = make(n);
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter_custom(|iters| {
                let start = Instant::now();
                for _ in 0..iters {
                    black_box(f());
                }
                let elapsed = start.elapsed();
                record(method, n, elapsed.as_secs_f64() * 1e9 / iters.max(1) as f64);
                elapsed
            });
        });
    }
    group.finish();
}

fn benches(c: &mut Criterion) {
    pair_benches(c);
    random_benches(c);
    translation_benches(c);
}

/// The entrance block against brute force and parry on regular pairs.
fn pair_benches(c: &mut Criterion) {
    bench(c, "build", &SIZES, |n| {
        let (a, b) = pair(n);
        Box::new(move || EntranceBlock::new(black_box(&a), black_box(&b)).edges().len() as f64)
    });
    bench(c, "query", &SIZES, |n| {
        let (a, b) = pair(n);
        let block = EntranceBlock::new(&a, &b);
        Box::new(move || black_box(&block).report().distance)
    });
    bench(c, "build+query", &SIZES, |n| {
        let (a, b) = pair(n);
        Box::new(move || EntranceBlock::new(black_box(&a), black_box(&b)).report().distance)
    });
    bench(c, "one_shot", &SIZES, |n| {
        let (a, b) = pair(n);
        Box::new(move || contact_report(black_box(&a), black_box(&b)).distance)
    });
    let brute_sizes: Vec<usize> = SIZES.iter().copied().filter(|&n| n <= BRUTE_MAX).collect();
    bench(c, "brute_force", &brute_sizes, |n| {
        let (a, b) = pair(n);
        Box::new(move || brute_force_report(black_box(&a), black_box(&b)).distance)
    });
    bench(c, "cached_relation", &SIZES, |n| {
        let (a, b) = pair(n);
        let cached = CachedBlock::new(&a, &b);
        let mut k = 0u32;
        Box::new(move || {
            // Overlapping translations around the start: O(log n) each.
            k = k.wrapping_add(1);
            let t = Vec2::new(0.1 * f64::from(k % 7), 0.1 * f64::from(k % 5));
            f64::from(u8::from(cached.relation(black_box(t)) == Relation::Intersecting))
        })
    });
    bench(c, "cached_distance_separated", &SIZES, |n| {
        let (a, b) = pair(n);
        let cached = CachedBlock::new(&a, &b);
        // Translations round the block, 4 out: computed here, so that the
        // timing is the query's and not a sine's and cosine's.
        let around: Vec<Vec2> = (0..64)
            .map(|k| {
                let angle = f64::from(k) * 0.098;
                Vec2::new(0.6 + 4.0 * angle.cos(), 0.3 + 4.0 * angle.sin())
            })
            .collect();
        let mut k = 0;
        Box::new(move || {
            k = (k + 1) % around.len();
            cached.signed_distance(black_box(around[k]))
        })
    });
    for (separated, ours, theirs) in
        [(false, "random_overlap", "parry_random_overlap"), (true, "random_separated", "parry_random_separated")]
    {
        bench(c, ours, &RANDOM_SIZES, |n| {
            let pairs = built(&random_pairs(n, separated));
            let mut k = 0;
            Box::new(move || {
                k = (k + 1) % pairs.len();
                contact_report(black_box(&pairs[k].0), black_box(&pairs[k].1)).distance
            })
        });
        bench(c, theirs, &RANDOM_SIZES, |n| {
            let pairs: Vec<(ParryPolygon, ParryPolygon)> =
                built(&random_pairs(n, separated)).iter().map(|(a, b)| (parry(a), parry(b))).collect();
            let id = Pose::identity();
            let mut k = 0;
            // A prediction distance past any gap, so parry returns the
            // distance of separated pairs as ours does.
            Box::new(move || {
                k = (k + 1) % pairs.len();
                query::contact(&id, black_box(&pairs[k].0), &id, black_box(&pairs[k].1), 100.0)
                    .ok()
                    .flatten()
                    .map_or(f64::NAN, |contact| contact.dist)
            })
        });
    }
}

/// Random point sets, hulled first: the block against parry.
fn random_benches(c: &mut Criterion) {
    bench(c, "random_from_points", &RANDOM_SIZES, |n| {
        let pairs = random_pairs(n, false);
        let mut k = 0;
        Box::new(move || {
            k = (k + 1) % pairs.len();
            let a = ConvexPolygon::new(black_box(&pairs[k].0)).expect("convex");
            let b = ConvexPolygon::new(black_box(&pairs[k].1)).expect("convex");
            contact_report(&a, &b).distance
        })
    });
    bench(c, "parry_random_from_points", &RANDOM_SIZES, |n| {
        let pairs: Vec<(Vec<Vector>, Vec<Vector>)> = random_pairs(n, false)
            .into_iter()
            .map(|(a, b)| {
                let v = |p: Vec<Vec2>| p.iter().map(|q| Vector::new(q.x, q.y)).collect::<Vec<_>>();
                (v(a), v(b))
            })
            .collect();
        let id = Pose::identity();
        let mut k = 0;
        Box::new(move || {
            k = (k + 1) % pairs.len();
            // parry's own cleaning constructor (drops collinear points).
            let a = ParryPolygon::from_convex_polyline(black_box(pairs[k].0.clone())).expect("convex");
            let b = ParryPolygon::from_convex_polyline(black_box(pairs[k].1.clone())).expect("convex");
            query::contact(&id, &a, &id, &b, 100.0).ok().flatten().map_or(f64::NAN, |contact| contact.dist)
        })
    });
    bench(c, "parry_contact", &SIZES, |n| {
        let (a, b) = pair(n);
        let (pa, pb) = (parry(&a), parry(&b));
        let id = Pose::identity();
        Box::new(move || {
            query::contact(&id, black_box(&pa), &id, black_box(&pb), 0.0)
                .ok()
                .flatten()
                .map_or(f64::NAN, |contact| contact.dist)
        })
    });
}

/// Sizes, pairs per size and translations per pair of the cached block's
/// random-translation comparison.
const TRANSLATION_SIZES: [usize; 3] = [64, 256, 1024];
const TRANSLATION_PAIRS: usize = 5;
const TRANSLATIONS: usize = 256;
/// The translations fill a disc of this radius around the overlapping pose:
/// the polygons' axes are 0.5 to 1.5, so most translations overlap and some
/// separate.
const TRANSLATION_RADIUS: f64 = 2.0;

/// Nanoseconds per query of every timing criterion made in the translation
/// comparison, by method, size and pair.
static PAIR_SAMPLES: Mutex<PairSamples> = Mutex::new(BTreeMap::new());
type PairSamples = BTreeMap<(&'static str, usize, usize), Vec<f64>>;

/// [`TRANSLATIONS`] seeded translations, uniform in the disc of
/// [`TRANSLATION_RADIUS`] around the origin (the pair as built).
fn translations() -> Vec<Vec2> {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    (0..TRANSLATIONS)
        .map(|_| {
            let r = TRANSLATION_RADIUS * rng.random_range(0.0..1.0f64).sqrt();
            let angle: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            Vec2::new(r * angle.cos(), r * angle.sin())
        })
        .collect()
}

/// The cached block against parry on one overlapping pair at a time: the
/// block built once, then a full report at each of the [`translations`],
/// against parry's `contact` with A's pose moved by the same translation
/// (parry's polygons are built outside the timing, the block inside it).
/// Each sample times both, one after the other, so that both see the same
/// load on a shared machine.
fn translation_benches(c: &mut Criterion) {
    let moves = translations();
    for n in TRANSLATION_SIZES {
        let mut group = c.benchmark_group(format!("contact/translations/{n}"));
        for (k, (a, b)) in built(&random_pairs(n, false)).iter().take(TRANSLATION_PAIRS).enumerate() {
            let (pa, pb) = (parry(a), parry(b));
            let id = Pose::identity();
            let ours = || {
                let cached = CachedBlock::new(black_box(a), black_box(b));
                moves.iter().map(|&t| cached.report(black_box(t)).distance).sum::<f64>()
            };
            let theirs = || {
                let contact = |t: &Vec2| query::contact(&Pose::translation(t.x, t.y), black_box(&pa), &id, &pb, 100.0);
                moves.iter().map(|t| contact(t).ok().flatten().map_or(f64::NAN, |c| c.dist)).sum::<f64>()
            };
            group.bench_function(BenchmarkId::new("pair", k), |bencher| {
                bencher.iter_custom(|iters| {
                    let start = Instant::now();
                    for _ in 0..iters {
                        black_box(ours());
                    }
                    let mid = Instant::now();
                    for _ in 0..iters {
                        black_box(theirs());
                    }
                    let spent = [mid - start, mid.elapsed()];
                    if let Ok(mut samples) = PAIR_SAMPLES.lock() {
                        for (method, time) in [("cached", spent[0]), ("parry", spent[1])] {
                            let ns = time.as_secs_f64() * 1e9 / (iters.max(1) * TRANSLATIONS as u64) as f64;
                            samples.entry((method, n, k)).or_default().push(ns);
                        }
                    }
                    spent[0] + spent[1]
                });
            });
        }
        group.finish();
    }
}

/// Per size: the median over pairs of each method's time per query, and the
/// median over pairs of parry's time over the cached block's.
fn translation_summary() {
    let Ok(samples) = PAIR_SAMPLES.lock() else { return };
    let mid = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied()
    };
    let mut rows = Vec::new();
    for n in TRANSLATION_SIZES {
        let per_pair = |method: &'static str| -> Vec<f64> {
            (0..TRANSLATION_PAIRS).filter_map(|k| samples.get(&(method, n, k)).map(|v| median(v))).collect()
        };
        let (ours, theirs) = (per_pair("cached"), per_pair("parry"));
        if ours.len() != theirs.len() || ours.is_empty() {
            continue;
        }
        let ratios = theirs.iter().zip(&ours).map(|(p, o)| p / o).collect();
        if let (Some(o), Some(p), Some(r)) = (mid(ours), mid(theirs), mid(ratios)) {
            rows.push((n, o, p, r));
        }
    }
    if rows.is_empty() {
        return;
    }
    println!(
        "\ncached block, build + {TRANSLATIONS} random translations (disc of radius {TRANSLATION_RADIUS}) per overlapping random pair, median over {TRANSLATION_PAIRS} pairs:"
    );
    println!("{:>6}{:>22}{:>22}{:>14}", "n", "cached ns/query", "parry ns/query", "parry/ours");
    for (n, o, p, r) in rows {
        println!("{n:>6}{o:>22.1}{p:>22.1}{r:>13.1}x");
    }
    println!("target: >= 20x from n = 64");
}

/// Samples criterion measures per benchmark after warming up.
const SAMPLE_SIZE: usize = 10;

/// The median of the measured samples. The warm-up's come first, and from
/// one call at a time upwards: counted in, they would move the median of a
/// sub-microsecond query by half, far from criterion's own estimates.
fn median(v: &[f64]) -> f64 {
    let mut v = v[v.len().saturating_sub(SAMPLE_SIZE)..].to_vec();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The table, slopes and ratios of whatever ran.
fn summary() {
    let Ok(samples) = SAMPLES.lock() else { return };
    if samples.is_empty() {
        return;
    }
    let medians: BTreeMap<(&str, usize), f64> = samples.iter().map(|(&k, v)| (k, median(v))).collect();
    let methods = [
        "build",
        "query",
        "build+query",
        "one_shot",
        "brute_force",
        "cached_relation",
        "cached_distance_separated",
        "parry_contact",
    ];
    println!("\ncontact summary: median ns per call, overlapping n-gon pairs (m = n)");
    print!("{:>27}", "n");
    for n in SIZES {
        print!("{n:>10}");
    }
    println!("{:>12}{:>12}", "slope all", "slope n≥64");
    for method in methods {
        let row: Vec<(f64, f64)> =
            SIZES.iter().filter_map(|&n| medians.get(&(method, n)).map(|&t| (n as f64, t))).collect();
        if row.is_empty() {
            continue;
        }
        print!("{method:>27}");
        for n in SIZES {
            match medians.get(&(method, n)) {
                Some(t) => print!("{t:>10.0}"),
                None => print!("{:>10}", "-"),
            }
        }
        let large: Vec<(f64, f64)> = row.iter().copied().filter(|&(n, _)| n >= 64.0).collect();
        let fmt = |s: Option<f64>| s.map_or_else(|| "-".to_owned(), |s| format!("{s:.2}"));
        println!("{:>12}{:>12}", fmt(log_log_slope(&row)), fmt(log_log_slope(&large)));
    }
    let ratio = |slow: &str, fast: &str, n: usize| Some(medians.get(&(slow, n))? / medians.get(&(fast, n))?);
    if let Some(r) = ratio("brute_force", "build+query", 256) {
        println!("brute force / entrance block (build+query) at n = 256: {r:.1}x (goal >= 10x)");
    }
    for n in [8, 16, 64, 256, 1024, 4096] {
        let goal = if n == 64 { " (goal >= 2x)" } else { "" };
        if let (Some(one), Some(both)) =
            (ratio("parry_contact", "one_shot", n), ratio("parry_contact", "build+query", n))
        {
            println!(
                "parry2d contact / ours at n = {n}: one-shot {one:.2}x{goal}, stored block build+query {both:.2}x"
            );
        }
    }
}

/// Ratios on random pairs, against their targets: parry's time over ours.
fn random_summary(medians: &BTreeMap<(&str, usize), f64>) {
    let ratio = |slow: &str, fast: &str, n: usize| Some(medians.get(&(slow, n))? / medians.get(&(fast, n))?);
    let any = RANDOM_SIZES.iter().any(|&n| ratio("parry_random_overlap", "random_overlap", n).is_some());
    if !any {
        return;
    }
    println!("\nrandom convex pairs (32 per size), parry2d contact time / ours:");
    println!("{:>6}{:>16}{:>16}{:>20}", "n", "overlapping", "separated", "from raw points");
    let fmt = |r: Option<f64>| r.map_or_else(|| "-".to_owned(), |r| format!("{r:.2}x"));
    for n in RANDOM_SIZES {
        println!(
            "{n:>6}{:>16}{:>16}{:>20}",
            fmt(ratio("parry_random_overlap", "random_overlap", n)),
            fmt(ratio("parry_random_separated", "random_separated", n)),
            fmt(ratio("parry_random_from_points", "random_from_points", n)),
        );
    }
    println!("targets: overlapping >= 1.5x, separated >= 1x, from raw points >= 1x");
    for method in ["random_overlap", "random_separated", "random_from_points"] {
        let row: Vec<(f64, f64)> =
            RANDOM_SIZES.iter().filter_map(|&n| medians.get(&(method, n)).map(|&t| (n as f64, t))).collect();
        if let Some(slope) = log_log_slope(&row) {
            println!("log-log slope of {method}: {slope:.2} (target <= 1.05)");
        }
    }
    for (cached, what) in [("cached_relation", "overlapping"), ("cached_distance_separated", "separated")] {
        if let Some(r) = ratio("parry_random_overlap", cached, 64) {
            println!(
                "cached block translation queries, {what}, at n = 64: parry random overlap / ours {r:.1}x (target >= 20x)"
            );
        }
    }
}

fn main() {
    let mut c = Criterion::default()
        .sample_size(SAMPLE_SIZE)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_millis(600))
        .configure_from_args();
    benches(&mut c);
    c.final_summary();
    summary();
    if let Ok(samples) = SAMPLES.lock() {
        let medians: BTreeMap<(&str, usize), f64> = samples.iter().map(|(&k, v)| (k, median(v))).collect();
        random_summary(&medians);
    }
    translation_summary();
}
