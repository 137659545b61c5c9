//! From TOML text to a validated [`Scene`]. Input is cleaned once, here, so
//! everything downstream can trust it.

use super::bounds;
use super::defaults as default;
use super::effects::EffectSet;
use super::error::SceneError;
use super::fields::FieldReader;
use super::file::{
    BodyKindFile, CameraFile, GoalFile, GoalKind, ObjectFile, PhysicsFile, SceneFile, ShapeKind, SoftBodyFile,
    SoftKindFile, TableFile,
};
use super::id::{ObjectId, SoftId};
use super::model::{
    BodyKind, CameraSpec, Color, Goal, ObjectSpec, PhysicsSpec, Scene, Shape, SoftBodySpec, SoftKind, SortingZone,
    SteeringGoal, Table, Target,
};
use super::work::Work;
use glam::{EulerRot, Quat, Vec2, Vec3};
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// Finds a scene: an existing path, else `tasks/NAME.toml` under the current
/// directory. `None` from both means: look for it among the built-in scenes
/// ([`super::builtin`]); the error then lists everything tried.
pub fn resolve_path(name_or_path: &str) -> Result<PathBuf, SceneError> {
    let direct = PathBuf::from(name_or_path);
    if direct.is_file() {
        return Ok(direct);
    }
    let local = PathBuf::from("tasks").join(scene_file(name_or_path));
    if local.is_file() {
        return Ok(local);
    }
    Err(SceneError::NotFound {
        name: name_or_path.to_string(),
        tried: format!(
            "{}, {}, the built-in scenes ({})",
            direct.display(),
            local.display(),
            super::builtin::scene_names().collect::<Vec<_>>().join(", ")
        ),
    })
}

/// `NAME.toml` for a bare name, the name itself when it ends in `.toml`.
fn scene_file(name_or_path: &str) -> String {
    if Path::new(name_or_path).extension().is_some_and(|e| e.eq_ignore_ascii_case("toml")) {
        name_or_path.to_string()
    } else {
        format!("{name_or_path}.toml")
    }
}

/// Resolves and loads a scene by name (`positioning`) or path: a file on
/// disk first, else the built-in copy of the same path or name.
pub fn load(name_or_path: &str) -> Result<Scene, SceneError> {
    match resolve_path(name_or_path) {
        Ok(path) => {
            let text =
                crate::files::read_capped(&path).map_err(|source| SceneError::Io { path: path.clone(), source })?;
            parse(&text, &path.display().to_string())
        }
        Err(not_found) => {
            // As on disk: the path itself, then under `tasks/`
            // (`positioning`, `cases/one_box`, `tasks/cases/one_box.toml`).
            let file = PathBuf::from(scene_file(name_or_path));
            let found = [file.clone(), Path::new("tasks").join(&file)]
                .into_iter()
                .find_map(|rel| super::builtin::file(&rel).map(|text| (rel, text)));
            match found {
                Some((rel, text)) => parse(text, &format!("{} (built in)", rel.display())),
                None => Err(not_found),
            }
        }
    }
}

/// Parses and validates scene TOML. `origin` names the file in errors.
pub fn parse(text: &str, origin: &str) -> Result<Scene, SceneError> {
    let fields = FieldReader::new(text, origin);
    let raw: SceneFile = fields.parse()?;
    Checker { fields, origin }.scene(raw)
}

/// The scene's checks; the wording of every error is [`FieldReader`]'s.
struct Checker<'a> {
    fields: FieldReader<'a>,
    origin: &'a str,
}

