//! The study's inferential statistics against published and independently
//! computed numbers: the repeated-measures ANOVA with its Greenhouse–Geisser
//! correction, paired t-tests with Holm's correction and dz, the
//! Cousineau–Morey within-subject CIs, the files they are written to, and
//! the paper's findings decided on them.

mod common;

use common::scratch;
use surfacelab::harness::study::cousineau_morey_half_widths;
use surfacelab::harness::study::{FINDINGS, FindingVerdict};
use surfacelab::harness::study::{REPORT_HTML, REPORT_MD};
use surfacelab::harness::study::{
    RunOptions, StudyDesign, TrialResult, TrialRow, TrialRunner, TrialSpec, run_study, summarize,
};
use surfacelab::harness::study::{TwoWayData, rm_anova};
use surfacelab::harness::study::{analyze, read_anova, write_anova, write_pairwise};
use surfacelab::harness::study::{holm, paired_t};
use surfacelab::pipeline::technique::TechniqueKind;

/// Maxwell & Delaney (2004), *Designing Experiments and Analyzing Data*, 2nd
/// ed., Table 12.1 (p. 574): reaction times (ms) of 10 subjects, noise
/// absent (angle 0°, 4°, 8°) then noise present (0°, 4°, 8°). The same data
/// ship as `md_12.1` in the R package afex, whose tests replicate the book.
const MD_12_1: [[f64; 6]; 10] = [
    [420.0, 420.0, 480.0, 480.0, 600.0, 780.0],
    [420.0, 480.0, 480.0, 360.0, 480.0, 600.0],
    [480.0, 480.0, 540.0, 660.0, 780.0, 780.0],
    [420.0, 540.0, 540.0, 480.0, 780.0, 900.0],
    [540.0, 660.0, 540.0, 480.0, 660.0, 720.0],
    [360.0, 420.0, 360.0, 360.0, 480.0, 540.0],
    [480.0, 480.0, 600.0, 540.0, 720.0, 840.0],
    [480.0, 600.0, 660.0, 540.0, 720.0, 900.0],
    [540.0, 600.0, 540.0, 480.0, 720.0, 780.0],
    [480.0, 420.0, 540.0, 540.0, 660.0, 780.0],
];

/// The table with angle as factor A (3 levels) and noise as B (2 levels),
/// A-major as `TwoWayData` wants.
fn md_angle_by_noise() -> Vec<Vec<f64>> {
    MD_12_1.iter().map(|r| vec![r[0], r[3], r[1], r[4], r[2], r[5]]).collect()
}

fn close(a: Option<f64>, b: f64, tol: f64) -> bool {
    a.is_some_and(|a| (a - b).abs() <= tol * b.abs().max(1e-300))
}

#[test]
fn anova_matches_maxwell_delaney_table_12_6() {
    let data = TwoWayData { levels_a: 3, levels_b: 2, subjects: md_angle_by_noise() };
    let r = rm_anova(&data).expect("anova");
    // Printed in Maxwell & Delaney (2004), Tables 12.5–12.6 (p. 578), as
    // replicated in afex's tests: SS, error SS, dfs and F.
    assert_eq!((r.a.df1, r.a.df2, r.b.df1, r.b.df2, r.ab.df1, r.ab.df2), (2, 18, 1, 9, 2, 18));
    for (e, ss, ss_err, f) in
        [(r.a, 289_920.0, 64_080.0, 40.72), (r.b, 285_660.0, 76_140.0, 33.77), (r.ab, 105_120.0, 20_880.0, 45.31)]
    {
        assert!((e.ss - ss).abs() < 1e-6, "{e:?}");
        assert!((e.ss_error - ss_err).abs() < 1e-6, "{e:?}");
        assert!((e.f.expect("F") - f).abs() < 0.005, "{e:?}");
    }
    // GG epsilon, p, corrected p and partial eta squared: pingouin 0.7.0
    // (`rm_anova(..., correction=True, effsize="np2")`, numpy 2.4.6, scipy
    // 1.17.1) on the same table, computed for this test.
    assert!(close(r.a.epsilon_gg, 0.961_636_518_15, 1e-9), "{:?}", r.a);
    assert!(close(r.ab.epsilon_gg, 0.903_977_069_151, 1e-9), "{:?}", r.ab);
    assert_eq!(r.b.epsilon_gg, Some(1.0), "a one-df effect is spherical");
    assert!(close(r.a.p, 2.086_763_200_5e-7, 1e-6));
    assert!(close(r.b.p, 2.559_736_583_62e-4, 1e-6));
    assert!(close(r.ab.p, 9.424_092_559_31e-8, 1e-6));
    assert!(close(r.a.p_gg, 3.401_704_844_17e-7, 1e-6));
    assert!(close(r.b.p_gg, 2.559_736_583_62e-4, 1e-6));
    assert!(close(r.ab.p_gg, 3.453_930_861_03e-7, 1e-6));
    assert!(close(r.a.eta_p2, 0.818_983_050_847, 1e-9));
    assert!(close(r.b.eta_p2, 0.789_552_238_806, 1e-9));
    assert!(close(r.ab.eta_p2, 0.834_285_714_286, 1e-9));
}

