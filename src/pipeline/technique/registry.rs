//! Techniques by name: the built-in ones and any a program adds.
//!
//! Comparing interaction techniques is the point of the study, so a new
//! technique must not need a fork. Every technique, built-in or not, is a
//! [`TechniqueSpec`] in one process-wide registry: a name, a label, the
//! effects it needs, the behaviour cases it does not claim, and a factory.
//! A [`TechniqueKind`] is a handle into it, so the command line, the
//! session, the study files, the behaviour table and the demo's menu all
//! take a registered technique the way they take a built-in one.
//!
//! The registry only grows: a kind, once handed out, names the same
//! technique for the life of the process, which keeps `TechniqueKind`
//! `Copy` and its order (built-in ones first, in the paper's order, then in
//! registration order) fixed for tables and files.
//!
//! ```
//! use surfacelab::pipeline::technique::{register, JointTechnique, TechniqueKind, TechniqueSpec};
//! use surfacelab::scene::Effect;
//!
//! // A variant of Joint under its own name (a real one would bring its own type).
//! let kind = register(
//!     TechniqueSpec::new("stiff_joint", |mut config| {
//!         config.joint_stiffness *= 4.0;
//!         Box::new(JointTechnique::new(config))
//!     })
//!     .label("Stiff joint")
//!     .needs(Effect::Joints),
//! )
//! .unwrap();
//! assert_eq!("stiff_joint".parse::<TechniqueKind>().unwrap(), kind);
//! assert!(TechniqueKind::registered().contains(&kind));
//! ```

use super::{
    DirectForce, HybridTechnique, JointTechnique, ParticleTechnique, ProxyTechnique, Technique, TechniqueConfig,
    TechniqueKind,
};
use crate::error::{ErrorKind, Kind};
use crate::scene::{Effect, EffectSet};
use std::fmt;
use std::sync::{Arc, LazyLock, PoisonError, RwLock};

/// Makes a technique from the session's configuration (the scene's
/// `[technique]` table with the command line's overrides).
pub type TechniqueFactory = dyn Fn(TechniqueConfig) -> Box<dyn Technique> + Send + Sync;

/// Everything the program knows of one technique besides its code.
#[derive(Clone)]
pub struct TechniqueSpec {
    name: &'static str,
    label: Option<&'static str>,
    effects: EffectSet,
    limits: Vec<(&'static str, &'static str)>,
    outside_suite: Option<&'static str>,
    factory: Arc<TechniqueFactory>,
}

impl TechniqueSpec {
    /// A technique called `name` (lower-case letters, digits, `_` and `-`:
    /// it goes into file names, CSV cells and comma-separated flags), made
    /// by `factory`.
    pub fn new(
        name: &'static str,
        factory: impl Fn(TechniqueConfig) -> Box<dyn Technique> + Send + Sync + 'static,
    ) -> TechniqueSpec {
        TechniqueSpec {
            name,
            label: None,
            effects: EffectSet::empty(),
            limits: Vec::new(),
            outside_suite: None,
            factory: Arc::new(factory),
        }
    }

    /// The name on plots, in reports and in the demo's menu (default: the
    /// name with its first letter upper-case).
    pub fn label(mut self, label: &'static str) -> TechniqueSpec {
        self.label = Some(label);
        self
    }

    /// A world effect the technique needs whatever the scene declares (Joint
    /// needs `joints`). The world simulates only the effects a scene calls
    /// for, so a technique that adds joints must say so here.
    pub fn needs(mut self, effect: Effect) -> TechniqueSpec {
        self.effects = self.effects.with(effect);
        self
    }

    /// A behaviour case this technique does not claim to manage: the suite
    /// measures and shows its cell, with `why`, instead of asserting the
    /// case's checks. Every other case is expected to work.
    pub fn limit(mut self, case: &'static str, why: &'static str) -> TechniqueSpec {
        self.limits.push((case, why));
        self
    }

    /// Leaves the technique out of the behaviour suite unless it is asked
    /// for by name (`behaviours --techniques`), for `why`.
    pub fn outside_suite(mut self, why: &'static str) -> TechniqueSpec {
        self.outside_suite = Some(why);
        self
    }

    /// The name given to [`TechniqueSpec::new`].
    pub fn name(&self) -> &'static str {
        self.name
    }
}

