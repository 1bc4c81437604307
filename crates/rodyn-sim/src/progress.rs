//! Progress of a long run on stderr: a bar on a terminal, and otherwise
//! (a log, a pipe) one line every few seconds once the run has lasted
//! that long, so a short run prints nothing and a long one is never silent.

use indicatif::{ProgressBar, ProgressStyle};
use std::cell::Cell;
use std::time::{Duration, Instant};

/// How long a run goes before its first plain progress line, and the
/// interval between lines.
const LINE_INTERVAL: Duration = Duration::from_secs(5);

/// The progress of one run of `total` steps.
pub struct Progress {
    bar: ProgressBar,
    name: &'static str,
    total: u64,
    last_line: Cell<Instant>,
}

impl Progress {
    /// A run called `name` of `total` steps, starting now.
    pub fn new(name: &'static str, total: u64) -> Self {
        let bar = ProgressBar::new(total);
        // The template is a constant; should it ever fail to parse, the
        // default style is still a progress bar.
        if let Ok(style) =
            ProgressStyle::with_template("{spinner} {msg} [{bar:40}] {pos}/{len} steps ({eta})")
        {
            bar.set_style(style);
        }
        bar.set_message(name);
        Self {
            bar,
            name,
            total,
            last_line: Cell::new(Instant::now()),
        }
    }

    /// Reports that `done` steps are taken.
    pub fn at(&self, done: u64) {
        self.bar.set_position(done);
        // Hidden: stderr is not a terminal.
        if self.bar.is_hidden() && self.last_line.get().elapsed() >= LINE_INTERVAL {
            self.last_line.set(Instant::now());
            eprintln!(
                "{}: {done}/{} steps ({:.0} %)",
                self.name,
                self.total,
                100.0 * done as f64 / self.total.max(1) as f64
            );
        }
    }

    /// Removes the bar.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}
