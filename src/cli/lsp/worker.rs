//! The analysis thread of `rts lsp`. Documents are analysed one at a time on a
//! thread of their own (with the stack evaluation needs), so the protocol loop
//! keeps reading messages while a scene evaluates; a newer edit cancels the
//! analysis of the text it replaces, and an analysis that runs past its time
//! stops with a diagnostic.

use rts::eval::EvalOptions;
use rts::ide::{self, Analysis};
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::atomic::Ordering;
use std::sync::mpsc;
use std::time::{Duration, Instant};
use tokio::sync::oneshot;

/// The longest one analysis may evaluate before it stops (`rts check` has no
/// such limit: this one keeps the editor answering).
pub const ANALYSIS_TIME: Duration = Duration::from_secs(3);

/// One document to analyse.
pub struct Job {
    /// Its path.
    pub path: PathBuf,
    /// Its text.
    pub text: String,
    /// Texts of the documents open in the editor, by canonical path.
    pub overlays: HashMap<PathBuf, String>,
    /// Evaluation options, with the cancellation flag of this job.
    pub options: EvalOptions,
    /// Where the analysis goes (`None`: cancelled, or it failed).
    pub reply: oneshot::Sender<Option<Analysis>>,
}

/// The analysis thread.
pub struct Worker {
    jobs: mpsc::Sender<Job>,
}

impl Worker {
    /// Starts the thread.
    pub fn start() -> std::io::Result<Worker> {
        let (jobs, inbox) = mpsc::channel::<Job>();
        std::thread::Builder::new()
            .name("rts-analysis".into())
            .stack_size(crate::cli::STACK_SIZE)
            .spawn(move || {
                for mut job in inbox {
                    let cancelled = |o: &EvalOptions| {
                        o.interrupt
                            .cancel
                            .as_ref()
                            .is_some_and(|c| c.load(Ordering::Relaxed))
                    };
                    if cancelled(&job.options) {
                        let _ = job.reply.send(None);
                        continue;
                    }
                    job.options.interrupt.deadline = Some(Instant::now() + ANALYSIS_TIME);
                    let analysis = super::guarded(|| {
                        ide::analyze(&job.path, &job.text, &job.overlays, &job.options)
                    });
                    let analysis = analysis.filter(|_| !cancelled(&job.options));
                    let _ = job.reply.send(analysis);
                }
            })?;
        Ok(Worker { jobs })
    }

    /// Queues `job`; false when the thread is gone.
    pub fn submit(&self, job: Job) -> bool {
        self.jobs.send(job).is_ok()
    }
}