impl fmt::Debug for TechniqueSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TechniqueSpec")
            .field("name", &self.name)
            .field("label", &self.label)
            .field("effects", &self.effects)
            .field("limits", &self.limits)
            .field("outside_suite", &self.outside_suite)
            .finish_non_exhaustive()
    }
}

/// Why a technique could not be registered.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RegistryError {
    #[error(
        "technique name {0:?} is not usable: use 1-32 lower-case ASCII letters, digits, '_' or '-', starting with a letter"
    )]
    BadName(&'static str),
    #[error("a technique named {0:?} is already registered")]
    Taken(&'static str),
    #[error("too many techniques registered")]
    Full,
}

impl Kind for RegistryError {
    /// Registering is the program's own set-up: a clash is a fault of the
    /// program, not of its user's files or flags.
    fn kind(&self) -> ErrorKind {
        ErrorKind::Runtime
    }
}

/// A set of techniques to add, for [`cli::main_with`](crate::cli::main_with):
/// a researcher's own binary registers its techniques here and gets every
/// subcommand with them.
///
/// ```no_run
/// use surfacelab::pipeline::technique::{ProxyTechnique, TechniqueRegistry};
///
/// let mut registry = TechniqueRegistry::new();
/// registry.register("heavy_proxy", |mut config| {
///     config.proxy_mass *= 10.0;
///     Box::new(ProxyTechnique::new(config))
/// });
/// std::process::exit(match surfacelab::cli::main_with(registry) {
///     code if code == std::process::ExitCode::SUCCESS => 0,
///     _ => 1,
/// });
/// ```
#[derive(Debug, Default)]
pub struct TechniqueRegistry {
    specs: Vec<TechniqueSpec>,
}

impl TechniqueRegistry {
    /// No techniques beyond the built-in ones.
    pub fn new() -> TechniqueRegistry {
        TechniqueRegistry::default()
    }

    /// Adds a technique with the defaults of [`TechniqueSpec::new`].
    pub fn register(
        &mut self,
        name: &'static str,
        factory: impl Fn(TechniqueConfig) -> Box<dyn Technique> + Send + Sync + 'static,
    ) -> &mut TechniqueRegistry {
        self.specs.push(TechniqueSpec::new(name, factory));
        self
    }

    /// Adds a technique described in full (label, effects, limits).
    pub fn with(&mut self, spec: TechniqueSpec) -> &mut TechniqueRegistry {
        self.specs.push(spec);
        self
    }

    /// Registers every technique in this set with the process, in order.
    pub fn install(self) -> Result<Vec<TechniqueKind>, RegistryError> {
        self.specs.into_iter().map(register).collect()
    }
}

/// Registers a technique with the process; from then on its name is
/// accepted wherever a built-in technique's is.
pub fn register(spec: TechniqueSpec) -> Result<TechniqueKind, RegistryError> {
    let name = spec.name;
    let usable = (1..=32).contains(&name.len())
        && name.starts_with(|c: char| c.is_ascii_lowercase())
        && name.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '-');
    if !usable {
        return Err(RegistryError::BadName(name));
    }
    let mut specs = REGISTRY.write().unwrap_or_else(PoisonError::into_inner);
    if specs.iter().any(|s| s.name == name) {
        return Err(RegistryError::Taken(name));
    }
    let rank = u16::try_from(specs.len()).map_err(|_| RegistryError::Full)?;
    specs.push(Arc::new(with_label(spec)));
    Ok(TechniqueKind::new(rank, name))
}

/// The built-in techniques, registered through the same [`TechniqueSpec`]
/// as any other, in the order of [`TechniqueKind::BUILT_IN`].
fn built_in() -> Vec<Arc<TechniqueSpec>> {
    let specs = vec![
        TechniqueSpec::new("direct", |c| Box::new(DirectForce::new(c))).label("Direct").outside_suite(
            "dropped after the paper's pilot: \"performance with this technique was so poor that we felt it needed \
             no further evaluation\"",
        ),
        TechniqueSpec::new("joint", |c| Box::new(JointTechnique::new(c))).label("Joint").needs(Effect::Joints),
        TechniqueSpec::new("proxy", |c| Box::new(ProxyTechnique::new(c))).label("Proxy"),
        TechniqueSpec::new("particle", |c| Box::new(ParticleTechnique::new(c))).label("Particle"),
        TechniqueSpec::new("hybrid", |c| Box::new(HybridTechnique::new(c))).label("Hybrid"),
    ];
    debug_assert!(specs.iter().zip(TechniqueKind::BUILT_IN).all(|(s, k)| s.name == k.name()));
    specs.into_iter().map(|s| Arc::new(with_label(s))).collect()
}

