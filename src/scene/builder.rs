//! Scenes built in Rust instead of written as TOML.
//!
//! A builder collects the same fields a scene file has and hands them to
//! the one validator ([`parse`](super::parse)), so a scene built in code
//! meets every bound a file does and its errors name the field the same
//! way (`objects[1].mass`). One scene definition, whichever way it is
//! written.
//!
//! ```
//! use surfacelab::scene::{Effect, SceneBuilder, ShapeSpec};
//!
//! let scene = SceneBuilder::new("one_puck")
//!     .effects(&[Effect::Gravity, Effect::Friction])
//!     .table(1.0, 0.75)
//!     .object("puck", ShapeSpec::Cylinder { radius: 0.04, height: 0.02 }, [0.0, 0.0], 0.1, "red")
//!     .positioning_target("puck", [0.2, 0.1], 0.015)
//!     .build()
//!     .unwrap();
//! assert_eq!(scene.objects.len(), 1);
//! assert!(SceneBuilder::new("bad").object("x", ShapeSpec::Sphere { radius: 0.03 }, [0.0, 0.0], -1.0, "red").build().is_err());
//! ```

use super::{Effect, Scene, SceneError};
use toml::{Table, Value};

/// An object's shape as a scene file gives it: full sizes, not half ones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShapeSpec {
    /// Width, depth and height (m).
    Box {
        size: [f32; 3],
    },
    Sphere {
        radius: f32,
    },
    /// Standing upright; `height` is the full height (m).
    Cylinder {
        radius: f32,
        height: f32,
    },
}

/// A scene under construction; [`SceneBuilder::build`] validates it.
#[derive(Debug, Clone)]
pub struct SceneBuilder {
    root: Table,
    objects: Vec<Value>,
    targets: Vec<Value>,
    dwell_s: Option<f32>,
}

impl SceneBuilder {
    /// A scene called `name` on a 1.0 × 0.75 m table, with no objects, no
    /// goal and no effects declared (objects then float: declare at least
    /// gravity and friction with [`SceneBuilder::effects`]).
    pub fn new(name: &str) -> SceneBuilder {
        let mut root = Table::new();
        root.insert("name".into(), Value::from(name));
        root.insert("description".into(), Value::from(format!("{name}, built in code")));
        root.insert("effects".into(), Value::Array(Vec::new()));
        root.insert("table".into(), Value::Table(Table::from_iter([("size".into(), floats(&[1.0, 0.75]))])));
        SceneBuilder { root, objects: Vec::new(), targets: Vec::new(), dwell_s: None }
    }

    /// The world effects the scene declares; the world simulates only these.
    pub fn effects(mut self, effects: &[Effect]) -> SceneBuilder {
        let names = effects.iter().map(|e| Value::from(e.name())).collect();
        self.root.insert("effects".into(), Value::Array(names));
        self
    }

    /// The table's width (x) and depth (y), metres.
    pub fn table(mut self, width: f32, depth: f32) -> SceneBuilder {
        if let Some(Value::Table(t)) = self.root.get_mut("table") {
            t.insert("size".into(), floats(&[width, depth]));
        }
        self
    }

    /// Seconds before a study trial of this scene counts as failed.
    pub fn time_limit(mut self, seconds: f32) -> SceneBuilder {
        self.root.insert("time_limit_s".into(), Value::from(f64::from(seconds)));
        self
    }

    /// The table's friction coefficient (default 0.6, a matte surface).
    pub fn table_friction(mut self, friction: f32) -> SceneBuilder {
        if let Some(Value::Table(t)) = self.root.get_mut("table") {
            t.insert("friction".into(), Value::from(f64::from(friction)));
        }
        self
    }

    /// A dynamic object resting on the table at `position` (m), of `mass`
    /// (kg) and a colour name or `#rrggbb`.
    pub fn object(mut self, name: &str, shape: ShapeSpec, position: [f32; 2], mass: f32, color: &str) -> SceneBuilder {
        let mut o = Table::new();
        o.insert("name".into(), Value::from(name));
        match shape {
            ShapeSpec::Box { size } => {
                o.insert("shape".into(), Value::from("box"));
                o.insert("size".into(), floats(&size));
            }
            ShapeSpec::Sphere { radius } => {
                o.insert("shape".into(), Value::from("sphere"));
                o.insert("radius".into(), Value::from(f64::from(radius)));
            }
            ShapeSpec::Cylinder { radius, height } => {
                o.insert("shape".into(), Value::from("cylinder"));
                o.insert("radius".into(), Value::from(f64::from(radius)));
                o.insert("height".into(), Value::from(f64::from(height)));
            }
        }
        o.insert("mass".into(), Value::from(f64::from(mass)));
        o.insert("color".into(), Value::from(color));
        o.insert("position".into(), floats(&position));
        self.objects.push(Value::Table(o));
        self
    }

