//! The 3-D view as an egui widget: takes the remaining space, turns mouse and
//! touch gestures into camera moves, frames the figure for the view's shape,
//! keeps a walking or running figure in view (follow mode), and draws the
//! scene — with wgpu through a paint callback when the renderer is installed
//! ([`super::gpu::install`]), otherwise as a painter's-algorithm 2-D
//! projection with egui shapes (tests, software fallbacks).

use egui::{Color32, Pos2, Rect, Shape, Stroke};
use glam::{Mat4, Vec3, Vec4};

use super::camera::Camera;
use super::gpu::{self, SceneCallback, ViewStyle};
use super::push_drag::PushDrag;
use super::scene::{GROUND_Y, Scene, SceneFrame};
use crate::view::ViewOptions;

/// Follow mode keeps asking for frames until the camera is this close to its goal, metres.
const FOLLOW_SETTLED: f32 = 0.005;

/// Shows `scene` through `camera` in all the space left in `ui`.
///
/// Gestures: drag to orbit; right / middle drag, shift + drag or two fingers
/// to pan; wheel, ctrl + wheel or pinch to zoom; double click to frame the
/// figure again, paused or running. The camera frames the figure's whole box
/// for the view's aspect ratio the first time it sees one (and whenever
/// `camera.framed` is cleared, as a new preset does), takes
/// `view.perspective`, and follows the figure's centre when `view.follow` is on.
pub fn show(
    ui: &mut egui::Ui,
    scene: &Scene,
    camera: &mut Camera,
    view: &ViewOptions,
) -> egui::Response {
    let (rect, response) = allocate(ui);
    steer(ui, &response, aspect(rect), scene, camera, view, true);
    draw(ui, rect, response.id.value(), scene, camera, view);
    response
}

/// [`show`] with the physics creature's trunk at `trunk` (world metres, and
/// whether it can be pushed sideways) to grab and push ([`PushDrag`]): a
/// drag that starts on it pushes instead of turning the camera. Returns the
/// view and the push a released drag asks for, world `[x, z]` m/s.
pub fn show_pushable(
    ui: &mut egui::Ui,
    scene: &Scene,
    camera: &mut Camera,
    view: &ViewOptions,
    grab: &mut PushDrag,
    trunk: Option<(Vec3, bool)>,
) -> (egui::Response, Option<[f64; 2]>) {
    let (rect, response) = allocate(ui);
    let sideways = trunk.is_some_and(|(_, sideways)| sideways);
    let on_screen = trunk.and_then(|(p, _)| screen_point(camera, rect, p));
    let pushed = grab.update(&response, on_screen, camera, sideways);
    let held = grab.is_held() || pushed.is_some();
    steer(ui, &response, aspect(rect), scene, camera, view, !held);
    draw(ui, rect, response.id.value(), scene, camera, view);
    if grab.is_held() {
        let pointer = ui.input(|i| i.pointer.latest_pos());
        let color = color32(super::physics_overlay::PUSH_COLOR);
        grab.paint(
            &ui.painter().with_clip_rect(rect),
            pointer,
            camera,
            sideways,
            color,
        );
        ui.ctx().set_cursor_icon(egui::CursorIcon::Grabbing);
    } else if on_screen.is_some_and(|at| {
        response
            .hover_pos()
            .is_some_and(|p| p.distance(at) <= super::push_drag::GRAB_RADIUS_PT)
    }) {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Grab);
    }
    (response, pushed)
}

/// Where the world point `p` (metres) is on screen in a view `rect` seen
/// through `camera`; `None` behind the near plane.
#[must_use]
pub fn screen_point(camera: &Camera, rect: Rect, p: Vec3) -> Option<Pos2> {
    Projector::new(rect, camera).point(p).map(|(at, _)| at)
}

/// A tool that can take a pointer gesture in the 3-D view before the camera
/// does (the IK engine's grab and pull).
pub trait ViewTool {
    /// Reads this frame's pointer on `response` over the view's `panes`
    /// (their rectangles, in order); returns whether the tool holds the
    /// gesture, so the camera stays still.
    fn update(&mut self, response: &egui::Response, panes: &[Rect], camera: &Camera) -> bool;

    /// Draws the tool's marks over `panes`.
    fn paint(&self, painter: &egui::Painter, panes: &[Rect], camera: &Camera);
}

/// [`show`] with a [`ViewTool`] that may take a drag before the camera.
pub fn show_with_tool(
    ui: &mut egui::Ui,
    scene: &Scene,
    camera: &mut Camera,
    view: &ViewOptions,
    tool: &mut dyn ViewTool,
) -> egui::Response {
    let (rect, response) = allocate(ui);
    let held = tool.update(&response, &[rect], camera);
    steer(ui, &response, aspect(rect), scene, camera, view, !held);
    draw(ui, rect, response.id.value(), scene, camera, view);
    tool.paint(ui.painter(), &[rect], camera);
    response
}

