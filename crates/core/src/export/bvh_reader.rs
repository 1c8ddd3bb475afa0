//! BVH reader: text to [`Bvh`], checking the grammar, the joint and channel
//! limits and that the MOTION table has exactly `Frames:` lines of exactly one
//! value per channel. Never panics; every error names a line.
//! ([`parse_bvh`] lists what is accepted and refused.)

use std::fmt;
use std::iter::Enumerate;
use std::str::{Lines, SplitWhitespace};

use glam::DVec3;

use super::{Bvh, BvhChannel, BvhJoint, MAX_BVH_CHANNELS_PER_JOINT, MAX_BVH_JOINTS};

/// Why a BVH text could not be read, at which (1-based) line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BvhError {
    /// 1-based line number of the problem (the last line for an early end of file).
    pub line: usize,
    /// What is wrong.
    pub reason: String,
}

impl BvhError {
    fn new(line: usize, reason: impl Into<String>) -> Self {
        Self {
            line,
            reason: reason.into(),
        }
    }
}

impl fmt::Display for BvhError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.reason)
    }
}

impl std::error::Error for BvhError {}

/// Reads a BVH file.
///
/// Accepted (lenient where real files vary): keywords in any ASCII case, tabs or
/// spaces, braces on their own line or at the end of a `ROOT`/`JOINT` line,
/// several ROOT blocks, `Frames:5` without a space, blank lines anywhere, a UTF-8
/// byte-order mark. Rejected: more than [`MAX_BVH_JOINTS`] joints, more than
/// [`MAX_BVH_CHANNELS_PER_JOINT`] channels on a joint, a second OFFSET / CHANNELS /
/// End Site in one block, a block without OFFSET, non-finite numbers, a frame
/// time that is not positive, and frame lines with the wrong number of values.
///
/// # Errors
/// A [`BvhError`] naming the line of the first problem: a missing or misplaced
/// keyword, an unbalanced brace, a bad number, too many joints or channels, or a
/// MOTION table whose line count or value count disagrees with the hierarchy.
pub fn parse_bvh(text: &str) -> Result<Bvh, BvhError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut cursor = Cursor::new(text);
    let (joints, channel_count) = parse_hierarchy(&mut cursor)?;
    let (frame_count, frame_time, motion) = parse_motion(&mut cursor, channel_count, text.len())?;
    Ok(Bvh {
        joints,
        frame_time,
        frame_count,
        channel_count,
        motion,
    })
}

/// Whitespace-separated words with their line numbers, crossing lines on demand.
struct Cursor<'a> {
    lines: Enumerate<Lines<'a>>,
    line: usize,
    words: SplitWhitespace<'a>,
    pending: Option<&'a str>,
}

impl<'a> Cursor<'a> {
    fn new(text: &'a str) -> Self {
        Self {
            lines: text.lines().enumerate(),
            line: 0,
            words: "".split_whitespace(),
            pending: None,
        }
    }

    /// The next word on the current line only.
    fn next_on_line(&mut self) -> Option<&'a str> {
        self.pending.take().or_else(|| self.words.next())
    }

    /// The next word anywhere, with its line number.
    fn next_word(&mut self) -> Option<(usize, &'a str)> {
        loop {
            if let Some(word) = self.next_on_line() {
                return Some((self.line, word));
            }
            let (i, line) = self.lines.next()?;
            self.line = i + 1;
            self.words = line.split_whitespace();
        }
    }

    /// The next non-blank line, trimmed, with its line number (for the MOTION section).
    fn next_line(&mut self) -> Option<(usize, &'a str)> {
        for (i, line) in self.lines.by_ref() {
            self.line = i + 1;
            let line = line.trim();
            if !line.is_empty() {
                return Some((self.line, line));
            }
        }
        None
    }

    fn end_of_file(&self, expected: &str) -> BvhError {
        BvhError::new(
            self.line.max(1),
            format!("file ends where {expected} was expected"),
        )
    }

    fn expect_word(&mut self, expected: &str) -> Result<usize, BvhError> {
        match self.next_word() {
            Some((line, word)) if word.eq_ignore_ascii_case(expected) => Ok(line),
            Some((line, word)) => Err(BvhError::new(
                line,
                format!("expected {expected:?}, found {word:?}"),
            )),
            None => Err(self.end_of_file(&format!("{expected:?}"))),
        }
    }

    fn number(&mut self, what: &str) -> Result<f64, BvhError> {
        let Some((line, word)) = self.next_word() else {
            return Err(self.end_of_file(what));
        };
        parse_finite(word)
            .ok_or_else(|| BvhError::new(line, format!("{what}: not a finite number {word:?}")))
    }

    fn vector(&mut self, what: &str) -> Result<DVec3, BvhError> {
        Ok(DVec3::new(
            self.number(what)?,
            self.number(what)?,
            self.number(what)?,
        ))
    }

    /// Joint name: the remaining words of the keyword's line up to an opening brace.
    fn name(&mut self, keyword_line: usize, keyword: &str) -> Result<String, BvhError> {
        let mut name = String::new();
        while let Some(word) = self.next_on_line() {
            if word == "{" {
                self.pending = Some(word);
                break;
            }
            if !name.is_empty() {
                name.push(' ');
            }
            name.push_str(word);
        }
        if name.is_empty() {
            return Err(BvhError::new(
                keyword_line,
                format!("{keyword} needs a name on the same line"),
            ));
        }
        Ok(name)
    }
}

