//! The `surfacelab` binary: parse, run, map errors to an exit code.

fn main() -> std::process::ExitCode {
    surfacelab::cli::main()
}
