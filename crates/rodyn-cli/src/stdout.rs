//! Standard output that its reader may close early.
//!
//! Rust ignores `SIGPIPE`, so a write to a pipe whose reader has gone
//! (`rodyn-sim … | head -1`) fails with `BrokenPipe`, and `println!`
//! panics on it. A reader that stopped early is no error — it has what it
//! wanted —, so [`emit`] drops the text, and the tool finishes its work
//! (the files it writes) and exits with its own status.

use std::fmt;
use std::io::{ErrorKind, Write};

/// Writes `text` to standard output; a closed pipe is ignored.
///
/// # Errors
/// Any other failure to write (a full disk behind a redirection), with
/// the system's reason.
pub fn emit(text: fmt::Arguments<'_>) -> Result<(), String> {
    match std::io::stdout().lock().write_fmt(text) {
        Err(e) if e.kind() != ErrorKind::BrokenPipe => {
            Err(format!("cannot write to standard output: {e}"))
        }
        _ => Ok(()),
    }
}

/// [`emit`] for the print macros: a failure other than a closed pipe ends
/// the program with its message and status 1, as a refused argument does.
#[doc(hidden)]
pub fn emit_or_exit(text: fmt::Arguments<'_>) {
    if let Err(message) = emit(text) {
        eprintln!("error: {message}");
        std::process::exit(1);
    }
}

/// `print!` for the tools: a reader that closed the pipe early is no
/// panic (see [`emit`]).
#[macro_export]
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::stdout::emit_or_exit(::std::format_args!($($arg)*))
    };
}

/// `println!` for the tools: a reader that closed the pipe early is no
/// panic (see [`emit`]).
#[macro_export]
macro_rules! outln {
    () => {
        $crate::stdout::emit_or_exit(::std::format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::stdout::emit_or_exit(::std::format_args!("{}\n", ::std::format_args!($($arg)*)))
    };
}