fn parse_finite(word: &str) -> Option<f64> {
    word.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// A joint whose block is still open, and what its block has declared so far.
struct OpenBlock {
    joint: usize,
    line: usize,
    has_offset: bool,
    has_channels: bool,
}

fn parse_hierarchy(cursor: &mut Cursor<'_>) -> Result<(Vec<BvhJoint>, usize), BvhError> {
    match cursor.next_word() {
        Some((_, word)) if word.eq_ignore_ascii_case("HIERARCHY") => {}
        Some((line, word)) => {
            return Err(BvhError::new(
                line,
                format!("expected \"HIERARCHY\", found {word:?}"),
            ));
        }
        None => return Err(BvhError::new(1, "empty file: expected \"HIERARCHY\"")),
    }
    let mut joints: Vec<BvhJoint> = Vec::new();
    let mut open: Vec<OpenBlock> = Vec::new();
    let mut channel_count = 0_usize;
    loop {
        let Some((line, word)) = cursor.next_word() else {
            return Err(match open.last() {
                Some(block) => BvhError::new(
                    cursor.line.max(1),
                    format!(
                        "file ends inside the block of {:?} opened at line {}",
                        joints[block.joint].name, block.line
                    ),
                ),
                None => cursor.end_of_file("\"MOTION\""),
            });
        };
        if word.eq_ignore_ascii_case("ROOT") || word.eq_ignore_ascii_case("JOINT") {
            let is_root = word.eq_ignore_ascii_case("ROOT");
            let parent = open.last().map(|block| block.joint);
            if is_root && parent.is_some() {
                return Err(BvhError::new(
                    line,
                    "ROOT inside another joint's block (use JOINT)",
                ));
            }
            if !is_root && parent.is_none() {
                return Err(BvhError::new(line, "JOINT outside any ROOT block"));
            }
            if joints.len() >= MAX_BVH_JOINTS {
                return Err(BvhError::new(
                    line,
                    format!("more than {MAX_BVH_JOINTS} joints"),
                ));
            }
            let name = cursor.name(line, if is_root { "ROOT" } else { "JOINT" })?;
            cursor.expect_word("{")?;
            open.push(OpenBlock {
                joint: joints.len(),
                line,
                has_offset: false,
                has_channels: false,
            });
            joints.push(BvhJoint {
                name,
                parent,
                offset: DVec3::ZERO,
                channels: Vec::new(),
                first_channel: channel_count,
                end_site: None,
            });
        } else if word.eq_ignore_ascii_case("OFFSET") {
            let Some(block) = open.last_mut() else {
                return Err(BvhError::new(line, "OFFSET outside a joint block"));
            };
            if block.has_offset {
                return Err(BvhError::new(line, "second OFFSET in one block"));
            }
            block.has_offset = true;
            joints[block.joint].offset = cursor.vector("OFFSET")?;
        } else if word.eq_ignore_ascii_case("CHANNELS") {
            let Some(block) = open.last_mut() else {
                return Err(BvhError::new(line, "CHANNELS outside a joint block"));
            };
            if block.has_channels {
                return Err(BvhError::new(line, "second CHANNELS in one block"));
            }
            block.has_channels = true;
            let Some((count_line, count_word)) = cursor.next_word() else {
                return Err(cursor.end_of_file("a channel count"));
            };
            let count = match count_word.parse::<usize>() {
                Ok(count) if count <= MAX_BVH_CHANNELS_PER_JOINT => count,
                Ok(count) => {
                    return Err(BvhError::new(
                        count_line,
                        format!(
                            "{count} channels; a joint has at most {MAX_BVH_CHANNELS_PER_JOINT}"
                        ),
                    ));
                }
                Err(_) => {
                    return Err(BvhError::new(
                        count_line,
                        format!("CHANNELS: not a channel count {count_word:?}"),
                    ));
                }
            };
            let joint = &mut joints[block.joint];
            joint.first_channel = channel_count;
            for _ in 0..count {
                let Some((channel_line, channel_word)) = cursor.next_word() else {
                    return Err(cursor.end_of_file("a channel name"));
                };
                let Some(channel) = BvhChannel::from_name(channel_word) else {
                    return Err(BvhError::new(
                        channel_line,
                        format!(
                            "unknown channel {channel_word:?} (CHANNELS {count} needs {count} channel names)"
                        ),
                    ));
                };
                joint.channels.push(channel);
            }
            channel_count += count;
        } else if word.eq_ignore_ascii_case("End") {
            let Some(block) = open.last() else {
                return Err(BvhError::new(line, "End Site outside a joint block"));
            };
            let joint = block.joint;
            cursor.expect_word("Site")?;
            if joints[joint].end_site.is_some() {
                return Err(BvhError::new(line, "second End Site in one block"));
            }
            cursor.expect_word("{")?;
            cursor.expect_word("OFFSET")?;
            let tip = cursor.vector("End Site OFFSET")?;
            cursor.expect_word("}")?;
            joints[joint].end_site = Some(tip);
        } else if word == "}" {
            let Some(block) = open.pop() else {
                return Err(BvhError::new(line, "\"}\" without a matching \"{\""));
            };
            if !block.has_offset {
                return Err(BvhError::new(
                    line,
                    format!(
                        "the block of {:?} (line {}) has no OFFSET",
                        joints[block.joint].name, block.line
                    ),
                ));
            }
        } else if word.eq_ignore_ascii_case("MOTION") {
            if let Some(block) = open.last() {
                return Err(BvhError::new(
                    line,
                    format!(
                        "MOTION inside the unclosed block of {:?} (line {})",
                        joints[block.joint].name, block.line
                    ),
                ));
            }
            if joints.is_empty() {
                return Err(BvhError::new(line, "MOTION before any ROOT"));
            }
            if let Some(extra) = cursor.next_on_line() {
                return Err(BvhError::new(
                    line,
                    format!("unexpected {extra:?} after MOTION"),
                ));
            }
            return Ok((joints, channel_count));
        } else {
            return Err(BvhError::new(line, format!("unexpected {word:?}")));
        }
    }
}

/// Strips an ASCII case-insensitive keyword from the start of `text`.
fn strip_keyword<'a>(text: &'a str, keyword: &str) -> Option<&'a str> {
    let head = text.get(..keyword.len())?;
    head.eq_ignore_ascii_case(keyword)
        .then(|| &text[keyword.len()..])
}

