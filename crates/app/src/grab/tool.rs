//! The hand in the 3-D view: hover, press, drag and release on the panes'
//! targets and effectors, as a [`ViewTool`] that takes the gesture before
//! the camera does.

use egui::{Color32, Rect, Stroke};

use super::hand::{Grab, GrabEvent, HandHold, SETTLE_FRAMES};
use super::pick::{nearest, on_drag_plane};
use crate::render::Camera;
use crate::render::viewport::{ViewTool, screen_point};

/// The highlight ring's colour (the view's selection yellow).
const HIGHLIGHT: Color32 = Color32::from_rgb(250, 204, 21);

impl Grab {
    /// The pane holding `at`, and its index.
    fn pane_at(panes: &[Rect], at: egui::Pos2) -> Option<(usize, Rect)> {
        panes
            .iter()
            .enumerate()
            .find(|(_, r)| r.contains(at))
            .map(|(k, r)| (k, *r))
    }
}

impl ViewTool for Grab {
    fn update(&mut self, response: &egui::Response, panes: &[Rect], camera: &Camera) -> bool {
        let (origin, latest, shift, touches) = response.ctx.input(|i| {
            (
                i.pointer.press_origin(),
                i.pointer.latest_pos(),
                i.modifiers.shift,
                i.multi_touch().is_some(),
            )
        });
        let points = |k: usize| self.panes.get(k).map_or(&[][..], |p| &p[..]);
        self.hover = None;
        if self.held.is_none()
            && let Some(pointer) = response.hover_pos()
            && let Some((k, rect)) = Self::pane_at(panes, pointer)
        {
            self.hover = nearest(camera, rect, points(k), pointer).map(|(p, _)| (k, p));
        }
        if self.held.is_none()
            && response.drag_started_by(egui::PointerButton::Primary)
            && !shift
            && !touches
            && let Some(from) = origin
            && let Some((k, rect)) = Self::pane_at(panes, from)
            && let Some((picked, _)) = nearest(camera, rect, points(k), from)
        {
            // Keep the pick's offset from the pointer, so the point does not jump to it.
            let under = on_drag_plane(camera, rect, from, picked.at).unwrap_or(picked.at);
            self.held = Some(HandHold {
                effector: picked.effector,
                pane: k,
                through: picked.at,
            });
            self.offset = picked.at - under;
        }
        let Some(held) = self.held else {
            return false;
        };
        if response.dragged() && !touches {
            if let (Some(pointer), Some(rect)) = (latest, panes.get(held.pane))
                && let Some(at) = on_drag_plane(camera, *rect, pointer, held.through)
            {
                self.events.push(GrabEvent::Hold {
                    effector: held.effector,
                    at: at + self.offset,
                });
                self.settle_frames = SETTLE_FRAMES;
            }
            response.ctx.set_cursor_icon(egui::CursorIcon::Grabbing);
            return true;
        }
        self.held = None;
        if self.pin_on_release {
            self.events.push(GrabEvent::Pin {
                effector: held.effector,
                on: true,
            });
        }
        self.events.push(GrabEvent::Release {
            effector: held.effector,
        });
        self.settle_frames = SETTLE_FRAMES;
        true
    }

    fn paint(&self, painter: &egui::Painter, panes: &[Rect], camera: &Camera) {
        let ring = |k: usize, effector: usize, width: f32| {
            let (Some(rect), Some(points)) = (panes.get(k), self.panes.get(k)) else {
                return;
            };
            for p in points.iter().filter(|p| p.effector == effector) {
                if let Some(at) = screen_point(camera, *rect, p.at.as_vec3()) {
                    painter.with_clip_rect(*rect).circle_stroke(
                        at,
                        12.0,
                        Stroke::new(width, HIGHLIGHT),
                    );
                }
            }
        };
        if let Some(held) = self.held {
            for k in 0..panes.len() {
                ring(k, held.effector, 3.0);
            }
        } else if let Some((k, p)) = self.hover {
            ring(k, p.effector, 2.0);
            painter.ctx().set_cursor_icon(egui::CursorIcon::Grab);
        }
    }
}
