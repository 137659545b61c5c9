//! `surfacelab contact [FILE|-]`: one 2D contact query as JSON.

use super::{ContactArgs, EXIT_USAGE};
use crate::contact;
use std::io::Read;
use std::process::ExitCode;

pub fn run(args: &ContactArgs) -> super::CommandResult {
    let input = if args.input == "-" {
        let cap = crate::scene::bounds::MAX_INPUT_BYTES;
        let mut s = String::new();
        if let Err(e) = std::io::stdin().take(cap + 1).read_to_string(&mut s) {
            eprintln!("surfacelab contact: cannot read standard input: {e}");
            return Ok(ExitCode::from(EXIT_USAGE));
        }
        if s.len() as u64 > cap {
            eprintln!("surfacelab contact: standard input is larger than the {} MiB an input may have", cap >> 20);
            return Ok(ExitCode::from(EXIT_USAGE));
        }
        s
    } else {
        match crate::files::read_capped_str(&args.input) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("surfacelab contact: cannot read {}: {e}", args.input);
                return Ok(ExitCode::from(EXIT_USAGE));
            }
        }
    };
    match contact::answer_json(&input, args.concave) {
        Ok(line) => {
            outln!("{line}")?;
            Ok(ExitCode::SUCCESS)
        }
        Err(e) => {
            eprintln!("surfacelab contact: {e}");
            Ok(ExitCode::from(EXIT_USAGE))
        }
    }
}
