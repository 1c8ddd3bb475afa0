//! The panels through egui_kittest: they exist, choosing a method or a motion
//! in the UI changes the lab, Pause stops the frame counter, and the
//! recording panel records and saves a take.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use gaitlab_app::{App, Settings};

fn harness() -> Harness<'static, App> {
    let mut lab = App::new(Settings::default());
    // Tests drive time themselves: start paused so the harness settles.
    lab.set_paused(true);
    // One step moves the human 2.8 cm at once (She 2006 starts the cycle at
    // once, no ramp from standing); the following camera eases after it over
    // up to a few dozen repaints (19 after five steps).
    Harness::builder()
        .with_size(egui::vec2(1200.0, 800.0))
        .with_max_steps(32)
        .build_ui_state(|ui, lab: &mut App| lab.ui(ui), lab)
}

/// The IK engine's collapsible sections, top to bottom.
const THESIS_SECTIONS: [&str; 7] = [
    "Method",
    "Motion",
    "Speed",
    "Target positions",
    "View",
    "Object transformation",
    "Recording",
];

#[test]
fn the_thesis_panels_are_there() {
    let mut harness = harness();
    harness.run();
    for label in
        THESIS_SECTIONS
            .into_iter()
            .chain(["Effector error (mm)", "Joint angles", "Reset", "Play"])
    {
        harness.get_by_label(label);
    }
}

#[test]
fn choosing_a_method_and_a_motion_in_the_ui_changes_the_lab() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label("Method").click();
    harness.run();
    harness.get_by_label("Damped least squares").click();
    harness.run();
    assert_eq!(
        harness.state().settings().method,
        gaitlab_core::ik::Method::Dls
    );
    // Fold the method panel again, so the motion panel fits the window.
    harness.get_by_label("Method").click();
    harness.run();
    harness.get_by_label("Motion").click();
    harness.run();
    harness.get_by_label("Wounded running").click();
    harness.run();
    assert_eq!(
        harness.state().settings().mode,
        gaitlab_core::preset::thesis::ThesisMode::WoundedRun
    );
}

#[test]
fn pause_stops_the_frame_counter_and_step_advances_one_frame() {
    let mut harness = harness();
    harness.run();
    assert!(harness.state().paused());
    let before = harness.state().frame();
    for _ in 0..5 {
        harness.step();
    }
    assert_eq!(harness.state().frame(), before, "paused");
    harness.get_by_label("Step").click();
    harness.run();
    assert_eq!(harness.state().frame(), before + 1, "one step");
}

#[test]
fn the_recording_panel_records_a_take_and_saves_it() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label("Recording").click();
    harness.run();
    harness.get_by_label("Record motion").click();
    harness.run();
    assert!(harness.state().recording(), "Record motion starts a take");
    for _ in 0..5 {
        harness.get_by_label("Step").click();
        harness.run();
    }
    harness.get_by_label("Stop motion").click();
    harness.run();
    assert!(!harness.state().recording());
    assert_eq!(harness.state().take().map(|t| t.frames()), Some(5));
    harness.get_by_label("Save BVH").click();
    harness.run();
    let download = harness.state_mut().take_download().expect("a BVH to save");
    assert!(
        download.text.starts_with("HIERARCHY"),
        "{}",
        &download.text[..20]
    );
    assert_eq!(
        download
            .text
            .lines()
            .filter(|l| l.starts_with("Frames:"))
            .count(),
        1
    );
    assert!(download.text.contains("Frames: 5"));
}

/// A paused lab on PODA preset `preset`, in a window `height` points tall.
fn poda_harness(preset: &str, height: f32) -> Harness<'static, App> {
    let mut lab = App::new(Settings::default());
    lab.set_paused(true);
    lab.set_preset(preset).expect("bundled");
    Harness::builder()
        .with_size(egui::vec2(1200.0, height))
        .build_ui_state(|ui, lab: &mut App| lab.ui(ui), lab)
}

#[test]
fn a_poda_creature_shows_the_gait_panel_with_its_footfall_diagram() {
    let mut harness = poda_harness("poda-quadruped", 800.0);
    harness.run();
    // The gait panel opens by itself.
    harness.get_by_label("Gait (PODA)");
    for slider in [
        "Period P (s)",
        "Duty factor",
        "Body speed (m/s)",
        "Stroke (m)",
    ] {
        assert!(
            harness.query_all_by_label(slider).next().is_some(),
            "{slider}"
        );
    }
    // Choose the bound through the gait combo box.
    harness.get_by_label("Gait").click();
    harness.run();
    harness.get_by_label("bound").click();
    harness.run();
    assert_eq!(
        harness
            .state()
            .driver()
            .poda()
            .map(|d| d.gait_name().to_owned()),
        Some("bound".to_owned())
    );
    assert!(
        harness.query_by_label("Method").is_none(),
        "no IK method panel for PODA"
    );
}

