//! The `rts` binary: parses the command line and runs it on a thread with a large
//! stack (deeply nested scenes recurse), mapping results to exit codes.

mod cli;

use clap::Parser;

fn main() {
    let parsed = cli::Cli::try_parse();
    let cli = match parsed {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() {
                cli::EXIT_USAGE
            } else {
                cli::EXIT_OK
            };
            let _ = e.print();
            std::process::exit(code);
        }
    };
    let worker = std::thread::Builder::new()
        .name("rts".into())
        .stack_size(512 << 20)
        .spawn(move || cli::run(cli));
    let code = match worker.map(std::thread::JoinHandle::join) {
        Ok(Ok(code)) => code,
        _ => {
            eprintln!(
                "error: rts stopped unexpectedly; please report this with the scene that caused it"
            );
            cli::EXIT_ERRORS
        }
    };
    std::process::exit(code);
}
