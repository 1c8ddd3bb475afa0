mod common;
use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::{ThesisMode, ThesisParams};
use gaitlab_motion::ThesisDriver;

fn params() -> ThesisParams {
    let mut p = common::human_params();
    if let Ok(s) = std::env::var("PATCH") {
        let mut v = serde_json::to_value(&p).unwrap();
        let patch: serde_json::Value = serde_json::from_str(&s).unwrap();
        merge(&mut v, &patch);
        p = serde_json::from_value(v).unwrap();
    }
    p
}
fn merge(a: &mut serde_json::Value, b: &serde_json::Value) {
    match (a, b) {
        (serde_json::Value::Object(a), serde_json::Value::Object(b)) => {
            for (k, v) in b {
                merge(a.entry(k.clone()).or_insert(serde_json::Value::Null), v);
            }
        }
        (a, b) => *a = b.clone(),
    }
}

#[test]
#[ignore]
fn sweep() {
    let mut skeleton = common::human();
    if let Ok(o) = std::env::var("TOE") {
        let v: Vec<f64> = o.split(',').map(|x| x.parse().unwrap()).collect();
        let mut effs = skeleton.effectors().to_vec();
        for e in effs.iter_mut().filter(|e| e.name.ends_with("foot")) {
            e.offset = glam::DVec3::new(v[0], v[1], v[2]);
        }
        skeleton = gaitlab_core::Skeleton::new(skeleton.joints().to_vec(), effs).unwrap();
    }
    if let Ok(k) = std::env::var("REST_KNEE") {
        let k: f64 = k.parse().unwrap();
        let mut js = skeleton.joints().to_vec();
        for j in js.iter_mut().filter(|j| j.name.ends_with("knee")) {
            j.rest = k;
            j.center = k;
        }
        skeleton = gaitlab_core::Skeleton::new(js, skeleton.effectors().to_vec()).unwrap();
    }
    let p = params();
    let secs: f64 = std::env::var("SECS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20.0);
    let methods: Vec<Method> = std::env::var("METHODS")
        .map(|s| s.split(',').map(|m| Method::parse(m).unwrap()).collect())
        .unwrap_or(vec![Method::Sdls, Method::Dls]);
    let modes: Vec<ThesisMode> = std::env::var("MODES")
        .map(|s| {
            s.split(',')
                .map(|m| ThesisMode::parse(m).unwrap())
                .collect()
        })
        .unwrap_or(ThesisMode::ALL.to_vec());
    let watch = [
        "left_hip_flex",
        "left_knee",
        "left_ankle",
        "right_knee",
        "left_shoulder_flex",
        "left_elbow",
        "lumbar_flex",
        "lumbar_bend",
        "thorax_twist",
        "left_shoulder_abduct",
        "left_wrist",
        "left_hip_abduct",
    ];
    let idx: Vec<usize> = watch
        .iter()
        .map(|n| skeleton.joint_index(n).unwrap())
        .collect();
    for &method in &methods {
        for &mode in &modes {
            let mut d = ThesisDriver::new(
                skeleton.clone(),
                p.clone(),
                mode,
                IkOptions {
                    method,
                    ..IkOptions::default()
                },
            )
            .unwrap();
            let mut lo = vec![f64::MAX; idx.len()];
            let mut hi = vec![f64::MIN; idx.len()];
            let n = (secs * 60.0) as usize;
            for f in 0..n {
                d.step(1.0 / 60.0);
                if f > 120 {
                    for (k, &j) in idx.iter().enumerate() {
                        lo[k] = lo[k].min(d.pose().joints[j]);
                        hi[k] = hi[k].max(d.pose().joints[j]);
                    }
                }
            }
            let m = d.ik_metrics().unwrap();
            let e = |i| {
                (
                    m.mean_error_m(i).unwrap() * 1e3,
                    m.max_error_m(i).unwrap() * 1e3,
                )
            };
            let (a, b, c, dd) = (e(0), e(1), e(2), e(3));
            println!(
                "{:>5} {:>12} feet {:5.2}/{:6.1} {:5.2}/{:6.1} hands {:5.1}/{:6.1} {:5.1}/{:6.1}",
                method.name(),
                mode.name(),
                a.0,
                a.1,
                b.0,
                b.1,
                c.0,
                c.1,
                dd.0,
                dd.1
            );
            let ranges: Vec<String> = watch
                .iter()
                .zip(lo.iter().zip(&hi))
                .map(|(n, (l, h))| format!("{n} [{l:.2},{h:.2}]"))
                .collect();
            println!("      {}", ranges.join(" "));
        }
    }
}

#[test]
#[ignore]
fn startup() {
    let skeleton = common::human();
    let p = params();
    let mode = ThesisMode::parse(&std::env::var("MODE").unwrap_or("run".into())).unwrap();
    let mut d = ThesisDriver::new(skeleton.clone(), p, mode, IkOptions::default()).unwrap();
    let lk = skeleton.joint_index("left_knee").unwrap();
    let rk = skeleton.joint_index("right_knee").unwrap();
    let la = skeleton.joint_index("left_ankle").unwrap();
    let lh = skeleton.joint_index("left_hip_flex").unwrap();
    for f in 0..90 {
        d.step(1.0 / 60.0);
        let t = d.targets().unwrap();
        let rel = t.position[0] - d.pose().root.position;
        let r = d.ik_report().unwrap();
        if f % 3 == 0 {
            println!(
                "{:5.2} Ltgt ({:5.2},{:5.2}) err {:6.1} {:6.1} lhip {:5.2} lknee {:5.2} lankle {:5.2} rknee {:5.2}",
                d.time(),
                rel.y,
                rel.z,
                r.effector_error_m[0] * 1e3,
                r.effector_error_m[1] * 1e3,
                d.pose().joints[lh],
                d.pose().joints[lk],
                d.pose().joints[la],
                d.pose().joints[rk]
            );
        }
    }
}

#[test]
#[ignore]
fn arm_fk() {
    let skeleton = common::human();
    let sf = skeleton.joint_index("left_shoulder_flex").unwrap();
    let el = skeleton.joint_index("left_elbow").unwrap();
    let lh = skeleton.effector_index("left_hand").unwrap();
    for (s, e) in [
        (-0.5, -1.6),
        (-0.3, -1.5),
        (0.3, -1.4),
        (0.5, -1.2),
        (0.6, -1.0),
        (-0.3, -0.8),
        (0.3, -0.3),
        (-0.2, -0.6),
    ] {
        let mut v = skeleton.rest_values();
        v[sf] = s;
        v[el] = e;
        let k = gaitlab_core::Kinematics::of(
            &skeleton,
            &gaitlab_core::Pose {
                root: Default::default(),
                joints: v,
            },
        );
        println!(
            "shoulder {s:5.2} elbow {e:5.2} -> hand rel root {:?}",
            k.effector_position[lh]
        );
    }
}
