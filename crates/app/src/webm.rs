//! A WebM writer for encoded VP8/VP9 frames: the container the browser's
//! video recording saves (She 2006 §6.2, "create a movie file"). It follows
//! EBML (RFC 8794) and the Matroska elements WebM keeps (RFC 9559): an EBML
//! header, then one Segment holding Info (timestamp scale 1 ms, the duration),
//! Tracks (one video track), Cues (one per cluster) and the Clusters of
//! SimpleBlocks.
//!
//! Unlike a `MediaRecorder` stream, the file carries its duration and a cue
//! for every cluster, so players know its length and can seek in it. A
//! cluster starts at each keyframe (and whenever a block's offset from its
//! cluster would pass the signed 16-bit millisecond range).
//!
//! Frames are muxed as they arrive; the header, whose sizes depend on the
//! whole take, is put in front by [`WebmMuxer::finish`]. Element sizes of the
//! masters, cue times and cue positions are written at a fixed 8 bytes, so the
//! Cues' length is known before the cluster offsets it records.

use std::fmt;

/// The codec of the frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VideoCodec {
    Vp8,
    Vp9,
}

impl VideoCodec {
    /// The Matroska codec id.
    #[must_use]
    pub fn codec_id(self) -> &'static str {
        match self {
            Self::Vp8 => "V_VP8",
            Self::Vp9 => "V_VP9",
        }
    }
}

/// Why a frame was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum WebmError {
    /// The first frame of a take must be a keyframe.
    FirstFrameNotKey,
    /// Timestamps must not go backwards (microseconds).
    TimestampBackwards { previous_us: u64, timestamp_us: u64 },
    /// A frame with no bytes.
    EmptyFrame,
}

impl fmt::Display for WebmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::FirstFrameNotKey => write!(f, "webm: the first frame is not a keyframe"),
            Self::TimestampBackwards {
                previous_us,
                timestamp_us,
            } => write!(
                f,
                "webm: frame timestamp {timestamp_us} µs is before the previous {previous_us} µs"
            ),
            Self::EmptyFrame => write!(f, "webm: an encoded frame has no bytes"),
        }
    }
}

impl std::error::Error for WebmError {}

// Element ids (RFC 8794 §11, RFC 9559 §5.1).
const EBML: u32 = 0x1A45_DFA3;
const EBML_VERSION: u32 = 0x4286;
const EBML_READ_VERSION: u32 = 0x42F7;
const EBML_MAX_ID_LENGTH: u32 = 0x42F2;
const EBML_MAX_SIZE_LENGTH: u32 = 0x42F3;
const DOC_TYPE: u32 = 0x4282;
const DOC_TYPE_VERSION: u32 = 0x4287;
const DOC_TYPE_READ_VERSION: u32 = 0x4285;
const SEGMENT: u32 = 0x1853_8067;
const INFO: u32 = 0x1549_A966;
const TIMESTAMP_SCALE: u32 = 0x2A_D7B1;
const MUXING_APP: u32 = 0x4D80;
const WRITING_APP: u32 = 0x5741;
const DURATION: u32 = 0x4489;
const TRACKS: u32 = 0x1654_AE6B;
const TRACK_ENTRY: u32 = 0xAE;
const TRACK_NUMBER: u32 = 0xD7;
const TRACK_UID: u32 = 0x73C5;
const TRACK_TYPE: u32 = 0x83;
const FLAG_LACING: u32 = 0x9C;
const CODEC_ID: u32 = 0x86;
const VIDEO: u32 = 0xE0;
const PIXEL_WIDTH: u32 = 0xB0;
const PIXEL_HEIGHT: u32 = 0xBA;
const CUES: u32 = 0x1C53_BB6B;
const CUE_POINT: u32 = 0xBB;
const CUE_TIME: u32 = 0xB3;
const CUE_TRACK_POSITIONS: u32 = 0xB7;
const CUE_TRACK: u32 = 0xF7;
const CUE_CLUSTER_POSITION: u32 = 0xF1;
const CLUSTER: u32 = 0x1F43_B675;
const CLUSTER_TIMESTAMP: u32 = 0xE7;
const SIMPLE_BLOCK: u32 = 0xA3;

/// Nanoseconds per timestamp tick: timestamps are whole milliseconds.
const TIMESTAMP_SCALE_NS: u64 = 1_000_000;
/// The one track's number.
const TRACK: u64 = 1;
/// Shown for the last frame when there is no earlier interval to copy, ms.
const DEFAULT_FRAME_MS: f64 = 1000.0 / 30.0;
/// Longest time the last frame is shown, ms.
const MAX_LAST_FRAME_MS: f64 = 100.0;
/// Bytes of one CuePoint with fixed 8-byte sizes and values (see the module doc).
const CUE_POINT_BYTES: usize = 1 + 8 + (1 + 1 + 8) + (1 + 8 + (1 + 1 + 1) + (1 + 1 + 8));

