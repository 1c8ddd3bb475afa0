//! Links (DESIGN.md "Browser: URL"): `?preset=NAME&mode=…&method=…` for bundled
//! presets and `#p=<base64url(deflate(JSON))>` for any preset or a whole lab.
//! Decoding is bounded and total: a hostile link gives an error text, never a
//! panic, and nothing in it is evaluated.
//!
//! The `#p=` JSON is either a bare preset (the first links) or a full-state
//! envelope, `{"gaitlab_link": 1, "bundled": NAME?, "preset": {…}, "state": {…}}`:
//! the preset JSON verbatim, the bundled preset it was when unedited, and a
//! command object (see [`crate::link_state`]) that restores the rest.

use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use gaitlab_core::preset::MAX_PRESET_BYTES;
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;
use serde_json::{Map, Value};

/// Longest `#p=` payload accepted, in characters (before decoding).
pub const MAX_LINK_CHARS: usize = 128 * 1024;

/// Largest inflated `#p=` JSON, bytes: a preset at its limit plus the state.
/// Checked while inflating, so a deflate bomb stops here.
pub const MAX_LINK_JSON_BYTES: usize = MAX_PRESET_BYTES + 64 * 1024;

/// Version of the full-state envelope this app writes and reads.
pub const LINK_VERSION: u64 = 1;

/// A whole lab as a link carries it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FullLink {
    /// The preset JSON, verbatim.
    pub preset_json: String,
    /// The bundled preset's name when `preset_json` is that preset unedited.
    pub bundled: Option<String>,
    /// A command object (keys of [`crate::link_state::LINK_KEYS`]).
    pub state: Map<String, Value>,
}

/// What a `#p=` payload holds.
#[derive(Clone, Debug, PartialEq)]
pub enum LinkPayload {
    /// A bare preset JSON (the first `#p=` links).
    Preset(String),
    /// A full-state envelope.
    Full(FullLink),
}

/// The envelope as this app writes it (the preset verbatim).
#[derive(Serialize)]
struct EnvelopeOut<'a> {
    gaitlab_link: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    bundled: Option<&'a str>,
    preset: &'a RawValue,
    state: &'a Map<String, Value>,
}

/// The envelope as read, the preset kept as raw text.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Envelope<'a> {
    gaitlab_link: Value,
    #[serde(default)]
    bundled: Option<String>,
    #[serde(borrow)]
    preset: &'a RawValue,
    #[serde(default)]
    state: Map<String, Value>,
}

/// What a link asks for. Values are raw strings, checked when applied.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LinkRequest {
    /// `preset=` (a bundled preset name).
    pub preset: Option<String>,
    /// `mode=`.
    pub mode: Option<String>,
    /// `method=`.
    pub method: Option<String>,
    /// The JSON of a `#p=` preset, already inflated.
    pub custom_preset: Option<String>,
    /// A `#p=` full-state link.
    pub full: Option<FullLink>,
    /// Problems met while reading the link (the rest still applies).
    pub errors: Vec<String>,
}

/// Percent-decodes one query component (`+` is a space). Invalid escapes are kept as text.
fn percent_decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' if i + 2 < bytes.len() => {
                let hex = |b: u8| (b as char).to_digit(16);
                match (hex(bytes[i + 1]), hex(bytes[i + 2])) {
                    (Some(h), Some(l)) => {
                        out.push((h * 16 + l) as u8);
                        i += 2;
                    }
                    _ => out.push(b'%'),
                }
            }
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Reads a page's query string (with or without the leading `?`) and fragment
/// (with or without `#`).
#[must_use]
pub fn parse(query: &str, fragment: &str) -> LinkRequest {
    let mut request = LinkRequest::default();
    for pair in query
        .trim_start_matches('?')
        .split('&')
        .filter(|p| !p.is_empty())
    {
        let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
        let value = percent_decode(value);
        if value.len() > 256 {
            request
                .errors
                .push(format!("link: the value of {key:?} is too long"));
            continue;
        }
        match key {
            "preset" => request.preset = Some(value),
            "mode" => request.mode = Some(value),
            "method" => request.method = Some(value),
            _ => {}
        }
    }
    let fragment = fragment.trim_start_matches('#');
    for part in fragment.split('&').filter(|p| !p.is_empty()) {
        if let Some(payload) = part.strip_prefix("p=") {
            match decode_payload(payload) {
                Ok(LinkPayload::Preset(json)) => request.custom_preset = Some(json),
                Ok(LinkPayload::Full(full)) => request.full = Some(full),
                Err(error) => request.errors.push(error),
            }
        }
    }
    request
}

