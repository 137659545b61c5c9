//! What one behaviour case is: files, what is measured, what is expected.

use crate::pipeline::technique::TechniqueKind;
use std::fmt;

/// A measured quantity of one run (units in each variant's doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Metric {
    /// The object's horizontal displacement along the case's axis (m).
    Along,
    /// [`Metric::Along`] over the lead hand's travel along the axis: the share of the hand's motion the object followed.
    Carry,
    /// Distance between the object's and the lead hand's horizontal displacements (m).
    FollowError,
    /// The object's horizontal displacement across the case's axis, absolute (m).
    Across,
    /// [`Metric::Across`] over [`Metric::Along`]: how far the object veered off the hand's line for each metre it went along it.
    Veer,
    /// Counter-clockwise turn about the vertical (deg), summed step by step from the poses (a ball's spin too).
    Yaw,
    /// Largest tilt of the object's up axis from the vertical (deg).
    MaxTilt,
    /// Highest rise of the object's centre above its start (m).
    MaxLift,
    /// Deepest fall of the object's centre below its start (m): off a platform, tipped over.
    MaxDrop,
    /// Largest displacement along the axis reached during the run (m).
    MaxAlong,
    /// Fastest motion back against the axis (m/s, positive = came back): a bounce.
    Bounce,
    /// The object's horizontal speed when the gesture ends (m/s).
    EndSpeed,
    /// How far the object point under the first hand's first touch moved (m): a pin holds.
    PinDrift,
    /// Deepest interpenetration between any two scene objects over the run (m).
    MaxOverlap,
    /// Share of the dynamic objects resting within `GATHER_RADIUS` (13 cm) of the table centre at the end.
    Gathered,
}

impl Metric {
    /// Column label with its unit.
    pub fn label(self) -> &'static str {
        match self {
            Metric::Along => "moved along (cm)",
            Metric::Carry => "carried (share of hand travel)",
            Metric::FollowError => "off the hand's path (cm)",
            Metric::Across => "moved across (cm)",
            Metric::Veer => "sideways over forward (share)",
            Metric::Yaw => "turned (deg)",
            Metric::MaxTilt => "max tilt (deg)",
            Metric::MaxLift => "max lift (mm)",
            Metric::MaxDrop => "max drop (mm)",
            Metric::MaxAlong => "furthest along (cm)",
            Metric::Bounce => "bounced back at (m/s)",
            Metric::EndSpeed => "speed at the end (m/s)",
            Metric::PinDrift => "pinned point moved (cm)",
            Metric::MaxOverlap => "max overlap (mm)",
            Metric::Gathered => "gathered (share)",
        }
    }

    /// Factor from SI to the label's unit.
    pub fn scale(self) -> f32 {
        match self {
            Metric::Along | Metric::FollowError | Metric::Across | Metric::MaxAlong | Metric::PinDrift => 100.0,
            Metric::MaxLift | Metric::MaxDrop | Metric::MaxOverlap => 1000.0,
            Metric::Carry
            | Metric::Veer
            | Metric::Yaw
            | Metric::MaxTilt
            | Metric::EndSpeed
            | Metric::Bounce
            | Metric::Gathered => 1.0,
        }
    }
}

/// A bound on one metric, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    pub metric: Metric,
    pub min: Option<f32>,
    pub max: Option<f32>,
}

impl Check {
    pub const fn at_least(metric: Metric, min: f32) -> Check {
        Check { metric, min: Some(min), max: None }
    }

    pub const fn at_most(metric: Metric, max: f32) -> Check {
        Check { metric, min: None, max: Some(max) }
    }

    pub const fn between(metric: Metric, min: f32, max: f32) -> Check {
        Check { metric, min: Some(min), max: Some(max) }
    }

    /// Whether `value` meets the bound (NaN never does).
    pub fn holds(&self, value: f32) -> bool {
        !value.is_nan() && self.min.is_none_or(|m| value >= m) && self.max.is_none_or(|m| value <= m)
    }
}

impl fmt::Display for Check {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.metric.scale();
        let v = |x: f32| {
            let text = format!("{:.3}", x * s);
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        };
        match (self.min, self.max) {
            (Some(a), Some(b)) => write!(f, "{} to {}", v(a), v(b)),
            (Some(a), None) => write!(f, "≥ {}", v(a)),
            (None, Some(b)) => write!(f, "≤ {}", v(b)),
            (None, None) => f.write_str("any"),
        }
    }
}

/// What the paper leads us to expect of one technique in one case.
#[derive(Debug, Clone, PartialEq)]
pub enum Expectation {
    /// The manipulation works: the case's own checks, the same for every technique.
    Works,
    /// The paper names a limit of this technique: these checks assert it, and `quote` is the paper's sentence.
    Limit { quote: &'static str, checks: Vec<Check> },
    /// The paper says nothing either way: measured and shown, not asserted.
    Shown { why: &'static str },
}

/// Which horizontal direction "along" means.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Axis {
    /// The first hand's displacement from its first key to its last.
    Hand,
    /// A fixed direction on the table (normalised when measured).
    Fixed([f32; 2]),
}

/// One behaviour: a scene, a gesture, and what should happen.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Short name, also the test filter (`cargo test --test behaviours NAME`).
    pub name: &'static str,
    /// Scene file, relative to the project root.
    pub scene: &'static str,
    /// Gesture file, relative to the project root.
    pub gesture: &'static str,
    /// The scene object measured.
    pub object: &'static str,
    pub axis: Axis,
    /// Seconds simulated after the gesture ends.
    pub settle_s: f64,
    /// What the paper shows or says, in its words where it has them.
    pub paper: &'static str,
    /// The checks where the manipulation works (the same for every technique).
    pub checks: Vec<Check>,
    /// Technique names with a different expectation (the paper's limits).
    /// A technique not listed is expected to work, so a new one joins the suite as such.
    pub others: Vec<(&'static str, Expectation)>,
}

impl Case {
    /// The expectation for `kind`: the case's own for the techniques it
    /// names, else shown unasserted where the technique declares a limit
    /// for this case, else the manipulation works.
    pub fn expectation(&self, kind: TechniqueKind) -> Expectation {
        if let Some((_, e)) = self.others.iter().find(|(n, _)| *n == kind.name()) {
            return e.clone();
        }
        kind.declared_limit(self.name).map_or(Expectation::Works, |why| Expectation::Shown { why })
    }

    /// The checks asserted for `kind` (none when only shown).
    pub fn checks_for(&self, kind: TechniqueKind) -> Vec<Check> {
        match self.expectation(kind) {
            Expectation::Works => self.checks.clone(),
            Expectation::Limit { checks, .. } => checks,
            Expectation::Shown { .. } => Vec::new(),
        }
    }

    /// Every metric the table shows for this case, in order, without repeats.
    pub fn metrics(&self) -> Vec<Metric> {
        let mut out: Vec<Metric> = Vec::new();
        let all = self.checks.iter().chain(self.others.iter().flat_map(|(_, e)| match e {
            Expectation::Limit { checks, .. } => checks.as_slice(),
            _ => &[],
        }));
        for c in all {
            if !out.contains(&c.metric) {
                out.push(c.metric);
            }
        }
        out
    }
}