impl Checker<'_> {
    /// Errors name the line where the field is written inside the table
    /// `span` (see [`FieldReader::key_offset`]).
    fn err(&self, span: &Range<usize>, field: impl Into<String>, message: impl Into<String>) -> SceneError {
        let field = field.into();
        self.fields.error(Some(self.fields.key_offset(span, &field)), field, message).into()
    }

    /// A finite number in `lo..=hi` (`hi` may be infinite).
    fn num(&self, span: &Range<usize>, field: &str, v: f32, lo: f32, hi: f32) -> Result<f32, SceneError> {
        Ok(self.fields.number(Some(self.fields.key_offset(span, field)), field, v, lo, hi)?)
    }

    fn positive(&self, span: &Range<usize>, field: &str, v: f32) -> Result<f32, SceneError> {
        Ok(self.fields.positive(Some(self.fields.key_offset(span, field)), field, v)?)
    }

    /// A finite number greater than 0 and at most `hi`.
    fn positive_upto(&self, span: &Range<usize>, field: &str, v: f32, hi: f32) -> Result<f32, SceneError> {
        let v = self.positive(span, field, v)?;
        if v > hi {
            return Err(self.err(span, field, format!("{} is out of range (at most {})", human(v), human(hi))));
        }
        Ok(v)
    }

    /// A finite number within a bound from [`bounds`].
    fn within(&self, span: &Range<usize>, field: &str, v: f32, (lo, hi): (f32, f32)) -> Result<f32, SceneError> {
        self.num(span, field, v, lo, hi)
    }

    /// A name other entries, goals and reports refer to: not empty or blank.
    fn named(&self, span: &Range<usize>, field: &str, name: &str) -> Result<(), SceneError> {
        if name.trim().is_empty() {
            return Err(self.err(span, field, "must not be empty: goals, reports and the demo name things by it"));
        }
        Ok(())
    }

    /// An integer in `lo..=hi`.
    fn count<T>(&self, span: &Range<usize>, field: &str, v: T, lo: T, hi: T) -> Result<T, SceneError>
    where
        T: Copy + PartialOrd + std::fmt::Display,
    {
        Ok(self.fields.in_range(Some(self.fields.key_offset(span, field)), field, v, lo, hi)?)
    }

    fn scene(&self, raw: SceneFile) -> Result<Scene, SceneError> {
        self.named(&(0..0), "name", &raw.name)?;
        let effects: EffectSet = raw.effects.iter().copied().collect();
        let table = self.table(raw.table)?;
        let camera = self.camera(raw.camera)?;
        // Where a work error points: the physics rate when the file sets one.
        let rate_span = raw.physics.as_ref().map(Spanned::span);
        let physics = self.physics(raw.physics)?;
        let (objects, names) = self.all_objects(raw.objects, &table)?;
        let soft_bodies = self.soft_bodies(raw.soft_bodies, &table, effects, &names)?;

        let time_limit_s = match raw.time_limit_s {
            Some(s) => {
                let span = s.span();
                self.positive_upto(&span, "time_limit_s", s.into_inner(), bounds::DURATION_S)?
            }
            None => default::TIME_LIMIT_S,
        };

        let goal = match raw.goal {
            Some(g) => {
                let span = g.span();
                let goal = self.goal(g, &table, &objects, &soft_bodies)?;
                // A goal that must hold still for longer than the trial
                // lasts can never be met.
                if let Some(dwell) = dwell_of(&goal).filter(|&d| d >= time_limit_s) {
                    return Err(self.err(
                        &span,
                        "goal.dwell_s",
                        format!(
                            "{} s of holding still is not less than the {} s time limit: the goal can never be met",
                            human(dwell),
                            human(time_limit_s)
                        ),
                    ));
                }
                goal
            }
            None => Goal::None,
        };

        let scene = Scene {
            name: raw.name,
            origin: self.origin.to_string(),
            description: raw.description,
            hint: raw.hint,
            effects,
            time_limit_s,
            table,
            camera,
            physics,
            objects,
            soft_bodies,
            goal,
            technique: raw.technique.iter().flatten().map(|(k, v)| (k.clone(), v.get_ref().clone())).collect(),
            technique_lines: raw
                .technique
                .iter()
                .flatten()
                .map(|(k, v)| (k.clone(), self.fields.line(v.span().start)))
                .collect(),
        };
        if let Err(message) = Work::of(&scene, scene.time_limit_s).check() {
            return Err(match rate_span {
                Some(span) => self.err(&span, "physics.timestep_hz", message),
                None => self.err(&(0..0), "time_limit_s", message),
            });
        }
        Ok(scene)
    }

    fn table(&self, raw: Spanned<TableFile>) -> Result<Table, SceneError> {
        let tspan = raw.span();
        let t = raw.into_inner();
        let width = self.within(&tspan, "table.size[0]", t.size[0], bounds::TABLE_SIDE_M)?;
        let depth = self.within(&tspan, "table.size[1]", t.size[1], bounds::TABLE_SIDE_M)?;
        let table_color = match &t.color {
            Some(c) => {
                Color::parse(c).ok_or_else(|| self.err(&tspan, "table.color", format!("unknown colour `{c}`")))?
            }
            None => Color { rgba: default::TABLE_COLOR },
        };
        let table = Table {
            width,
            depth,
            friction: self.num(&tspan, "table.friction", t.friction.unwrap_or(default::TABLE_FRICTION), 0.0, 10.0)?,
            restitution: self.num(
                &tspan,
                "table.restitution",
                t.restitution.unwrap_or(default::TABLE_RESTITUTION),
                0.0,
                1.0,
            )?,
            color: table_color,
            walls: t.walls.unwrap_or(default::TABLE_WALLS),
        };
        Ok(table)
    }

    fn camera(&self, raw: Option<Spanned<CameraFile>>) -> Result<CameraSpec, SceneError> {
        let camera = match raw {
            Some(c) => {
                let span = c.span();
                CameraSpec {
                    height: self.within(&span, "camera.height", c.into_inner().height, bounds::CAMERA_HEIGHT_M)?,
                }
            }
            None => CameraSpec { height: default::CAMERA_HEIGHT },
        };
        Ok(camera)
    }

    fn physics(&self, raw: Option<Spanned<PhysicsFile>>) -> Result<PhysicsSpec, SceneError> {
        let mut physics = PhysicsSpec::default();
        if let Some(p) = raw {
            let span = p.span();
            let p = p.into_inner();
            if let Some(hz) = p.timestep_hz {
                physics.dt = 1.0 / self.num(&span, "physics.timestep_hz", hz, 10.0, 10_000.0)?;
            }
            if let Some(n) = p.solver_iterations {
                physics.solver_iterations = self.count(&span, "physics.solver_iterations", n, 1, 100)?;
            }
            if let Some(n) = p.pgs_iterations {
                physics.pgs_iterations = self.count(&span, "physics.pgs_iterations", n, 1, 100)?;
            }
            if let Some(l) = p.length_unit {
                physics.length_unit = self.within(&span, "physics.length_unit", l, bounds::LENGTH_UNIT_M)?;
            }
            if let Some(n) = p.ccd_substeps {
                physics.ccd_substeps = self.count(&span, "physics.ccd_substeps", n, 0, bounds::CCD_SUBSTEPS)?;
            }
            if let Some(hz) = p.contact_hz {
                physics.contact_hz = self.num(&span, "physics.contact_hz", hz, 1.0, 10_000.0)?;
            }
            if let Some(g) = p.give_way {
                physics.give_way = g;
            }
            if let Some(v) = p.max_speed {
                physics.max_speed = self.within(&span, "physics.max_speed", v, bounds::MAX_SPEED_M_S)?;
            }
        }
        Ok(physics)
    }

    /// Every object (copies expanded), and their names, each once.
    fn all_objects(
        &self,
        raw: Vec<Spanned<ObjectFile>>,
        table: &Table,
    ) -> Result<(Vec<ObjectSpec>, std::collections::HashSet<String>), SceneError> {
        let mut objects = Vec::new();
        // Where each object was written (its entry's index and span), for
        // the duplicate-name error.
        let mut written = Vec::new();
        for (i, o) in raw.into_iter().enumerate() {
            let span = o.span();
            self.objects(i, o, table, &mut objects)?;
            written.resize(objects.len(), (i, span));
        }
        // O(n log n): a pairwise check takes seconds for tens of thousands of names.
        let mut seen = std::collections::HashSet::with_capacity(objects.len());
        for (a, (i, span)) in objects.iter().zip(&written) {
            if !seen.insert(a.name.clone()) {
                return Err(self.err(
                    span,
                    format!("objects[{i}].name"),
                    format!("`{}` is the name of two objects", a.name),
                ));
            }
        }
        Ok((objects, seen))
    }

    /// Every soft body; a name may not repeat an object's or another's.
    fn soft_bodies(
        &self,
        raw: Vec<Spanned<SoftBodyFile>>,
        table: &Table,
        effects: EffectSet,
        object_names: &std::collections::HashSet<String>,
    ) -> Result<Vec<SoftBodySpec>, SceneError> {
        let mut soft_bodies = Vec::new();
        let mut soft_names = std::collections::HashSet::new();
        for (i, b) in raw.into_iter().enumerate() {
            let span = b.span();
            let spec = self.soft_body(i, b, table, effects)?;
            if object_names.contains(&spec.name) || !soft_names.insert(spec.name.clone()) {
                return Err(self.err(
                    &span,
                    format!("soft_bodies[{i}].name"),
                    format!("`{}` is already the name of an object or soft body", spec.name),
                ));
            }
            soft_bodies.push(spec);
        }
        Ok(soft_bodies)
    }

    fn objects(
        &self,
        i: usize,
        o: Spanned<ObjectFile>,
        table: &Table,
        out: &mut Vec<ObjectSpec>,
    ) -> Result<(), SceneError> {
        let span = o.span();
        let o = o.into_inner();
        let f = |field: &str| format!("objects[{i}].{field}");
        self.named(&span, &f("name"), &o.name)?;
        let shape = self.object_shape(&span, i, &o)?;
        let body = match o.body.unwrap_or(BodyKindFile::Dynamic) {
            BodyKindFile::Dynamic => BodyKind::Dynamic,
            BodyKindFile::Fixed => BodyKind::Fixed,
        };
        let mass = match (body, o.mass) {
            (BodyKind::Dynamic, None) => return Err(self.err(&span, f("mass"), "a dynamic object needs `mass` (kg)")),
            (_, Some(m)) => self.within(&span, &f("mass"), m, bounds::MASS_KG)?,
            (BodyKind::Fixed, None) => 0.0,
        };
        let color = Color::parse(&o.color).ok_or_else(|| {
            let names: Vec<&str> = Color::NAMED.iter().map(|(n, _)| *n).collect();
            self.err(
                &span,
                f("color"),
                format!("unknown colour `{}` (use #rrggbb or one of {})", o.color, names.join(", ")),
            )
        })?;
        let rot = o.rotation_deg.unwrap_or([0.0; 3]);
        for (k, v) in rot.iter().enumerate() {
            self.num(&span, &f(&format!("rotation_deg[{k}]")), *v, -360.0, 360.0)?;
        }
        let rotation = Quat::from_euler(EulerRot::XYZ, rot[0].to_radians(), rot[1].to_radians(), rot[2].to_radians());
        let base = match o.position.as_slice() {
            [x, y] => Vec3::new(*x, *y, shape.half_z()),
            [x, y, z] => Vec3::new(*x, *y, *z),
            _ => return Err(self.err(&span, f("position"), "must be [x, y] or [x, y, z]")),
        };
        let p = bounds::POSITION_M;
        for (k, v) in base.to_array().iter().enumerate() {
            self.num(&span, &f(&format!("position[{k}]")), *v, -p, p)?;
        }
        // Checked before anything is allocated for the copies.
        let max = u32::try_from(bounds::MAX_OBJECTS).unwrap_or(u32::MAX);
        let count = self.count(&span, &f("count"), o.count.unwrap_or(default::OBJECT_COUNT), 1, max)?;
        if out.len() + count as usize > bounds::MAX_OBJECTS {
            return Err(self.err(
                &span,
                f("count"),
                format!(
                    "{count} would make {} objects; a scene may have at most {}",
                    out.len() + count as usize,
                    bounds::MAX_OBJECTS
                ),
            ));
        }
        let (step, row_step, per_row) = self.copy_layout(&span, i, &o, count)?;
        for k in 0..count {
            let offset = step * (k % per_row) as f32 + row_step * (k / per_row) as f32;
            let position = base + offset.extend(0.0);
            self.copy_on_table(&span, i, k, position, body, table)?;
            let name = if count == 1 { o.name.clone() } else { format!("{}{}", o.name, k + 1) };
            out.push(ObjectSpec {
                name,
                shape,
                mass,
                friction: self.num(&span, &f("friction"), o.friction.unwrap_or(default::OBJECT_FRICTION), 0.0, 10.0)?,
                restitution: self.num(
                    &span,
                    &f("restitution"),
                    o.restitution.unwrap_or(default::OBJECT_RESTITUTION),
                    0.0,
                    1.0,
                )?,
                color,
                position,
                rotation,
                body,
                linear_damping: self.num(
                    &span,
                    &f("linear_damping"),
                    o.linear_damping.unwrap_or(default::OBJECT_DAMPING),
                    0.0,
                    100.0,
                )?,
                angular_damping: self.num(
                    &span,
                    &f("angular_damping"),
                    o.angular_damping.unwrap_or(default::OBJECT_DAMPING),
                    0.0,
                    100.0,
                )?,
            });
        }
        Ok(())
    }

    /// An object's shape, from the keys its `shape` needs.
    fn object_shape(&self, span: &Range<usize>, i: usize, o: &ObjectFile) -> Result<Shape, SceneError> {
        let span = span.clone();
        let f = |field: &str| format!("objects[{i}].{field}");
        let need = |v: Option<f32>, field: &str| {
            v.ok_or_else(|| self.err(&span, f(field), format!("a {:?} needs `{field}`", o.shape).to_lowercase()))
        };
        Ok(match o.shape {
            ShapeKind::Box => {
                let s = o.size.ok_or_else(|| self.err(&span, f("size"), "a box needs `size = [x, y, z]`"))?;
                for (k, v) in s.iter().enumerate() {
                    self.within(&span, &f(&format!("size[{k}]")), *v, bounds::OBJECT_SIZE_M)?;
                }
                Shape::Box { half_extents: Vec3::from(s) / 2.0 }
            }
            ShapeKind::Sphere => Shape::Sphere {
                radius: self.within(&span, &f("radius"), need(o.radius, "radius")?, bounds::OBJECT_SIZE_M)?,
            },
            ShapeKind::Cylinder => Shape::Cylinder {
                radius: self.within(&span, &f("radius"), need(o.radius, "radius")?, bounds::OBJECT_SIZE_M)?,
                half_height: self.within(&span, &f("height"), need(o.height, "height")?, bounds::OBJECT_SIZE_M)? / 2.0,
            },
            ShapeKind::Capsule => Shape::Capsule {
                radius: self.within(&span, &f("radius"), need(o.radius, "radius")?, bounds::OBJECT_SIZE_M)?,
                half_height: self.num(&span, &f("height"), need(o.height, "height")?, 0.0, bounds::OBJECT_SIZE_M.1)?
                    / 2.0,
            },
        })
    }

    /// Where an object's `count` copies go: `step` between copies in a row,
    /// `row_step` between rows of `per_row`.
    fn copy_layout(
        &self,
        span: &Range<usize>,
        i: usize,
        o: &ObjectFile,
        count: u32,
    ) -> Result<(Vec2, Vec2, u32), SceneError> {
        let span = span.clone();
        let f = |field: &str| format!("objects[{i}].{field}");
        let p = bounds::POSITION_M;
        let vector = |name: &str, v: Option<[f32; 2]>| -> Result<Vec2, SceneError> {
            let v = v.unwrap_or([0.0, 0.0]);
            for (k, c) in v.iter().enumerate() {
                self.num(&span, &f(&format!("{name}[{k}]")), *c, -p, p)?;
            }
            Ok(Vec2::from(v))
        };
        let step = vector("step", o.step)?;
        let row_step = vector("row_step", o.row_step)?;
        let per_row = match o.per_row {
            Some(n) => self.count(&span, &f("per_row"), n, 1, count)?,
            None => count,
        };
        // Copies at one spot are one solid overlap the solver cannot
        // separate (thousands of boxes at one spot take gigabytes and never settle).
        if per_row > 1 && step == Vec2::ZERO {
            return Err(self.err(&span, f("step"), format!("{count} copies need a `step` that is not [0, 0]")));
        }
        if count > per_row && row_step == Vec2::ZERO {
            return Err(self.err(
                &span,
                f("row_step"),
                format!("{count} copies in rows of {per_row} need a `row_step` that is not [0, 0]"),
            ));
        }
        Ok((step, row_step, per_row))
    }

    /// Copy `k` of object `i` lies near the table, and on it if it moves.
    fn copy_on_table(
        &self,
        span: &Range<usize>,
        i: usize,
        k: u32,
        position: Vec3,
        body: BodyKind,
        table: &Table,
    ) -> Result<(), SceneError> {
        let f = |field: &str| format!("objects[{i}].{field}");
        let p = bounds::POSITION_M;
        if !(position.is_finite() && position.abs().max_element() <= p) {
            return Err(self.err(
                span,
                f("position"),
                format!(
                    "copy {} lies at ({}, {}), farther than {p} m from the table centre",
                    k + 1,
                    human(position.x),
                    human(position.y)
                ),
            ));
        }
        if !table_contains(table, position.truncate()) && body == BodyKind::Dynamic {
            return Err(self.err(
                span,
                f("position"),
                format!(
                    "({:.3}, {:.3}) lies off the table (±{:.3} × ±{:.3})",
                    position.x,
                    position.y,
                    table.width / 2.0,
                    table.depth / 2.0
                ),
            ));
        }
        Ok(())
    }

    /// One `[[soft_bodies]]` entry. Its effect must be declared: a scene
    /// that does not ask for soft bodies never pays for them.
    fn soft_body(
        &self,
        i: usize,
        b: Spanned<SoftBodyFile>,
        table: &Table,
        effects: EffectSet,
    ) -> Result<SoftBodySpec, SceneError> {
        let span = b.span();
        let b = b.into_inner();
        let f = |field: &str| format!("soft_bodies[{i}].{field}");
        self.named(&span, &f("name"), &b.name)?;
        let kind = match b.kind {
            SoftKindFile::Cloth => SoftKind::Cloth,
            SoftKindFile::Volume => SoftKind::Volume,
        };
        let dims = match kind {
            SoftKind::Cloth => 2,
            SoftKind::Volume => 3,
        };
        if b.size.len() != dims {
            let want = if dims == 2 { "[x, y]" } else { "[x, y, z]" };
            return Err(self.err(&span, f("size"), format!("a {} needs `size = {want}`", kind.name())));
        }
        let mut size = Vec3::ZERO;
        for (k, v) in b.size.iter().enumerate() {
            size[k] = self.within(&span, &f(&format!("size[{k}]")), *v, bounds::OBJECT_SIZE_M)?;
        }
        let thickness = self.positive(
            &span,
            &f("thickness"),
            b.thickness.unwrap_or(match kind {
                SoftKind::Cloth => default::CLOTH_THICKNESS,
                SoftKind::Volume => default::VOLUME_THICKNESS,
            }),
        )?;
        if thickness > default::MAX_SOFT_THICKNESS {
            return Err(self.err(
                &span,
                f("thickness"),
                format!("{thickness} is out of range (up to {} m)", default::MAX_SOFT_THICKNESS),
            ));
        }
        let entry = SoftEntry { span: &span, i, file: &b, kind, size };
        let resolution = self.soft_resolution(&entry)?;
        let position = self.soft_position(&entry, thickness, table)?;
        let mass = self.soft_mass(&entry)?;
        self.cloth_only_keys(&entry)?;
        let tear_strain = match b.tear_strain {
            Some(t) => Some(
                self.positive(&span, &f("tear_strain"), t)
                    .and_then(|t| self.num(&span, &f("tear_strain"), t, 0.0, 10.0))?,
            ),
            None => None,
        };
        let color = Color::parse(&b.color)
            .ok_or_else(|| self.err(&span, f("color"), format!("unknown colour `{}`", b.color)))?;
        let spec = SoftBodySpec {
            name: b.name,
            kind,
            size,
            resolution,
            position,
            mass,
            stiffness: self.num(
                &span,
                &f("stiffness"),
                b.stiffness.unwrap_or(default::SOFT_STIFFNESS_HZ),
                0.1,
                10_000.0,
            )?,
            bending: self.num(&span, &f("bending"), b.bending.unwrap_or(default::CLOTH_BENDING_HZ), 0.0, 10_000.0)?,
            tear_strain,
            friction: self.num(&span, &f("friction"), b.friction.unwrap_or(default::SOFT_FRICTION), 0.0, 10.0)?,
            thickness,
            damping: self.num(&span, &f("damping"), b.damping.unwrap_or(default::SOFT_DAMPING), 0.0, 100.0)?,
            crumple: self.num(&span, &f("crumple"), b.crumple.unwrap_or(0.0), 0.0, 0.6)?,
            crease: self.num(&span, &f("crease"), b.crease.unwrap_or(0.0), 0.0, 0.5)?,
            color,
        };
        for e in spec.required_effects().iter() {
            if !effects.contains(e) {
                let (field, what) = match e {
                    super::Effect::Tearing => (f("tear_strain"), "tearing".to_string()),
                    _ => (f("kind"), format!("a {}", kind.name())),
                };
                return Err(self.err(&span, field, format!("{what} needs the `{e}` effect: add it to `effects`")));
            }
        }
        Ok(spec)
    }

    /// Where a soft body starts: as written, or resting on the table at
    /// `[x, y]`; on the table either way.
    fn soft_position(&self, e: &SoftEntry, thickness: f32, table: &Table) -> Result<Vec3, SceneError> {
        let (span, kind, size, f) = (e.span, e.kind, e.size, |field: &str| e.field(field));
        let position = match e.file.position.as_slice() {
            [x, y] => Vec3::new(*x, *y, if kind == SoftKind::Cloth { thickness } else { size.z / 2.0 + thickness }),
            [x, y, z] => Vec3::new(*x, *y, *z),
            _ => return Err(self.err(span, f("position"), "must be [x, y] or [x, y, z]")),
        };
        for (k, v) in position.to_array().iter().enumerate() {
            self.num(span, &f(&format!("position[{k}]")), *v, -bounds::POSITION_M, bounds::POSITION_M)?;
        }
        if !table_contains(table, position.truncate()) {
            return Err(self.err(
                span,
                f("position"),
                format!("({:.3}, {:.3}) lies off the table", position.x, position.y),
            ));
        }
        Ok(position)
    }

    /// A soft body's particle grid: as written, or from its size at the
    /// kind's default spacing; never more particles than the bound.
    fn soft_resolution(&self, e: &SoftEntry) -> Result<[usize; 3], SceneError> {
        let (span, kind, size, f) = (e.span, e.kind, e.size, |field: &str| e.field(field));
        let dims = if kind == SoftKind::Cloth { 2 } else { 3 };
        let spacing = if kind == SoftKind::Cloth { default::CLOTH_SPACING } else { default::VOLUME_SPACING };
        let resolution = if let Some(r) = &e.file.resolution {
            if r.len() != dims {
                return Err(self.err(
                    span,
                    f("resolution"),
                    format!("needs {dims} entries, one per side, got {}", r.len()),
                ));
            }
            let mut out = [1usize; 3];
            let (lo, hi) = default::RESOLUTION_RANGE;
            for (k, n) in r.iter().enumerate() {
                out[k] = self.count(span, &f(&format!("resolution[{k}]")), *n, lo, hi)? as usize;
            }
            out
        } else {
            let (lo, hi) = default::AUTO_RESOLUTION;
            let n = |l: f32| ((l / spacing).round() as usize + 1).clamp(lo, hi);
            [n(size.x), n(size.y), if dims == 3 { n(size.z) } else { 1 }]
        };
        let particles = resolution.iter().product::<usize>();
        if particles > default::MAX_SOFT_PARTICLES {
            return Err(self.err(
                span,
                f("resolution"),
                format!("{particles} particles is too many (at most {})", default::MAX_SOFT_PARTICLES),
            ));
        }
        Ok(resolution)
    }

    /// Keys only a cloth has, on anything else, are an error (not ignored).
    fn cloth_only_keys(&self, e: &SoftEntry) -> Result<(), SceneError> {
        if e.kind == SoftKind::Cloth {
            return Ok(());
        }
        let (span, b, f) = (e.span, e.file, |field: &str| e.field(field));
        if b.bending.is_some() {
            return Err(self.err(span, f("bending"), "only a cloth has bending springs"));
        }
        if b.crumple.is_some() {
            return Err(self.err(span, f("crumple"), "only a cloth can start crumpled"));
        }
        if b.crease.is_some() {
            return Err(self.err(span, f("crease"), "only a cloth creases"));
        }
        Ok(())
    }

    /// A soft body's mass: `mass`, or `density` times its area (cloth) or
    /// volume, one of the two.
    fn soft_mass(&self, e: &SoftEntry) -> Result<f32, SceneError> {
        let (span, b, kind, size, f) = (e.span, e.file, e.kind, e.size, |field: &str| e.field(field));
        let dims = if kind == SoftKind::Cloth { 2 } else { 3 };
        let measure = if dims == 2 { size.x * size.y } else { size.x * size.y * size.z };
        let mass = match (b.mass, b.density) {
            (Some(m), None) => self.within(span, &f("mass"), m, bounds::MASS_KG)?,
            (None, Some(d)) => {
                let mass = self.within(span, &f("density"), d, bounds::DENSITY)? * measure;
                let (lo, hi) = bounds::MASS_KG;
                if !(lo..=hi).contains(&mass) {
                    return Err(self.err(
                        span,
                        f("density"),
                        format!("gives a mass of {} kg, out of range ({}..={} kg)", human(mass), human(lo), human(hi)),
                    ));
                }
                mass
            }
            (Some(_), Some(_)) => return Err(self.err(span, f("density"), "give `mass` or `density`, not both")),
            (None, None) => {
                return Err(self.err(span, f("mass"), format!("a {} needs `mass` (kg) or `density`", kind.name())));
            }
        };
        Ok(mass)
    }

    fn goal(
        &self,
        g: Spanned<GoalFile>,
        table: &Table,
        objects: &[ObjectSpec],
        soft: &[SoftBodySpec],
    ) -> Result<Goal, SceneError> {
        let span = g.span();
        let g = g.into_inner();
        if let Some(key) = g.given().into_iter().find(|k| !g.kind.keys().contains(k)) {
            let keys = g.kind.keys().iter().map(|k| format!("`{k}`")).collect::<Vec<_>>();
            let keys = if keys.is_empty() { "none".to_string() } else { keys.join(", ") };
            return Err(self.err(
                &span,
                format!("goal.{key}"),
                format!("a {} goal has no `{key}` (its keys: `kind`, {keys})", g.kind.name()),
            ));
        }
        let dwell_s = self.num(&span, "goal.dwell_s", g.dwell_s.unwrap_or(default::DWELL_S), 0.0, 60.0)?;
        let r = GoalReader { c: self, span, table, objects, soft, dwell_s };
        match g.kind {
            GoalKind::None => Ok(Goal::None),
            GoalKind::Positioning => r.positioning(g),
            GoalKind::Sorting => r.sorting(g),
            GoalKind::Steering => r.steering(&g),
            GoalKind::Gather => r.gather(&g),
            GoalKind::Region => r.region(&g),
            GoalKind::ClothFlat | GoalKind::Torn => r.soft_body(&g),
        }
    }
}

