//! The layering of ARCHITECTURE.md, checked by reading the sources: no
//! `crate::` path reaches a layer its module may not read, and only the
//! world names the physics engine. Reading the files keeps the check free
//! of any tool beyond the standard library; a unit check of each rule on a
//! made-up bad source proves it can fail.

use std::fs;
use std::path::{Path, PathBuf};

/// The physics engine's crate name, built so that this file does not name
/// it where the check below reads.
const ENGINE: &str = concat!("rapier", "3d");

/// The only folder that may name [`ENGINE`].
const ENGINE_HOME: &str = "src/pipeline/world/";

/// Each layer and the layers it may read, as ARCHITECTURE.md's picture and
/// its "What each layer may touch" list give them. A module reads its own
/// layer freely; `error`, `files`, `contact` and `scene` are readable by
/// every layer but each other's rules.
fn may_read(layer: &str) -> Option<&'static [&'static str]> {
    const BASE: [&str; 4] = ["error", "files", "contact", "scene"];
    const STACK: [&str; 13] = [
        "error",
        "files",
        "contact",
        "scene",
        "input",
        "pipeline::surface",
        "pipeline::vision",
        "pipeline::technique",
        "pipeline::world",
        "session",
        "harness",
        "render",
        "app",
    ];
    Some(match layer {
        "error" => &[],
        "files" => &["error"],
        // The renderer's input is a draw list; it reads nothing else.
        "contact" | "scene" | "render" => &["error", "files"],
        "pipeline::world" => &["error", "files", "scene"],
        "pipeline::surface" => &BASE,
        "pipeline::vision" | "input" => &["error", "files", "contact", "scene", "pipeline::surface"],
        "pipeline::technique" => {
            &["error", "files", "contact", "scene", "pipeline::surface", "pipeline::vision", "pipeline::world"]
        }
        // From the session up, each layer reads everything before it in
        // this order (render is the app's, not the harness's).
        "session" => &STACK[..9],
        "harness" => &STACK[..10],
        "app" => &STACK[..12],
        "cli" => &STACK[..13],
        _ => return None,
    })
}

/// The layer a `crate::` path (without the `crate::`) or a source file's
/// module path (`pipeline::technique::particle`) belongs to: the
/// pipeline's stages are layers of their own, every other top-level module
/// is one. `None` for the pipeline itself (its facade).
fn layer_of(path: &str) -> Option<String> {
    let mut parts = path.split("::").filter(|p| !p.is_empty());
    let top = parts.next()?;
    if top == "pipeline" { parts.next().map(|stage| format!("pipeline::{stage}")) } else { Some(top.to_string()) }
}

/// A source file's module path: `src/pipeline/vision/flow.rs` is
/// `pipeline::vision::flow`.
fn module_of(file: &Path, src: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap_or(file).with_extension("");
    let parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).filter(|p| p != "mod").collect();
    parts.join("::")
}

/// The code of a line: empty for a comment line, else the line up to a
/// trailing `//` comment (a `//` inside a string literal ends it too
/// early, which only hides text from the check, never adds any).
fn code(line: &str) -> &str {
    let t = line.trim_start();
    if t.starts_with("//") {
        return "";
    }
    t.split("//").next().unwrap_or("")
}

/// Every `crate::` path in `source` that the layer `layer` may not read,
/// as `line N: path`.
fn layer_violations(layer: &str, source: &str) -> Vec<String> {
    let Some(allowed) = may_read(layer) else { return vec![format!("unknown layer `{layer}`")] };
    let mut out = Vec::new();
    for (n, line) in source.lines().enumerate() {
        let code = code(line);
        let mut rest = code;
        while let Some(at) = rest.find("crate::") {
            let after = &rest[at + "crate::".len()..];
            let end = after.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == ':')).unwrap_or(after.len());
            let path = after[..end].trim_end_matches(':');
            rest = &after[end..];
            // A preceding word character means another crate's path
            // (`surfacelab::crate::…` does not occur; `my_crate::` does).
            let before = code[..code.len() - after.len() - "crate::".len()].chars().last();
            if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_') {
                continue;
            }
            let Some(target) = layer_of(path) else {
                out.push(format!("line {}: crate::{path} (the whole pipeline)", n + 1));
                continue;
            };
            if target != layer && !allowed.contains(&target.as_str()) {
                out.push(format!("line {}: crate::{path} ({layer} may not read {target})", n + 1));
            }
        }
    }
    out
}