/// Writes an element id (its bytes already carry the length marker).
fn put_id(out: &mut Vec<u8>, id: u32) {
    let bytes = id.to_be_bytes();
    let skip = bytes.iter().take_while(|&&b| b == 0).count();
    out.extend_from_slice(&bytes[skip..]);
}

/// Writes `size` as the shortest EBML variable-size integer (the all-ones
/// pattern of each length means "unknown", so it is avoided).
fn put_size(out: &mut Vec<u8>, size: u64) {
    let len = (1..=8u32)
        .find(|&len| size < (1u64 << (7 * len)) - 1)
        .unwrap_or(8);
    put_size_fixed(out, size, len);
}

/// Writes `size` as an EBML variable-size integer of exactly `len` bytes.
fn put_size_fixed(out: &mut Vec<u8>, size: u64, len: u32) {
    let marked = size | (1u64 << (7 * len));
    out.extend_from_slice(&marked.to_be_bytes()[(8 - len as usize)..]);
}

/// Writes an unsigned integer element in as few bytes as it needs.
fn put_uint(out: &mut Vec<u8>, id: u32, value: u64) {
    let bytes = value.to_be_bytes();
    let skip = bytes.iter().take_while(|&&b| b == 0).count().min(7);
    put_id(out, id);
    put_size(out, (8 - skip) as u64);
    out.extend_from_slice(&bytes[skip..]);
}

/// Writes an unsigned integer element in exactly 8 bytes.
fn put_uint8(out: &mut Vec<u8>, id: u32, value: u64) {
    put_id(out, id);
    put_size(out, 8);
    out.extend_from_slice(&value.to_be_bytes());
}

fn put_text(out: &mut Vec<u8>, id: u32, text: &str) {
    put_id(out, id);
    put_size(out, text.len() as u64);
    out.extend_from_slice(text.as_bytes());
}

fn put_float(out: &mut Vec<u8>, id: u32, value: f64) {
    put_id(out, id);
    put_size(out, 8);
    out.extend_from_slice(&value.to_be_bytes());
}

/// Writes a master element around `body`, its size in 8 bytes.
fn put_master(out: &mut Vec<u8>, id: u32, body: &[u8]) {
    put_id(out, id);
    put_size_fixed(out, body.len() as u64, 8);
    out.extend_from_slice(body);
}

/// Muxes one video track of encoded frames into a WebM file.
#[derive(Debug)]
pub struct WebmMuxer {
    codec: VideoCodec,
    width_px: u32,
    height_px: u32,
    /// The Clusters, back to back, as they will follow the Cues.
    clusters: Vec<u8>,
    /// `(time ms, offset in clusters)` of every cluster.
    cues: Vec<(u64, usize)>,
    /// Start (in `clusters`) and timestamp (ms) of the cluster being filled.
    open: Option<(usize, u64)>,
    first_us: Option<u64>,
    last_us: u64,
    last_ms: u64,
    frames: u64,
}

impl WebmMuxer {
    /// A muxer for frames of `codec` at `width_px` × `height_px`.
    #[must_use]
    pub fn new(codec: VideoCodec, width_px: u32, height_px: u32) -> Self {
        Self {
            codec,
            width_px,
            height_px,
            clusters: Vec::new(),
            cues: Vec::new(),
            open: None,
            first_us: None,
            last_us: 0,
            last_ms: 0,
            frames: 0,
        }
    }

    /// Frames muxed so far.
    #[must_use]
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// Adds one encoded frame shown from `timestamp_us` (any origin: the
    /// first frame of the take is time 0).
    ///
    /// # Errors
    /// If the first frame is not a keyframe, the frame is empty or its
    /// timestamp is before the previous frame's.
    pub fn push(
        &mut self,
        timestamp_us: u64,
        keyframe: bool,
        data: &[u8],
    ) -> Result<(), WebmError> {
        if data.is_empty() {
            return Err(WebmError::EmptyFrame);
        }
        let first_us = match self.first_us {
            Some(first) => {
                if timestamp_us < self.last_us {
                    return Err(WebmError::TimestampBackwards {
                        previous_us: self.last_us,
                        timestamp_us,
                    });
                }
                first
            }
            None if !keyframe => return Err(WebmError::FirstFrameNotKey),
            None => *self.first_us.insert(timestamp_us),
        };
        let ms = (timestamp_us - first_us + 500) / 1000;
        let offset_ms = self.open.map(|(_, start_ms)| ms - start_ms);
        if keyframe || offset_ms.is_none_or(|d| d > i16::MAX as u64) {
            self.close_cluster();
            self.open = Some((self.clusters.len(), ms));
            self.cues.push((ms, self.clusters.len()));
            put_id(&mut self.clusters, CLUSTER);
            put_size_fixed(&mut self.clusters, 0, 8); // patched by close_cluster
            put_uint(&mut self.clusters, CLUSTER_TIMESTAMP, ms);
        }
        let start_ms = self.open.map_or(ms, |(_, start)| start);
        let relative = i16::try_from(ms - start_ms).unwrap_or(i16::MAX);
        put_id(&mut self.clusters, SIMPLE_BLOCK);
        put_size(&mut self.clusters, data.len() as u64 + 4);
        put_size(&mut self.clusters, TRACK);
        self.clusters.extend_from_slice(&relative.to_be_bytes());
        self.clusters.push(if keyframe { 0x80 } else { 0x00 });
        self.clusters.extend_from_slice(data);
        self.last_us = timestamp_us;
        self.last_ms = ms;
        self.frames += 1;
        Ok(())
    }

