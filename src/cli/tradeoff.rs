//! `surfacelab tradeoff --out DIR [--quick]`: what accuracy costs in time.

use super::TradeoffArgs;
use crate::harness::tradeoff::{TradeoffOptions, run_tradeoff};
use std::io::IsTerminal;
use std::process::ExitCode;

pub fn run(args: &TradeoffArgs) -> super::CommandResult {
    let t0 = std::time::Instant::now();
    let rows = run_tradeoff(&TradeoffOptions {
        out: args.out.clone(),
        quick: args.quick,
        progress: std::io::stderr().is_terminal(),
    })?;
    let off: Vec<String> =
        rows.iter().filter(|r| r.default && !r.on_front).map(|r| format!("{}={}", r.knob, r.value)).collect();
    outln!(
        "surfacelab tradeoff: {} settings in {:.0} s; defaults off their Pareto front: {}; files in {} (tradeoff.csv, tradeoff.md, one PNG per knob)",
        rows.len(),
        t0.elapsed().as_secs_f64(),
        if off.is_empty() { "none".to_string() } else { off.join(", ") },
        args.out.display()
    )?;
    Ok(ExitCode::SUCCESS)
}