#[test]
fn anova_degenerate_inputs_give_no_statistics() {
    // One subject: no error term.
    let one = rm_anova(&TwoWayData { levels_a: 3, levels_b: 2, subjects: vec![vec![1.0; 6]] }).expect("anova");
    assert_eq!((one.a.f, one.a.df2), (None, 0));
    // One level of B: B and A×B have no contrasts; A is a one-way ANOVA.
    let rows: Vec<Vec<f64>> = MD_12_1.iter().map(|r| r[..3].to_vec()).collect();
    let oneway = rm_anova(&TwoWayData { levels_a: 3, levels_b: 1, subjects: rows }).expect("anova");
    assert_eq!((oneway.b.df1, oneway.b.f, oneway.ab.f), (0, None, None));
    assert_eq!((oneway.a.df1, oneway.a.df2), (2, 18));
    // No error variance (every subject the same shifted pattern): no F.
    let flat = vec![vec![1.0, 2.0, 3.0, 4.0], vec![2.0, 3.0, 4.0, 5.0], vec![0.0, 1.0, 2.0, 3.0]];
    let r = rm_anova(&TwoWayData { levels_a: 2, levels_b: 2, subjects: flat }).expect("anova");
    assert_eq!(r.a.f, None);
    assert!(rm_anova(&TwoWayData { levels_a: 2, levels_b: 2, subjects: vec![vec![1.0; 3]] }).is_err());
}

#[test]
fn paired_tests_and_holm_match_scipy_on_the_angle_means() {
    // Angle means over noise, per subject; scipy 1.17.1 `ttest_rel` and
    // pingouin `multicomp(method="holm")`, computed for this test (afex's
    // emmeans "multivariate" output prints the same t: −6.194, −8.159, −3.25).
    let m: Vec<[f64; 3]> = MD_12_1
        .iter()
        .map(|r| [f64::midpoint(r[0], r[3]), f64::midpoint(r[1], r[4]), f64::midpoint(r[2], r[5])])
        .collect();
    let col = |k: usize| m.iter().map(|r| r[k]).collect::<Vec<f64>>();
    let tests = [paired_t(&col(0), &col(1)), paired_t(&col(0), &col(2)), paired_t(&col(1), &col(2))]
        .map(|t| t.expect("paired test"));
    let expected = [
        (-108.0, -6.194_224_814_51, 1.599_714_280_69e-4, -1.958_785_875_3, 3.199_428_561_37e-4),
        (-168.0, -8.158_801_243_8, 1.891_159_484_08e-5, -2.580_039_490_7, 5.673_478_452_24e-5),
        (-60.0, -3.253_956_867_28, 9.934_285_491_86e-3, -1.028_991_510_86, 9.934_285_491_86e-3),
    ];
    let adjusted = holm(&tests.iter().map(|t| t.p).collect::<Vec<_>>());
    for ((t, (diff, tv, p, dz, p_holm)), adj) in tests.iter().zip(expected).zip(adjusted) {
        assert!((t.mean_diff - diff).abs() < 1e-9 && t.df == 9);
        assert!(close(t.t, tv, 1e-9) && close(t.p, p, 1e-6) && close(t.dz, dz, 1e-9), "{t:?}");
        assert!(close(adj, p_holm, 1e-6), "{adj:?} vs {p_holm}");
    }
}

#[test]
fn holm_by_hand() {
    // Sorted 0.01, 0.03, 0.04 -> x3, x2, x1 = 0.03, 0.06, 0.04 -> monotone 0.03, 0.06, 0.06.
    let adj = holm(&[Some(0.01), Some(0.04), Some(0.03)]);
    let want = [0.03, 0.06, 0.06];
    for (a, w) in adj.iter().zip(want) {
        assert!((a.expect("p") - w).abs() < 1e-12, "{adj:?}");
    }
    // Tests that could not run do not count: m = 2.
    assert_eq!(holm(&[Some(0.2), None, Some(0.01)]), vec![Some(0.2), None, Some(0.02)]);
    assert_eq!(holm(&[Some(0.6), Some(0.7)]), vec![Some(1.0), Some(1.0)]);
}