#[test]
fn the_body_path_panel_swaps_in_a_circle() {
    let mut harness = poda_harness("hexapod", 1400.0);
    harness.run();
    harness.get_by_label("Body path").click();
    harness.run();
    harness.get_by_label("Circle").click();
    harness.run();
    let closed = harness
        .state()
        .driver()
        .poda()
        .map(|d| d.path().is_closed());
    assert_eq!(closed, Some(true));
}

#[test]
fn the_body_path_panel_says_how_far_the_body_is_off_its_path() {
    let mut harness = poda_harness("hexapod", 1400.0);
    harness.run();
    harness.get_by_label("Body path").click();
    harness.run();
    // The issue's tight closed path, scaled to the hexapod: it cuts corners.
    harness
        .state_mut()
        .command(
            r#"{"path":{"kind":"catmull_rom","closed":true,"points":[[0,0],[0.3,0.15],[0.6,-0.15],[0.9,0.3],[0.6,0.6],[0,0.45]]}}"#,
        )
        .expect("valid path");
    harness.state_mut().set_paused(false);
    for _ in 0..600 {
        harness.state_mut().advance(1.0 / 60.0);
    }
    harness.state_mut().set_paused(true);
    // The path view was redrawn for the moved body: let the frames settle.
    harness.run_steps(40);
    let most = harness
        .state()
        .driver()
        .poda()
        .map(|d| d.path_error_max_m())
        .expect("PODA");
    assert!(most > 0.01, "{most} m");
    let label = harness
        .query_all_by_label_contains("Body off its path")
        .next()
        .map(|node| {
            let node = node.accesskit_node();
            node.value().or_else(|| node.label()).unwrap_or_default()
        })
        .expect("the line under the path view");
    assert!(
        label.ends_with(&format!("{:.0} mm at most", most * 1e3)),
        "{label} (at most {most} m)"
    );
}

#[test]
fn the_engine_selector_switches_to_poda() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label("PODA gaits").click();
    harness.run();
    assert_eq!(harness.state().creature().name, "poda-biped");
    assert!(harness.state().driver().poda().is_some());
}

#[test]
fn the_side_by_side_controls_change_the_comparison() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label("Side by side").click();
    harness.run();
    harness.get_by_label("Compare methods").click();
    harness.run();
    let views = |h: &Harness<'static, App>| -> Vec<&'static str> {
        h.state()
            .comparison()
            .map(|c| c.config.views.iter().map(|m| m.name()).collect())
            .unwrap_or_default()
    };
    assert_eq!(views(&harness), ["transpose", "pinv", "dls", "sdls"]);
    // Four method cards with their formulas and sliders, and one table of
    // their figures, a column each.
    harness.get_by_label("Δθ = Jᵀ(JJᵀ + λ²I)⁻¹ e");
    assert_eq!(harness.query_all_by_label("jitter").count(), 1);
    for column in ["1 · transpose", "2 · pinv", "3 · dls", "4 · sdls"] {
        harness.get_by_label(column);
    }
    harness.get_by_label("2 views").click();
    harness.run();
    assert_eq!(views(&harness), ["transpose", "pinv"]);
    harness.get_by_label("4 views").click();
    harness.run();
    assert_eq!(views(&harness), ["transpose", "pinv", "dls", "sdls"]);
    // View 1's method: open its combo box and pick CCD.
    harness.get_by_label("View 1").click();
    harness.run();
    harness.get_by_label("Cyclic coordinate descent").click();
    harness.run();
    assert_eq!(views(&harness), ["ccd", "pinv", "dls", "sdls"]);
    harness.get_by_label("Scenario").click();
    harness.run();
    harness
        .get_by_label("Singularity (stretched limbs)")
        .click();
    harness.run();
    let scenario = harness.state().comparison().map(|c| c.config.scenario);
    assert_eq!(
        scenario,
        Some(gaitlab_app::compare::CompareScenario::Singularity)
    );
    harness.get_by_label("Compare methods").click();
    harness.run();
    assert!(harness.state().comparison().is_none());
}

