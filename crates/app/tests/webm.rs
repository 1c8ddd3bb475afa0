//! The WebM writer read back by a separate EBML reader written here from
//! RFC 8794 / RFC 9559: header fields, block times, keyframes, clusters and
//! the cues that point at them.

use gaitlab_app::webm::{VideoCodec, WebmError, WebmMuxer};

/// One element: id (with its length marker), body range.
#[derive(Debug, Clone, Copy)]
struct Element {
    id: u32,
    at: usize,
    body: usize,
    end: usize,
}

/// Reads a variable-size integer at `p`: (value without marker, length).
fn vint(b: &[u8], p: usize) -> (u64, usize) {
    let len = b[p].leading_zeros() as usize + 1;
    assert!(len <= 8, "bad vint at {p}");
    let mut v = u64::from(b[p]) & ((1u64 << (8 - len)) - 1);
    for &byte in &b[p + 1..p + len] {
        v = (v << 8) | u64::from(byte);
    }
    (v, len)
}

fn children(b: &[u8], from: usize, to: usize) -> Vec<Element> {
    let mut out = Vec::new();
    let mut p = from;
    while p < to {
        let id_len = b[p].leading_zeros() as usize + 1;
        let id = b[p..p + id_len]
            .iter()
            .fold(0u32, |a, &x| (a << 8) | u32::from(x));
        let (size, size_len) = vint(b, p + id_len);
        let body = p + id_len + size_len;
        let end = body + usize::try_from(size).expect("size fits usize");
        assert!(end <= to, "element {id:x} at {p} overruns its parent");
        out.push(Element {
            id,
            at: p,
            body,
            end,
        });
        p = end;
    }
    assert_eq!(p, to, "children do not fill their parent");
    out
}

fn find(b: &[u8], parent: Element, id: u32) -> Element {
    *children(b, parent.body, parent.end)
        .iter()
        .find(|e| e.id == id)
        .unwrap_or_else(|| panic!("no element {id:x} in {:x}", parent.id))
}

fn uint(b: &[u8], e: Element) -> u64 {
    b[e.body..e.end]
        .iter()
        .fold(0, |a, &x| (a << 8) | u64::from(x))
}

fn text(b: &[u8], e: Element) -> &str {
    std::str::from_utf8(&b[e.body..e.end]).expect("UTF-8 text")
}

/// A take: (timestamp µs, keyframe, bytes) per frame.
fn take() -> Vec<(u64, bool, Vec<u8>)> {
    // 40 ms apart from 1.5 s of an arbitrary clock, a keyframe each second,
    // one 50 s gap (past a cluster's ±32.767 s block offsets).
    let mut frames = Vec::new();
    let mut t = 1_500_000;
    for i in 0..60u64 {
        if i == 45 {
            t += 50_000_000;
        }
        frames.push((t, i % 25 == 0, vec![i as u8; 10 + i as usize]));
        t += 40_000;
    }
    frames
}