#[test]
fn cousineau_morey_by_hand() {
    // Subjects (1, 3), (2, 6), (3, 3); grand mean 3. Normalised: (2, 4),
    // (1, 5), (3, 3): SD 1 in both conditions. Half-width = t(.975, 2) · 1 ·
    // √(2/1) / √3 = 4.302653 · 0.816497 = 3.513101.
    let h = cousineau_morey_half_widths(&[vec![1.0, 3.0], vec![2.0, 6.0], vec![3.0, 3.0]]);
    assert_eq!(h.len(), 2);
    for w in h {
        assert!((w.expect("half width") - 3.513_101_24).abs() < 1e-6);
    }
    // Maxwell & Delaney's table, numpy/scipy computed for this test.
    let h = cousineau_morey_half_widths(&MD_12_1.iter().map(|r| r.to_vec()).collect::<Vec<_>>());
    let want = [38.576_247_13, 56.923_713_9, 26.497_190_61, 42.610_298_81, 37.934_156_56, 48.030_236_8];
    for (w, e) in h.iter().zip(want) {
        assert!(close(*w, e, 1e-8), "{w:?} vs {e}");
    }
    assert_eq!(cousineau_morey_half_widths(&[vec![1.0, 2.0]]), vec![None, None]);
}

// ------------------------------------------------------------ through the harness

/// Positioning only; Joint, Proxy, Particle = 0°, 4°, 8°; feedback on = noise absent.
fn md_design() -> StudyDesign {
    StudyDesign { participants: 10, tasks: vec!["positioning".into()], repetitions: 2, ..StudyDesign::default() }
}

/// Each measured repetition of participant p's cell is the book's value ± 30
/// ms (rep 1 −30, rep 2 +30), so the cell mean is the book's value; practice
/// is slower. Times in "seconds" are the book's milliseconds / 10.
struct MdRunner;

impl TrialRunner for MdRunner {
    fn run(&self, spec: &TrialSpec) -> anyhow::Result<TrialResult> {
        let angle = match spec.technique {
            TechniqueKind::JOINT => 0,
            TechniqueKind::PROXY => 1,
            _ => 2,
        };
        let noise = usize::from(!spec.feedback);
        let value = MD_12_1[spec.participant as usize - 1][noise * 3 + angle] / 10.0;
        let t = match spec.repetition {
            0 => value * 2.0,
            1 => value - 3.0,
            _ => value + 3.0,
        };
        Ok(TrialResult {
            completion_time_s: t,
            completed: true,
            restarts: 0,
            objects_placed: 8,
            steps: 0,
            ..TrialResult::default()
        })
    }
}

fn quiet() -> RunOptions {
    RunOptions { jobs: 2, progress: false, report_errors: false, shard: None, fsync: false }
}

#[test]
fn a_run_writes_the_anova_pairwise_and_report_files() {
    let dir = scratch("md_run");
    let design = md_design();
    run_study(&design, &dir, &MdRunner, &quiet()).expect("run");
    let anova = std::fs::read_to_string(dir.join("anova.csv")).expect("anova.csv");
    let mut lines = anova.lines();
    assert_eq!(lines.next(), Some("task,effect,df1,df2,F,p,epsilon_gg,p_gg,eta_p2"));
    let effects: Vec<&str> = lines.map(|l| l.split(',').nth(1).expect("effect")).collect();
    assert_eq!(effects, ["technique", "feedback", "technique:feedback"]);
    let rows = read_anova(&dir.join("anova.csv")).expect("read");
    for (row, f) in rows.iter().zip([40.72, 33.77, 45.31]) {
        assert_eq!(row.task, "positioning");
        assert!((row.f.expect("F") - f).abs() < 0.005, "{row:?}");
    }
    assert!(close(rows[0].epsilon_gg, 0.961_636_518_15, 1e-9));

    let pairwise = std::fs::read_to_string(dir.join("pairwise.csv")).expect("pairwise.csv");
    let mut lines = pairwise.lines();
    assert_eq!(lines.next(), Some("task,a,b,mean_diff_s,t,df,p_holm,dz"));
    let first: Vec<&str> = lines.next().expect("a row").split(',').collect();
    assert_eq!(&first[..3], ["positioning", "joint", "proxy"]);
    assert!((first[3].parse::<f64>().expect("diff") + 10.8).abs() < 1e-9, "{first:?}");
    assert_eq!(first[5], "9");
    assert_eq!(pairwise.lines().count(), 1 + 3);

    let summary = std::fs::read_to_string(dir.join("summary.csv")).expect("summary.csv");
    assert!(summary.starts_with(
        "task,technique,feedback,participants,trials,completed,failed,mean_s,sd_s,ci95_low_s,ci95_high_s,errors,ci95_within_low_s,ci95_within_high_s\n"
    ));

    let md = std::fs::read_to_string(dir.join(REPORT_MD)).expect("report.md");
    for needle in [
        "| P10 | off, on | Proxy, Particle, Joint |",
        "![",
        "technique:feedback",
        "Joint is fastest for positioning | reproduced",
        "Strategy shares: not recorded",
        "Proxy and Particle are faster than Joint for sorting | not tested",
    ] {
        assert!(md.contains(needle), "report.md lacks {needle:?}:\n{md}");
    }
    let html = std::fs::read_to_string(dir.join(REPORT_HTML)).expect("report.html");
    assert!(html.contains("<img alt=") && html.contains("src=\"data:image/png;base64,iVBORw0KGgo"));
    assert!(html.contains("<td>technique:feedback</td>"));
}

