//! Printing that survives a closed pipe or a full disk: `println!` panics when standard output
//! cannot be written ("failed printing to stdout"); these macros end the process with a clear
//! message and exit code 74 (`EX_IOERR`) instead. Messages to standard error are best effort.

use std::fmt::Arguments;
use std::io::Write;

/// The exit code when standard output cannot be written (`EX_IOERR` of sysexits.h).
pub const EXIT_OUTPUT_ERROR: i32 = 74;

/// Writes one line to standard output, or ends the process when it cannot be written.
pub fn line(args: Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    let written = out.write_fmt(args).and_then(|()| out.write_all(b"\n")).and_then(|()| out.flush());
    if let Err(e) = written {
        let _ = writeln!(std::io::stderr(), "cannot write to standard output: {e}");
        std::process::exit(EXIT_OUTPUT_ERROR);
    }
}

/// Writes one line to standard error, ignoring failure (there is nowhere left to report it).
pub fn note(args: Arguments<'_>) {
    let _ = writeln!(std::io::stderr(), "{args}");
}

/// `println!` that exits with a message instead of panicking when standard output is closed
/// or full.
macro_rules! outln {
    () => { $crate::output::line(format_args!("")) };
    ($($arg:tt)*) => { $crate::output::line(format_args!($($arg)*)) };
}

/// `eprintln!` that ignores a closed standard error instead of panicking.
macro_rules! errln {
    () => { $crate::output::note(format_args!("")) };
    ($($arg:tt)*) => { $crate::output::note(format_args!($($arg)*)) };
}

/// Prints `{"status": "error", "error": message}` on standard output and gives exit code 2:
/// the contract of every subcommand for input it cannot use.
pub fn error_report(message: impl std::fmt::Display) -> std::process::ExitCode {
    let report = trailmark::solve::ErrorReport::new(message);
    line(format_args!("{}", serde_json::to_string(&report).unwrap_or_default()));
    std::process::ExitCode::from(2)
}