/// Shows several scenes through one shared camera, side by side: 2 panes split
/// the space left and right, 4 make a 2 × 2 grid (any other count makes
/// columns). Each pane is labelled with its text, after a swatch of its
/// colour, in the top-left corner. Gestures anywhere move the shared camera;
/// framing and follow use the first scene.
pub fn show_split(
    ui: &mut egui::Ui,
    panes: &[(&Scene, &str, Color32)],
    camera: &mut Camera,
    view: &ViewOptions,
    tool: &mut dyn ViewTool,
) -> egui::Response {
    let (rect, response) = allocate(ui);
    let rects = split_rects(rect, panes.len());
    let held = tool.update(&response, &rects, camera);
    if let (Some((first, _, _)), Some(pane)) = (panes.first(), rects.first()) {
        steer(ui, &response, aspect(*pane), first, camera, view, !held);
    }
    for (i, ((scene, label, colour), pane)) in panes.iter().zip(&rects).enumerate() {
        draw(ui, *pane, response.id.with(i).value(), scene, camera, view);
        legend(ui, *pane, &[(*colour, label)]);
    }
    tool.paint(ui.painter(), &rects, camera);
    response
}

/// Shows one scene holding several figures (the comparison's overlay) with a
/// key in the top-left corner: each figure's colour and name.
pub fn show_overlay(
    ui: &mut egui::Ui,
    scene: &Scene,
    key: &[(Color32, &str)],
    camera: &mut Camera,
    view: &ViewOptions,
    tool: &mut dyn ViewTool,
) -> egui::Response {
    let response = show_with_tool(ui, scene, camera, view, tool);
    legend(ui, response.rect, key);
    response
}

/// Rows of a colour swatch and a text on a backdrop, from the top-left corner of `rect`.
fn legend(ui: &egui::Ui, rect: Rect, rows: &[(Color32, &str)]) {
    let text_color = ui.visuals().strong_text_color();
    let backdrop = ui.visuals().extreme_bg_color.gamma_multiply(0.8);
    let painter = ui.painter().with_clip_rect(rect);
    let swatch = 12.0;
    let mut at = rect.left_top() + egui::vec2(6.0, 4.0);
    for (colour, text) in rows {
        let galley = painter.layout_no_wrap(
            (*text).to_owned(),
            egui::FontId::proportional(14.0),
            text_color,
        );
        let size = egui::vec2(swatch + 6.0 + galley.size().x, galley.size().y.max(swatch));
        painter.rect_filled(Rect::from_min_size(at, size).expand(3.0), 3.0, backdrop);
        let square = Rect::from_center_size(
            at + egui::vec2(swatch * 0.5, size.y * 0.5),
            egui::vec2(swatch, swatch),
        );
        painter.rect_filled(square, 2.0, *colour);
        painter.galley(at + egui::vec2(swatch + 6.0, 0.0), galley, text_color);
        at.y += size.y + 8.0;
    }
}

/// The panes of [`show_split`]: `count` rectangles tiling `rect` with a 2-point gap.
#[must_use]
pub fn split_rects(rect: Rect, count: usize) -> Vec<Rect> {
    let gap = 2.0;
    let (columns, rows) = match count {
        0 | 1 => (1, 1),
        4 => (2, 2),
        n => (n, 1),
    };
    let width = (rect.width() - gap * (columns - 1) as f32) / columns as f32;
    let height = (rect.height() - gap * (rows - 1) as f32) / rows as f32;
    (0..count.max(1))
        .map(|i| {
            let (c, r) = (i % columns, i / columns);
            Rect::from_min_size(
                rect.min + egui::vec2(c as f32 * (width + gap), r as f32 * (height + gap)),
                egui::vec2(width.max(1.0), height.max(1.0)),
            )
        })
        .collect()
}

/// All the space left in `ui` (a sensible size where that is unbounded).
fn allocate(ui: &mut egui::Ui) -> (Rect, egui::Response) {
    let available = ui.available_size();
    let size = egui::vec2(
        if available.x.is_finite() {
            available.x
        } else {
            640.0
        },
        if available.y.is_finite() {
            available.y
        } else {
            400.0
        },
    )
    .max(egui::vec2(1.0, 1.0));
    ui.allocate_exact_size(size, egui::Sense::click_and_drag())
}

/// Width / height of `rect`.
fn aspect(rect: Rect) -> f32 {
    rect.width() / rect.height().max(1.0)
}