/// A `[[soft_bodies]]` entry while its derived values (grid, position,
/// mass) are checked: where it is written, its index, the entry, and its
/// kind and size, checked before them.
struct SoftEntry<'a> {
    span: &'a Range<usize>,
    i: usize,
    file: &'a SoftBodyFile,
    kind: SoftKind,
    size: Vec3,
}

impl SoftEntry<'_> {
    /// The path of one of its keys in error messages.
    fn field(&self, field: &str) -> String {
        format!("soft_bodies[{}].{field}", self.i)
    }
}

/// What a `[goal]` table's kinds share while they are checked: where the
/// table is written, and the table, objects and soft bodies its names and
/// points refer to. One method per goal kind.
struct GoalReader<'a> {
    c: &'a Checker<'a>,
    span: Range<usize>,
    table: &'a Table,
    objects: &'a [ObjectSpec],
    soft: &'a [SoftBodySpec],
    dwell_s: f32,
}

impl GoalReader<'_> {
    fn err(&self, field: impl Into<String>, message: impl Into<String>) -> SceneError {
        self.c.err(&self.span, field, message)
    }

    /// The object a required name field names.
    fn object_named(&self, name: Option<&String>, field: &str) -> Result<ObjectId, SceneError> {
        let n = name.ok_or_else(|| self.err(field, format!("this goal needs `{field}`")))?;
        self.objects
            .iter()
            .position(|o| &o.name == n)
            .map(ObjectId::new)
            .ok_or_else(|| self.err(field, format!("no object named `{n}`")))
    }

    /// A finite point on the table, from the table written at `sp`.
    fn on_table(&self, p: [f32; 2], sp: &Range<usize>, field: &str) -> Result<Vec2, SceneError> {
        let v = Vec2::from(p);
        if !v.is_finite() {
            return Err(self.c.err(sp, field, "must be finite"));
        }
        if !table_contains(self.table, v) {
            return Err(self.c.err(
                sp,
                field,
                format!(
                    "({:.3}, {:.3}) lies off the table (±{:.3} × ±{:.3})",
                    v.x,
                    v.y,
                    self.table.width / 2.0,
                    self.table.depth / 2.0
                ),
            ));
        }
        Ok(v)
    }

    /// A required point on the table.
    fn point(&self, p: Option<[f32; 2]>, field: &str, kind: &str) -> Result<Vec2, SceneError> {
        let name = field.trim_start_matches("goal.");
        let p = p.ok_or_else(|| self.err(field, format!("a {kind} goal needs `{name}`")))?;
        self.on_table(p, &self.span, field)
    }

    /// A length in `(0, GOAL_LENGTH_M]`.
    fn length(&self, field: &str, v: f32) -> Result<f32, SceneError> {
        self.c.positive_upto(&self.span, field, v, bounds::GOAL_LENGTH_M)
    }

    /// Each entry of a goal's non-empty list (`goal.targets`, `goal.zones`),
    /// checked by `check` with the entry's index and its span in the file.
    fn each_entry<T, U>(
        &self,
        list: Vec<Spanned<T>>,
        field: &str,
        needs: &str,
        check: impl Fn(usize, &Range<usize>, T) -> Result<U, SceneError>,
    ) -> Result<Vec<U>, SceneError> {
        if list.is_empty() {
            return Err(self.err(field, needs));
        }
        list.into_iter().enumerate().map(|(i, entry)| check(i, &entry.span(), entry.into_inner())).collect()
    }

    fn positioning(&self, g: GoalFile) -> Result<Goal, SceneError> {
        let needs = "a positioning goal needs at least one [[goal.targets]]";
        let targets = self.each_entry(g.targets, "goal.targets", needs, |i, tspan, t| {
            let object = self.objects.iter().position(|o| o.name == t.object).map(ObjectId::new).ok_or_else(|| {
                self.c.err(tspan, format!("goal.targets[{i}].object"), format!("no object named `{}`", t.object))
            })?;
            Ok(Target {
                object,
                position: self.on_table(t.position, tspan, &format!("goal.targets[{i}].position"))?,
                tolerance: self.c.positive_upto(
                    tspan,
                    &format!("goal.targets[{i}].tolerance"),
                    t.tolerance.unwrap_or(default::TARGET_TOLERANCE),
                    bounds::GOAL_LENGTH_M,
                )?,
            })
        })?;
        Ok(Goal::Positioning { targets, dwell_s: self.dwell_s })
    }

    fn sorting(&self, g: GoalFile) -> Result<Goal, SceneError> {
        let needs = "a sorting goal needs at least one [[goal.zones]]";
        let zones = self.each_entry(g.zones, "goal.zones", needs, |i, zspan, z| {
            let min = self.on_table(z.min, zspan, &format!("goal.zones[{i}].min"))?;
            let max = self.on_table(z.max, zspan, &format!("goal.zones[{i}].max"))?;
            if min.x >= max.x || min.y >= max.y {
                return Err(self.c.err(zspan, format!("goal.zones[{i}]"), "min must be below max on both axes"));
            }
            let color = Color::parse(&z.color).ok_or_else(|| {
                self.c.err(zspan, format!("goal.zones[{i}].color"), format!("unknown colour `{}`", z.color))
            })?;
            Ok(SortingZone { color, min, max })
        })?;
        Ok(Goal::Sorting { zones, dwell_s: self.dwell_s })
    }

    fn steering(&self, g: &GoalFile) -> Result<Goal, SceneError> {
        let object = self.object_named(g.object.as_ref(), "goal.object")?;
        let platform = match &g.platform {
            Some(_) => Some(self.object_named(g.platform.as_ref(), "goal.platform")?),
            None => None,
        };
        let mut waypoints = Vec::new();
        for (i, w) in g.waypoints.iter().enumerate() {
            waypoints.push(self.on_table(*w, &self.span, &format!("goal.waypoints[{i}]"))?);
        }
        let finish = self.point(g.finish, "goal.finish", "steering")?;
        Ok(Goal::Steering(SteeringGoal {
            object,
            platform,
            waypoints,
            waypoint_radius: self
                .length("goal.waypoint_radius", g.waypoint_radius.unwrap_or(default::WAYPOINT_RADIUS))?,
            finish,
            finish_radius: self.length("goal.finish_radius", g.finish_radius.unwrap_or(default::FINISH_RADIUS))?,
        }))
    }

    fn gather(&self, g: &GoalFile) -> Result<Goal, SceneError> {
        let center = self.point(g.center, "goal.center", "gather")?;
        let radius = g.radius.ok_or_else(|| self.err("goal.radius", "a gather goal needs `radius`"))?;
        Ok(Goal::Gather {
            center,
            radius: self.length("goal.radius", radius)?,
            fraction: self.c.num(
                &self.span,
                "goal.fraction",
                g.fraction.unwrap_or(default::GATHER_FRACTION),
                0.0,
                1.0,
            )?,
            dwell_s: self.dwell_s,
        })
    }

    fn region(&self, g: &GoalFile) -> Result<Goal, SceneError> {
        let min = self.point(g.min, "goal.min", "region")?;
        let max = self.point(g.max, "goal.max", "region")?;
        if min.x >= max.x || min.y >= max.y {
            return Err(self.err("goal.max", "must be above `min` on both axes"));
        }
        let max_height = match g.max_height {
            Some(h) => self.length("goal.max_height", h)?,
            None => f32::INFINITY,
        };
        let dwell_s = self.dwell_s;
        // The named thing may be a soft body (a block squeezed into a cavity).
        if let Some(body) = g.object.as_ref().and_then(|n| self.soft.iter().position(|b| &b.name == n)).map(SoftId::new)
        {
            return Ok(Goal::SoftRegion { body, min, max, max_height, dwell_s });
        }
        let object = self.object_named(g.object.as_ref(), "goal.object")?;
        // The region holds the object when its whole footprint is inside
        // and its centre is at most `max_height` up; an object whose
        // narrowest side is wider than the region, or whose centre cannot
        // come down that low in any pose, is never held.
        let spec = &self.objects[object.index()];
        let (narrowest, lowest) = least_width_and_height(&spec.shape);
        if narrowest > (max - min).min_element() {
            return Err(self.err(
                "goal.max",
                format!(
                    "the region is {:.3} m across at its narrowest, and `{}` is {:.3} m across at its narrowest: \
                     the goal can never be met",
                    (max - min).min_element(),
                    spec.name,
                    narrowest
                ),
            ));
        }
        if max_height < lowest {
            return Err(self.err(
                "goal.max_height",
                format!(
                    "{} m is below the lowest the centre of `{}` can rest ({:.3} m): the goal can never be met",
                    human(max_height),
                    spec.name,
                    lowest
                ),
            ));
        }
        Ok(Goal::Region { object, min, max, max_height, dwell_s })
    }

    /// `cloth_flat` and `torn`: goals on a named soft body.
    fn soft_body(&self, g: &GoalFile) -> Result<Goal, SceneError> {
        let (c, span) = (self.c, &self.span);
        let name =
            g.body.as_ref().ok_or_else(|| self.err("goal.body", "this goal needs `body`, the name of a soft body"))?;
        let body = self
            .soft
            .iter()
            .position(|b| &b.name == name)
            .map(SoftId::new)
            .ok_or_else(|| self.err("goal.body", format!("no soft body named `{name}`")))?;
        let spec = &self.soft[body.index()];
        if g.kind == GoalKind::ClothFlat {
            if spec.kind != SoftKind::Cloth {
                return Err(self.err("goal.body", format!("`{name}` is not a cloth")));
            }
            let min_area_fraction = c.num(
                span,
                "goal.min_area_fraction",
                g.min_area_fraction.unwrap_or(default::MIN_AREA_FRACTION),
                0.01,
                1.0,
            )?;
            Ok(Goal::ClothFlat { body, min_area_fraction, dwell_s: self.dwell_s })
        } else {
            if spec.tear_strain.is_none() {
                return Err(self.err("goal.body", format!("`{name}` cannot tear: give it a `tear_strain`")));
            }
            let pieces = c.count(span, "goal.pieces", g.pieces.unwrap_or(default::TEAR_PIECES), 2, 100)?;
            let min_piece_fraction = c.num(
                span,
                "goal.min_piece_fraction",
                g.min_piece_fraction.unwrap_or(default::MIN_PIECE_FRACTION),
                0.0,
                1.0 / pieces as f32,
            )?;
            Ok(Goal::Torn { body, pieces: pieces as usize, min_piece_fraction })
        }
    }
}

