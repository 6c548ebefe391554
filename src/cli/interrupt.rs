//! Ctrl-C and `kill`: a run stopped while it writes an image, a checkpoint or a
//! manifest removes the temporary file first ([`rts::files`] lists them), then
//! exits with 128 + the signal's number (130 for SIGINT, 143 for SIGTERM, 129
//! for SIGHUP), as a shell reports a process the signal killed. Files already
//! complete (frames, the last checkpoint) stay.

/// Starts the thread that waits for SIGINT, SIGTERM and SIGHUP.
#[cfg(unix)]
pub fn install() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        // Without the handler the signal ends the process as it always did; a
        // temporary file may then be left (named `.NAME.XXXXXX.tmp`).
        return;
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            rts::files::remove_temporaries_and_exit(128 + signal);
        }
    });
}

/// Elsewhere signals end the process as they always did.
#[cfg(not(unix))]
pub fn install() {}
