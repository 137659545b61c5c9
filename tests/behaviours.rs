//! The behaviour suite: the paper's manipulations, each a scene
//! file plus a gesture file replayed through the real pipeline under every
//! technique, asserted against the paper's expectation. The cases, their
//! physical thresholds and the paper's words live in `src/harness/behaviour/cases.rs`
//! (one definition for these tests, `surfacelab behaviours` and the demo).
//!
//! One test per case, so `cargo test --release --test behaviours ball_spin`
//! runs one. `behaviour_table` prints the whole behaviour × technique table
//! (`-- --nocapture`); each case is simulated once per process whichever
//! test asks first.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::OnceLock;
use surfacelab::harness::behaviour::{
    Case, CellVerdict, Expectation, GAPS, Measurement, Metric, cases, cells, markdown, run_case, suite_kinds,
};
use surfacelab::pipeline::technique::TechniqueKind;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn all_cases() -> &'static [Case] {
    static CASES: OnceLock<Vec<Case>> = OnceLock::new();
    CASES.get_or_init(cases)
}

/// Each case's outcomes under every suite technique, computed once.
fn outcomes(name: &str) -> &'static [Measurement] {
    static CACHE: OnceLock<BTreeMap<&'static str, OnceLock<Vec<Measurement>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| all_cases().iter().map(|c| (c.name, OnceLock::new())).collect());
    let case = all_cases().iter().find(|c| c.name == name).unwrap_or_else(|| panic!("no behaviour case `{name}`"));
    cache[name].get_or_init(|| {
        suite_kinds()
            .into_iter()
            .map(|k| run_case(case, k, root()).unwrap_or_else(|e| panic!("{name} under {k}: {e}")))
            .collect()
    })
}

/// Asserts every cell of one case; the message lists each miss with its number.
fn assert_case(name: &str) {
    let case = all_cases().iter().find(|c| c.name == name).expect("case");
    let mut misses = Vec::new();
    for o in outcomes(name) {
        assert_eq!(o.nan_count, 0, "{name} under {}: NaN in the world", o.technique);
        for cell in cells(case, o) {
            if cell.verdict.is_failure() {
                let what = match case.expectation(o.technique) {
                    Expectation::Limit { quote, .. } => format!("the paper's limit (\"{quote}\")"),
                    _ => format!("the paper: {}", case.paper),
                };
                misses.push(format!(
                    "{} / {}: {} = {:.4} (SI), expected {} — {what}",
                    name,
                    o.technique,
                    cell.metric.label(),
                    cell.value,
                    cell.check.map_or("-".to_string(), |c| c.to_string()),
                ));
            }
        }
    }
    assert!(misses.is_empty(), "{} cell(s) miss their expectation:\n{}", misses.len(), misses.join("\n"));
}

macro_rules! behaviour_tests {
    ($($name:ident),* $(,)?) => {
        $( #[test] fn $name() { assert_case(stringify!($name)); } )*
        const TESTED: &[&str] = &[$(stringify!($name)),*];
    };
}

behaviour_tests!(
    pin_and_spin_small_box,
    pin_and_spin_one_box,
    two_finger_twist,
    two_finger_twist_slow,
    flat_hand_turn,
    heavy_flat_hand,
    heavy_fingertip,
    grip_block,
    cylinder_top_drag,
    side_push_floor_000,
    side_push_floor_045,
    side_push_floor_090,
    side_push_floor_135,
    side_push_floor_180,
    side_push_floor_225,
    side_push_floor_270,
    side_push_floor_315,
    side_push_platform_000,
    side_push_platform_045,
    side_push_platform_090,
    side_push_platform_135,
    side_push_platform_180,
    side_push_platform_225,
    side_push_platform_270,
    side_push_platform_315,
    side_push_platform_wide_000,
    side_push_platform_wide_045,
    side_push_platform_wide_090,
    side_push_platform_wide_135,
    side_push_platform_wide_180,
    side_push_platform_wide_225,
    side_push_platform_wide_270,
    side_push_platform_wide_315,
    ball_light_touch,
    ball_spin,
    ball_under_hand,
    ball_under_hand_off_centre,
    ball_under_hand_forward,
    ball_stop_flat_hand,
    ball_bounce_hand_edge,
    flick_from_rest,
    flick_fast,
    gather_hand_edges,
    gather_forearms,
    grasp_flat_hands,
    grasp_pinch,
    fingers_over_ball_drag,
    flat_hand_beside_ball,
);

#[test]
fn every_case_has_a_test_and_its_files() {
    let names: Vec<&str> = all_cases().iter().map(|c| c.name).collect();
    assert_eq!(names, TESTED, "tests/behaviours.rs lists exactly the suite's cases, in order");
    for c in all_cases() {
        assert!(root().join(c.scene).is_file(), "{}: scene {} missing", c.name, c.scene);
        assert!(root().join(c.gesture).is_file(), "{}: gesture {} missing", c.name, c.gesture);
        assert!(!c.checks.is_empty(), "{}: no check", c.name);
    }
}

/// One line of the known-gap baseline: case, technique, measure, the
/// measured value in the table's unit and the check it misses.
fn gap_line(case: &str, technique: TechniqueKind, metric: Metric, value: f32, check: &str) -> String {
    format!("{case} | {technique} | {} | {:.1} | {check}", metric.label(), value * metric.scale())
}

/// The known gaps (src/harness/behaviour/gaps.rs) are exactly the cells that
/// miss today, and exactly the ones recorded with their measured values in
/// `tests/snapshots/known_gaps.txt`: each names a case, technique and
/// measure the suite has, and each still misses its check. A gap that starts
/// to pass must come off both lists; a new gap is an explicit change to the
/// baseline, with its measurement.
#[test]
fn known_gaps_match_their_baseline_and_still_miss() {
    let mut measured = Vec::new();
    for g in GAPS {
        let case = all_cases().iter().find(|c| c.name == g.case).unwrap_or_else(|| panic!("gap names no case: {g:?}"));
        let o = outcomes(g.case)
            .iter()
            .find(|o| o.technique == g.technique)
            .unwrap_or_else(|| panic!("gap names a technique outside the suite: {g:?}"));
        let cell = cells(case, o)
            .into_iter()
            .find(|c| c.metric == g.metric)
            .unwrap_or_else(|| panic!("gap names a measure the case does not show: {g:?}"));
        assert_eq!(
            cell.verdict,
            CellVerdict::KnownGap,
            "{} / {} / {} = {:.4} now meets its check: take it off GAPS and the baseline",
            g.case,
            g.technique,
            g.metric.label(),
            cell.value
        );
        let check = cell.check.expect("a known gap misses a check").to_string();
        measured.push(gap_line(g.case, g.technique, g.metric, cell.value, &check));
    }
    let path = root().join("tests/snapshots/known_gaps.txt");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let recorded: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty() && !l.starts_with('#')).collect();
    assert_eq!(
        measured,
        recorded,
        "the known gaps as measured (left) differ from {} (right): a gap added, closed or re-measured is an \
         explicit change to both lists",
        path.display()
    );
}

