//! The scenes and gestures that ship with surfacelab, embedded in the
//! binary by `build.rs`: a name like `positioning` or a repository path like
//! `tasks/cases/one_box.toml` or `assets/gestures/flick.toml` works from
//! any folder. A file on disk at the same path is read instead, so a
//! checkout's edited copy always wins.

use std::path::{Component, Path};

include!(concat!(env!("OUT_DIR"), "/builtin_files.rs"));

/// The built-in text at repository path `path` (`./` and `\` tolerated).
pub fn file(path: &Path) -> Option<&'static str> {
    let parts: Vec<String> = path
        .components()
        .filter_map(|c| match c {
            Component::Normal(s) => Some(s.to_string_lossy().into_owned()),
            _ => None,
        })
        .collect();
    if parts.is_empty() || path.is_absolute() {
        return None;
    }
    let key = parts.join("/");
    FILES.iter().find(|(rel, _)| *rel == key).map(|(_, text)| *text)
}

/// Names of the built-in scenes directly under `tasks/` (`positioning`, ...).
pub fn scene_names() -> impl Iterator<Item = &'static str> {
    FILES.iter().filter_map(|(rel, _)| rel.strip_prefix("tasks/")?.strip_suffix(".toml")).filter(|n| !n.contains('/'))
}

/// Names of the built-in gestures under `assets/gestures/`, without the
/// extension (`flick`, `behaviours/flick_fast`, ...).
pub fn gesture_names() -> impl Iterator<Item = &'static str> {
    FILES.iter().filter_map(|(rel, _)| rel.strip_prefix("assets/gestures/")?.strip_suffix(".toml"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_study_tasks_and_the_gestures_are_built_in() {
        for name in ["positioning", "sorting", "steering"] {
            assert!(scene_names().any(|n| n == name), "{name}");
        }
        let text = file(Path::new("./tasks/cases/one_box.toml")).expect("a case scene");
        assert!(text.contains("name = \"one_box\""));
        assert!(file(Path::new("assets/gestures/flick.toml")).is_some_and(|t| t.contains("surfacelab-gesture")));
        assert!(file(Path::new("tasks/nothing.toml")).is_none());
        assert!(
            gesture_names().any(|n| n == "fingertip_drag") && gesture_names().any(|n| n == "behaviours/flick_fast")
        );
        assert!(file(Path::new("/tasks/positioning.toml")).is_none(), "absolute paths are files only");
    }
}
