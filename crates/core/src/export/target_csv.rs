//! The effector-target CSV that `gaitlab track` follows (DESIGN.md, "Contracts"):
//! a header row `t` then `x,y,z` per effector in the skeleton's effector order,
//! then one row per sample time. Reader and writer.
//!
//! The format is described on [`parse_target_csv`].

use std::fmt::Write;

use glam::DVec3;

use super::WriteError;
use super::csv_error::CsvError;
use super::target_track::{MAX_TARGET_ROWS, TargetTrack};
use super::text::{CsvFields, write_round_trip, write_suffixed_field};

/// Largest target CSV text accepted, bytes (64 MiB).
pub const MAX_TARGET_CSV_BYTES: usize = 64 * 1024 * 1024;

/// Reads a target CSV for a skeleton with `effector_count` effectors.
///
/// ```text
/// t,left_foot_x,left_foot_y,left_foot_z,right_foot_x,right_foot_y,right_foot_z
/// 0,0.1,0,0.2,-0.1,0,0
/// 0.5,0.1,0.05,0.45,-0.1,0,0.1
/// ```
///
/// The reader is strict on counts and numbers and lenient on names: the header
/// must have exactly `1 + 3k` columns for a skeleton with `k` effectors, but any
/// names will do. Times in seconds must be finite and strictly increasing;
/// positions are metres in the world frame. Blank lines are skipped, fields may be
/// quoted (RFC 4180) and padded with spaces, `\r\n` line ends and a UTF-8
/// byte-order mark are accepted. Limits: [`MAX_TARGET_CSV_BYTES`] of text and
/// [`MAX_TARGET_ROWS`] data rows. The reader never panics; errors name the line
/// and column (`line 7, column 4: not a number "abc"`).
///
/// # Errors
/// A [`CsvError`] for the first problem: input over [`MAX_TARGET_CSV_BYTES`],
/// no header, a header that is all numbers or has a column count other than
/// `1 + 3 · effector_count`, a row with the wrong column count, an empty field, a
/// field that is not a finite number, a time not after the previous row's, no data
/// rows, or more than [`MAX_TARGET_ROWS`] rows.
pub fn parse_target_csv(text: &str, effector_count: usize) -> Result<TargetTrack, CsvError> {
    if text.len() > MAX_TARGET_CSV_BYTES {
        return Err(CsvError::detached(format!(
            "the input is {} bytes, more than the limit of {MAX_TARGET_CSV_BYTES} (64 MiB)",
            text.len()
        )));
    }
    let Some(columns) = effector_count.checked_mul(3).and_then(|c| c.checked_add(1)) else {
        return Err(CsvError::detached(format!(
            "{effector_count} effectors is too many"
        )));
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, line)| (i + 1, line))
        .filter(|(_, line)| !line.trim().is_empty());

    let Some((header_line, header)) = lines.next() else {
        return Err(CsvError::detached(
            "empty input: expected a header row (t, then x,y,z for each effector)",
        ));
    };
    let header_columns = count_fields(header_line, header)?;
    let all_numbers =
        CsvFields::new(header).all(|field| field.is_ok_and(|f| f.parse::<f64>().is_ok()));
    if all_numbers {
        return Err(CsvError::on_line(
            header_line,
            "the first row must be a header (t, then x,y,z for each effector), not numbers",
        ));
    }
    if header_columns != columns {
        return Err(CsvError::on_line(
            header_line,
            format!(
                "the header has {header_columns} columns; expected {columns} (t, then x,y,z for each of {effector_count} effectors)"
            ),
        ));
    }

    let mut times: Vec<f64> = Vec::new();
    let mut positions: Vec<DVec3> = Vec::new();
    for (line, row) in lines {
        if times.len() >= MAX_TARGET_ROWS {
            return Err(CsvError::on_line(
                line,
                format!("more than {MAX_TARGET_ROWS} data rows"),
            ));
        }
        let found = count_fields(line, row)?;
        if found != columns {
            return Err(CsvError::on_line(
                line,
                format!("expected {columns} columns, found {found}"),
            ));
        }
        let mut xyz = [0.0; 3];
        for (index, field) in CsvFields::new(row).enumerate() {
            let column = index + 1;
            let field = field.map_err(|reason| CsvError::at(line, column, reason))?;
            let value = parse_value(line, column, field)?;
            if index == 0 {
                if let Some(&previous) = times.last()
                    && value <= previous
                {
                    return Err(CsvError::at(
                        line,
                        column,
                        format!(
                            "time {value} is not after the previous time {previous} (times must increase strictly)"
                        ),
                    ));
                }
                times.push(value);
            } else {
                let axis = (index - 1) % 3;
                xyz[axis] = value;
                if axis == 2 {
                    positions.push(DVec3::from_array(xyz));
                }
            }
        }
    }
    if times.is_empty() {
        return Err(CsvError::on_line(
            header_line,
            "no data rows after the header",
        ));
    }
    TargetTrack::new(times, positions, effector_count)
}

