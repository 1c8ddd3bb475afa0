//! A `std::fmt::Write` over a buffered file, for the core's I/O-free writers
//! (BVH, CSV). The first I/O error is kept and reported at the end.

use std::fmt;
use std::io::{BufWriter, Write};

use crate::fail::Failure;

/// Buffered file that accepts formatted text.
pub struct FileSink {
    path: String,
    out: BufWriter<std::fs::File>,
    error: Option<std::io::Error>,
}

impl FileSink {
    /// Creates (truncates) `path`.
    pub fn create(path: &str) -> Result<Self, Failure> {
        let file = std::fs::File::create(path).map_err(|e| Failure::io(path, e))?;
        Ok(Self {
            path: path.to_owned(),
            out: BufWriter::new(file),
            error: None,
        })
    }

    /// Flushes, returning the first error met while writing.
    pub fn finish(mut self) -> Result<(), Failure> {
        if let Some(error) = self.error.take() {
            return Err(Failure::io(&self.path, error));
        }
        self.out.flush().map_err(|e| Failure::io(&self.path, e))
    }

    /// Turns a writer error into a failure, preferring the underlying I/O error.
    pub fn fail(&mut self, error: impl fmt::Display) -> Failure {
        match self.error.take() {
            Some(io) => Failure::io(&self.path, io),
            None => Failure::io(&self.path, error),
        }
    }
}

impl fmt::Write for FileSink {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        if self.error.is_some() {
            return Err(fmt::Error);
        }
        self.out.write_all(s.as_bytes()).map_err(|e| {
            self.error = Some(e);
            fmt::Error
        })
    }
}
