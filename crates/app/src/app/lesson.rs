//! The app's side of a teacher's lesson ([`crate::lesson`]): setting and
//! leaving it, which panels and plots it leaves on screen.

use super::App;
use crate::lab::Effect;
use crate::lesson::Lesson;

impl App {
    /// Sets the lesson (`None` leaves it); a lesson with a note opens the
    /// note. `panels` are the control panels' titles it may hide.
    ///
    /// # Errors
    /// `lesson.…: reason` ([`Lesson::check`]); nothing changes then.
    pub fn set_lesson(&mut self, lesson: Option<Lesson>, panels: &[&str]) -> Result<(), String> {
        if let Some(lesson) = &lesson {
            lesson.check(panels)?;
        }
        if self.session.lesson == lesson {
            return Ok(());
        }
        self.layout.lesson_note_open = lesson.as_ref().is_some_and(|l| !l.note.trim().is_empty());
        if lesson.as_ref().is_some_and(|l| l.opens("Jacobian")) {
            self.jacobian.open_request = Some(true);
        }
        self.session.lesson = lesson;
        self.outbox.push(Effect::LinkChanged);
        Ok(())
    }

    /// The lesson, if one runs.
    #[must_use]
    pub fn lesson(&self) -> Option<&Lesson> {
        self.session.lesson.as_ref()
    }

    /// Whether the lesson hides the control panel titled `title`.
    #[must_use]
    pub fn lesson_hides(&self, title: &str) -> bool {
        self.lesson().is_some_and(|l| l.hides(title))
    }

    /// Whether the lesson pins any plot (the plot area then always shows).
    #[must_use]
    pub fn lesson_pins_plots(&self) -> bool {
        self.lesson().is_some_and(|l| !l.pin_plots.is_empty())
    }
}