/// Gestures (when `gestures`: not while a drag pushes the trunk), framing
/// (first sight, double click, new preset: for a view of width / height
/// `aspect`) and follow mode for the camera.
fn steer(
    ui: &egui::Ui,
    response: &egui::Response,
    aspect: f32,
    scene: &Scene,
    camera: &mut Camera,
    view: &ViewOptions,
    gestures: bool,
) {
    camera.perspective = view.perspective;
    if gestures && camera.handle_input(response) {
        ui.ctx().request_repaint();
    }
    if let Some(bounds) = scene.bounds() {
        camera.keep_outside(&bounds);
    }
    if gestures && response.dragged() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Grabbing);
    }
    if !camera.framed
        && let Some(bounds) = scene.bounds()
    {
        camera.frame_for(&bounds, aspect);
        let centre = bounds.centre();
        camera.ground_m = scene.ground_height_m(centre.x, centre.z) as f32;
        ui.ctx().request_repaint();
    }
    if view.follow
        && let Some(centre) = scene.centre()
    {
        let ground_m = scene.ground_height_m(centre.x, centre.z) as f32;
        let centre = centre.as_vec3();
        let dt = ui.input(|i| i.stable_dt).clamp(0.0, 0.1);
        camera.follow(centre, dt);
        camera.follow_ground(ground_m, dt);
        if (ground_m - camera.ground_m).abs() > FOLLOW_SETTLED {
            ui.ctx().request_repaint();
        }
        if let Some(bounds) = scene.bounds()
            && camera.keep_in_view(&bounds, aspect)
        {
            ui.ctx().request_repaint();
        }
        let gap = (centre + camera.follow_offset - camera.target) * Vec3::new(1.0, 0.0, 1.0);
        if gap.length() > FOLLOW_SETTLED || camera.follow_velocity.length() > FOLLOW_SETTLED {
            ui.ctx().request_repaint();
        }
    }
}

/// Draws `scene` into `rect` (wgpu when installed, else egui shapes); `id`
/// keys the view's GPU targets.
fn draw(ui: &egui::Ui, rect: Rect, id: u64, scene: &Scene, camera: &Camera, view: &ViewOptions) {
    if !ui.is_rect_visible(rect) {
        return;
    }
    let style = ViewStyle::from_visuals(ui.visuals());
    if gpu::is_installed(ui.ctx()) {
        let callback = SceneCallback::new(
            id,
            ui.ctx().cumulative_frame_nr(),
            rect,
            *camera,
            std::sync::Arc::clone(scene.frame()),
            view,
            style,
        );
        ui.painter()
            .add(egui_wgpu::Callback::new_paint_callback(rect, callback));
    } else {
        let mut shapes = Vec::new();
        fallback_shapes(rect, scene.frame(), camera, view, &style, &mut shapes);
        ui.painter().with_clip_rect(rect).extend(shapes);
    }
}

/// A scene colour (sRGB and alpha, 0–1) as egui's.
pub(crate) fn color32(c: [f32; 4]) -> Color32 {
    let byte = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
    Color32::from_rgba_unmultiplied(byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3]))
}

/// World → screen for one view.
struct Projector {
    view_proj: Mat4,
    rect: Rect,
    /// Projection's y scale (`1 / tan(fov/2)`, or `1 / half height` orthographic).
    y_scale: f32,
}

impl Projector {
    fn new(rect: Rect, camera: &Camera) -> Self {
        let aspect = rect.width() / rect.height().max(1.0);
        Self {
            view_proj: camera.view_projection(aspect),
            rect,
            y_scale: camera.projection(aspect).y_axis.y,
        }
    }

    fn clip(&self, p: Vec3) -> Vec4 {
        self.view_proj * p.extend(1.0)
    }

    fn to_screen(&self, clip: Vec4) -> Pos2 {
        let ndc = clip.truncate() / clip.w;
        let centre = self.rect.center();
        Pos2::new(
            centre.x + ndc.x * 0.5 * self.rect.width(),
            centre.y - ndc.y * 0.5 * self.rect.height(),
        )
    }

    /// Screen position and depth (clip w) of `p`, if in front of the near plane.
    fn point(&self, p: Vec3) -> Option<(Pos2, f32)> {
        let clip = self.clip(p);
        (clip.z >= 0.0 && clip.w > 0.0).then(|| (self.to_screen(clip), clip.w))
    }

    /// The segment a–b clipped to the near plane, on screen.
    fn segment(&self, a: Vec3, b: Vec3) -> Option<[Pos2; 2]> {
        let (mut ca, mut cb) = (self.clip(a), self.clip(b));
        if ca.z < 0.0 && cb.z < 0.0 {
            return None;
        }
        if ca.z < 0.0 {
            ca = ca.lerp(cb, ca.z / (ca.z - cb.z));
        } else if cb.z < 0.0 {
            cb = cb.lerp(ca, cb.z / (cb.z - ca.z));
        }
        (ca.w > 0.0 && cb.w > 0.0).then(|| [self.to_screen(ca), self.to_screen(cb)])
    }

