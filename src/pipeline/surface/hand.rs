//! Models of hands and tangibles lying on the glass.
//!
//! Each model is a union of [`Footprint`]s in a local frame whose +y points
//! along the fingers (away from the wrist) and whose +x points to the
//! little-finger side of a right hand, placed on the table by a [`Pose`].
//! Sizes are those of an adult hand as seen by a diffuse-illumination table:
//! a fingertip touches with a patch about 1.5 cm across, a flat palm about
//! 9 x 10 cm, a forearm about 25 x 7 cm.

use std::sync::Arc;

use super::footprint::{Footprint, Patch};
use super::outline::Outline;

/// What is touching the glass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HandKind {
    /// `n` fingertips (1..=5) side by side; the fifth is the thumb, below
    /// and to the left of the index. The pose is the middle of the row.
    Fingertips(u8),
    /// A right hand lying flat: palm, four fingers and thumb. The pose is
    /// the palm centre.
    FlatHand,
    /// The side of the hand (little-finger edge), as used to sweep or
    /// gather; it runs along the local y axis.
    Edge,
    /// A closed fist resting on the backs of the fingers.
    Fist,
    /// A forearm laid on the table, wrist towards +y.
    Forearm,
    /// A 30 x 3 cm ruler along the local x axis.
    Ruler,
    /// The rim of a cup's base, a ring 7.6 cm across.
    Cup,
    /// A credit-card sized card (8.6 x 5.4 cm).
    Card,
    /// An arbitrary outline, drawn as it is: what a tracker that sends
    /// contours saw. The shape is the hand's [`Hand::outline`]; it has no
    /// template, so it is not in [`HandKind::ALL`] (nothing can put one
    /// down by picking a kind).
    Contour,
}

impl HandKind {
    /// Every kind made from a template, in the order the UI lists them
    /// ([`HandKind::Contour`] is made from an outline instead).
    pub const ALL: [Self; 8] = [
        Self::Fingertips(1),
        Self::FlatHand,
        Self::Edge,
        Self::Fist,
        Self::Forearm,
        Self::Ruler,
        Self::Cup,
        Self::Card,
    ];

    /// The name used in gesture files.
    pub fn name(self) -> &'static str {
        match self {
            Self::Fingertips(_) => "fingertips",
            Self::FlatHand => "flat_hand",
            Self::Edge => "edge",
            Self::Fist => "fist",
            Self::Forearm => "forearm",
            Self::Ruler => "ruler",
            Self::Cup => "cup",
            Self::Card => "card",
            Self::Contour => "contour",
        }
    }

    /// The kind called `name` in a gesture file (fingertip count apart).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().chain([Self::Contour]).find(|k| k.name() == name)
    }
}

/// Where a hand lies: position on the table (metres) and rotation of its
/// local frame (radians, counter-clockwise; 0 = fingers pointing to +y).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    pub x: f32,
    pub y: f32,
    pub angle: f32,
}

/// One hand or tangible at one instant.
///
/// Not `Copy`: a [`HandKind::Contour`] hand carries its outline, shared
/// behind an `Arc` so that cloning a hand stays cheap.
#[derive(Debug, Clone, PartialEq)]
pub struct Hand {
    /// Identity chosen by whoever drives the hand (gesture file, mouse);
    /// unrelated to the contact ids that vision assigns.
    pub id: u32,
    pub kind: HandKind,
    pub pose: Pose,
    /// How far apart fingers are: 0 = pressed together (two fingertips at
    /// spread 0 merge into one blob), 1 = relaxed, 2 = wide. Only
    /// `Fingertips` and `FlatHand` use it.
    pub spread: f32,
    /// Uniform size factor, 1 = the adult sizes of the module doc.
    pub scale: f32,
    /// 0..=1; the grey level of the touch is proportional to it. 0 is a
    /// hand hovering out of sight.
    pub pressure: f32,
    /// The shape of a [`HandKind::Contour`] hand in its own frame (placed
    /// by `pose` and `scale` like every template); `None` for every other
    /// kind. A contour hand without one touches nothing.
    pub outline: Option<Arc<Outline>>,
}

/// Fingertip contact patch: 1.5 cm across, a little longer along the finger.
const TIP_RADII: [f32; 2] = [0.0075, 0.009];
/// Fingertip centre spacing at spread 0: less than the patch width, so
/// neighbouring fingertips overlap and merge.
const TIP_SPACING_CLOSED: f32 = 0.013;
/// Extra fingertip spacing per unit of spread.
const TIP_SPACING_PER_SPREAD: f32 = 0.012;
/// Grey of the fingers of a flat hand relative to the palm: they press less.
const FINGER_LEVEL: f32 = 0.85;

impl Hand {
    /// A relaxed hand of `kind` at `(x, y)`, angle 0, full pressure.
    pub fn new(id: u32, kind: HandKind, x: f32, y: f32) -> Self {
        Self { id, kind, pose: Pose { x, y, angle: 0.0 }, spread: 1.0, scale: 1.0, pressure: 1.0, outline: None }
    }