#[test]
fn the_preset_editor_shows_the_json_path_of_a_bad_edit_and_keeps_the_creature() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label("Edit preset…").click();
    harness.run();
    assert!(harness.state().editor().open, "the button opens the editor");
    harness.get_by_label("Preset editor");
    let good = harness.state().editor().text.clone();
    // A joint axis of zero length: the core names its JSON path.
    let bad = good.replacen("\"axis\": [1, 0, 0]", "\"axis\": [0, 0, 0]", 1);
    assert_ne!(bad, good);
    harness.state_mut().set_editor_text(&bad);
    harness.run();
    harness.get_by_label("edited, not applied");
    harness.get_by_label("Apply").click();
    harness.run();
    let error = harness
        .state()
        .editor()
        .error
        .clone()
        .expect("the bad edit is refused");
    assert!(
        error.contains("skeleton.joints[0].axis"),
        "the message names the JSON path: {error}"
    );
    // Shown in the user's terms: the joint's name after its index, and the
    // line the axis stands on.
    let line = bad
        .lines()
        .position(|l| l.contains("\"axis\": [0, 0, 0]"))
        .map(|k| k + 1)
        .expect("the edited line");
    let first = harness.state().creature().skeleton.joints()[0].name.clone();
    let shown = format!(
        "Invalid preset (line {line}): skeleton.joints[0] ({first}).axis: must be a non-zero vector"
    );
    harness.get_by_label(&shown);
    assert_eq!(
        harness.state().creature().name,
        "human",
        "the old creature runs"
    );
    assert_eq!(harness.state().creature().skeleton.joints()[0].axis.x, 1.0);

    // A good edit (a new name) changes the running creature.
    let renamed = good.replacen("\"name\": \"human\"", "\"name\": \"human-tall\"", 1);
    harness.state_mut().set_editor_text(&renamed);
    harness.run();
    harness.get_by_label("Apply").click();
    harness.run();
    assert!(harness.state().editor().error.is_none());
    assert_eq!(harness.state().creature().name, "human-tall");
    assert!(
        harness.query_by_label(&shown).is_none(),
        "the message is gone"
    );
    // A good Apply says so, and Undo runs the preset from before it again.
    let joints = harness.state().creature().skeleton.joint_count();
    harness.get_by_label(&format!("Applied: human-tall, {joints} joints"));
    harness.get_by_label("Undo").click();
    harness.run();
    assert_eq!(harness.state().creature().name, "human");
    harness.get_by_label("Undone: back to human");
    assert!(!harness.state().editor().dirty());
    // Back to the bundled preset itself, not a copy of its text.
    let state: serde_json::Value =
        serde_json::from_str(&harness.state().state_json()).expect("state JSON");
    assert_eq!(state["custom_preset"], false);
}

#[test]
fn copy_link_shows_the_link_and_download_preset_queues_the_json() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label("Copy link").click();
    harness.run();
    let expected = harness.state().share_link().expect("a link");
    assert!(
        expected.starts_with("#p="),
        "natively the page address is empty"
    );
    harness.get_by_value(&expected);
    harness.get_by_label("Download preset").click();
    harness.run();
    let download = harness.state_mut().take_download().expect("queued");
    assert_eq!(download.file_name, "human.json");
    assert_eq!(
        download.text,
        gaitlab_core::preset::bundled_json("human").expect("bundled")
    );
}

#[test]
fn the_gait_panel_says_while_legs_take_a_switch_on() {
    let mut harness = poda_harness("poda-quadruped", 1400.0);
    harness.run();
    let says = |h: &Harness<'static, App>| {
        h.query_all_by_label_contains("Legs taking the change on")
            .next()
            .is_some()
    };
    assert!(!says(&harness), "a steady trot says nothing");
    harness.state_mut().set_paused(false);
    for _ in 0..60 {
        harness.state_mut().advance(1.0 / 60.0);
    }
    harness
        .state_mut()
        .command(r#"{"gait":"pace"}"#)
        .expect("valid");
    harness.state_mut().advance(1.0 / 60.0);
    harness.state_mut().set_paused(true);
    harness.run_steps(5);
    assert!(says(&harness), "the pace is being taken on");
    harness.state_mut().set_paused(false);
    for _ in 0..900 {
        harness.state_mut().advance(1.0 / 60.0);
    }
    harness.state_mut().set_paused(true);
    harness.run_steps(5);
    assert!(!says(&harness), "the legs have the pace");
}