    /// A positioning goal's target: `object` must come to rest within
    /// `tolerance` (m) of `position`.
    pub fn positioning_target(mut self, object: &str, position: [f32; 2], tolerance: f32) -> SceneBuilder {
        let mut t = Table::new();
        t.insert("object".into(), Value::from(object));
        t.insert("position".into(), floats(&position));
        t.insert("tolerance".into(), Value::from(f64::from(tolerance)));
        self.targets.push(Value::Table(t));
        self
    }

    /// How long a positioned object must rest on its target before it
    /// counts (s; default 0.5).
    pub fn dwell(mut self, seconds: f32) -> SceneBuilder {
        self.dwell_s = Some(seconds);
        self
    }

    /// A `[technique]` setting (see the technique settings' reference).
    pub fn technique_setting(mut self, key: &str, value: impl Into<Value>) -> SceneBuilder {
        let table = self.root.entry("technique").or_insert_with(|| Value::Table(Table::new()));
        if let Value::Table(t) = table {
            t.insert(key.into(), value.into());
        }
        self
    }

    /// The scene as the TOML text a scene file would hold.
    pub fn to_toml(&self) -> String {
        let mut root = self.root.clone();
        if !self.objects.is_empty() {
            root.insert("objects".into(), Value::Array(self.objects.clone()));
        }
        if !self.targets.is_empty() {
            let mut goal = Table::from_iter([
                ("kind".to_owned(), Value::from("positioning")),
                ("targets".to_owned(), Value::Array(self.targets.clone())),
            ]);
            if let Some(d) = self.dwell_s {
                goal.insert("dwell_s".to_owned(), Value::from(f64::from(d)));
            }
            root.insert("goal".into(), Value::Table(goal));
        }
        root.to_string()
    }

    /// Validates the scene exactly as a scene file is validated.
    pub fn build(&self) -> Result<Scene, SceneError> {
        let name = self.root.get("name").and_then(Value::as_str).unwrap_or("scene");
        super::parse(&self.to_toml(), &format!("{name} (built in code)"))
    }
}

fn floats(v: &[f32]) -> Value {
    Value::Array(v.iter().map(|&x| Value::from(f64::from(x))).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_built_scene_equals_the_same_scene_read_from_a_file() {
        let built = SceneBuilder::new("one_box")
            .effects(&[Effect::Gravity, Effect::Friction, Effect::Joints])
            .object("box", ShapeSpec::Box { size: [0.14, 0.14, 0.03] }, [0.0, 0.0], 0.2, "orange")
            .build()
            .expect("valid");
        let file = super::super::parse(
            "name = \"one_box\"\ndescription = \"x\"\neffects = [\"gravity\", \"friction\", \"joints\"]\n\
             [table]\nsize = [1.0, 0.75]\n[[objects]]\nname = \"box\"\nshape = \"box\"\n\
             size = [0.14, 0.14, 0.03]\nmass = 0.2\ncolor = \"orange\"\nposition = [0.0, 0.0]\n",
            "file",
        )
        .expect("valid");
        assert_eq!(built.objects, file.objects);
        assert_eq!((built.effects, built.table, built.physics), (file.effects, file.table, file.physics));
    }

    #[test]
    fn a_bad_field_is_named_as_in_a_file() {
        let err = SceneBuilder::new("bad")
            .object("a", ShapeSpec::Sphere { radius: 0.03 }, [0.0, 0.0], 0.1, "red")
            .object("b", ShapeSpec::Sphere { radius: 0.03 }, [0.2, 0.0], 0.0, "red")
            .build()
            .expect_err("zero mass");
        let text = crate::error::chain(&err);
        assert!(text.contains("bad (built in code)") && text.contains("objects[1].mass"), "{text}");
        let err = SceneBuilder::new("off")
            .object("a", ShapeSpec::Sphere { radius: 0.03 }, [0.0, 0.0], 0.1, "red")
            .positioning_target("a", [3.0, 0.0], 0.01)
            .build()
            .expect_err("target off the table");
        assert!(crate::error::chain(&err).contains("goal.targets[0]"), "{}", crate::error::chain(&err));
    }
}
