//! The lab's outbox: effects the front end carries out for the lab (hand a file
//! to the person, open the file picker, update the address bar, start or stop
//! the video recorder). The lab queues them; the web glue drains them once a
//! frame ([`crate::Lab::drain_effects`]) instead of polling flags.

/// A file for the person: name, MIME type and contents.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Download {
    /// Suggested file name.
    pub file_name: String,
    /// MIME type.
    pub mime: &'static str,
    /// Contents.
    pub text: String,
}

/// Something the front end should do.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Effect {
    /// Hand this file to the person (web: a download).
    Download(Download),
    /// Open the preset file picker.
    PickFile,
    /// The state a link shows changed: replace the address bar's URL.
    LinkChanged,
    /// The preset changed: push a history entry (so Back returns to the
    /// previous preset), then the URL as for [`Effect::LinkChanged`].
    PresetChanged,
    /// Start recording video of the 3-D view.
    StartVideo,
    /// Stop the video recording and hand the file to the person.
    StopVideo,
}

/// Effects queued since the front end last drained them, oldest first.
///
/// Address-bar and picker requests are kept once however often they are
/// queued; a video start and stop queued without a drain between them cancel
/// out. Natively nothing drains: only downloads accumulate, and
/// [`Outbox::take_download`] takes them.
#[derive(Debug, Default)]
pub struct Outbox {
    effects: Vec<Effect>,
}

impl Outbox {
    /// Queues `effect`.
    pub fn push(&mut self, effect: Effect) {
        let opposite = match effect {
            Effect::StartVideo => Some(Effect::StopVideo),
            Effect::StopVideo => Some(Effect::StartVideo),
            _ => None,
        };
        if let Some(opposite) = opposite
            && let Some(i) = self.effects.iter().position(|e| *e == opposite)
        {
            self.effects.remove(i);
            return;
        }
        if !matches!(effect, Effect::Download(_)) && self.effects.contains(&effect) {
            return;
        }
        self.effects.push(effect);
    }

    /// Takes every queued effect, oldest first (an empty outbox allocates nothing).
    pub fn drain(&mut self) -> Vec<Effect> {
        std::mem::take(&mut self.effects)
    }

    /// Takes the oldest queued download, if any.
    pub fn take_download(&mut self) -> Option<Download> {
        let i = self
            .effects
            .iter()
            .position(|e| matches!(e, Effect::Download(_)))?;
        match self.effects.remove(i) {
            Effect::Download(download) => Some(download),
            _ => None,
        }
    }

    /// Forgets address-bar updates (the address bar already shows the state,
    /// as after opening a link).
    pub fn forget_link_changes(&mut self) {
        self.effects
            .retain(|e| !matches!(e, Effect::LinkChanged | Effect::PresetChanged));
    }

    /// Whether `effect` is queued.
    #[must_use]
    pub fn contains(&self, effect: &Effect) -> bool {
        self.effects.contains(effect)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn download(name: &str) -> Effect {
        Effect::Download(Download {
            file_name: name.to_owned(),
            mime: "text/plain",
            text: String::new(),
        })
    }

    #[test]
    fn repeated_requests_are_kept_once_and_downloads_in_order() {
        let mut outbox = Outbox::default();
        outbox.push(Effect::LinkChanged);
        outbox.push(download("a"));
        outbox.push(Effect::LinkChanged);
        outbox.push(Effect::PickFile);
        outbox.push(Effect::PickFile);
        outbox.push(download("b"));
        assert_eq!(
            outbox.take_download().map(|d| d.file_name).as_deref(),
            Some("a")
        );
        assert_eq!(
            outbox.drain(),
            vec![Effect::LinkChanged, Effect::PickFile, download("b")]
        );
        assert!(outbox.drain().is_empty());
    }

    #[test]
    fn a_video_start_and_stop_without_a_drain_cancel_out() {
        let mut outbox = Outbox::default();
        outbox.push(Effect::StartVideo);
        outbox.push(Effect::StopVideo);
        assert!(outbox.drain().is_empty());
        outbox.push(Effect::StartVideo);
        outbox.push(Effect::LinkChanged);
        outbox.push(Effect::PresetChanged);
        outbox.forget_link_changes();
        assert_eq!(outbox.drain(), vec![Effect::StartVideo]);
    }
}
