//! Number and field formatting shared by the writers, and the CSV field
//! splitter shared by the readers (RFC 4180 quoting on one line; no
//! multi-line fields, which none of gaitlab's formats need).

use std::fmt::{self, Write};

/// Writes `value` with exactly `decimals` digits after the point (never in
/// exponent form, which some BVH readers reject). Values that would print as
/// `-0.000…` print as `0.000…`. `zero_below` is `0.5 · 10^-decimals`.
pub(crate) fn write_fixed(
    out: &mut impl Write,
    value: f64,
    decimals: usize,
    zero_below: f64,
) -> fmt::Result {
    let value = if value.abs() < zero_below { 0.0 } else { value };
    write!(out, "{value:.decimals$}")
}

/// `0.5 · 10^-decimals`: magnitudes below it print as zero with `decimals` digits.
pub(crate) fn zero_below(decimals: usize) -> f64 {
    let exponent = i32::try_from(decimals).unwrap_or(i32::MAX);
    0.5 * 10.0_f64.powi(-exponent)
}

/// Writes `value` in the shortest text that parses back to the same `f64`:
/// plain decimal for ordinary magnitudes, exponent form (`1.5e-9`) for very
/// small or very large ones so no value needs hundreds of digits.
pub(crate) fn write_round_trip(out: &mut impl Write, value: f64) -> fmt::Result {
    let magnitude = value.abs();
    if value == 0.0 || !value.is_finite() || (1e-5..1e16).contains(&magnitude) {
        write!(out, "{value}")
    } else {
        write!(out, "{value:e}")
    }
}

/// Writes one CSV field, quoting it (RFC 4180) when it holds a comma, a quote,
/// a line break or leading/trailing spaces.
pub(crate) fn write_csv_field(out: &mut impl Write, field: &str) -> fmt::Result {
    let needs_quotes = field.contains([',', '"', '\n', '\r']) || field.trim() != field;
    if !needs_quotes {
        return out.write_str(field);
    }
    out.write_char('"')?;
    for (i, part) in field.split('"').enumerate() {
        if i > 0 {
            out.write_str("\"\"")?;
        }
        out.write_str(part)?;
    }
    out.write_char('"')
}

/// Writes `<name><suffix>` as one CSV field, quoting only if the name needs it.
pub(crate) fn write_suffixed_field(
    out: &mut impl Write,
    name: &str,
    suffix: &str,
) -> std::fmt::Result {
    if name.contains([',', '"', '\n', '\r']) || name.trim_start() != name {
        let mut field = String::with_capacity(name.len() + suffix.len());
        field.push_str(name);
        field.push_str(suffix);
        write_csv_field(out, &field)
    } else {
        out.write_str(name)?;
        out.write_str(suffix)
    }
}

/// Iterator over the fields of one CSV line, yielding each field's text with
/// surrounding spaces trimmed and enclosing quotes removed (a doubled quote inside
/// stays doubled: readers here only need names' count and numbers' text).
/// A malformed quoted field yields `Err(reason)` and ends the iteration.
pub(crate) struct CsvFields<'a> {
    rest: Option<&'a str>,
}

impl<'a> CsvFields<'a> {
    pub(crate) fn new(line: &'a str) -> Self {
        Self { rest: Some(line) }
    }
}

impl<'a> Iterator for CsvFields<'a> {
    type Item = Result<&'a str, &'static str>;

    fn next(&mut self) -> Option<Self::Item> {
        let rest = self.rest.take()?;
        let trimmed = rest.trim_start();
        if let Some(quoted) = trimmed.strip_prefix('"') {
            // Find the closing quote, skipping doubled quotes.
            let bytes = quoted.as_bytes();
            let mut i = 0;
            let close = loop {
                match bytes.get(i) {
                    None => return Some(Err("unterminated quoted field")),
                    Some(b'"') if bytes.get(i + 1) == Some(&b'"') => i += 2,
                    Some(b'"') => break i,
                    Some(_) => i += 1,
                }
            };
            let inside = &quoted[..close];
            let after = quoted[close + 1..].trim_start();
            if after.is_empty() {
                return Some(Ok(inside));
            }
            return match after.strip_prefix(',') {
                Some(next) => {
                    self.rest = Some(next);
                    Some(Ok(inside))
                }
                None => Some(Err("text after a closing quote")),
            };
        }
        match rest.split_once(',') {
            Some((field, next)) => {
                self.rest = Some(next);
                Some(Ok(field.trim()))
            }
            None => Some(Ok(rest.trim())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fields(line: &str) -> Vec<Result<&str, &'static str>> {
        CsvFields::new(line).collect()
    }

    #[test]
    fn splits_plain_and_quoted_fields() {
        assert_eq!(fields("t, a ,b"), vec![Ok("t"), Ok("a"), Ok("b")]);
        assert_eq!(
            fields("\"x,y\",\"he said \"\"hi\"\"\", 3"),
            vec![Ok("x,y"), Ok("he said \"\"hi\"\""), Ok("3")]
        );
        assert_eq!(fields("a,"), vec![Ok("a"), Ok("")]);
        assert_eq!(fields(""), vec![Ok("")]);
        assert_eq!(fields("\"open"), vec![Err("unterminated quoted field")]);
        assert_eq!(fields("\"a\"b,c"), vec![Err("text after a closing quote")]);
    }

    #[test]
    fn quotes_fields_that_need_it() {
        let mut out = String::new();
        for name in ["plain", "a,b", "say \"x\"", " pad"] {
            write_csv_field(&mut out, name).expect("string sink");
            out.push('|');
        }
        assert_eq!(out, "plain|\"a,b\"|\"say \"\"x\"\"\"|\" pad\"|");
    }

    #[test]
    fn round_trip_numbers_parse_back_exactly() {
        for value in [
            0.0,
            -0.0,
            1.0,
            -2.5,
            0.1,
            1.0 / 3.0,
            1e-300,
            -7.25e-9,
            6.02e23,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            let mut out = String::new();
            write_round_trip(&mut out, value).expect("string sink");
            assert!(out.len() < 30, "{out}");
            assert_eq!(
                out.parse::<f64>().expect("parses").to_bits(),
                value.to_bits(),
                "{out}"
            );
        }
    }

    #[test]
    fn fixed_numbers_have_no_negative_zero() {
        let mut out = String::new();
        write_fixed(&mut out, -1e-12, 6, zero_below(6)).expect("string sink");
        out.push(' ');
        write_fixed(&mut out, -0.25, 3, zero_below(3)).expect("string sink");
        assert_eq!(out, "0.000000 -0.250");
    }
}