/// The lines of `source` that name the physics engine.
fn engine_mentions(source: &str) -> Vec<String> {
    source
        .lines()
        .enumerate()
        .filter(|(_, line)| code(line).contains(ENGINE))
        .map(|(n, line)| format!("line {}: {}", n + 1, line.trim()))
        .collect()
}

/// Every `.rs` file under `dir`, in path order (none where it cannot be
/// read).
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let (mut files, mut dirs) = (Vec::new(), vec![dir.to_path_buf()]);
    while let Some(dir) = dirs.pop() {
        for path in fs::read_dir(&dir).into_iter().flatten().filter_map(|e| e.ok().map(|e| e.path())) {
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn no_module_reads_a_layer_below_its_own() {
    let src = root().join("src");
    let files = rust_files(&src);
    let mut found = Vec::new();
    for file in &files {
        let module = module_of(file, &src);
        // The crate root and the binary wire the layers together; the
        // pipeline's facade only names its stages.
        if matches!(module.as_str(), "lib" | "main" | "pipeline") {
            continue;
        }
        let layer = layer_of(&module).expect("a module path");
        let text = fs::read_to_string(file).expect("readable source");
        found.extend(layer_violations(&layer, &text).into_iter().map(|v| format!("{}: {v}", file.display())));
    }
    assert!(files.len() > 100, "found only {} source files under {}", files.len(), src.display());
    assert!(found.is_empty(), "imports against ARCHITECTURE.md's layers:\n{}", found.join("\n"));
}

#[test]
fn only_the_world_names_the_physics_engine() {
    let files: Vec<PathBuf> =
        ["src", "tests", "benches", "examples"].iter().flat_map(|d| rust_files(&root().join(d))).collect();
    let home = root().join(ENGINE_HOME);
    let mut found = Vec::new();
    for file in files.iter().filter(|f| !f.starts_with(&home)) {
        let text = fs::read_to_string(file).expect("readable source");
        found.extend(engine_mentions(&text).into_iter().map(|m| format!("{}: {m}", file.display())));
    }
    assert!(found.is_empty(), "the physics engine named outside {ENGINE_HOME}:\n{}", found.join("\n"));
}

#[test]
fn the_checks_catch_a_bad_source() {
    // A scene reaching down into the app, a technique into the session, a
    // renderer into the scene: each one violation, with its line.
    let bad = "use crate::error::Error;\nuse crate::app::Lab;\n";
    assert_eq!(layer_violations("scene", bad), vec!["line 2: crate::app::Lab (scene may not read app)"]);
    let bad = "fn f() {\n    let s = crate::session::Session::new();\n}\n";
    assert_eq!(layer_violations("pipeline::technique", bad).len(), 1);
    assert_eq!(layer_violations("render", "use crate::scene::Scene;").len(), 1);
    // Within a layer, upwards, in comments and in other crates' paths: none.
    let good = "use crate::pipeline::world::World;\n// crate::app::Lab\nuse super::crate_name::x;\n";
    assert!(layer_violations("pipeline::technique", good).is_empty());
    assert!(layer_violations("harness", "use crate::harness::study::Trial;").is_empty());
    // The engine named in code, not in a comment.
    let engine = format!("use {ENGINE}::prelude::*;\n// the {ENGINE} world\n");
    assert_eq!(engine_mentions(&engine).len(), 1);
    assert_eq!(module_of(Path::new("src/pipeline/vision/mod.rs"), Path::new("src")), "pipeline::vision");
    assert_eq!(layer_of("pipeline::vision::flow").as_deref(), Some("pipeline::vision"));
    assert_eq!(layer_of("harness::study::design").as_deref(), Some("harness"));
}
