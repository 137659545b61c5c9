//! `surfacelab participants fitts`: the simulated participants' drags
//! against Fitts' law (src/harness/fitts).

use super::{FittsArgs, ParticipantsAction, ParticipantsArgs};
use crate::harness::fitts::{self, FittsDesign};
use std::process::ExitCode;

pub fn run(args: &ParticipantsArgs) -> super::CommandResult {
    match &args.action {
        ParticipantsAction::Fitts(a) => run_fitts(a),
    }
}

fn run_fitts(args: &FittsArgs) -> super::CommandResult {
    let defaults = FittsDesign::default();
    let design = FittsDesign {
        technique: args.technique,
        distances_m: args.distances.clone().unwrap_or(defaults.distances_m),
        widths_m: args.widths.clone().unwrap_or(defaults.widths_m),
        participants: args.participants,
        repetitions: args.reps,
        seed: args.seed,
    };
    let jobs = if args.jobs == 0 { std::thread::available_parallelism().map_or(1, usize::from) } else { args.jobs };
    let t0 = std::time::Instant::now();
    let rows = fitts::run(&design, jobs)?;
    let Some(fit) = fitts::fit(&rows) else {
        eprintln!(
            "surfacelab participants fitts: too few completed trials to fit ({} of {}): give two or more distances or widths and --reps 2 or more",
            rows.iter().filter(|r| r.completed).count(),
            rows.len()
        );
        return Ok(ExitCode::FAILURE);
    };
    fitts::write(&args.out, &rows, &fit)?;
    outln!(
        "surfacelab participants fitts: {} drags under {} ({} completed) in {:.1} s",
        fit.trials,
        args.technique.label(),
        fit.completed,
        t0.elapsed().as_secs_f64()
    )?;
    outln!(
        "  MT = {:.3} + {:.3} ID s (R² = {:.3} over {} conditions); throughput {:.2} bits/s (ISO 9241-9, effective width)",
        fit.a_s,
        fit.b_s_per_bit,
        fit.r2,
        fit.conditions,
        fit.throughput_bits_s
    )?;
    outln!("  files in {}: fitts.csv, fitts.json, fitts.png", args.out.display())?;
    Ok(ExitCode::SUCCESS)
}