#[test]
fn the_physics_panel_names_the_lab_additions_and_has_every_creatures_inputs() {
    // The bundled biped runs by the paper's laws alone; the kangaroo keeps
    // its speed ramp (for changes of speed) and starts on its cycle; the
    // quadruped runs every gait by eq. 2 alone and changes gait by the
    // paper's take-over: no switch line.
    for (preset, want) in [
        ("raibert-biped", "Lab's additions: none"),
        (
            "raibert-kangaroo",
            "Lab's additions (not in the paper): speed ramp, hop integrator",
        ),
        ("raibert-quadruped", "Lab's additions: none"),
    ] {
        let mut harness = poda_harness(preset, 1400.0);
        harness.run();
        assert!(
            harness.query_all_by_label(want).next().is_some(),
            "{preset}: no line \"{want}\""
        );
        let on_cycle = harness
            .query_all_by_label("Start: on the gait's cycle (the lab's)")
            .next()
            .is_some();
        assert_eq!(
            on_cycle,
            preset == "raibert-kangaroo",
            "{preset}: the start line"
        );
        // No bundled preset enters a gait at its own start any more.
        let to_start = harness
            .query_all_by_label(
                "Switch into trot, bound, gallop: at the gait's own start (the lab's)",
            )
            .next()
            .is_some();
        assert!(!to_start, "{preset}: the switch line");
        let jump = harness
            .query_all_by_label("Place a box 3 m ahead")
            .next()
            .is_some();
        assert_eq!(
            jump,
            preset == "raibert-kangaroo",
            "{preset}: the jump button"
        );
        for slider in ["Hop height (m)", "Scale L"] {
            assert!(
                harness.query_all_by_label_contains(slider).next().is_some(),
                "{preset}: no slider {slider}"
            );
        }
    }
}

