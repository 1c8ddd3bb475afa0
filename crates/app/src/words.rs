//! Human words for the page (issue 43 item 5): display names for the bundled
//! presets ("Raibert–Hodgins quadruped"), and joints, effectors and legs read
//! out of their code names ("left_hip_flex" → "left hip (flexion)",
//! "front-left-foot" → "front left foot", PODA's "L1_coxa" → "left 1 coxa").
//! The code names stay in tooltips, commands, links and files.

/// The bundled presets' display names, by preset name.
const PRESET_TITLES: [(&str, &str); 10] = [
    ("human", "Human (She 2006 §3.1)"),
    ("she-2006", "Human, She 2006 as written"),
    ("ik-quadruped", "Quadruped for IK"),
    ("poda-quadruped", "PODA quadruped"),
    ("poda-biped", "PODA biped"),
    ("hexapod", "Hexapod (PODA)"),
    ("insect-14", "Fourteen-legged insect (PODA)"),
    ("raibert-biped", "Raibert–Hodgins biped"),
    ("raibert-quadruped", "Raibert–Hodgins quadruped"),
    ("raibert-kangaroo", "Raibert–Hodgins kangaroo"),
];

/// The display name of preset `name`: a bundled preset's title, else the
/// name as written.
#[must_use]
pub fn preset_title(name: &str) -> &str {
    PRESET_TITLES
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(name, |(_, title)| title)
}

/// A last word of a joint's name that says which way it turns, in words.
const MOTIONS: [(&str, &str); 9] = [
    ("flex", "flexion"),
    ("abduct", "abduction"),
    ("twist", "twist"),
    ("bend", "side bend"),
    ("roll", "roll"),
    ("pitch", "pitch"),
    ("x", "x"),
    ("y", "y"),
    ("z", "z"),
];

/// `name` (a joint, effector or leg's code name) in words: its parts split
/// at `_`, `-` and between a side letter and its number, `L`/`R` as left and
/// right, a last word naming the motion put in brackets; a name of one
/// plain word is returned as it is.
#[must_use]
pub fn in_words(name: &str) -> String {
    let mut words: Vec<String> = Vec::new();
    for part in name.split(['_', '-', ' ']).filter(|p| !p.is_empty()) {
        let (letters, digits) = part.split_at(
            part.find(|c: char| c.is_ascii_digit())
                .unwrap_or(part.len()),
        );
        let side = match letters {
            "L" | "l" if !digits.is_empty() || part.len() == 1 => Some("left"),
            "R" | "r" if !digits.is_empty() || part.len() == 1 => Some("right"),
            _ => None,
        };
        match side {
            Some(side) => {
                words.push(side.to_owned());
                if !digits.is_empty() {
                    words.push(digits.to_owned());
                }
            }
            None => words.push(part.to_owned()),
        }
    }
    if words.len() > 1
        && let Some(last) = words.last_mut()
        && let Some((_, motion)) = MOTIONS.iter().find(|(code, _)| code == last)
    {
        *last = format!("({motion})");
    }
    if words.is_empty() {
        name.to_owned()
    } else {
        words.join(" ")
    }
}

/// A plot series' name in words: `in_words` of its name with a unit in
/// brackets after it kept ("left_hip_flex (°)" → "left hip (flexion) (°)").
#[must_use]
pub fn series_in_words(series: &str) -> String {
    match series.split_once(" (") {
        Some((name, unit)) => format!("{} ({unit}", in_words(name)),
        None => in_words(series),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn code_names_read_as_words() {
        for (code, words) in [
            ("left_hip_flex", "left hip (flexion)"),
            ("right_shoulder_abduct", "right shoulder (abduction)"),
            ("left_front_elbow_x", "left front elbow (x)"),
            ("front-left-foot", "front left foot"),
            ("rear-right-hip-roll", "rear right hip (roll)"),
            ("L1_coxa", "left 1 coxa"),
            ("R3", "right 3"),
            ("lumbar_bend", "lumbar (side bend)"),
            ("thorax_twist", "thorax (twist)"),
            ("neck_3", "neck 3"),
            ("head", "head"),
            ("x", "x"),
            ("", ""),
        ] {
            assert_eq!(in_words(code), words, "{code}");
        }
        assert_eq!(
            series_in_words("left_hip_flex (°)"),
            "left hip (flexion) (°)"
        );
        assert_eq!(series_in_words("left_foot"), "left foot");
    }

    #[test]
    fn every_bundled_preset_has_a_title() {
        for name in gaitlab_core::preset::bundled_names() {
            assert_ne!(preset_title(name), name, "{name} has no title");
        }
        assert_eq!(preset_title("my-creature"), "my-creature");
    }
}