#[test]
fn findings_are_decided_by_their_tests() {
    let design = md_design();
    let rows: Vec<TrialRow> =
        design.trials().iter().map(|spec| TrialRow::new(spec, &MdRunner.run(spec).expect("trial"))).collect();
    let analysis = analyze(&design, &rows);
    let verdicts: Vec<(&str, FindingVerdict)> = FINDINGS.iter().map(|f| (f.id, f.judge(&analysis).verdict)).collect();
    // Joint (0°) beats 4° and 8° (Holm p .00032, .000057). Joint's feedback
    // effect (+3.0 s, scipy p = .244) is not significant. Particle's (8°)
    // feedback cost exceeds Joint's by 20.4 s (scipy t = 9.16, p = 7.4e-6).
    assert_eq!(verdicts[0], ("joint_fastest_positioning", FindingVerdict::Reproduced));
    assert_eq!(verdicts[1], ("feedback_little_for_joint", FindingVerdict::Reproduced));
    assert_eq!(verdicts[2], ("feedback_more_for_particle", FindingVerdict::Reproduced));
    assert!(
        matches!(verdicts[3].1, FindingVerdict::NotTested(_)) && matches!(verdicts[4].1, FindingVerdict::NotTested(_))
    );
    let little = FINDINGS[1].judge(&analysis);
    assert!(little.evidence.contains("+3.0 s") && little.evidence.contains("0.244"), "{}", little.evidence);

    // Swap Joint and Particle: Joint is now slowest, and its feedback effect large.
    let swapped: Vec<TrialRow> = rows
        .iter()
        .map(|r| {
            let technique = match r.technique {
                TechniqueKind::JOINT => TechniqueKind::PARTICLE,
                TechniqueKind::PARTICLE => TechniqueKind::JOINT,
                t => t,
            };
            TrialRow { technique, ..r.clone() }
        })
        .collect();
    let analysis = analyze(&design, &swapped);
    assert_eq!(FINDINGS[0].judge(&analysis).verdict, FindingVerdict::NotReproduced);
    assert_eq!(FINDINGS[1].judge(&analysis).verdict, FindingVerdict::NotReproduced);
    assert_eq!(FINDINGS[2].judge(&analysis).verdict, FindingVerdict::NotReproduced);
}