#[test]
fn the_waypoint_panel_lays_a_square_the_biped_steers_along() {
    let mut harness = poda_harness("raibert-biped", 1400.0);
    harness.run();
    harness.get_by_label("Path (waypoints)").click();
    harness.run();
    harness.get_by_label("Square 8 m").click();
    harness.run();
    let points = harness
        .state()
        .driver()
        .physics()
        .map(|d| d.waypoints().to_vec())
        .expect("physics");
    assert_eq!(points.len(), 4, "{points:?}");
    // The first corner is 8 m ahead of where the biped stood (+z).
    assert!((points[0][1] - 8.0).abs() < 0.5, "{points:?}");
    harness.state_mut().set_paused(false);
    for _ in 0..(16 * 60) {
        harness.state_mut().advance(1.0 / 60.0);
    }
    let driver = harness.state().driver().physics().expect("physics");
    assert!(
        driver.waypoint() >= 2,
        "reached {} waypoints in 16 s",
        driver.waypoint()
    );
    assert_eq!(driver.resets(), 0);
    // The same path by command, and a bad one refused with its key.
    let lab = harness.state_mut();
    assert_eq!(
        lab.command(r#"{"waypoints": [[0, 100000]]}"#)
            .err()
            .as_deref(),
        Some("waypoints[0]: must be [x, z] within ±10000 m")
    );
    lab.command(r#"{"waypoints": []}"#).expect("cleared");
    assert!(
        lab.driver()
            .physics()
            .is_some_and(|d| d.waypoints().is_empty())
    );
}

#[test]
fn a_push_by_command_is_judged_and_a_planar_creature_refuses_a_sideways_one() {
    let mut harness = poda_harness("raibert-kangaroo", 1400.0);
    harness.run();
    let lab = harness.state_mut();
    assert_eq!(
        lab.command(r#"{"push_mps": [0.3, 0]}"#).err().as_deref(),
        Some(
            "push_mps: this creature is planar (forward and up only): a sideways push (0.3 m/s) has nowhere to go"
        )
    );
    assert!(
        lab.command(r#"{"push_mps": [0, 11]}"#)
            .is_err_and(|e| e.starts_with("push_mps: ")),
        "above 10 m/s"
    );
    lab.command(r#"{"push_mps": [0, -0.3]}"#).expect("pushed");
    lab.set_paused(false);
    for _ in 0..(6 * 60) {
        lab.advance(1.0 / 60.0);
    }
    let pushes = lab
        .driver()
        .physics()
        .map(|d| d.pushes().to_vec())
        .expect("physics");
    assert_eq!(pushes.len(), 1, "{pushes:?}");
    assert_eq!(pushes[0].dv_mps, [0.0, -0.3]);
    assert!(
        pushes[0].recovered().is_some(),
        "judged after 5 s: {pushes:?}"
    );
}

#[test]
fn the_panel_pushes_forward_draws_the_push_and_judges_it() {
    use gaitlab_app::render::physics_overlay::PUSH_COLOR;
    let mut harness = poda_harness("raibert-quadruped", 1400.0);
    harness.run_steps(30);
    // Run `seconds` of the creature, then pause again for the panel.
    let run_for = |harness: &mut Harness<'static, App>, seconds: f64| {
        let lab = harness.state_mut();
        lab.set_paused(false);
        for _ in 0..(seconds * 60.0) as usize {
            lab.advance(1.0 / 60.0);
        }
        lab.set_paused(true);
        // The view eases toward the moved creature: a few frames to settle.
        harness.run_steps(30);
    };
    let drawn = |lab: &App| {
        lab.stage()
            .scene()
            .segments()
            .iter()
            .filter(|s| s.color == PUSH_COLOR)
            .count()
    };
    run_for(&mut harness, 2.0);
    harness.get_by_label("Push forward").click();
    harness.run_steps(2);
    assert_eq!(
        drawn(harness.state()),
        5,
        "the arrow at once, paused: a shaft and four barbs"
    );
    run_for(&mut harness, 0.1);
    let pushes = harness
        .state()
        .driver()
        .physics()
        .map(|d| d.pushes().to_vec())
        .expect("physics");
    assert_eq!(pushes.len(), 1, "{pushes:?}");
    // Heading 0: forward is +z, 0.3 m/s.
    assert!((pushes[0].dv_mps[1] - 0.3).abs() < 1e-12 && pushes[0].dv_mps[0].abs() < 1e-12);
    assert_eq!(drawn(harness.state()), 5, "still drawn 0.1 s on");
    run_for(&mut harness, 6.0);
    assert_eq!(drawn(harness.state()), 0, "gone a second after");
    assert!(
        harness
            .query_all_by_label_contains("Last push at t = ")
            .next()
            .is_some()
    );
}

/// A drag that starts on the trunk pushes the creature the way it was
/// dragged, by its length, instead of turning the camera; a drag elsewhere
/// turns the camera and pushes nothing.
#[test]
fn dragging_the_trunk_pushes_it_and_leaves_the_camera() {
    let mut harness = poda_harness("raibert-quadruped", 1400.0);
    harness.run_steps(30);
    let lab = harness.state_mut();
    lab.set_paused(false);
    for _ in 0..60 {
        lab.advance(1.0 / 60.0);
    }
    lab.set_paused(true);
    harness.run_steps(30);
    let trunk = trunk_point(&harness);
    let pushes = |harness: &Harness<'static, App>| {
        harness
            .state()
            .driver()
            .physics()
            .map(|d| d.pushes().to_vec())
            .expect("physics")
    };
    // A drag elsewhere in the view turns the camera and pushes nothing.
    let before = harness.state().camera();
    let elsewhere = trunk + egui::vec2(0.0, 150.0);
    harness.drag_at(elsewhere);
    harness.hover_at(elsewhere + egui::vec2(40.0, 0.0));
    harness.hover_at(elsewhere + egui::vec2(80.0, 0.0));
    harness.drop_at(elsewhere + egui::vec2(80.0, 0.0));
    harness.run_steps(2);
    assert!(pushes(&harness).is_empty());
    let camera = harness.state().camera();
    assert!((camera.yaw - before.yaw).abs() > 0.3, "the camera turned");
    // Re-read the trunk: the camera turned.
    let trunk = trunk_point(&harness);
    // 100 points straight up the screen: 0.3 m/s away from the camera.
    harness.drag_at(trunk + egui::vec2(2.0, 2.0));
    harness.hover_at(trunk + egui::vec2(2.0, -40.0));
    harness.hover_at(trunk + egui::vec2(2.0, -98.0));
    harness.run_steps(1);
    harness.drop_at(trunk + egui::vec2(2.0, -98.0));
    harness.run_steps(2);
    let got = pushes(&harness);
    assert_eq!(got.len(), 1, "{got:?}");
    let [x, z] = got[0].dv_mps;
    assert!((x.hypot(z) - 0.3).abs() < 0.01, "{x} {z}");
    let away = camera.forward();
    let away = glam::DVec2::new(f64::from(away.x), f64::from(away.z)).normalize();
    assert!((x * away.x + z * away.y) > 0.29, "along the view: {x} {z}");
    // The camera did not turn (it may follow the creature).
    let after = harness.state().camera();
    assert_eq!(
        (after.yaw, after.pitch, after.distance),
        (camera.yaw, camera.pitch, camera.distance),
        "the camera did not turn"
    );
}

#[test]
fn the_physics_plots_each_hold_one_unit_and_open_on_a_phone() {
    // Wide: four plots, one unit each, their axes labelled.
    let mut harness = poda_harness("raibert-biped", 900.0);
    harness.run();
    for title in [
        "Height and leg length",
        "Ground force",
        "Trunk attitude",
        "State (Figure 4)",
    ] {
        harness.get_by_label(title);
    }
    // On a phone the plots are a drawer of their own, closed at first; the
    // controls drawer and the plots drawer never show together.
    let mut lab = App::new(Settings::default());
    lab.set_paused(true);
    lab.set_preset("raibert-biped").expect("bundled");
    assert!(lab.command(r#"{"narrow": true}"#).is_ok());
    let mut harness = Harness::builder()
        .with_size(egui::vec2(390.0, 844.0))
        .build_ui_state(|ui, lab: &mut App| lab.ui(ui), lab);
    harness.run();
    assert!(harness.query_all_by_label("Ground force").next().is_none());
    // Touch targets: the phone bar's buttons are at least 44 px tall.
    for label in ["Controls", "Plots", "Reset", "Play", "Step"] {
        let height = harness.get_by_label(label).rect().height();
        assert!(
            height >= gaitlab_app::ui::TOUCH_TARGET_PT,
            "{label}: {height} px"
        );
    }
    harness.get_by_label("Plots").click();
    harness.run();
    assert!(harness.state().plots_open());
    harness.get_by_label("Ground force");
    harness.get_by_label("Controls").click();
    harness.run();
    let lab = harness.state();
    assert!(lab.controls_open() && !lab.plots_open());
}

#[test]
fn a_first_visit_finds_the_intro_the_help_and_presets_by_engine() {
    let mut harness = harness();
    harness.run();
    harness.get_by_label(gaitlab_app::ui::panels::INTRO);
    assert!(
        harness.query_by_label("The 3-D view").is_none(),
        "help starts closed"
    );
    harness.get_by_label("Help").click();
    harness.run();
    assert!(harness.state().help_open());
    // The help window: the view's key, the controls, the engines.
    for text in [
        "The 3-D view",
        "the figure's left side (left_knee, front-left-foot, PODA's L1…); the plots draw its series in blues",
        "IK targets the effectors follow",
        "Moving around",
        "orbit the camera (one finger on a touch screen)",
        "The engines",
        "Physics (Raibert & Hodgins 1991)",
    ] {
        harness.get_by_label(text);
    }
    // The button (the window's title is "Help" too, and comes after it).
    harness
        .get_all_by_label("Help")
        .next()
        .expect("the Help button")
        .click();
    harness.run();
    assert!(!harness.state().help_open(), "Help closes it again");
    assert!(
        harness.query_by_label("The 3-D view").is_none(),
        "and the window goes"
    );
    // The preset menu groups the bundled presets by engine.
    harness.get_by_label("Preset").click();
    harness.run();
    for text in ["PODA gaits", "Raibert–Hodgins kangaroo", "PODA quadruped"] {
        assert!(
            harness.query_all_by_label(text).next().is_some(),
            "the menu lists {text}"
        );
    }
    harness.get_by_label("Raibert–Hodgins kangaroo").click();
    harness.run();
    assert_eq!(harness.state().creature().name, "raibert-kangaroo");
}

#[test]
fn a_recording_shows_a_red_dot_above_the_view() {
    let shown = |harness: &Harness<'static, App>| {
        harness
            .query_all_by_label_contains("Recording motion")
            .next()
            .is_some()
    };
    let mut harness = harness();
    harness.run();
    assert!(!shown(&harness));
    harness.state_mut().start_recording();
    harness.state_mut().single_step();
    harness.run();
    harness.get_by_label_contains("Recording motion ·");
    harness.state_mut().stop_recording();
    harness.run();
    assert!(!shown(&harness));
}

#[test]
fn the_speed_slider_shows_the_tested_speeds_and_warns_outside_them() {
    let mut harness = poda_harness("raibert-quadruped", 1400.0);
    harness.run();
    harness.get_by_label("tested 1.0–2.3 m/s (the green band)");
    assert!(harness.state_mut().command(r#"{"speed_mps": 3.6}"#).is_ok());
    harness.run();
    harness.get_by_label("Outside the tested 1.0–2.3 m/s: it may fall or miss the speed");
}

#[test]
fn a_lesson_opens_with_its_note_and_leaves_out_its_hidden_panels() {
    let mut harness = harness();
    harness.run();
    assert!(
        layout(&harness)["panels_shown"]
            .as_array()
            .is_some_and(|p| p.contains(&"Method".into()))
    );
    if let Err(error) = harness.state_mut().command(
        r#"{"lesson": {"note": "Watch the hands.", "hide_panels": ["Method", "Recording"], "pin_plots": ["errors"]}}"#,
    ) {
        panic!("{error}");
    }
    harness.run();
    // The note first, in its window.
    harness.get_by_label("Watch the hands.");
    let shown = layout(&harness)["panels_shown"].clone();
    let has = |title: &str| shown.as_array().is_some_and(|p| p.contains(&title.into()));
    assert!(!has("Method") && !has("Recording"), "{shown}");
    assert!(has("Motion") && has("Lesson"), "{shown}");
    // The pinned plot only.
    harness.get_by_label("Effector error (mm)");
    assert!(harness.query_by_label("Joint angles").is_none());
    harness.get_by_label("Start").click();
    harness.run();
    assert_eq!(layout(&harness)["lesson_note_open"], false);
    assert!(harness.query_by_label("Watch the hands.").is_none());
    harness.get_by_label("Leave the lesson").click();
    harness.run();
    assert!(harness.state().lesson().is_none());
    harness.run();
    assert!(
        layout(&harness)["panels_shown"]
            .as_array()
            .is_some_and(|p| p.contains(&"Method".into()))
    );
    harness.get_by_label("Joint angles");
}

/// A paused lab of `preset` on a 390 × 844 phone after the command `setup`.
fn phone_harness(preset: &str, setup: &str) -> Harness<'static, App> {
    let mut lab = App::new(Settings::default());
    if let Err(error) = lab.set_preset(preset) {
        panic!("{error}");
    }
    lab.set_paused(true);
    if let Err(error) = lab.command(setup) {
        panic!("{error}");
    }
    Harness::builder()
        .with_size(egui::vec2(390.0, 844.0))
        .build_ui_state(|ui, lab: &mut App| lab.ui(ui), lab)
}

/// Asserts the last frame's touch audit found no target under 44 points
/// (or cut off) and returns how many it measured.
fn no_small_targets(harness: &Harness<'static, App>, what: &str) -> u64 {
    let checked = layout(harness);
    println!(
        "{what}: {} targets, small {}",
        checked["touch_targets_checked"], checked["small_touch_targets_pt"]
    );
    assert_eq!(
        checked["small_touch_targets_pt"],
        serde_json::json!([]),
        "{what}"
    );
    checked["touch_targets_checked"].as_u64().unwrap_or(0)
}

/// Where the trunk is drawn on the screen (`state().layout.trunk_pt`).
fn trunk_point(harness: &Harness<'static, App>) -> egui::Pos2 {
    let at = &layout(harness)["trunk_pt"];
    egui::pos2(
        at[0].as_f64().expect("trunk x") as f32,
        at[1].as_f64().expect("trunk y") as f32,
    )
}

/// `state().layout` of the harness's lab.
fn layout(harness: &Harness<'static, App>) -> serde_json::Value {
    let state: serde_json::Value =
        serde_json::from_str(&harness.state().state_json()).unwrap_or_default();
    state["layout"].clone()
}

#[test]
fn every_touch_target_on_a_phone_measures_at_least_44_points() {
    for (preset, setup) in [
        ("human", r#"{"narrow": true}"#),
        (
            "human",
            r#"{"narrow": true, "compare": {"views": ["pinv", "dls", "sdls", "transpose"]}}"#,
        ),
        ("hexapod", r#"{"narrow": true}"#),
        ("raibert-quadruped", r#"{"narrow": true}"#),
    ] {
        let mut harness = phone_harness(preset, setup);
        harness.run();
        harness.get_by_label("Controls").click();
        harness.run();
        // Every section open, so its widgets are laid out and measured.
        let others = [
            "Side by side",
            "Make a lesson",
            "Gait",
            "Path",
            "Path (waypoints)",
        ];
        for header in THESIS_SECTIONS.into_iter().chain(others) {
            let found = harness
                .query_all_by_label(header)
                .next()
                .map(|node| node.click());
            if found.is_some() {
                harness.run();
            }
        }
        harness.run();
        let targets = no_small_targets(&harness, &format!("{preset} {setup}: controls drawer"));
        assert!(targets >= 40, "{targets} targets");
        harness.get_by_label("Plots").click();
        harness.run();
        harness.run();
        no_small_targets(&harness, &format!("{preset} {setup}: plots drawer"));
    }
}

#[test]
fn the_windows_on_a_phone_have_only_full_size_targets_and_close() {
    for (setup, title) in [
        (r#"{"narrow": true, "help": true}"#, "Help"),
        (r#"{"narrow": true, "editor_open": true}"#, "Preset editor"),
        (
            r#"{"narrow": true, "lesson": {"note": "Watch the hands."}}"#,
            "Lesson",
        ),
    ] {
        let mut harness = phone_harness("human", setup);
        harness.run();
        harness.run();
        assert!(no_small_targets(&harness, setup) >= 5);
        // The title heads the content; Close closes it.
        assert!(
            harness.query_all_by_label(title).next().is_some(),
            "{title}"
        );
        harness.get_by_label("Close").click();
        harness.run();
        harness.run();
        assert!(harness.query_by_label("Close").is_none(), "{setup}: closed");
    }
}

#[test]
fn the_scale_slider_warns_outside_the_tested_scales() {
    let mut harness = poda_harness("raibert-quadruped", 1400.0);
    harness.run();
    let warning = "Outside the tested L = 0.25–4: it may fall";
    assert!(harness.query_by_label(warning).is_none(), "L = 1 is tested");
    assert!(
        harness
            .state_mut()
            .command(r#"{"physics_scale": 6}"#)
            .is_ok()
    );
    harness.run();
    harness.get_by_label(warning);
    // Beyond the slider's own range: the creature keeps the L it was given.
    let state: serde_json::Value =
        serde_json::from_str(&harness.state().state_json()).unwrap_or_default();
    assert_eq!(state["physics"]["scale"], 6.0);
}

/// Issue 43 item 5: the PODA gait panel's messages (the stability warning,
/// the derived values, a gait change being taken on) keep their place, so
/// the section headers below the panel hold still through 20 s of play with
/// gait switches and edits (a click aimed at one lands on it). The run must
/// show the messages coming and going, or it proves nothing.
#[test]
fn the_sections_below_the_poda_panel_hold_still_through_play_and_gait_switches() {
    let mut harness = poda_harness("hexapod", 1400.0);
    harness.run_steps(4);
    let header_y = |h: &Harness<'static, App>| {
        (
            h.get_by_label("Phases and steps").rect().top(),
            h.get_by_label("Center angles and gains").rect().top(),
        )
    };
    // Which of the panel's messages show: the warning, derived values, a change taken on.
    let messages = |lab: &App| {
        let readout = lab.driver().poda_readout();
        (
            readout.as_ref().is_some_and(|r| {
                r.stability.unstable_share > gaitlab_app::ui::panels::UNSTABLE_WARNING_SHARE
            }),
            !lab.gait_derived().is_empty(),
            readout.as_ref().is_some_and(|r| r.shifting),
        )
    };
    let start = header_y(&harness);
    let mut seen = std::collections::BTreeSet::new();
    harness.state_mut().set_paused(false);
    for k in 0..(20 * 10_u32) {
        // A switch or an edit every 2 s; 0.1 s of play between frames drawn.
        if k % 20 == 0 {
            let lab = harness.state_mut();
            let done = match (k / 20) % 4 {
                0 => lab.set_gait("tripod"),
                1 => lab.edit_gait("duty_factor", 0.3),
                2 => lab.set_gait("wave"),
                _ => lab.edit_gait("speed_mps", 0.35),
            };
            if let Err(error) = done {
                panic!("{k}: {error}");
            }
        }
        let lab = harness.state_mut();
        for _ in 0..6 {
            lab.advance(1.0 / 60.0);
        }
        seen.insert(messages(harness.state()));
        harness.run_steps(1);
        assert_eq!(
            header_y(&harness),
            start,
            "the headers moved at {:.1} s",
            f64::from(k) * 0.1
        );
    }
    println!("messages seen (warning, derived, shifting): {seen:?}");
    assert!(
        seen.len() >= 3,
        "the messages did not come and go: {seen:?}"
    );
}

/// A lesson that names the Jacobian panel opens its section (issue 44 item
/// 5): closed before, "One iteration (I)" on screen after; a lesson that
/// names a panel it cannot open is refused with the names it can.
#[test]
fn a_lesson_opens_the_jacobian_panel() {
    let mut harness = harness();
    harness.run();
    assert!(
        harness.query_by_label("One iteration (I)").is_none(),
        "the Jacobian section starts closed"
    );
    let error = harness
        .state_mut()
        .command(r#"{"lesson": {"open_panels": ["Motion"]}}"#)
        .err()
        .unwrap_or_default();
    assert!(
        error.starts_with("lesson.open_panels[0]") && error.contains("Jacobian"),
        "{error}"
    );
    if let Err(error) = harness
        .state_mut()
        .command(r#"{"lesson": {"note": "Watch σ₃.", "open_panels": ["Jacobian"]}, "lesson_note_open": false}"#)
    {
        panic!("{error}");
    }
    harness.run();
    harness.get_by_label("One iteration (I)");
}