/// Number of fields on a line, or the position of a malformed quoted field.
fn count_fields(line: usize, text: &str) -> Result<usize, CsvError> {
    let mut count = 0;
    for field in CsvFields::new(text) {
        count += 1;
        field.map_err(|reason| CsvError::at(line, count, reason))?;
    }
    Ok(count)
}

fn parse_value(line: usize, column: usize, field: &str) -> Result<f64, CsvError> {
    if field.is_empty() {
        return Err(CsvError::at(line, column, "empty value"));
    }
    match field.parse::<f64>() {
        Ok(value) if value.is_finite() => Ok(value),
        Ok(_) => Err(CsvError::at(
            line,
            column,
            format!("not a finite number {field:?}"),
        )),
        Err(_) => Err(CsvError::at(
            line,
            column,
            format!("not a number {field:?}"),
        )),
    }
}

/// Streaming target CSV writer. It refuses anything its reader would refuse
/// (wrong counts, non-finite numbers, times that do not increase, too many rows),
/// so every file it completes reads back.
#[derive(Clone, Debug)]
#[must_use]
pub struct TargetCsvWriter {
    effector_count: usize,
    header_written: bool,
    previous_time: Option<f64>,
    rows: usize,
}

impl TargetCsvWriter {
    /// A writer for `effector_count` effectors.
    pub fn new(effector_count: usize) -> Self {
        Self {
            effector_count,
            header_written: false,
            previous_time: None,
            rows: 0,
        }
    }

    /// Writes `t,<name>_x,<name>_y,<name>_z,…` for the effector names, in effector order.
    ///
    /// # Errors
    /// [`WriteError::ValueCount`] for the wrong number of names, [`WriteError::Order`]
    /// for a second header, [`WriteError::Sink`] if the output fails.
    pub fn write_header<S: AsRef<str>>(
        &mut self,
        out: &mut impl Write,
        effector_names: &[S],
    ) -> Result<(), WriteError> {
        if self.header_written {
            return Err(WriteError::Order(
                "the target CSV header was already written",
            ));
        }
        if effector_names.len() != self.effector_count {
            return Err(WriteError::ValueCount {
                what: "effector names",
                expected: self.effector_count,
                found: effector_names.len(),
            });
        }
        out.write_char('t')?;
        for name in effector_names {
            for suffix in ["_x", "_y", "_z"] {
                out.write_char(',')?;
                write_suffixed_field(out, name.as_ref(), suffix)?;
            }
        }
        out.write_char('\n')?;
        self.header_written = true;
        Ok(())
    }

    /// Writes one row: time `t` (seconds) and one target per effector (metres).
    ///
    /// # Errors
    /// [`WriteError::Order`] before the header, [`WriteError::ValueCount`] for the
    /// wrong number of targets or past [`MAX_TARGET_ROWS`] rows,
    /// [`WriteError::NonFinite`], [`WriteError::TimeNotIncreasing`] (nothing is
    /// written then), [`WriteError::Sink`] if the output fails.
    pub fn write_row(
        &mut self,
        out: &mut impl Write,
        t: f64,
        targets: &[DVec3],
    ) -> Result<(), WriteError> {
        if !self.header_written {
            return Err(WriteError::Order(
                "write the target CSV header before any row",
            ));
        }
        if targets.len() != self.effector_count {
            return Err(WriteError::ValueCount {
                what: "effector targets",
                expected: self.effector_count,
                found: targets.len(),
            });
        }
        if self.rows >= MAX_TARGET_ROWS {
            return Err(WriteError::ValueCount {
                what: "rows at most (the reader's limit)",
                expected: MAX_TARGET_ROWS,
                found: self.rows + 1,
            });
        }
        if !t.is_finite() || targets.iter().any(|p| !p.is_finite()) {
            return Err(WriteError::NonFinite {
                what: "target row",
                row: self.rows,
            });
        }
        if let Some(previous) = self.previous_time
            && t <= previous
        {
            return Err(WriteError::TimeNotIncreasing {
                row: self.rows,
                time: t,
                previous,
            });
        }
        write_round_trip(out, t)?;
        for p in targets {
            for value in [p.x, p.y, p.z] {
                out.write_char(',')?;
                write_round_trip(out, value)?;
            }
        }
        out.write_char('\n')?;
        self.previous_time = Some(t);
        self.rows += 1;
        Ok(())
    }
}

/// Writes a whole target CSV for `track`, with one name per effector.
///
/// # Errors
/// As [`TargetCsvWriter::write_header`] and [`TargetCsvWriter::write_row`].
pub fn write_target_csv<S: AsRef<str>>(
    out: &mut impl Write,
    effector_names: &[S],
    track: &TargetTrack,
) -> Result<(), WriteError> {
    let mut writer = TargetCsvWriter::new(track.effector_count());
    writer.write_header(out, effector_names)?;
    for (row, &t) in track.times().iter().enumerate() {
        writer.write_row(out, t, track.row(row).unwrap_or_default())?;
    }
    Ok(())
}
