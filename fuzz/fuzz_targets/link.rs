//! A page link → the lab (DESIGN.md "Browser: URL"; issue 6 item 2). The first
//! byte picks how the rest is used: as the raw `#fragment`, as the raw
//! `?query`, or as JSON that is deflated and base64url-encoded into `#p=` (so
//! the fuzzer reaches the envelope, preset and command code behind the codec).
//! The lab must take any link without a panic and keep running a few frames.
#![no_main]

use gaitlab_app::lab::Lab;
use gaitlab_app::link;
use gaitlab_app::settings::Settings;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&mode, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let mut lab = Lab::new(Settings::default());
    match mode % 3 {
        0 => lab.open_link("", text),
        1 => lab.open_link(text, ""),
        _ => lab.open_link("", &format!("#p={}", link::encode_preset(text))),
    }
    for _ in 0..3 {
        lab.advance(1.0 / 60.0);
    }
    let _ = lab.state_json();
});
