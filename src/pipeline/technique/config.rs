//! Every technique parameter in one place, with documented defaults, and
//! overridable from a scene file's `[technique]` table.

use serde::{Deserialize, Serialize};

/// Shape of a proxy body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ProxyShape {
    /// A cube under the contact centre (the paper's default).
    Cube,
    Sphere,
    /// A long capsule from the camera's near plane down to the touched
    /// surface: it also collides with objects' sides at any height.
    Capsule,
}

/// What grey level (pressure) changes, when enabled (the paper's own suggestion).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PressureMode {
    Off,
    /// Proxy and particle weight (press) scale with the grey level.
    Weight,
}

/// What Joint and Proxy take a contact to touch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HitTest {
    /// The object under the contact's centroid, else the one its outline
    /// overlaps (see `hit_test.rs`): a flat hand whose centre misses a ball
    /// still grabs it (Joint) or lands its proxy on it (Proxy).
    Outline,
    /// The object under the contact's centroid only: the paper's
    /// point-based techniques, as its study ran them.
    Centroid,
}

/// Parameters of all four techniques. Units: kg, m, s, N.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
#[allow(clippy::struct_excessive_bools)] // one switch per particle variant, each a `[technique]` key
pub struct TechniqueConfig {
    // Direct force
    /// Force per unit of relative velocity per kg of the touched object (1/s):
    /// a viscous drag towards the hand's velocity, i.e. kinetic friction only.
    pub direct_gain: f32,

    // Joint
    /// Spring stiffness (N/m) between the contact and its anchor.
    pub joint_stiffness: f32,
    /// Spring damping (N·s/m).
    pub joint_damping: f32,
    /// Force (N) above which a joint breaks (its line disappears).
    pub joint_break_force: f32,

    // Proxy
    pub proxy_shape: ProxyShape,
    /// Proxy mass (kg): its inertia, i.e. how much momentum it hands to an
    /// object per step while driven towards the contact. A finger is driven
    /// by an arm, so this is large.
    pub proxy_mass: f32,
    /// Proxy weight (N): how hard it presses into what it stands on, which
    /// sets the friction it can exert (the paper's "weight of a finger").
    /// Applied through the body's gravity scale, so inertia and press are
    /// separate knobs.
    pub proxy_weight: f32,
    /// Half size of a cube proxy / radius of a sphere or capsule proxy (m).
    pub proxy_size: f32,
    /// Static/kinetic friction coefficient of proxies and particles.
    pub friction: f32,

    // Particle
    /// Take every n-th outline column and row (forwarded to the vision stage).
    pub particle_stride: usize,
    /// Sobel magnitude (grey levels per pixel) an outline pixel needs to
    /// become a particle (forwarded to the vision stage's edge threshold).
    pub particle_edge_threshold: f32,
    /// Particle radius (m).
    pub particle_radius: f32,
    /// Particle mass (kg): inertia, as for proxies. A particle is given the
    /// hand's velocity at the start of each step and loses what it gives
    /// away during it, so whatever it drags settles below the hand's speed
    /// by the resisting force x dt / the contact's particle mass (0.68 N of
    /// table friction under a pressed 100 g box: 3.5 mm/s at 0.2 kg, 1.8 at
    /// 0.4 for a 16-particle fingertip), so a fingertip dragging that box
    /// from its centre carries it nearer the hand's full travel the heavier
    /// its particles (`fingertip_drag_moves_the_box_about_ten_cm`). Heavier
    /// particles also push harder than the behaviour suite lets a hand: from
    /// about 0.8 kg two flat hands carry the grasp block most of the way
    /// without gripping it (their palms reach over its top and behind it;
    /// `surfacelab behaviours`, `grasp_flat_hands`).
    pub particle_mass: f32,
    /// Particle weight (N): press per particle, as for proxies. Friction
    /// therefore grows with contact area (the paper's observation).
    pub particle_weight: f32,
    /// At most this many particles per frame (the rest are dropped evenly).
    pub particle_cap: usize,
    /// Reuse particle bodies across frames instead of creating and destroying them.
    pub particle_pooled: bool,
    /// Line-of-sight particles: each a thin capsule from the point its ray
    /// touched up towards the eye (the paper's "thin capsule ... which
    /// stretches from the 3D camera near plane to the surface of the touched
    /// object"), so an outline sliding towards a tall object meets the rim
    /// the user sees instead of riding onto its top; `false` gives ball
    /// particles. Measured by `surfacelab behaviours` (the `side_push_*` cases).
    pub particle_capsules: bool,
    /// Simulate only particles that can touch something movable this step:
    /// one landing on bare table or a fixed object, out of reach of every
    /// dynamic object and soft body, is drawn as feedback but gets no body
    /// (it would press on the table and nothing else). Off: the paper's
    /// every-particle-a-body.
    pub particle_cull: bool,
    /// Hands rest on what they land on: a contact that landed on a movable
    /// object holds the sides of its line-of-sight particles up at the
    /// object's height and presses on it with the flat of the hand (see the
    /// Particle technique's `rest` module; Particle and Hybrid). Off: the
    /// paper's particles, on the outline only, each side drawn from whatever
    /// its own ray meets.
    pub particle_rest: bool,
    /// A hand's skin sticks to what it rests on: while a resting contact's
    /// centre has slipped less than a few millimetres over the object under
    /// it since it last stuck, its particles on that object also take up
    /// that slip within the step (see the Particle technique's `rest`
    /// module). Off: the paper's particles, which match the hand's velocity
    /// only, so a lag once taken is never made up.
    pub particle_stick: bool,
    /// A resting hand's particles on what it rests on move as one pad, a
    /// rigid body, so its press goes where the surface meets it (see the
    /// Particle technique's `pad` module): the finger over its bone, held
    /// by the arm. Off: each particle presses with its own weight where it
    /// is, as the paper's do.
    pub particle_pad: bool,

