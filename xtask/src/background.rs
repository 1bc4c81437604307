//! Steps that `cargo xtask test` runs beside the others.
//!
//! Much of the test command keeps one core of two busy: QEMU, the test
//! binaries' single-threaded stretches, the browser, Miri's interpreter.
//! A step whose result no other step reads (Miri, clippy, rustdoc) can run
//! in that time. Its output goes to a log under the target folder, printed
//! when [`Background::finish`] collects it; a step that fails before then
//! stops it ([`Drop`]).

use anyhow::{bail, Context, Result};
use std::fs::File;
use std::os::unix::process::CommandExt;
use std::path::PathBuf;
use std::process::{Child, Command};
use std::time::Instant;

use crate::shell;

/// One command running in the background, in a process group of its own
/// so that stopping it stops the cargo and compiler processes it started.
pub struct Background {
    name: &'static str,
    child: Child,
    log: PathBuf,
    started: Instant,
}

impl Background {
    /// Starts `command`, its output into `target/<log>`.
    pub fn start(name: &'static str, mut command: Command, log: &str) -> Result<Self> {
        let log = shell::target_dir().join(log);
        std::fs::create_dir_all(shell::target_dir())?;
        let file = File::create(&log).with_context(|| format!("cannot write {}", log.display()))?;
        command
            .stdout(file.try_clone()?)
            .stderr(file)
            .process_group(0);
        println!(
            "{name}: started in the background: {} > {}",
            shell::describe(&command),
            log.display()
        );
        let child = command
            .spawn()
            .with_context(|| format!("cannot start {}", shell::describe(&command)))?;
        Ok(Background {
            name,
            child,
            log,
            started: Instant::now(),
        })
    }

    /// Waits for the command, prints its log, and fails when it failed.
    pub fn finish(mut self) -> Result<()> {
        let status = self
            .child
            .wait()
            .with_context(|| format!("waiting for {}", self.name))?;
        let log = std::fs::read_to_string(&self.log).unwrap_or_default();
        println!("{log}");
        println!(
            "{}: finished after {:.0} s in the background (log: {})",
            self.name,
            self.started.elapsed().as_secs_f64(),
            self.log.display()
        );
        if !status.success() {
            bail!("{} failed with {status} (its log above)", self.name);
        }
        Ok(())
    }
}

impl Drop for Background {
    /// A step that failed before this one was collected stops it and the
    /// processes it started.
    fn drop(&mut self) {
        if matches!(self.child.try_wait(), Ok(None)) {
            let group = format!("-{}", self.child.id());
            let _ = Command::new("kill").args(["-TERM", "--", &group]).status();
            let _ = self.child.wait();
        }
    }
}
