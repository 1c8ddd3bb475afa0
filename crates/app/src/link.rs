//! Links (DESIGN.md "Browser: URL"): `?preset=NAME&mode=…&method=…` for bundled
//! presets and `#p=<base64url(deflate(preset JSON))>` for any preset. Decoding is
//! bounded and total: a hostile link gives an error text, never a panic, and
//! nothing in it is evaluated.

use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use gaitlab_core::preset::MAX_PRESET_BYTES;

/// Longest `#p=` payload accepted, in characters (before decoding).
pub const MAX_LINK_CHARS: usize = 128 * 1024;

/// What a link asks for. Values are raw strings, checked when applied.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LinkRequest {
    /// `preset=` (a bundled preset name).
    pub preset: Option<String>,
    /// `mode=`.
    pub mode: Option<String>,
    /// `method=`.
    pub method: Option<String>,
    /// The JSON of a `#p=` preset, already inflated.
    pub custom_preset: Option<String>,
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
            match decode_preset(payload) {
                Ok(json) => request.custom_preset = Some(json),
                Err(error) => request.errors.push(error),
            }
        }
    }
    request
}

/// Decodes a `#p=` payload into preset JSON text.
///
/// # Errors
/// A readable reason: too long, not base64url, not deflate, too large once
/// inflated (over the 256 KiB preset limit), or not UTF-8.
pub fn decode_preset(payload: &str) -> Result<String, String> {
    if payload.len() > MAX_LINK_CHARS {
        return Err(format!(
            "link: the preset in #p= is longer than {} KiB",
            MAX_LINK_CHARS / 1024
        ));
    }
    let compressed = URL_SAFE_NO_PAD
        .decode(payload.trim_end_matches('='))
        .map_err(|e| format!("link: #p= is not base64url ({e})"))?;
    let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&compressed, MAX_PRESET_BYTES)
        .map_err(|e| match e.status {
            miniz_oxide::inflate::TINFLStatus::HasMoreOutput => {
                format!(
                    "link: the preset in #p= is larger than {} KiB",
                    MAX_PRESET_BYTES / 1024
                )
            }
            _ => "link: #p= is not deflate-compressed data".to_owned(),
        })?;
    String::from_utf8(json).map_err(|_| "link: the preset in #p= is not UTF-8 text".to_owned())
}

/// Encodes preset JSON as a `#p=` payload (raw deflate, base64url without padding).
#[must_use]
pub fn encode_preset(json: &str) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 9))
}

/// The query string for a bundled preset, mode and method (`?preset=…&mode=…&method=…`).
#[must_use]
pub fn query(preset: &str, mode: &str, method: &str) -> String {
    let clean = |s: &str| {
        s.chars()
            .filter(|c| c.is_ascii_alphanumeric() || *c == '-' || *c == '_')
            .collect::<String>()
    };
    format!(
        "?preset={}&mode={}&method={}",
        clean(preset),
        clean(mode),
        clean(method)
    )
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
        assert!(error.contains("larger than 256 KiB"), "{error}");
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
            query("human", "run", "dls"),
            "?preset=human&mode=run&method=dls"
        );
        assert_eq!(
            query("a&b=c", "run", "<x>"),
            "?preset=abc&mode=run&method=x"
        );
    }
}