/// How long a goal needs its objects to rest in place, where it does.
fn dwell_of(goal: &Goal) -> Option<f32> {
    match *goal {
        Goal::Positioning { dwell_s, .. }
        | Goal::Sorting { dwell_s, .. }
        | Goal::Gather { dwell_s, .. }
        | Goal::Region { dwell_s, .. }
        | Goal::SoftRegion { dwell_s, .. }
        | Goal::ClothFlat { dwell_s, .. } => Some(dwell_s),
        _ => None,
    }
}

/// A shape's least width across and the lowest its centre can rest on the
/// table, over every pose: a box lies on its largest face, so both come
/// from its smallest extent; a cylinder lies on its side or stands.
fn least_width_and_height(shape: &Shape) -> (f32, f32) {
    match *shape {
        Shape::Box { half_extents } => (2.0 * half_extents.min_element(), half_extents.min_element()),
        Shape::Sphere { radius } | Shape::Capsule { radius, .. } => (2.0 * radius, radius),
        Shape::Cylinder { radius, half_height } => (2.0 * radius.min(half_height), radius.min(half_height)),
    }
}

fn table_contains(table: &Table, p: Vec2) -> bool {
    p.x.abs() <= table.width / 2.0 + 1e-6 && p.y.abs() <= table.depth / 2.0 + 1e-6
}

/// A number as people write it: plain for ordinary magnitudes, in
/// scientific notation (`1e30`) when it would need many digits.
fn human(v: f32) -> String {
    super::fields::human(f64::from(v))
}
