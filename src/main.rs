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
            let argv: Vec<String> = std::env::args().collect();
            match cli::case_twin_error(&e, &argv) {
                Some(message) => eprintln!("{message}"),
                None => {
                    let _ = e.print();
                }
            }
            std::process::exit(code);
        }
    };
    // Render threads get the main thread's stack (deeply nested scenes recurse
    // there too); the global pool is built once, here.
    let _ = rayon::ThreadPoolBuilder::new()
        .stack_size(cli::STACK_SIZE)
        .build_global();
    let worker = std::thread::Builder::new()
        .name("rts".into())
        .stack_size(cli::STACK_SIZE)
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