    // Shared limits
    /// Contact speeds above this are clamped (m/s): lost tracking never flings.
    pub max_contact_speed: f32,
    pub pressure: PressureMode,
    /// How Joint and Proxy find what a contact touches.
    pub hit_test: HitTest,
}

impl Default for TechniqueConfig {
    fn default() -> Self {
        TechniqueConfig {
            direct_gain: 50.0,
            joint_stiffness: 150.0,
            joint_damping: 8.0,
            joint_break_force: 25.0,
            proxy_shape: ProxyShape::Cube,
            proxy_mass: 1.0,
            proxy_weight: 2.0,
            proxy_size: 0.008,
            friction: 1.5,
            particle_stride: 3,
            particle_edge_threshold: 12.0,
            particle_radius: 0.003,
            particle_mass: 0.4,
            particle_weight: 0.08,
            particle_cap: 4000,
            particle_pooled: true,
            particle_capsules: true,
            particle_cull: true,
            particle_rest: true,
            particle_stick: true,
            particle_pad: true,
            max_contact_speed: 4.0,
            pressure: PressureMode::Off,
            hit_test: HitTest::Outline,
        }
    }
}

/// A `[technique]` table that does not fit [`TechniqueConfig`]: the file,
/// and where known the line and the field, worded as scene errors are.
#[derive(Debug, thiserror::Error)]
#[error("{origin}{}: {}{message}", line.map(|l| format!(":{l}")).unwrap_or_default(), field.as_ref().map_or_else(|| "[technique]: ".into(), |f| format!("field `technique.{f}`: ")))]
pub struct ConfigError {
    pub origin: String,
    pub line: Option<usize>,
    pub field: Option<String>,
    pub message: String,
}

impl crate::error::Kind for ConfigError {
    /// The table comes from a scene file the user named.
    fn kind(&self) -> crate::error::ErrorKind {
        crate::error::ErrorKind::BadInput
    }
}

impl TechniqueConfig {
    /// Defaults overridden by a scene's `[technique]` table; errors name
    /// the scene file, the line and the field.
    pub fn from_scene(scene: &crate::scene::Scene) -> Result<Self, ConfigError> {
        Self::from_table_at(&scene.technique, &scene.origin, &scene.technique_lines)
    }

    /// Defaults overridden by a `[technique]` table whose key lines are unknown.
    pub fn from_scene_table(table: &toml::Table, origin: &str) -> Result<Self, ConfigError> {
        Self::from_table_at(table, origin, &std::collections::BTreeMap::new())
    }

    fn from_table_at(
        table: &toml::Table,
        origin: &str,
        lines: &std::collections::BTreeMap<String, usize>,
    ) -> Result<Self, ConfigError> {
        let error = |field: Option<&str>, message: String| ConfigError {
            origin: origin.to_string(),
            line: field.and_then(|f| lines.get(f).copied()),
            field: field.map(str::to_owned),
            message,
        };
        let parse =
            |t: &toml::Table| -> Result<TechniqueConfig, toml::de::Error> { toml::Value::Table(t.clone()).try_into() };
        let cfg = parse(table).map_err(|whole| {
            // toml names the bad value but not its key: try the keys one
            // at a time to find it.
            let bad = table.iter().find_map(|(k, v)| {
                let one: toml::Table = std::iter::once((k.clone(), v.clone())).collect();
                parse(&one).err().map(|e| (k.as_str(), e))
            });
            match bad {
                Some((k, e)) => error(Some(k), e.message().to_string()),
                None => error(None, whole.message().to_string()),
            }
        })?;
        cfg.check().map_err(|(field, message)| error(Some(field), message))?;
        Ok(cfg)
    }

    /// Checks ranges against `scene::bounds`; the message names the field
    /// and the bound.
    pub fn validate(&self) -> Result<(), String> {
        self.check().map_err(|(field, message)| format!("`{field}`: {message}"))
    }