/// Prints the behaviour × technique table (docs/behaviours.md's, regenerated by
/// `cargo test --release --test behaviours -- --nocapture` or
/// `surfacelab behaviours`), and asserts that every printed cell has an
/// expectation (the case's works-check or the paper's quoted limit) and
/// meets it, or is a listed known gap.
#[test]
fn behaviour_table() {
    let kinds = suite_kinds();
    let all: Vec<Measurement> = all_cases().iter().flat_map(|c| outcomes(c.name).iter().cloned()).collect();
    assert_eq!(all.len(), all_cases().len() * kinds.len(), "one outcome per case and technique");
    let table = markdown(all_cases(), &kinds, &all);
    println!("\n{table}");
    let printed: Vec<_> = all_cases()
        .iter()
        .flat_map(|c| all.iter().filter(move |o| o.case == c.name).flat_map(move |o| cells(c, o)))
        .collect();
    let rows: usize = all_cases().iter().map(|c| c.metrics().len()).sum();
    assert_eq!(printed.len(), rows * kinds.len(), "one cell per row and technique");
    let name = |cell: &surfacelab::harness::behaviour::Cell| {
        format!("{} / {} / {} = {:.4}", cell.case, cell.technique, cell.metric.label(), cell.value)
    };
    let unexpected: Vec<String> = printed.iter().filter(|c| c.verdict == CellVerdict::Shown).map(name).collect();
    assert!(unexpected.is_empty(), "{} cells have no expectation:\n{}", unexpected.len(), unexpected.join("\n"));
    let failing: Vec<String> = printed.iter().filter(|c| c.verdict.is_failure()).map(name).collect();
    assert!(failing.is_empty(), "{} cells miss their expectation:\n{}", failing.len(), failing.join("\n"));
    let gaps = printed.iter().filter(|c| c.verdict == CellVerdict::KnownGap).count();
    assert_eq!(gaps, GAPS.len(), "every known gap is a printed cell, and every missed cell a known gap");
    let held = printed.iter().filter(|c| matches!(c.verdict, CellVerdict::Pass | CellVerdict::LimitHolds)).count();
    assert_eq!(held + gaps, printed.len(), "every other cell meets its expectation");
}

/// For Joint alone (whatever the other techniques do): a flat hand whose
/// centroid misses a ball, its fingers over it, gets no prism under the
/// ball (one there would lift it), and a hand edge across the
/// rolling ball's path still stops it from the side and sends it back,
/// without lifting it.
#[test]
fn joint_prisms_never_lift_a_ball_and_push_it_from_the_side() {
    let case = |name: &str| all_cases().iter().find(|c| c.name == name).expect("case");
    let beside = run_case(case("flat_hand_beside_ball"), TechniqueKind::JOINT, root()).expect("run");
    assert!(beside.get(Metric::MaxLift) <= 0.005, "lifted {:.4} m", beside.get(Metric::MaxLift));
    let bounce = run_case(case("ball_bounce_hand_edge"), TechniqueKind::JOINT, root()).expect("run");
    assert!(bounce.get(Metric::MaxLift) <= 0.005, "the edge lifted the ball {:.4} m", bounce.get(Metric::MaxLift));
    assert!(bounce.get(Metric::Bounce) >= 0.05, "came back at only {:.3} m/s", bounce.get(Metric::Bounce));
    assert!(bounce.get(Metric::MaxAlong) <= 0.534, "passed the edge: {:.3} m", bounce.get(Metric::MaxAlong));
}
