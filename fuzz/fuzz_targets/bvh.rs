//! BVH text → gaitlab's BVH reader: `Ok` or a `BvhError` naming the line,
//! never a panic; an accepted file's motion table has one row of the right
//! width per frame.
#![no_main]

use gaitlab_core::export::parse_bvh;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(bvh) = parse_bvh(text) {
        assert_eq!(bvh.motion.len(), bvh.frame_count * bvh.channel_count);
        let channels: usize = bvh.joints.iter().map(|j| j.channels.len()).sum();
        assert_eq!(channels, bvh.channel_count);
        for (i, joint) in bvh.joints.iter().enumerate() {
            assert!(joint.parent.is_none_or(|p| p < i), "parents come first");
        }
        assert!(bvh.motion.iter().all(|v| v.is_finite()));
    }
});