    /// Writes the size of the open cluster.
    fn close_cluster(&mut self) {
        if let Some((start, _)) = self.open.take() {
            let body = (self.clusters.len() - start - 4 - 8) as u64;
            let mut size = Vec::with_capacity(8);
            put_size_fixed(&mut size, body, 8);
            self.clusters[start + 4..start + 12].copy_from_slice(&size);
        }
    }

    /// The take's duration, ms: the last frame's time plus the mean frame
    /// interval (at most 100 ms) for the last frame to be seen.
    #[must_use]
    pub fn duration_ms(&self) -> f64 {
        if self.frames == 0 {
            return 0.0;
        }
        let last = self.last_ms as f64;
        let shown = if self.frames >= 2 {
            (last / (self.frames - 1) as f64).clamp(1.0, MAX_LAST_FRAME_MS)
        } else {
            DEFAULT_FRAME_MS
        };
        last + shown
    }

    /// The finished file.
    #[must_use]
    pub fn finish(mut self, writing_app: &str) -> Vec<u8> {
        self.close_cluster();
        let mut info = Vec::new();
        put_uint(&mut info, TIMESTAMP_SCALE, TIMESTAMP_SCALE_NS);
        put_text(&mut info, MUXING_APP, "gaitlab webm");
        put_text(&mut info, WRITING_APP, writing_app);
        put_float(&mut info, DURATION, self.duration_ms());

        let mut video = Vec::new();
        put_uint(&mut video, PIXEL_WIDTH, u64::from(self.width_px));
        put_uint(&mut video, PIXEL_HEIGHT, u64::from(self.height_px));
        let mut entry = Vec::new();
        put_uint(&mut entry, TRACK_NUMBER, TRACK);
        put_uint(&mut entry, TRACK_UID, TRACK);
        put_uint(&mut entry, TRACK_TYPE, 1);
        put_uint(&mut entry, FLAG_LACING, 0);
        put_text(&mut entry, CODEC_ID, self.codec.codec_id());
        put_master(&mut entry, VIDEO, &video);
        let mut tracks = Vec::new();
        put_master(&mut tracks, TRACK_ENTRY, &entry);

        let mut segment = Vec::new();
        put_master(&mut segment, INFO, &info);
        put_master(&mut segment, TRACKS, &tracks);
        let cues_bytes = 4 + 8 + self.cues.len() * CUE_POINT_BYTES;
        let clusters_at = segment.len() + cues_bytes;
        let mut cues = Vec::with_capacity(cues_bytes);
        for &(ms, offset) in &self.cues {
            let mut positions = Vec::new();
            put_uint(&mut positions, CUE_TRACK, TRACK);
            put_uint8(
                &mut positions,
                CUE_CLUSTER_POSITION,
                (clusters_at + offset) as u64,
            );
            let mut point = Vec::new();
            put_uint8(&mut point, CUE_TIME, ms);
            put_master(&mut point, CUE_TRACK_POSITIONS, &positions);
            put_master(&mut cues, CUE_POINT, &point);
        }
        put_master(&mut segment, CUES, &cues);
        debug_assert_eq!(segment.len(), clusters_at);

        let mut header = Vec::new();
        put_uint(&mut header, EBML_VERSION, 1);
        put_uint(&mut header, EBML_READ_VERSION, 1);
        put_uint(&mut header, EBML_MAX_ID_LENGTH, 4);
        put_uint(&mut header, EBML_MAX_SIZE_LENGTH, 8);
        put_text(&mut header, DOC_TYPE, "webm");
        put_uint(&mut header, DOC_TYPE_VERSION, 4);
        put_uint(&mut header, DOC_TYPE_READ_VERSION, 2);
        let mut out = Vec::with_capacity(header.len() + segment.len() + self.clusters.len() + 32);
        put_master(&mut out, EBML, &header);
        put_id(&mut out, SEGMENT);
        put_size_fixed(&mut out, (segment.len() + self.clusters.len()) as u64, 8);
        out.extend_from_slice(&segment);
        out.extend_from_slice(&self.clusters);
        out
    }
}