    /// A [`HandKind::Contour`] hand whose outline is `outline` (table
    /// metres) at full pressure: its pose is the middle of the outline's
    /// bounds, angle 0, scale 1, and it carries the outline relative to it.
    pub fn contour(id: u32, outline: &Outline) -> Self {
        let (local, centre) = outline.centred();
        let mut hand = Self::new(id, HandKind::Contour, centre[0], centre[1]);
        hand.outline = Some(Arc::new(local));
        hand
    }

    /// The outline's rings on the table (metres), for a contour hand.
    pub fn outline_rings(&self) -> Option<Vec<Vec<[f32; 2]>>> {
        self.outline.as_ref().map(|o| o.placed([self.pose.x, self.pose.y], self.pose.angle, self.scale.max(0.0)))
    }

    pub fn with_angle(mut self, angle: f32) -> Self {
        self.pose.angle = angle;
        self
    }

    pub fn with_spread(mut self, spread: f32) -> Self {
        self.spread = spread;
        self
    }

    pub fn with_pressure(mut self, pressure: f32) -> Self {
        self.pressure = pressure;
        self
    }

    pub fn with_scale(mut self, scale: f32) -> Self {
        self.scale = scale;
        self
    }

    /// The footprint's bounding box on the table, `[min, max]` in metres.
    pub fn bounds(&self) -> [[f32; 2]; 2] {
        let mut lo = [f32::MAX; 2];
        let mut hi = [f32::MIN; 2];
        for p in self.outline_rings().iter().flatten().flatten() {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        for p in self.patches() {
            let [a, b] = p.shape.bounds();
            for k in 0..2 {
                lo[k] = lo[k].min(a[k]);
                hi[k] = hi[k].max(b[k]);
            }
        }
        [lo, hi]
    }

    /// The footprint on the table, in table metres: the template's parts
    /// (none for a [`HandKind::Contour`], whose shape is its outline).
    pub fn patches(&self) -> Vec<Patch> {
        let mut out = Vec::new();
        self.push_patches(&mut out);
        out
    }

    /// Appends the footprint to `out` (the rasterizer reuses one buffer).
    pub fn push_patches(&self, out: &mut Vec<Patch>) {
        let start = out.len();
        local_patches(self.kind, self.spread.max(0.0), out);
        let s = self.scale.max(0.0);
        for p in &mut out[start..] {
            p.shape = scaled(p.shape, s).placed([self.pose.x, self.pose.y], self.pose.angle);
        }
    }
}

fn scaled(shape: Footprint, s: f32) -> Footprint {
    let v = |p: [f32; 2]| [p[0] * s, p[1] * s];
    match shape {
        Footprint::Ellipse { centre, radii, angle } => Footprint::Ellipse { centre: v(centre), radii: v(radii), angle },
        Footprint::Capsule { a, b, radius } => Footprint::Capsule { a: v(a), b: v(b), radius: radius * s },
        Footprint::RoundedRect { centre, half, angle, corner } => {
            Footprint::RoundedRect { centre: v(centre), half: v(half), angle, corner: corner * s }
        }
        Footprint::Ring { centre, radius, half_width } => {
            Footprint::Ring { centre: v(centre), radius: radius * s, half_width: half_width * s }
        }
    }
}

fn patch(shape: Footprint, level: f32) -> Patch {
    Patch { shape, level }
}

/// A capsule from `a` to `b` pressing at `level`: a forearm, a hand's side.
fn capsule(a: [f32; 2], b: [f32; 2], radius: f32, level: f32) -> Patch {
    patch(Footprint::Capsule { a, b, radius }, level)
}

/// A rounded rectangle on the origin, square to the hand, pressing fully:
/// a palm, a fist, an object's flat base.
fn slab(half: [f32; 2], corner: f32) -> Patch {
    patch(Footprint::RoundedRect { centre: [0.0, 0.0], half, angle: 0.0, corner }, 1.0)
}

/// A capsule of `length` starting at `base`, pointing `angle` radians
/// counter-clockwise from +y.
fn digit(base: [f32; 2], angle: f32, length: f32, radius: f32) -> Footprint {
    let (sin, cos) = angle.sin_cos();
    Footprint::Capsule { a: base, b: [base[0] - sin * length, base[1] + cos * length], radius }
}

/// The footprint of `kind` in its local frame at scale 1.
fn local_patches(kind: HandKind, spread: f32, out: &mut Vec<Patch>) {
    match kind {
        HandKind::Fingertips(n) => {
            let n = n.clamp(1, 5);
            let fingers = n.min(4);
            let spacing = TIP_SPACING_CLOSED + TIP_SPACING_PER_SPREAD * spread;
            for i in 0..fingers {
                let k = f32::from(i) - f32::from(fingers - 1) * 0.5;
                // The middle fingers reach further than the outer ones.
                let y = -0.003 * k * k;
                out.push(patch(Footprint::Ellipse { centre: [k * spacing, y], radii: TIP_RADII, angle: 0.0 }, 1.0));
            }
            if n == 5 {
                let x = -(1.5 * spacing + 0.012 + 0.01 * spread);
                out.push(patch(Footprint::Ellipse { centre: [x, -0.045], radii: [0.009, 0.011], angle: 0.5 }, 1.0));
            }
        }
        HandKind::FlatHand => {
            out.push(slab([0.043, 0.048], 0.02));
            // Index, middle, ring, little: base x, length, radius.
            let fingers =
                [(-0.030, 0.075, 0.0085), (-0.010, 0.082, 0.0085), (0.010, 0.077, 0.0082), (0.030, 0.060, 0.0075)];
            for (i, (x, len, r)) in fingers.into_iter().enumerate() {
                let splay = (1.5 - i as f32) * 0.12 * spread;
                out.push(patch(digit([x, 0.040], splay, len, r), FINGER_LEVEL));
            }
            out.push(patch(digit([-0.036, -0.022], 0.7 + 0.3 * spread, 0.055, 0.0095), FINGER_LEVEL));
        }
        HandKind::Edge => {
            out.push(capsule([0.0, -0.05], [0.0, 0.03], 0.012, 1.0));
            out.push(capsule([0.0, 0.03], [0.004, 0.09], 0.008, 0.8));
        }
        HandKind::Fist => out.push(slab([0.04, 0.0225], 0.015)),
        HandKind::Forearm => {
            out.push(capsule([0.0, -0.09], [0.0, 0.0], 0.035, 1.0));
            out.push(capsule([0.0, 0.0], [0.0, 0.1], 0.027, 0.9));
        }
        HandKind::Ruler => out.push(slab([0.15, 0.015], 0.001)),
        HandKind::Cup => out.push(patch(Footprint::Ring { centre: [0.0, 0.0], radius: 0.035, half_width: 0.003 }, 1.0)),
        HandKind::Card => out.push(slab([0.043, 0.027], 0.003)),
        HandKind::Contour => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn extent(hand: &Hand) -> [[f32; 2]; 2] {
        hand.bounds()
    }

    #[test]
    fn sizes_are_realistic() {
        let size = |kind| {
            let [lo, hi] = extent(&Hand::new(1, kind, 0.0, 0.0));
            [hi[0] - lo[0], hi[1] - lo[1]]
        };
        let tip = size(HandKind::Fingertips(1));
        assert!((tip[0] - 0.015).abs() < 1e-4);
        let hand = size(HandKind::FlatHand);
        assert!(hand[0] > 0.09 && hand[0] < 0.16, "{hand:?}");
        assert!(hand[1] > 0.16 && hand[1] < 0.21, "{hand:?}");
        let arm = size(HandKind::Forearm);
        assert!((arm[0] - 0.07).abs() < 1e-3 && (arm[1] - 0.252).abs() < 1e-3);
        let ruler = size(HandKind::Ruler);
        assert!((ruler[0] - 0.30).abs() < 1e-4 && (ruler[1] - 0.03).abs() < 1e-4);
    }

    #[test]
    fn pose_moves_and_turns_the_footprint() {
        let hand = Hand::new(1, HandKind::Forearm, 0.2, -0.1).with_angle(std::f32::consts::FRAC_PI_2);
        let [lo, hi] = extent(&hand);
        // A quarter turn counter-clockwise lays the arm along x, wrist to -x.
        assert!(hi[0] - lo[0] > 0.24 && hi[1] - lo[1] < 0.08);
        assert!(hand.patches().iter().any(|p| p.shape.distance([0.2, -0.1]) < 0.0));
        assert!(lo[0] < 0.2 - 0.12);
    }

    #[test]
    fn names_round_trip() {
        for kind in HandKind::ALL {
            assert_eq!(HandKind::from_name(kind.name()), Some(kind));
        }
        assert_eq!(HandKind::from_name("tentacle"), None);
        assert_eq!(HandKind::from_name("contour"), Some(HandKind::Contour));
        assert!(!HandKind::ALL.contains(&HandKind::Contour));
    }

    #[test]
    fn a_contour_hand_is_placed_where_its_outline_lies() {
        let ring = vec![[0.2, 0.1], [0.3, 0.1], [0.3, 0.14], [0.2, 0.14]];
        let hand = Hand::contour(4, &Outline::new(vec![ring]).expect("valid"));
        assert_eq!(hand.kind, HandKind::Contour);
        assert!((hand.pose.x - 0.25).abs() < 1e-6 && (hand.pose.y - 0.12).abs() < 1e-6);
        assert!(hand.patches().is_empty());
        let [lo, hi] = hand.bounds();
        assert!((lo[0] - 0.2).abs() < 1e-6 && (hi[1] - 0.14).abs() < 1e-6, "{lo:?} {hi:?}");
        // Moving the pose moves the outline.
        let mut moved = hand.clone();
        moved.pose.x += 0.1;
        assert!((moved.bounds()[0][0] - 0.3).abs() < 1e-6);
    }
}