#[test]
fn a_take_reads_back_with_its_header_blocks_clusters_and_cues() {
    let mut muxer = WebmMuxer::new(VideoCodec::Vp9, 640, 360);
    let frames = take();
    for (t, key, data) in &frames {
        muxer.push(*t, *key, data).expect("frame muxed");
    }
    assert_eq!(muxer.frames(), 60);
    let b = muxer.finish("gaitlab test");

    let top = children(&b, 0, b.len());
    assert_eq!(top.len(), 2, "EBML header and one Segment");
    assert_eq!(top[0].id, 0x1A45_DFA3);
    assert_eq!(text(&b, find(&b, top[0], 0x4282)), "webm");
    assert_eq!(uint(&b, find(&b, top[0], 0x4285)), 2, "DocTypeReadVersion");
    let segment = top[1];
    assert_eq!(segment.id, 0x1853_8067);

    let info = find(&b, segment, 0x1549_A966);
    assert_eq!(uint(&b, find(&b, info, 0x2A_D7B1)), 1_000_000, "1 ms ticks");
    let d = find(&b, info, 0x4489);
    let duration = f64::from_be_bytes(b[d.body..d.end].try_into().expect("8-byte float"));
    // Last frame at 59 × 40 ms + 50 s = 52.36 s, shown for the mean interval capped at 100 ms.
    assert!((duration - 52_460.0).abs() < 1e-9, "duration {duration} ms");

    let track = find(&b, find(&b, segment, 0x1654_AE6B), 0xAE);
    assert_eq!(text(&b, find(&b, track, 0x86)), "V_VP9");
    assert_eq!(uint(&b, find(&b, track, 0xD7)), 1);
    let video = find(&b, track, 0xE0);
    assert_eq!(uint(&b, find(&b, video, 0xB0)), 640);
    assert_eq!(uint(&b, find(&b, video, 0xBA)), 360);

    // Blocks in order, with their times (ms from the first frame), keyframe flags and bytes.
    let clusters: Vec<Element> = children(&b, segment.body, segment.end)
        .into_iter()
        .filter(|e| e.id == 0x1F43_B675)
        .collect();
    let mut blocks = Vec::new();
    for cluster in &clusters {
        let parts = children(&b, cluster.body, cluster.end);
        assert_eq!(parts[0].id, 0xE7, "a cluster opens with its timestamp");
        let start = uint(&b, parts[0]);
        for block in &parts[1..] {
            assert_eq!(block.id, 0xA3);
            let (track, n) = vint(&b, block.body);
            assert_eq!(track, 1);
            let rel = i16::from_be_bytes([b[block.body + n], b[block.body + n + 1]]);
            let flags = b[block.body + n + 2];
            let time = (start as i64 + i64::from(rel)) as u64;
            blocks.push((
                time,
                flags & 0x80 != 0,
                b[block.body + n + 3..block.end].to_vec(),
            ));
        }
    }
    assert_eq!(blocks.len(), frames.len());
    for (i, ((time, key, data), (t, k, d))) in blocks.iter().zip(&frames).enumerate() {
        let expected_ms = (t - frames[0].0 + 500) / 1000;
        assert_eq!(*time, expected_ms, "frame {i} time");
        assert_eq!(key, k, "frame {i} keyframe flag");
        assert_eq!(data, d, "frame {i} bytes");
    }
    // Clusters at the keyframes 0, 25, 50 and at the 50 s gap (frame 45).
    assert_eq!(clusters.len(), 4);

    // One cue per cluster, with its time and its offset from the segment's body.
    let cues = children(
        &b,
        find(&b, segment, 0x1C53_BB6B).body,
        find(&b, segment, 0x1C53_BB6B).end,
    );
    assert_eq!(cues.len(), clusters.len());
    for (cue, cluster) in cues.iter().zip(&clusters) {
        let time = uint(&b, find(&b, *cue, 0xB3));
        let positions = find(&b, *cue, 0xB7);
        let offset = uint(&b, find(&b, positions, 0xF1)) as usize;
        assert_eq!(
            segment.body + offset,
            cluster.at,
            "cue points at its cluster"
        );
        let start = uint(&b, children(&b, cluster.body, cluster.end)[0]);
        assert_eq!(time, start, "cue time is the cluster's");
    }
}

#[test]
fn frames_that_cannot_be_muxed_are_refused_and_the_take_goes_on() {
    let mut muxer = WebmMuxer::new(VideoCodec::Vp8, 320, 240);
    assert_eq!(muxer.push(0, false, &[1]), Err(WebmError::FirstFrameNotKey));
    assert_eq!(muxer.push(0, true, &[]), Err(WebmError::EmptyFrame));
    muxer.push(1_000, true, &[1, 2]).expect("keyframe muxed");
    let err = muxer.push(999, false, &[3]).expect_err("backwards refused");
    assert_eq!(
        err,
        WebmError::TimestampBackwards {
            previous_us: 1_000,
            timestamp_us: 999
        }
    );
    assert!(err.to_string().contains("999 µs"), "{err}");
    muxer.push(34_000, false, &[3]).expect("frame muxed");
    assert_eq!(muxer.frames(), 2);
    assert!((muxer.duration_ms() - 66.0).abs() < 1e-9);
    let b = muxer.finish("t");
    let top = children(&b, 0, b.len());
    let track = find(&b, find(&b, top[1], 0x1654_AE6B), 0xAE);
    assert_eq!(text(&b, find(&b, track, 0x86)), "V_VP8");
}

#[test]
fn an_empty_take_is_still_a_well_formed_file() {
    let b = WebmMuxer::new(VideoCodec::Vp9, 2, 2).finish("t");
    let top = children(&b, 0, b.len());
    assert_eq!(top.len(), 2);
    let ids: Vec<u32> = children(&b, top[1].body, top[1].end)
        .iter()
        .map(|e| e.id)
        .collect();
    assert_eq!(ids, [0x1549_A966, 0x1654_AE6B, 0x1C53_BB6B]);
}
