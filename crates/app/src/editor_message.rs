//! The preset editor's problem in the user's terms (issue 21 item 4): the
//! JSON path with the name of each indexed joint, body or leg
//! (`skeleton.joints[3] (left_ankle).axis`), the line it stands on, and
//! serde's type words put plainly ("a list of 3 numbers", not "a sequence of
//! 3 f64 values"). Pure functions over the error text and the edited JSON.

use serde_json::Value;

/// A problem with an edited preset, as the editor shows it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EditorProblem {
    /// What is wrong and where, in the user's terms.
    pub message: String,
    /// The line of the text it stands on (1-based), when known.
    pub line: Option<usize>,
}

/// Explains `error` (the lab's `preset: json.path: reason`, or a syntax
/// error's `preset: reason at line L column C`) for the editor holding `text`.
#[must_use]
pub fn explain(error: &str, text: &str) -> EditorProblem {
    // A loaded file's problem: `file NAME: preset: …`, the name kept.
    let (file, error) = match error.split_once(": preset: ") {
        Some((file, rest)) if file.starts_with("file ") => (Some(file), rest),
        _ => (None, error.strip_prefix("preset: ").unwrap_or(error)),
    };
    let mut problem = explain_preset(error, text);
    if let Some(file) = file {
        problem.message = format!("{file}: {}", problem.message);
    }
    problem
}

fn explain_preset(error: &str, text: &str) -> EditorProblem {
    let (body, mut line) = split_position(error);
    let (path, reason) = match body.split_once(": ") {
        Some((path, reason)) if is_json_path(path) => (Some(path), reason),
        _ => (None, body),
    };
    let reason = plain_words(reason);
    let Some(path) = path else {
        return EditorProblem {
            message: reason,
            line,
        };
    };
    let segments = parse_path(path);
    let json = serde_json::from_str::<Value>(text).ok();
    if line.is_none() {
        line = line_of(text, &segments);
    }
    let named = json
        .as_ref()
        .map_or_else(|| path.to_owned(), |j| named_path(j, &segments));
    EditorProblem {
        message: format!("{named}: {reason}"),
        line,
    }
}

/// One step of a JSON path.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Segment {
    Key(String),
    Index(usize),
}

/// Splits serde's trailing " at line L column C" off, keeping the line.
fn split_position(error: &str) -> (&str, Option<usize>) {
    if let Some(at) = error.rfind(" at line ") {
        let tail = &error[at + " at line ".len()..];
        let mut words = tail.split_whitespace();
        if let (Some(line), Some("column"), Some(column), None) =
            (words.next(), words.next(), words.next(), words.next())
            && column.parse::<usize>().is_ok()
            && let Ok(line) = line.parse::<usize>()
        {
            return (&error[..at], Some(line));
        }
    }
    (error, None)
}

/// Whether `s` reads as a JSON path: keys joined by dots, `[index]` after a key.
fn is_json_path(s: &str) -> bool {
    !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '[' | ']' | '-'))
        && s.chars()
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
}

fn parse_path(path: &str) -> Vec<Segment> {
    let mut out = Vec::new();
    for part in path.split('.') {
        let mut rest = part;
        if let Some(open) = rest.find('[') {
            if open > 0 {
                out.push(Segment::Key(rest[..open].to_owned()));
            }
            rest = &rest[open..];
            while let Some(close) = rest.find(']') {
                if let Ok(index) = rest[1..close].parse() {
                    out.push(Segment::Index(index));
                }
                rest = &rest[close + 1..];
            }
        } else if !rest.is_empty() {
            out.push(Segment::Key(rest.to_owned()));
        }
    }
    out
}

/// The path written back with ` (name)` after each index whose element has
/// a `name` (joints, effectors, legs) or a `joint` (physics bodies).
fn named_path(json: &Value, segments: &[Segment]) -> String {
    let mut out = String::new();
    let mut at = Some(json);
    for segment in segments {
        match segment {
            Segment::Key(key) => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
                at = at.and_then(|v| v.get(key));
            }
            Segment::Index(index) => {
                out.push_str(&format!("[{index}]"));
                at = at.and_then(|v| v.get(index));
                let name = at.and_then(|v| v.get("name").or_else(|| v.get("joint")));
                if let Some(name) = name.and_then(Value::as_str) {
                    out.push_str(&format!(" ({name})"));
                }
            }
        }
    }
    out
}

/// serde's words for types, in the words of someone editing JSON.
fn plain_words(reason: &str) -> String {
    let mut s = reason.to_owned();
    for (from, to) in [
        ("invalid type: string ", "found the text "),
        ("invalid type: integer ", "found the number "),
        ("invalid type: floating point ", "found the number "),
        ("invalid type: map", "found an object"),
        ("invalid type: sequence", "found a list"),
        ("invalid type: boolean ", "found "),
        ("invalid type: null", "found null"),
        ("invalid length ", "found a list of "),
        ("a sequence of ", "a list of "),
        (" f64 values", " numbers"),
        ("expected f64", "expected a number"),
        ("expected usize", "expected a whole number"),
        ("expected u32", "expected a whole number"),
        ("expected u64", "expected a whole number"),
        ("a tuple of size ", "a list of "),
        (
            "key must be a string",
            "a key must be text in double quotes",
        ),
        ("struct ", "object "),
        ("a sequence", "a list"),
        ("a map", "an object"),
    ] {
        s = s.replace(from, to);
    }
    s
}

