//! The `medax` command-line tool. Run without arguments for the demo.

mod cli;

fn main() -> std::process::ExitCode {
    cli::run()
}