/// Inflates a `#p=` payload into text of at most `limit` bytes.
fn inflate(payload: &str, limit: usize) -> Result<String, String> {
    if payload.len() > MAX_LINK_CHARS {
        return Err(format!(
            "link: #p= is longer than {} KiB ({} characters)",
            MAX_LINK_CHARS / 1024,
            payload.len()
        ));
    }
    let compressed = URL_SAFE_NO_PAD
        .decode(payload.trim_end_matches('='))
        .map_err(|e| format!("link: #p= is not base64url ({e})"))?;
    let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&compressed, limit).map_err(
        |e| match e.status {
            miniz_oxide::inflate::TINFLStatus::HasMoreOutput => {
                format!(
                    "link: #p= inflates to more than {} KiB",
                    limit.div_ceil(1024)
                )
            }
            _ => "link: #p= is not deflate-compressed data (truncated or damaged?)".to_owned(),
        },
    )?;
    String::from_utf8(json).map_err(|_| "link: #p= is not UTF-8 text".to_owned())
}

/// Decodes a `#p=` payload into preset JSON text (a bare-preset link).
///
/// # Errors
/// A readable reason: too long, not base64url, not deflate, too large once
/// inflated (over the 256 KiB preset limit), or not UTF-8.
pub fn decode_preset(payload: &str) -> Result<String, String> {
    inflate(payload, MAX_PRESET_BYTES)
}

/// Decodes a `#p=` payload: a bare preset or a full-state envelope.
///
/// # Errors
/// A readable `link: …` reason: too long, not base64url, not deflate, too
/// large once inflated, not UTF-8, not a JSON object, an envelope of another
/// version or with a malformed field.
pub fn decode_payload(payload: &str) -> Result<LinkPayload, String> {
    let text = inflate(payload, MAX_LINK_JSON_BYTES)?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| format!("link: #p= is not JSON ({e})"))?;
    let Some(object) = value.as_object() else {
        return Err("link: #p= must hold a JSON object".to_owned());
    };
    if !object.contains_key("gaitlab_link") {
        if text.len() > MAX_PRESET_BYTES {
            return Err(format!(
                "link: the preset in #p= is larger than {} KiB",
                MAX_PRESET_BYTES / 1024
            ));
        }
        return Ok(LinkPayload::Preset(text));
    }
    let envelope: Envelope<'_> =
        serde_json::from_str(&text).map_err(|e| format!("link: #p= envelope: {e}"))?;
    if envelope.gaitlab_link.as_u64() != Some(LINK_VERSION) {
        return Err(format!(
            "link: gaitlab_link: version {} is not one this app reads (it reads {LINK_VERSION})",
            envelope.gaitlab_link
        ));
    }
    let preset_json = envelope.preset.get();
    if preset_json.len() > MAX_PRESET_BYTES {
        return Err(format!(
            "link: preset: larger than {} KiB",
            MAX_PRESET_BYTES / 1024
        ));
    }
    Ok(LinkPayload::Full(FullLink {
        preset_json: preset_json.to_owned(),
        bundled: envelope.bundled,
        state: envelope.state,
    }))
}

/// Encodes text as a `#p=` payload (raw deflate, base64url without padding).
fn deflate(text: &str) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(text.as_bytes(), 9))
}

/// Encodes preset JSON as a `#p=` payload (raw deflate, base64url without padding).
#[must_use]
pub fn encode_preset(json: &str) -> String {
    deflate(json)
}

/// Encodes a whole lab as a `#p=` payload (the envelope, deflated, base64url).
///
/// # Errors
/// If `preset_json` is not JSON (the lab only holds presets that parsed).
pub fn encode_full(link: &FullLink) -> Result<String, String> {
    let preset = RawValue::from_string(link.preset_json.clone())
        .map_err(|e| format!("link: the preset is not JSON ({e})"))?;
    let envelope = EnvelopeOut {
        gaitlab_link: LINK_VERSION,
        bundled: link.bundled.as_deref(),
        preset: &preset,
        state: &link.state,
    };
    let text = serde_json::to_string(&envelope).map_err(|e| format!("link: {e}"))?;
    Ok(deflate(&text))
}