    /// [`Self::validate`], with the field apart.
    fn check(&self) -> Result<(), (&'static str, String)> {
        use crate::scene::bounds as b;
        let ranged = [
            ("proxy_size", self.proxy_size, b::TECHNIQUE_SIZE_M),
            ("particle_radius", self.particle_radius, b::TECHNIQUE_SIZE_M),
            ("proxy_mass", self.proxy_mass, b::TECHNIQUE_MASS_KG),
            ("particle_mass", self.particle_mass, b::TECHNIQUE_MASS_KG),
            ("proxy_weight", self.proxy_weight, b::TECHNIQUE_WEIGHT_N),
            ("particle_weight", self.particle_weight, b::TECHNIQUE_WEIGHT_N),
            ("max_contact_speed", self.max_contact_speed, b::MAX_SPEED_M_S),
            ("joint_break_force", self.joint_break_force, (b::TECHNIQUE_MIN_FORCE_N, b::TECHNIQUE_GAIN)),
            ("direct_gain", self.direct_gain, (0.0, b::TECHNIQUE_GAIN)),
            ("joint_stiffness", self.joint_stiffness, (0.0, b::TECHNIQUE_GAIN)),
            ("joint_damping", self.joint_damping, (0.0, b::TECHNIQUE_GAIN)),
            ("friction", self.friction, (0.0, b::TECHNIQUE_GAIN)),
            ("particle_edge_threshold", self.particle_edge_threshold, (0.0, b::TECHNIQUE_GAIN)),
        ];
        let human = crate::scene::human;
        for (name, v, (lo, hi)) in ranged {
            if !v.is_finite() {
                return Err((name, format!("must be a finite number, got {v}")));
            }
            if !(lo..=hi).contains(&v) {
                return Err((
                    name,
                    format!(
                        "{} is out of range ({}..={})",
                        human(f64::from(v)),
                        human(f64::from(lo)),
                        human(f64::from(hi))
                    ),
                ));
            }
        }
        if !(1..=b::PARTICLE_STRIDE).contains(&self.particle_stride) {
            return Err((
                "particle_stride",
                format!("{} is out of range (1..={})", self.particle_stride, b::PARTICLE_STRIDE),
            ));
        }
        if self.particle_cap > b::PARTICLE_CAP {
            return Err(("particle_cap", format!("{} is out of range (0..={})", self.particle_cap, b::PARTICLE_CAP)));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scene_overrides_and_errors_name_the_field() {
        let t: toml::Table = toml::from_str("proxy_mass = 0.5\nproxy_shape = \"sphere\"").expect("toml");
        let c = TechniqueConfig::from_scene_table(&t, "x.toml").expect("valid");
        assert_eq!(c.proxy_mass, 0.5);
        assert_eq!(c.proxy_shape, ProxyShape::Sphere);
        assert_eq!(c.particle_stride, TechniqueConfig::default().particle_stride);

        let t: toml::Table = toml::from_str("proxy_mas = 0.5").expect("toml");
        let e = TechniqueConfig::from_scene_table(&t, "x.toml").expect_err("unknown field");
        assert!(e.to_string().contains("proxy_mas"), "{e}");
        let t: toml::Table = toml::from_str("proxy_mass = -1.0").expect("toml");
        let e = TechniqueConfig::from_scene_table(&t, "x.toml").expect_err("negative");
        assert!(e.to_string().contains("proxy_mass"), "{e}");
    }

    #[test]
    fn technique_errors_name_the_file_line_and_field() {
        let scene = |technique: &str| {
            let text = format!(
                "name = \"t\"\neffects = [\"gravity\"]\n[table]\nsize = [1.0, 0.75]\n[technique]\nproxy_mass = 0.5\n{technique}\n"
            );
            crate::scene::parse(&text, "t.toml").expect("the scene itself is valid")
        };
        let err = |technique: &str| TechniqueConfig::from_scene(&scene(technique)).expect_err(technique).to_string();
        let e = err("pressure = \"loud\"");
        assert!(e.starts_with("t.toml:7: field `technique.pressure`: unknown variant `loud`"), "{e}");
        assert_eq!(
            err("particle_radius = 1e30"),
            "t.toml:7: field `technique.particle_radius`: 1e30 is out of range (0.0005..=0.1)"
        );
        let e = err("proxy_mas = 1.0");
        assert!(e.starts_with("t.toml:7: field `technique.proxy_mas`: unknown field `proxy_mas`"), "{e}");
        assert_eq!(TechniqueConfig::from_scene(&scene("")).expect("valid").proxy_mass, 0.5);
    }

    #[test]
    fn a_parameter_past_its_bound_names_the_bound() {
        let err = |text: &str| {
            let t: toml::Table = toml::from_str(text).expect("toml");
            TechniqueConfig::from_scene_table(&t, "x.toml").expect_err(text).to_string()
        };
        assert_eq!(
            err("particle_radius = 1e30"),
            "x.toml: field `technique.particle_radius`: 1e30 is out of range (0.0005..=0.1)"
        );
        assert_eq!(
            err("proxy_mass = 1e-30"),
            "x.toml: field `technique.proxy_mass`: 1e-30 is out of range (0.001..=1000)"
        );
        assert_eq!(
            err("particle_cap = 1000000000"),
            "x.toml: field `technique.particle_cap`: 1000000000 is out of range (0..=100000)"
        );
        assert_eq!(err("direct_gain = nan"), "x.toml: field `technique.direct_gain`: must be a finite number, got NaN");
    }
}
