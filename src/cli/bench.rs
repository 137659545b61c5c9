//! `surfacelab bench --out DIR [--quick] [--participants N,N,..]`: how cost
//! grows with the work.

use super::BenchArgs;
use crate::harness::scaling::{BenchOptions, run_bench};
use std::process::ExitCode;

pub fn run(args: &BenchArgs) -> super::CommandResult {
    let (_, summaries) = run_bench(&BenchOptions {
        out: args.out.clone(),
        quick: args.quick,
        participants: args.participants.0.clone(),
        progress: true,
        point: args.point,
    })?;
    outln!("| curve | log-log slope | at the largest x | dominant stage there |")?;
    outln!("|---|---|---|---|")?;
    for c in &summaries {
        let slope = c.slope.map_or_else(|| "-".to_string(), |b| format!("{b:.2}"));
        let dominant = c.dominant.map_or_else(String::new, |(stage, share)| format!("{stage} ({:.0}%)", 100.0 * share));
        outln!("| {} | {slope} | {} | {dominant} |", c.curve.name(), c.largest_x)?;
    }
    outln!("surfacelab bench: files in {} (scaling.csv, scaling.md, scaling.png)", args.out.display())?;
    Ok(ExitCode::SUCCESS)
}