#[test]
fn failed_trials_count_at_the_limit_and_incomplete_participants_are_left_out() {
    let design = StudyDesign { participants: 3, tasks: vec!["sorting".into()], ..StudyDesign::default() };
    let spec = |p: u32, technique, feedback, rep| {
        design
            .trials()
            .into_iter()
            .find(|t| t.participant == p && t.technique == technique && t.feedback == feedback && t.repetition == rep)
            .expect("trial")
    };
    let mut rows = Vec::new();
    for p in 1..=3u32 {
        for technique in [TechniqueKind::JOINT, TechniqueKind::PROXY, TechniqueKind::PARTICLE] {
            for feedback in [true, false] {
                for rep in 1..=2 {
                    let s = spec(p, technique, feedback, rep);
                    let time = 10.0 * f64::from(p) + f64::from(rep);
                    // P2's Proxy/on rep 2 hits a 50 s limit; P3's Joint/off has no time at all.
                    let row = if p == 2 && technique == TechniqueKind::PROXY && feedback && rep == 2 {
                        TrialRow::new(
                            &s,
                            &TrialResult {
                                completion_time_s: 50.0,
                                completed: false,
                                restarts: 0,
                                objects_placed: 1,
                                steps: 3000,
                                ..TrialResult::default()
                            },
                        )
                    } else if p == 3 && technique == TechniqueKind::JOINT && !feedback {
                        TrialRow::failed(&s)
                    } else {
                        TrialRow::new(
                            &s,
                            &TrialResult {
                                completion_time_s: time,
                                completed: true,
                                restarts: 0,
                                objects_placed: 8,
                                steps: 0,
                                ..TrialResult::default()
                            },
                        )
                    };
                    rows.push(row);
                }
            }
        }
    }
    let analysis = analyze(&design, &rows);
    let cells = &analysis.cells[0];
    assert_eq!(cells.participants, vec![1, 2]);
    assert_eq!(cells.incomplete, vec![3]);
    // P2's Proxy/on cell: (21 + 50) / 2, the timed-out trial at its limit.
    assert!((cells.values[1][cells.cell(1, 0)] - 35.5).abs() < 1e-12);
    let summary = summarize(&design, &rows);
    let proxy_on = summary.iter().find(|s| s.technique == TechniqueKind::PROXY && s.feedback).expect("row");
    assert_eq!((proxy_on.completed, proxy_on.failed, proxy_on.errors), (5, 1, 0));
    let joint_off = summary.iter().find(|s| s.technique == TechniqueKind::JOINT && !s.feedback).expect("row");
    assert_eq!((joint_off.completed, joint_off.failed, joint_off.errors), (4, 2, 2));

    let dir = scratch("files");
    std::fs::create_dir_all(&dir).expect("dir");
    write_anova(&dir.join("anova.csv"), &analysis.anova).expect("anova");
    write_pairwise(&dir.join("pairwise.csv"), &analysis.pairwise).expect("pairwise");
    assert_eq!(read_anova(&dir.join("anova.csv")).expect("read"), analysis.anova);
}

#[test]
fn the_report_reads_strategy_shares_when_trials_csv_has_them() {
    use surfacelab::harness::study::{Block, report_blocks, strategy_counts};
    let dir = scratch("strategies");
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("trials.csv");
    // Only the columns the report reads, plus the new one; practice rows are left out.
    std::fs::write(
        &path,
        "participant,technique,practice,strategy\n\
         1,joint,false,fingertip_drag\n1,joint,false,fingertip_drag\n1,joint,false,pinch\n\
         1,joint,true,forearm_sweep\n1,proxy,false,two_handed_gather\n",
    )
    .expect("write");
    let counts = strategy_counts(&path).expect("read").expect("a strategy column");
    assert_eq!(counts["joint"]["fingertip_drag"], 2);
    assert_eq!(counts["joint"]["pinch"], 1);
    assert!(!counts["joint"].contains_key("forearm_sweep"));
    let design = md_design();
    let blocks = report_blocks(&design, &[], &analyze(&design, &[]), Some(&counts), &[]);
    let table = blocks
        .iter()
        .find_map(|b| match b {
            Block::Table { head, rows } if head[1] == "strategy" => Some(rows.clone()),
            _ => None,
        })
        .expect("a strategy table");
    assert_eq!(table[0], ["Joint", "fingertip_drag", "2", "67%"]);
    assert_eq!(table[2], ["Proxy", "two_handed_gather", "1", "100%"]);
    // Without the column: none.
    std::fs::write(&path, "participant,technique,practice\n1,joint,false\n").expect("write");
    assert_eq!(strategy_counts(&path).expect("read"), None);
    // With the column empty in every measured row (replayed trials): none either.
    std::fs::write(&path, "participant,technique,practice,strategy\n1,joint,false,\n1,joint,true,pinch\n")
        .expect("write");
    assert_eq!(strategy_counts(&path).expect("read"), None);
}

#[test]
fn an_untested_finding_names_the_technique_the_design_lacks() {
    // Joint and Particle on sorting: the sorting finding needs Proxy too.
    let design = StudyDesign {
        tasks: vec!["sorting".into()],
        techniques: vec![TechniqueKind::JOINT, TechniqueKind::PARTICLE],
        ..md_design()
    };
    let rows: Vec<TrialRow> =
        design.trials().iter().map(|spec| TrialRow::new(spec, &MdRunner.run(spec).expect("trial"))).collect();
    let sorting = FINDINGS.iter().find(|f| f.task == "sorting").expect("a sorting finding");
    let judged = sorting.judge(&analyze(&design, &rows));
    assert_eq!(judged.verdict, FindingVerdict::NotTested("the design lacks proxy".into()));
}