fn parse_motion(
    cursor: &mut Cursor<'_>,
    channel_count: usize,
    text_len: usize,
) -> Result<(usize, f64, Vec<f64>), BvhError> {
    let Some((frames_line, text)) = cursor.next_line() else {
        return Err(cursor.end_of_file("\"Frames: N\""));
    };
    let frames_text = strip_keyword(text, "Frames")
        .and_then(|rest| rest.trim_start().strip_prefix(':'))
        .ok_or_else(|| {
            BvhError::new(
                frames_line,
                format!("expected \"Frames: N\", found {text:?}"),
            )
        })?
        .trim();
    let frame_count = frames_text.parse::<usize>().map_err(|_| {
        BvhError::new(
            frames_line,
            format!("Frames: not a whole number of frames {frames_text:?}"),
        )
    })?;

    let Some((time_line, text)) = cursor.next_line() else {
        return Err(cursor.end_of_file("\"Frame Time: T\""));
    };
    let time_text = strip_keyword(text, "Frame")
        .and_then(|rest| strip_keyword(rest.trim_start(), "Time"))
        .and_then(|rest| rest.trim_start().strip_prefix(':'))
        .ok_or_else(|| {
            BvhError::new(
                time_line,
                format!("expected \"Frame Time: T\", found {text:?}"),
            )
        })?
        .trim();
    let frame_time = parse_finite(time_text)
        .filter(|&t| t > 0.0)
        .ok_or_else(|| {
            BvhError::new(
                time_line,
                format!("Frame Time: not a positive number of seconds {time_text:?}"),
            )
        })?;

    // Every value takes at least two bytes of text, so this never over-reserves by much.
    let mut motion = Vec::with_capacity(
        frame_count
            .saturating_mul(channel_count)
            .min(text_len / 2 + 1),
    );
    let mut frames_read = 0_usize;
    while let Some((line, text)) = cursor.next_line() {
        frames_read += 1;
        if frames_read > frame_count {
            return Err(BvhError::new(
                line,
                format!("more frame lines than the {frame_count} declared by \"Frames:\""),
            ));
        }
        let mut values = 0_usize;
        for word in text.split_whitespace() {
            values += 1;
            if values > channel_count {
                break;
            }
            let value = parse_finite(word).ok_or_else(|| {
                BvhError::new(
                    line,
                    format!("value {values} of {channel_count}: not a finite number {word:?}"),
                )
            })?;
            motion.push(value);
        }
        if values != channel_count {
            let found = if values > channel_count {
                text.split_whitespace().count()
            } else {
                values
            };
            return Err(BvhError::new(
                line,
                format!("expected {channel_count} values (one per channel), found {found}"),
            ));
        }
    }
    if frames_read < frame_count {
        return Err(BvhError::new(
            cursor.line.max(1),
            format!("\"Frames: {frame_count}\" declared but only {frames_read} frame lines follow"),
        ));
    }
    Ok((frame_count, frame_time, motion))
}
