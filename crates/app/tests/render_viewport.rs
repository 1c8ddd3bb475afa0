//! The 3-D view widget through egui_kittest (no wgpu: the 2-D painter
//! fallback): it frames the figure on first sight, drags orbit and pan the
//! camera, the wheel zooms, a double click frames again, and the fallback
//! projection puts primitives where the camera says.

use egui_kittest::Harness;
use gaitlab_app::render::camera::{ORBIT_RADIANS_PER_POINT, gestures};
use gaitlab_app::render::gpu::ViewStyle;
use gaitlab_app::render::scene::{Capsule, Segment, Sphere};
use gaitlab_app::render::viewport::{self, fallback_shapes};
use gaitlab_app::render::{Camera, Scene, SceneFrame};
use gaitlab_app::view::ViewOptions;
use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use glam::{DVec3, Vec3};

struct State {
    scene: Scene,
    camera: Camera,
    view: ViewOptions,
    /// Gestures seen by the last frame's response (to check what egui reported).
    dragged: bool,
}

/// A two-legged figure standing on the ground at the origin.
fn figure() -> Scene {
    let joints = vec![
        Joint::revolute("pelvis", None, DVec3::ZERO, DVec3::X),
        Joint::revolute("left_hip", Some(0), DVec3::new(0.1, 0.0, 0.0), DVec3::X),
        Joint::revolute("right_hip", Some(0), DVec3::new(-0.1, 0.0, 0.0), DVec3::X),
        Joint::revolute("chest", Some(0), DVec3::new(0.0, 0.5, 0.0), DVec3::X),
    ];
    let foot = |name: &str, joint| Effector {
        name: name.to_owned(),
        joint,
        offset: DVec3::new(0.0, -0.9, 0.0),
        orientation: false,
    };
    let skeleton = Skeleton::new(joints, vec![foot("left_foot", 1), foot("right_foot", 2)])
        .expect("valid skeleton");
    let root = DVec3::new(0.0, 0.9, 0.0);
    let pose = Pose {
        root: RootTransform {
            position: root,
            ..RootTransform::default()
        },
        joints: vec![0.0; 4],
    };
    let kin = Kinematics::of(&skeleton, &pose);
    let mut scene = Scene::new();
    scene.fill(&skeleton, &kin, root, None, &ViewOptions::default());
    scene
}

fn harness() -> Harness<'static, State> {
    let state = State {
        scene: figure(),
        camera: Camera::default(),
        view: ViewOptions::default(),
        dragged: false,
    };
    Harness::builder()
        .with_size(egui::vec2(600.0, 400.0))
        .build_ui_state(
            |ui, state: &mut State| {
                let response = viewport::show(ui, &state.scene, &mut state.camera, &state.view);
                state.dragged |= response.dragged();
            },
            state,
        )
}