/// The query string for a bundled preset and, where they apply, the IK
/// mode and method (`?preset=…[&mode=…[&method=…]]`): the address bar says
/// only what is on screen (issue 43 item 5) — no method while a comparison
/// runs several, no mode or method for a PODA or physics creature.
#[must_use]
pub fn query(preset: &str, mode: Option<&str>, method: Option<&str>) -> String {
    let clean = |s: &str| {
        s.chars()
            .filter(|c| c.is_ascii_alphanumeric() || *c == '-' || *c == '_')
            .collect::<String>()
    };
    let mut query = format!("?preset={}", clean(preset));
    if let Some(mode) = mode {
        query.push_str("&mode=");
        query.push_str(&clean(mode));
        if let Some(method) = method {
            query.push_str("&method=");
            query.push_str(&clean(method));
        }
    }
    query
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn query_fields_are_read_and_decoded() {
        let request = parse("?preset=human&mode=wounded%2Drun&method=dls&extra=1", "");
        assert_eq!(request.preset.as_deref(), Some("human"));
        assert_eq!(request.mode.as_deref(), Some("wounded-run"));
        assert_eq!(request.method.as_deref(), Some("dls"));
        assert!(request.errors.is_empty());
    }

    #[test]
    fn presets_round_trip_through_the_fragment() {
        let json = gaitlab_core::preset::bundled_json("human").expect("bundled");
        let payload = encode_preset(json);
        assert!(payload.len() < json.len() / 2, "deflate shrinks the preset");
        let request = parse("", &format!("#p={payload}"));
        assert_eq!(request.custom_preset.as_deref(), Some(json));
    }

    #[test]
    fn hostile_links_give_errors_not_panics() {
        for fragment in [
            "#p=",
            "#p=%%%",
            "#p=!!!!",
            "#p=AAAA",
            "#p=////",
            "#p=8J-mlQ",
        ] {
            let request = parse("", fragment);
            assert!(
                request.custom_preset.is_none() || request.custom_preset.as_deref() == Some(""),
                "{fragment}"
            );
        }
        // A zip bomb: 10 MiB of spaces deflates to a few KiB but must not inflate past the limit.
        let bomb = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            &vec![b' '; 10 << 20],
            9,
        ));
        let error = decode_preset(&bomb).expect_err("too large");
        assert!(error.contains("more than 256 KiB"), "{error}");
        let error = decode_payload(&bomb).expect_err("too large");
        assert!(error.contains("more than 320 KiB"), "{error}");
        let long = "A".repeat(MAX_LINK_CHARS + 1);
        assert!(
            decode_preset(&long)
                .expect_err("too long")
                .contains("longer than")
        );
        for query in [
            "?%",
            "?preset=%zz",
            "?=&&==",
            "?preset",
            &format!("?mode={}", "x".repeat(1000)),
        ] {
            let _ = parse(query, "");
        }
        assert_eq!(parse("?preset=%zz", "").preset.as_deref(), Some("%zz"));
    }

    #[test]
    fn query_strings_are_clean() {
        assert_eq!(
            query("human", Some("run"), Some("dls")),
            "?preset=human&mode=run&method=dls"
        );
        assert_eq!(
            query("a&b=c", Some("run"), Some("<x>")),
            "?preset=abc&mode=run&method=x"
        );
        assert_eq!(
            query("she-2006", Some("walk"), None),
            "?preset=she-2006&mode=walk"
        );
        assert_eq!(query("hexapod", None, Some("sdls")), "?preset=hexapod");
    }

    fn sample_link() -> FullLink {
        let mut state = Map::new();
        state.insert("mode".into(), Value::from("run"));
        state.insert("lambda".into(), Value::from(0.123_456_789));
        state.insert(
            "camera".into(),
            serde_json::json!({"yaw_rad": 0.5, "target_m": [0.0, 1.0, -2.5]}),
        );
        FullLink {
            preset_json: gaitlab_core::preset::bundled_json("human")
                .expect("bundled")
                .trim()
                .to_owned(),
            bundled: Some("human".into()),
            state,
        }
    }

    #[test]
    fn full_links_round_trip_every_field() {
        let link = sample_link();
        let payload = encode_full(&link).expect("encodes");
        assert!(
            payload.len() < link.preset_json.len() / 2,
            "{} characters",
            payload.len()
        );
        assert_eq!(
            decode_payload(&payload).expect("decodes"),
            LinkPayload::Full(link.clone())
        );
        let request = parse("?preset=hexapod", &format!("#p={payload}"));
        assert_eq!(request.full, Some(link.clone()));
        assert!(request.errors.is_empty());
        // An edited preset with no bundled name, and no state.
        let edited = FullLink {
            preset_json: link.preset_json.replace("\"human\"", "\"edited\""),
            bundled: None,
            state: Map::new(),
        };
        let payload = encode_full(&edited).expect("encodes");
        assert_eq!(decode_payload(&payload), Ok(LinkPayload::Full(edited)));
        // Old links (a bare preset) still read as presets.
        let old = encode_preset(&link.preset_json);
        assert_eq!(
            decode_payload(&old),
            Ok(LinkPayload::Preset(link.preset_json.clone()))
        );
    }

    /// The error for a payload, which must be an error.
    fn broken(payload: &str) -> String {
        match decode_payload(payload) {
            Err(error) => {
                assert!(error.starts_with("link: "), "{error}");
                error
            }
            Ok(decoded) => panic!("{payload:.40}… decoded to {decoded:?}"),
        }
    }

    #[test]
    fn damaged_full_links_give_errors_that_say_what_is_wrong() {
        let payload = encode_full(&sample_link()).expect("encodes");
        // Truncated anywhere: never a panic, always an error.
        for cut in [1, 2, 10, payload.len() / 2, payload.len() - 3] {
            let error = broken(&payload[..cut]);
            assert!(
                error.contains("deflate") || error.contains("base64") || error.contains("JSON"),
                "cut at {cut}: {error}"
            );
        }
        // Flipped characters: every position in the first 200 and the last 50,
        // replaced by another base64url character.
        let bytes = payload.as_bytes();
        let mut failures = 0;
        for at in (0..200).chain(bytes.len() - 50..bytes.len()) {
            let mut flipped = bytes.to_vec();
            flipped[at] = if flipped[at] == b'A' { b'z' } else { b'A' };
            let text = String::from_utf8(flipped).expect("ascii");
            // A flip may still decode (deflate has no checksum) but must not panic.
            if decode_payload(&text).is_err() {
                failures += 1;
            }
        }
        assert!(failures > 150, "{failures} of 250 flips were caught");
        let error = broken(&"A".repeat(10 << 20));
        assert!(error.contains("longer than 128 KiB"), "{error}");
        let error = broken("not*base64");
        assert!(error.contains("base64url"), "{error}");
        let wrap = |json: &str| encode_preset(json);
        let error = broken(&wrap("[1, 2, 3]"));
        assert!(error.contains("JSON object"), "{error}");
        let error = broken(&wrap("\"text\""));
        assert!(error.contains("JSON object"), "{error}");
        let error = broken(&wrap("{\"gaitlab_link\": 2, \"preset\": {}}"));
        assert!(error.contains("version 2"), "{error}");
        let error = broken(&wrap("{\"gaitlab_link\": \"1\", \"preset\": {}}"));
        assert!(error.contains("version"), "{error}");
        let error = broken(&wrap("{\"gaitlab_link\": 1}"));
        assert!(error.contains("preset"), "{error}");
        let error = broken(&wrap("{\"gaitlab_link\": 1, \"preset\": {}, \"eval\": 1}"));
        assert!(error.contains("eval"), "{error}");
        let error = broken(&wrap(
            "{\"gaitlab_link\": 1, \"preset\": {}, \"state\": []}",
        ));
        assert!(error.contains("envelope"), "{error}");
        let error = broken(&wrap(&"[".repeat(100_000)));
        assert!(error.contains("JSON"), "{error}");
        let invalid_utf8 = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            &[b'{', 0xff, 0xfe, b'}'],
            9,
        ));
        assert!(broken(&invalid_utf8).contains("UTF-8"));
    }
}
