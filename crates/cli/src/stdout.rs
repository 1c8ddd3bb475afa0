//! Standard output for every report the CLI prints (`--json`, tables, a
//! model): each line goes through the locked stdout handle, and a reader that
//! has gone away (`gaitlab run human --json | head -c1`, a closed pipe) ends
//! the command quietly with exit status 0 — what it had to say was cut off on
//! purpose by the reader — instead of the panic of `println!`. Any other
//! error writing stdout exits with status 1 and `error: stdout: <reason>`.

use std::fmt;
use std::io::{ErrorKind, Write};

/// Writes `text` to standard output and flushes it; see the module's rules
/// for a closed pipe.
pub fn write(text: fmt::Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    if let Err(error) = out.write_fmt(text).and_then(|()| out.flush()) {
        if error.kind() == ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: stdout: {error}");
        std::process::exit(1);
    }
}

/// `print!` through [`write()`].
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::stdout::write(format_args!($($arg)*))
    };
}

/// `println!` through [`write()`].
macro_rules! outln {
    () => {
        $crate::stdout::write(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::stdout::write(format_args!("{}\n", format_args!($($arg)*)))
    };
}

pub(crate) use {out, outln};
