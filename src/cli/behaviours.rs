//! `surfacelab behaviours`: the behaviour suite's table (src/harness/behaviour).

use super::{BehavioursArgs, EXIT_USAGE};
use crate::harness::behaviour::{CellVerdict, cases, cells, markdown, run_suite, suite_kinds};
use std::process::ExitCode;
use std::time::Instant;

pub fn run(args: &BehavioursArgs) -> super::CommandResult {
    let kinds = args.techniques.clone().unwrap_or_else(suite_kinds);
    let all = cases();
    let chosen: Vec<_> = all.into_iter().filter(|c| args.case.as_deref().is_none_or(|f| c.name.contains(f))).collect();
    if chosen.is_empty() {
        eprintln!("surfacelab behaviours: --case: no case name contains `{}`", args.case.as_deref().unwrap_or(""));
        return Ok(ExitCode::from(EXIT_USAGE));
    }
    let jobs = if args.jobs == 0 { std::thread::available_parallelism().map_or(1, usize::from) } else { args.jobs };
    let t0 = Instant::now();
    let outcomes = run_suite(&chosen, &kinds, std::path::Path::new("."), jobs)?;
    out!("{}", markdown(&chosen, &kinds, &outcomes))?;
    let all_cells: Vec<_> = chosen
        .iter()
        .flat_map(|c| outcomes.iter().filter(move |o| o.case == c.name).flat_map(move |o| cells(c, o)))
        .collect();
    let failures = all_cells.iter().filter(|cell| cell.verdict.is_failure()).count();
    let gaps = all_cells.iter().filter(|cell| cell.verdict == CellVerdict::KnownGap).count();
    eprintln!(
        "surfacelab behaviours: {} cases x {} techniques in {:.1} s; {failures} cells miss their expectation, \
         {gaps} more are known gaps (src/harness/behaviour/gaps.rs)",
        chosen.len(),
        kinds.len(),
        t0.elapsed().as_secs_f64(),
    );
    if args.check && failures > 0 { Ok(ExitCode::FAILURE) } else { Ok(ExitCode::SUCCESS) }
}