    /// On-screen size, points, of `radius` metres at depth `w`.
    fn radius(&self, radius: f32, w: f32) -> f32 {
        radius * self.y_scale / w * 0.5 * self.rect.height()
    }
}

/// The figure's box on screen, `[x, y, width, height]` in the units of
/// `rect` (a view rectangle `[x, y, width, height]`, e.g. physical pixels):
/// the smallest rectangle holding every bone and sphere of `scene` (each with
/// its radius) seen through `camera`. `None` without a figure, or when part of
/// it is behind the near plane (then it is not wholly in view).
#[must_use]
pub fn figure_box(scene: &Scene, camera: &Camera, rect: [f32; 4]) -> Option<[f32; 4]> {
    let [x, y, width, height] = rect;
    if width.is_nan() || height.is_nan() || width < 1.0 || height < 1.0 {
        return None;
    }
    let projector = Projector::new(
        Rect::from_min_size(Pos2::new(x, y), egui::vec2(width, height)),
        camera,
    );
    let balls = scene
        .capsules()
        .iter()
        .flat_map(|c| [(c.a, c.radius), (c.b, c.radius)])
        .chain(scene.spheres().iter().map(|s| (s.centre, s.radius)));
    let mut out: Option<Rect> = None;
    for (centre, radius) in balls {
        let (at, w) = projector.point(Vec3::from_array(centre))?;
        let r = projector.radius(radius, w);
        let ball = Rect::from_center_size(at, egui::vec2(2.0 * r, 2.0 * r));
        out = Some(out.map_or(ball, |b| b.union(ball)));
    }
    out.map(|b| [b.min.x, b.min.y, b.width(), b.height()])
}

/// The scene as egui shapes: background, ground grid, bones and spheres sorted
/// far to near, then segments. Used when wgpu is not available; allocates
/// (this is not the hot path).
pub fn fallback_shapes(
    rect: Rect,
    frame: &SceneFrame,
    camera: &Camera,
    view: &ViewOptions,
    style: &ViewStyle,
    shapes: &mut Vec<Shape>,
) {
    shapes.push(Shape::rect_filled(rect, 0.0, color32(style.background)));
    if rect.width() < 1.0 || rect.height() < 1.0 {
        return;
    }
    let projector = Projector::new(rect, camera);

    if view.grid {
        let stroke = Stroke::new(1.0, color32(style.grid));
        let (cx, cz) = (camera.target.x.round(), camera.target.z.round());
        let reach = 10.0;
        for k in -10..=10 {
            let k = k as f32;
            let lines = [
                (
                    Vec3::new(cx + k, GROUND_Y, cz - reach),
                    Vec3::new(cx + k, GROUND_Y, cz + reach),
                ),
                (
                    Vec3::new(cx - reach, GROUND_Y, cz + k),
                    Vec3::new(cx + reach, GROUND_Y, cz + k),
                ),
            ];
            for (a, b) in lines {
                if let Some(points) = projector.segment(a, b) {
                    shapes.push(Shape::line_segment(points, stroke));
                }
            }
        }
    }

    // Solids, painter's algorithm: farthest first.
    let mut solids: Vec<(f32, Shape)> =
        Vec::with_capacity(frame.capsules.len() + frame.spheres.len());
    for capsule in &frame.capsules {
        let (a, b) = (Vec3::from_array(capsule.a), Vec3::from_array(capsule.b));
        let (Some((pa, wa)), Some((pb, wb))) = (projector.point(a), projector.point(b)) else {
            continue;
        };
        let width = 2.0 * projector.radius(capsule.radius, 0.5 * (wa + wb));
        let color = color32(capsule.color);
        let shape = Shape::Vec(vec![
            Shape::line_segment([pa, pb], Stroke::new(width, color)),
            Shape::circle_filled(pa, 0.5 * width, color),
            Shape::circle_filled(pb, 0.5 * width, color),
        ]);
        solids.push((0.5 * (wa + wb), shape));
    }
    for sphere in &frame.spheres {
        let Some((p, w)) = projector.point(Vec3::from_array(sphere.centre)) else {
            continue;
        };
        let radius = projector.radius(sphere.radius, w);
        // Spheres sit on bone ends: nudge them in front of their bones.
        solids.push((
            w - sphere.radius,
            Shape::circle_filled(p, radius, color32(sphere.color)),
        ));
    }
    solids.sort_by(|a, b| b.0.total_cmp(&a.0));
    shapes.extend(solids.into_iter().map(|(_, shape)| shape));

    for segment in &frame.segments {
        let (a, b) = (Vec3::from_array(segment.a), Vec3::from_array(segment.b));
        if let Some(points) = projector.segment(a, b) {
            shapes.push(Shape::line_segment(
                points,
                Stroke::new(segment.width, color32(segment.color)),
            ));
        }
    }
}