/// The spec with its label settled: the one given, else the name with its
/// first letter upper-case. Made once per registration and kept for the
/// life of the process, as the registry is.
fn with_label(mut spec: TechniqueSpec) -> TechniqueSpec {
    if spec.label.is_none() {
        let mut chars = spec.name.chars();
        let label: String = chars.next().map(|c| c.to_ascii_uppercase()).into_iter().chain(chars).collect();
        spec.label = Some(Box::leak(label.into_boxed_str()));
    }
    spec
}

static REGISTRY: LazyLock<RwLock<Vec<Arc<TechniqueSpec>>>> = LazyLock::new(|| RwLock::new(built_in()));

fn spec(kind: TechniqueKind) -> Arc<TechniqueSpec> {
    let specs = REGISTRY.read().unwrap_or_else(PoisonError::into_inner);
    // A kind is only made by `register` or is a built-in constant, so its
    // rank is always in the registry, which never shrinks.
    Arc::clone(&specs[kind.rank()])
}

/// Every registered kind, in rank order.
pub(super) fn kinds() -> Vec<TechniqueKind> {
    let specs = REGISTRY.read().unwrap_or_else(PoisonError::into_inner);
    specs.iter().enumerate().map(|(rank, s)| TechniqueKind::new(rank as u16, s.name)).collect()
}

impl TechniqueKind {
    /// The name used on plots and in reports (`Joint`).
    pub fn label(self) -> &'static str {
        // Every registered spec has its label settled (`with_label`).
        spec(self).label.unwrap_or(self.name())
    }

    /// Effects this technique needs on top of the scene's declaration.
    pub fn required_effects(self) -> EffectSet {
        spec(self).effects
    }

    /// Builds the technique with a configuration.
    pub fn build(self, config: TechniqueConfig) -> Box<dyn Technique> {
        (spec(self).factory)(config)
    }

    /// Why this technique does not claim the behaviour case `case`, if it
    /// declared so.
    pub fn declared_limit(self, case: &str) -> Option<&'static str> {
        spec(self).limits.iter().find(|(c, _)| *c == case).map(|&(_, why)| why)
    }

    /// Why the behaviour suite leaves this technique out unless asked, if it does.
    pub fn outside_suite(self) -> Option<&'static str> {
        spec(self).outside_suite
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_techniques_come_from_the_registry() {
        let kinds = TechniqueKind::registered();
        assert_eq!(&kinds[..5], &TechniqueKind::BUILT_IN);
        assert_eq!(TechniqueKind::JOINT.required_effects(), EffectSet::empty().with(Effect::Joints));
        assert_eq!(TechniqueKind::PARTICLE.required_effects(), EffectSet::empty());
        assert!(TechniqueKind::DIRECT.outside_suite().is_some());
        assert!(TechniqueKind::PROXY.outside_suite().is_none());
        assert_eq!(TechniqueKind::HYBRID.label(), "Hybrid");
    }

    #[test]
    fn names_are_checked_and_unique() {
        let proxy = |c| Box::new(ProxyTechnique::new(c)) as Box<dyn Technique>;
        assert_eq!(register(TechniqueSpec::new("joint", proxy)), Err(RegistryError::Taken("joint")));
        for bad in ["", "Magnet", "a,b", "9lives", "two words"] {
            assert_eq!(register(TechniqueSpec::new(bad, proxy)), Err(RegistryError::BadName(bad)));
        }
        let kind =
            register(TechniqueSpec::new("registry_test_proxy", proxy).limit("flick", "no flicks")).expect("a new name");
        assert!(kind > TechniqueKind::HYBRID);
        assert_eq!(kind.label(), "Registry_test_proxy");
        assert_eq!(kind.declared_limit("flick"), Some("no flicks"));
        assert_eq!(kind.declared_limit("pinch"), None);
        assert_eq!("REGISTRY_TEST_PROXY".parse::<TechniqueKind>(), Ok(kind));
        assert_eq!(
            register(TechniqueSpec::new("registry_test_proxy", proxy)),
            Err(RegistryError::Taken("registry_test_proxy"))
        );
    }
}