/// The line (1-based) where the value at `segments` starts in `text`, by a
/// scan that follows objects and arrays; `None` if the text never reaches it.
fn line_of(text: &str, segments: &[Segment]) -> Option<usize> {
    #[derive(Debug)]
    enum Frame {
        Object { key: Option<String>, want_key: bool },
        Array { index: usize },
    }
    let at_target = |stack: &[Frame]| {
        stack.len() == segments.len()
            && stack
                .iter()
                .zip(segments)
                .all(|(frame, segment)| match (frame, segment) {
                    (Frame::Object { key: Some(k), .. }, Segment::Key(s)) => k == s,
                    (Frame::Array { index }, Segment::Index(i)) => index == i,
                    _ => false,
                })
    };
    let bytes = text.as_bytes();
    let mut stack: Vec<Frame> = Vec::new();
    let mut line = 1;
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        match c {
            b'\n' => line += 1,
            b' ' | b'\t' | b'\r' | b':' => {}
            b',' => match stack.last_mut() {
                Some(Frame::Object { want_key, .. }) => *want_key = true,
                Some(Frame::Array { index }) => *index += 1,
                None => {}
            },
            b'}' | b']' => {
                stack.pop();
            }
            _ => {
                let is_key = matches!(stack.last(), Some(Frame::Object { want_key: true, .. }));
                if !is_key && at_target(&stack) {
                    return Some(line);
                }
                match c {
                    b'{' => stack.push(Frame::Object {
                        key: None,
                        want_key: true,
                    }),
                    b'[' => stack.push(Frame::Array { index: 0 }),
                    b'"' => {
                        let start = i + 1;
                        i += 1;
                        while i < bytes.len() && bytes[i] != b'"' {
                            if bytes[i] == b'\\' {
                                i += 1;
                            } else if bytes[i] == b'\n' {
                                line += 1;
                            }
                            i += 1;
                        }
                        if is_key && let Some(Frame::Object { key, want_key }) = stack.last_mut() {
                            *key = Some(
                                String::from_utf8_lossy(&bytes[start..i.min(bytes.len())])
                                    .into_owned(),
                            );
                            *want_key = false;
                        }
                    }
                    _ => {
                        // A number or a literal: up to the next delimiter.
                        while i + 1 < bytes.len()
                            && !matches!(
                                bytes[i + 1],
                                b',' | b'}' | b']' | b'\n' | b' ' | b'\r' | b'\t'
                            )
                        {
                            i += 1;
                        }
                    }
                }
            }
        }
        i += 1;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = r#"{
  "name": "tiny",
  "skeleton": {
    "joints": [
      {"name": "hip", "axis": [1, 0, 0]},
      {
        "name": "left_knee",
        "axis": [0, 0, 0]
      }
    ]
  }
}"#;

    #[test]
    fn a_semantic_error_names_the_joint_and_finds_its_line() {
        let p = explain(
            "preset: skeleton.joints[1].axis: must be a non-zero vector",
            TEXT,
        );
        assert_eq!(
            p.message,
            "skeleton.joints[1] (left_knee).axis: must be a non-zero vector"
        );
        assert_eq!(p.line, Some(8));
        let p = explain("preset: skeleton.joints[0].axis[2]: must be finite", TEXT);
        assert_eq!(
            p.message,
            "skeleton.joints[0] (hip).axis[2]: must be finite"
        );
        assert_eq!(p.line, Some(5));
        assert_eq!(explain("preset: name: too long", TEXT).line, Some(2));
    }

    #[test]
    fn a_type_error_speaks_of_numbers_and_lists_and_keeps_serdes_line() {
        let p = explain(
            "preset: skeleton.joints[1].axis: invalid length 2, expected a sequence of 3 f64 values at line 8 column 9",
            TEXT,
        );
        assert_eq!(
            p.message,
            "skeleton.joints[1] (left_knee).axis: found a list of 2, expected a list of 3 numbers"
        );
        assert_eq!(p.line, Some(8));
        let p = explain(
            "preset: skeleton.joints[1].axis[0]: invalid type: string \"a\", expected f64 at line 8 column 13",
            TEXT,
        );
        assert!(
            p.message
                .ends_with("found the text \"a\", expected a number"),
            "{}",
            p.message
        );
        assert!(!p.message.contains("f64"));
    }

    #[test]
    fn a_loaded_files_problem_keeps_the_files_name() {
        let p = explain(
            "file tiny.json: preset: skeleton.joints[1].axis: must be a non-zero vector",
            TEXT,
        );
        assert_eq!(
            p.message,
            "file tiny.json: skeleton.joints[1] (left_knee).axis: must be a non-zero vector"
        );
        assert_eq!(p.line, Some(8));
    }

    #[test]
    fn a_syntax_error_keeps_its_line_without_a_path() {
        let p = explain("preset: key must be a string at line 18 column 9", "{");
        assert_eq!(p.message, "a key must be text in double quotes");
        assert_eq!(p.line, Some(18));
        let p = explain(
            "preset: EOF while parsing an object at line 3 column 1",
            "{",
        );
        assert_eq!(p.message, "EOF while parsing an object");
    }

    #[test]
    fn strings_with_brackets_and_escapes_do_not_confuse_the_scan() {
        let text =
            "{\n \"a\": \"x]}\\\"[\",\n \"b\": [\n  1,\n  {\"name\": \"n\", \"c\": 2}\n ]\n}";
        assert_eq!(line_of(text, &parse_path("b[1].c")), Some(5));
        assert_eq!(line_of(text, &parse_path("b[0]")), Some(4));
        assert_eq!(line_of(text, &parse_path("missing")), None);
        let p = explain("preset: b[1].c: must be positive", text);
        assert_eq!(p.message, "b[1] (n).c: must be positive");
    }
}
