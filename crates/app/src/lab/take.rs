//! The lab's motion take: recording each simulated frame into the engine
//! layer's [`Take`] (pose, effectors, targets) and saving it, or its last
//! seconds, as BVH or CSV (She 2006 §6.2's recording panel).

use gaitlab_core::driver::Driver;
use gaitlab_engine::{AnyDriver, Take};

use super::outbox::Download;

/// The take being recorded or last recorded.
#[derive(Default)]
pub struct TakeRecorder {
    /// The take, once a recording started.
    take: Option<Take>,
    /// Whether simulated frames are being appended to `take`.
    recording: bool,
}

impl TakeRecorder {
    /// Starts a new take of `driver`'s skeleton (the one drawn: a physics
    /// creature's is scaled by L) at `fps` frames per second; the previous one
    /// is dropped.
    pub fn start(&mut self, driver: &AnyDriver, fps: f64) {
        self.take = Some(Take::new(
            driver.skeleton(),
            fps,
            driver.targets().is_some(),
        ));
        self.recording = true;
    }

    /// Stops appending (the take stays available to save).
    pub fn stop(&mut self) {
        self.recording = false;
    }

    /// Drops the take (it belongs to a skeleton that is gone).
    pub fn clear(&mut self) {
        self.take = None;
        self.recording = false;
    }

    /// Whether frames are being appended.
    #[must_use]
    pub fn recording(&self) -> bool {
        self.recording
    }

    /// The current or last take.
    #[must_use]
    pub fn take(&self) -> Option<&Take> {
        self.take.as_ref()
    }

    /// Appends `driver`'s current frame when recording; a full take stops the
    /// recording and returns the message to show.
    pub fn record(&mut self, driver: &AnyDriver) -> Option<String> {
        if !self.recording {
            return None;
        }
        let Some(take) = self.take.as_mut() else {
            self.recording = false;
            return None;
        };
        let targets = driver.targets().map(|t| &t.position[..]).unwrap_or(&[]);
        let pushed = take.push(
            driver.time(),
            driver.pose(),
            driver.effector_positions(),
            targets,
        );
        if pushed {
            return None;
        }
        self.recording = false;
        take.is_full().then(|| {
            format!(
                "recording: stopped at the {:.0} s limit",
                gaitlab_engine::MAX_TAKE_S
            )
        })
    }

    /// The take as a `bvh` or `csv` file named `gaitlab-{stem}.{format}`: its
    /// last `last_s` seconds, or the whole take for `None`.
    ///
    /// # Errors
    /// An unknown format, no take, a bad `last_s`, or the writer's reason.
    pub fn save(
        &self,
        driver: &AnyDriver,
        format: &str,
        last_s: Option<f64>,
        stem: &str,
    ) -> Result<Download, String> {
        let take = self
            .take
            .as_ref()
            .ok_or("save: nothing recorded yet (start a recording first)")?;
        let skeleton = driver.skeleton();
        let (text, mime) = match format {
            "bvh" => (take.to_bvh(skeleton, last_s)?, "text/plain"),
            "csv" => (take.to_csv(skeleton, last_s)?, "text/csv"),
            other => return Err(format!("save: unknown format {other:?} (bvh, csv)")),
        };
        Ok(Download {
            file_name: format!("gaitlab-{stem}.{format}"),
            mime,
            text,
        })
    }
}
