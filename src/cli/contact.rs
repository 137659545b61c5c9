//! `surfacelab contact [FILE|-]`: one 2D contact query as JSON.

use super::{ContactArgs, EXIT_USAGE};
use crate::contact;
use std::io::Read;
use std::process::ExitCode;

pub fn run(args: &ContactArgs) -> ExitCode {
    let input = if args.input == "-" {
        let mut s = String::new();
        if let Err(e) = std::io::stdin().read_to_string(&mut s) {
            eprintln!("surfacelab contact: cannot read standard input: {e}");
            return ExitCode::from(EXIT_USAGE);
        }
        s
    } else {
        match std::fs::read_to_string(&args.input) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("surfacelab contact: cannot read {}: {e}", args.input);
                return ExitCode::from(EXIT_USAGE);
            }
        }
    };
    match contact::answer_json(&input, args.concave) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("surfacelab contact: {e}");
            ExitCode::from(EXIT_USAGE)
        }
    }
}