fn drag(
    harness: &mut Harness<'static, State>,
    button: egui::PointerButton,
    from: egui::Pos2,
    by: egui::Vec2,
) {
    harness.event(egui::Event::PointerMoved(from));
    harness.event(egui::Event::PointerButton {
        pos: from,
        button,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    for i in 1..=10 {
        harness.event(egui::Event::PointerMoved(from + by * (i as f32 / 10.0)));
    }
    harness.event(egui::Event::PointerButton {
        pos: from + by,
        button,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    harness.run();
}

#[test]
fn render_viewport_frames_the_figure_on_first_sight() {
    let mut harness = harness();
    harness.run();
    let state = harness.state();
    let centre = state.scene.centre().expect("centre").as_vec3();
    assert!(state.camera.framed);
    assert!(
        (state.camera.target - centre).length() < 1e-5,
        "{} vs {centre}",
        state.camera.target
    );
}

#[test]
fn render_viewport_drag_orbits_and_keeps_the_distance() {
    let mut harness = harness();
    harness.run();
    let before = harness.state().camera;
    drag(
        &mut harness,
        egui::PointerButton::Primary,
        egui::pos2(300.0, 200.0),
        egui::vec2(100.0, 0.0),
    );
    let after = harness.state().camera;
    assert!(harness.state().dragged, "egui saw a drag");
    // Dragging right turns the camera the other way round the figure.
    let turned = (before.yaw - after.yaw).rem_euclid(std::f32::consts::TAU);
    assert!(
        turned > 0.3 && turned <= 100.0 * ORBIT_RADIANS_PER_POINT + 1e-4,
        "turned {turned} rad"
    );
    assert!(
        (after.pitch - before.pitch).abs() < 1e-6,
        "horizontal drag keeps the pitch"
    );
    assert_eq!(after.distance, before.distance);
    assert_eq!(after.target, before.target);
}

#[test]
fn render_viewport_secondary_drag_pans_and_the_wheel_zooms() {
    let mut harness = harness();
    harness.run();
    let before = harness.state().camera;
    drag(
        &mut harness,
        egui::PointerButton::Secondary,
        egui::pos2(300.0, 200.0),
        egui::vec2(-80.0, 40.0),
    );
    let panned = harness.state().camera;
    assert_eq!(panned.yaw, before.yaw, "panning does not orbit");
    let moved = panned.target - before.target;
    assert!(moved.length() > 0.05, "target moved {moved}");
    // Dragging left moves the scene left: the target goes right.
    assert!(moved.dot(before.right()) > 0.0);

    harness.event(egui::Event::PointerMoved(egui::pos2(300.0, 200.0)));
    harness.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, 120.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: egui::Modifiers::NONE,
    });
    for _ in 0..30 {
        harness.step();
    }
    let zoomed = harness.state().camera;
    assert!(
        zoomed.distance < panned.distance * 0.9,
        "{} -> {}",
        panned.distance,
        zoomed.distance
    );
}

#[test]
fn render_viewport_double_click_frames_again() {
    let mut harness = harness();
    harness.run();
    drag(
        &mut harness,
        egui::PointerButton::Secondary,
        egui::pos2(300.0, 200.0),
        egui::vec2(-150.0, 60.0),
    );
    let centre = harness.state().scene.centre().expect("centre").as_vec3();
    assert!((harness.state().camera.target - centre).length() > 0.05);
    let at = egui::pos2(300.0, 200.0);
    harness.event(egui::Event::PointerMoved(at));
    harness.run();
    // Both clicks in one frame: the harness spaces queued events further apart
    // than egui's double-click delay.
    for _ in 0..2 {
        for pressed in [true, false] {
            harness.input_mut().events.push(egui::Event::PointerButton {
                pos: at,
                button: egui::PointerButton::Primary,
                pressed,
                modifiers: egui::Modifiers::NONE,
            });
        }
    }
    harness.run();
    let camera = harness.state().camera;
    assert!(camera.framed);
    assert!(
        (camera.target - centre).length() < 1e-4,
        "{} vs {centre}",
        camera.target
    );
}

#[test]
fn render_viewport_gestures_read_nothing_without_input() {
    let mut harness = Harness::new_ui(|ui| {
        let response =
            ui.allocate_response(egui::vec2(100.0, 100.0), egui::Sense::click_and_drag());
        let input = gestures(&response);
        assert_eq!(input.orbit, glam::Vec2::ZERO);
        assert_eq!(input.pan, glam::Vec2::ZERO);
        assert_eq!(input.zoom, 1.0);
        assert_eq!(input.scroll, 0.0);
        assert!(!input.reframe);
    });
    harness.run();
}

#[test]
fn render_viewport_fallback_projects_what_the_camera_sees() {
    let rect = egui::Rect::from_min_size(egui::pos2(50.0, 20.0), egui::vec2(400.0, 300.0));
    let camera = Camera {
        target: Vec3::new(0.0, 1.0, 0.0),
        yaw: 0.0,
        pitch: 0.0,
        distance: 4.0,
        framed: true,
        ..Camera::default()
    };
    let frame = SceneFrame {
        capsules: vec![Capsule::new(
            Vec3::new(0.0, 0.5, 0.0),
            Vec3::new(0.0, 1.5, 0.0),
            0.05,
            [1.0; 4],
        )],
        spheres: vec![
            Sphere::new(Vec3::new(0.0, 1.0, 0.0), 0.1, [0.0, 0.0, 1.0, 1.0]),
            // Behind the camera: not drawn.
            Sphere::new(Vec3::new(0.0, 1.0, 10.0), 0.1, [0.0, 1.0, 0.0, 1.0]),
        ],
        segments: vec![Segment::new(Vec3::ZERO, Vec3::X, 2.0, [1.0, 0.0, 0.0, 1.0])],
        ..SceneFrame::default()
    };
    let view = ViewOptions {
        grid: false,
        ..ViewOptions::default()
    };
    let style = ViewStyle::from_visuals(&egui::Visuals::dark());
    let mut shapes = Vec::new();
    fallback_shapes(rect, &frame, &camera, &view, &style, &mut shapes);
    // Background, the capsule, one sphere, the segment.
    assert_eq!(shapes.len(), 4, "{shapes:#?}");
    let egui::Shape::Circle(sphere) = &shapes[2] else {
        panic!(
            "the sphere is drawn after the capsule behind it: {:?}",
            shapes[2]
        );
    };
    assert!(
        (sphere.center - rect.center()).length() < 1e-3,
        "{:?}",
        sphere.center
    );
    // 0.1 m at 4 m with a 40° field of view in a 300-point-high view.
    let expected = 0.1 / (4.0 * 20_f32.to_radians().tan()) * 150.0;
    assert!((sphere.radius - expected).abs() < 0.05 * expected);
    let egui::Shape::LineSegment { points, .. } = &shapes[3] else {
        panic!("segment: {:?}", shapes[3]);
    };
    // The x axis from the origin runs to the right, below the centre (the target is 1 m up).
    assert!(points[1].x > points[0].x && points[0].y > rect.center().y);
}
