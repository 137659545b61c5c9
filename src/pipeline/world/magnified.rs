//! Contact determination for centimetre-sized convex shapes, done in a frame
//! magnified [`MAGNIFICATION`] times.
//!
//! parry decides contacts between two convex shapes that have no dedicated
//! routine (cylinder–cylinder, cylinder–box, capsule–box, Joint's prisms:
//! its "polygonal feature map" path) with GJK and EPA, whose tolerances are
//! absolute (`gjk::eps_tol`, EPA's `dist_tol = eps_tol * scale.max(1.0)`).
//! At the size of the `gather` pieces (2.2 cm discs, 1 cm tall) they give
//! up: on overlapping disc pairs (centres 5-18 mm apart, all yaws) most
//! manifolds are wrong by more than 1 mm (saying "touching" or "apart" for
//! discs millimetres into each other), and the solver, never told, lets
//! swept pieces pass through each other. The same pairs magnified are all
//! right (test `overlapping_discs_get_their_true_depth`). Box–box pairs
//! have their own routine, but it clips one face against the other and
//! drops where their edges cross whenever a determinant in m^4 falls under
//! `f32::EPSILON` (`closest_points_line2d`), which for 2 cm edges is at any
//! angle: many overlapping chip pairs come out more than 1 mm off, and a
//! chip resting tilted on another sinks into it for good while its manifold
//! says they barely touch; magnified, only a few steeply tilted pairs do
//! (test `overlapping_chips_get_their_true_depth`). The shapes are value
//! types, so the pair is rebuilt 10x larger, its contacts computed there,
//! and the manifold scaled back: the geometry is exactly the same, only
//! the tolerances shrink relative to it. Pairs with exact routines (balls,
//! capsule–capsule) are left as they are, and so are the parts of
//! composite shapes (parry's own dispatcher recurses into them; no scene
//! or technique here builds one). Shape casts (CCD) are parry's.
//!
//! Design: docs/design/magnified-contacts.md.

use glam::Vec3;
use rapier3d::parry::query::details::NormalConstraints;
use rapier3d::parry::query::{
    ClosestPoints, Contact, ContactManifold, ContactManifoldsWorkspace, DefaultQueryDispatcher, NonlinearRigidMotion,
    PersistentQueryDispatcher, QueryDispatcher, ShapeCastHit, ShapeCastOptions, Unsupported,
};
use rapier3d::parry::query::{ShapeDistance, ShapeIntersection};
use rapier3d::parry::shape::{Capsule, ConvexPolyhedron, Cuboid, Cylinder, Shape, ShapeType};
use rapier3d::prelude::Pose;

/// How much larger the frame is in which GJK/EPA pairs are decided: 10x
/// brings a centimetre piece to the decimetre scale at which parry's
/// absolute tolerances are negligible (no disc pair wrong in
/// `overlapping_discs_get_their_true_depth`; see the module doc and
/// `tests/world.rs`).
pub const MAGNIFICATION: f32 = 10.0;

/// A convex shape rebuilt `MAGNIFICATION` times larger.
enum Magnified {
    Cuboid(Cuboid),
    Cylinder(Cylinder),
    Capsule(Capsule),
    Polyhedron(ConvexPolyhedron),
}

impl Magnified {
    fn of(shape: &dyn Shape) -> Option<Magnified> {
        let s = MAGNIFICATION;
        match shape.shape_type() {
            ShapeType::Cuboid => shape.as_cuboid().map(|c| Magnified::Cuboid(Cuboid::new(c.half_extents * s))),
            ShapeType::Cylinder => {
                shape.as_cylinder().map(|c| Magnified::Cylinder(Cylinder::new(c.half_height * s, c.radius * s)))
            }
            ShapeType::Capsule => shape
                .as_capsule()
                .map(|c| Magnified::Capsule(Capsule::new(c.segment.a * s, c.segment.b * s, c.radius * s))),
            ShapeType::ConvexPolyhedron => {
                shape.as_convex_polyhedron().and_then(|p| p.clone().scaled(Vec3::splat(s))).map(Magnified::Polyhedron)
            }
            _ => None,
        }
    }

    fn shape(&self) -> &dyn Shape {
        match self {
            Magnified::Cuboid(c) => c,
            Magnified::Cylinder(c) => c,
            Magnified::Capsule(c) => c,
            Magnified::Polyhedron(p) => p,
        }
    }
}

/// Both shapes magnified, when parry decides the pair with absolute
/// tolerances (GJK/EPA, or box–box face clipping; `None` for pairs parry
/// decides exactly, and for anything not convex).
fn magnified_pair(g1: &dyn Shape, g2: &dyn Shape) -> Option<(Magnified, Magnified)> {
    let exact = matches!(
        (g1.shape_type(), g2.shape_type()),
        (ShapeType::Ball, _) | (_, ShapeType::Ball) | (ShapeType::Capsule, ShapeType::Capsule)
    );
    if exact {
        return None;
    }
    Some((Magnified::of(g1)?, Magnified::of(g2)?))
}

fn magnify_pose(pos12: &Pose) -> Pose {
    Pose::from_parts(pos12.translation * MAGNIFICATION, pos12.rotation)
}

fn scale_manifold<M, C>(m: &mut ContactManifold<M, C>, k: f32) {
    for p in &mut m.points {
        p.local_p1 *= k;
        p.local_p2 *= k;
        p.dist *= k;
    }
}

/// parry's default dispatcher, with GJK/EPA pairs decided in a magnified
/// frame (module doc). Installed in every [`super::World`]'s narrow phase,
/// and used by [`super::World::max_object_overlap`] to measure piles.
#[derive(Debug, Clone, Copy, Default)]
pub struct MagnifiedDispatcher;

impl QueryDispatcher for MagnifiedDispatcher {
    fn intersection_test(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
    ) -> Result<ShapeIntersection, Unsupported> {
        DefaultQueryDispatcher.intersection_test(pos12, g1, g2)
    }

    fn distance(&self, pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape) -> Result<ShapeDistance, Unsupported> {
        DefaultQueryDispatcher.distance(pos12, g1, g2)
    }

    fn contact(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: f32,
    ) -> Result<Option<Contact>, Unsupported> {
        let Some((m1, m2)) = magnified_pair(g1, g2) else {
            return DefaultQueryDispatcher.contact(pos12, g1, g2, prediction);
        };
        let k = 1.0 / MAGNIFICATION;
        let c =
            DefaultQueryDispatcher.contact(&magnify_pose(pos12), m1.shape(), m2.shape(), prediction * MAGNIFICATION)?;
        Ok(c.map(|c| Contact { point1: c.point1 * k, point2: c.point2 * k, dist: c.dist * k, ..c }))
    }

    fn closest_points(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        max_dist: f32,
    ) -> Result<ClosestPoints, Unsupported> {
        DefaultQueryDispatcher.closest_points(pos12, g1, g2, max_dist)
    }

    fn cast_shapes(
        &self,
        pos12: &Pose,
        local_vel12: Vec3,
        g1: &dyn Shape,
        g2: &dyn Shape,
        options: ShapeCastOptions,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        DefaultQueryDispatcher.cast_shapes(pos12, local_vel12, g1, g2, options)
    }

    fn cast_shapes_nonlinear(
        &self,
        motion1: &NonlinearRigidMotion,
        g1: &dyn Shape,
        motion2: &NonlinearRigidMotion,
        g2: &dyn Shape,
        start_time: f32,
        end_time: f32,
        stop_at_penetration: bool,
    ) -> Result<Option<ShapeCastHit>, Unsupported> {
        DefaultQueryDispatcher.cast_shapes_nonlinear(
            motion1,
            g1,
            motion2,
            g2,
            start_time,
            end_time,
            stop_at_penetration,
        )
    }
}

impl<M, C> PersistentQueryDispatcher<M, C> for MagnifiedDispatcher
where
    M: Default + Clone + Send + Sync,
    C: Default + Copy + Send + Sync,
{
    fn contact_manifolds(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        prediction: f32,
        manifolds: &mut Vec<ContactManifold<M, C>>,
        workspace: &mut Option<ContactManifoldsWorkspace>,
    ) -> Result<(), Unsupported> {
        let Some((m1, m2)) = magnified_pair(g1, g2) else {
            return DefaultQueryDispatcher.contact_manifolds(pos12, g1, g2, prediction, manifolds, workspace);
        };
        // The previous step's points are matched against the new ones (warm
        // starts), so they enter in the magnified frame too.
        for m in manifolds.iter_mut() {
            scale_manifold(m, MAGNIFICATION);
        }
        let result = DefaultQueryDispatcher.contact_manifolds(
            &magnify_pose(pos12),
            m1.shape(),
            m2.shape(),
            prediction * MAGNIFICATION,
            manifolds,
            workspace,
        );
        for m in manifolds.iter_mut() {
            scale_manifold(m, 1.0 / MAGNIFICATION);
        }
        result
    }

    fn contact_manifold_convex_convex(
        &self,
        pos12: &Pose,
        g1: &dyn Shape,
        g2: &dyn Shape,
        normal_constraints1: Option<&dyn NormalConstraints>,
        normal_constraints2: Option<&dyn NormalConstraints>,
        prediction: f32,
        manifold: &mut ContactManifold<M, C>,
    ) -> Result<(), Unsupported> {
        let Some((m1, m2)) = magnified_pair(g1, g2) else {
            return DefaultQueryDispatcher.contact_manifold_convex_convex(
                pos12,
                g1,
                g2,
                normal_constraints1,
                normal_constraints2,
                prediction,
                manifold,
            );
        };
        scale_manifold(manifold, MAGNIFICATION);
        let result = DefaultQueryDispatcher.contact_manifold_convex_convex(
            &magnify_pose(pos12),
            m1.shape(),
            m2.shape(),
            normal_constraints1,
            normal_constraints2,
            prediction * MAGNIFICATION,
            manifold,
        );
        scale_manifold(manifold, 1.0 / MAGNIFICATION);
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;

    /// The `gather` task's disc: 2.2 cm across, 1 cm tall, standing on z.
    fn disc() -> (Cylinder, Quat) {
        (Cylinder::new(0.005, 0.011), Quat::from_rotation_x(std::f32::consts::FRAC_PI_2))
    }

    fn deepest<D: PersistentQueryDispatcher>(d: &D, pos12: &Pose, a: &dyn Shape, b: &dyn Shape) -> Option<f32> {
        let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
        d.contact_manifolds(pos12, a, b, 0.002, &mut manifolds, &mut None).expect("supported pair");
        manifolds.iter().flat_map(|m| m.points.iter().map(|p| p.dist)).reduce(f32::min)
    }

    /// Side-by-side discs at the same height, centres `d` apart at `yaw`:
    /// they overlap by exactly 2r - d (or are pushed apart vertically by
    /// their height, whichever is less).
    fn pairs() -> impl Iterator<Item = (f32, Pose)> {
        let (_, up) = disc();
        (0..400).map(move |i| {
            let d = 0.005 + 0.013 * ((i % 20) as f32 / 20.0);
            let yaw = (i / 20) as f32 * 0.157;
            let p2 =
                Pose::from_parts(Vec3::new(d * yaw.cos(), d * yaw.sin(), 0.0), Quat::from_rotation_z(0.7 * yaw) * up);
            let p1 = Pose::from_parts(Vec3::ZERO, up);
            ((d - 0.022).max(-0.010), p1.inv_mul(&p2))
        })
    }

    #[test]
    fn overlapping_discs_get_their_true_depth() {
        let (c, _) = disc();
        let wrong = pairs()
            .filter(|(truth, pos12)| {
                deepest(&MagnifiedDispatcher, pos12, &c, &c).is_none_or(|d| (d - truth).abs() > 0.001)
            })
            .count();
        assert_eq!(wrong, 0, "{wrong} of 400 overlapping disc pairs got a manifold more than 1 mm off");
        for (truth, pos12) in pairs() {
            let got = MagnifiedDispatcher.contact(&pos12, &c, &c, 0.0).expect("supported").expect("overlapping");
            assert!((got.dist - truth).abs() < 0.001, "contact {} for {truth}", got.dist);
        }
    }

    #[test]
    fn exact_pairs_are_left_to_parry() {
        // A ball on a box: parry's exact routine, the same answer either way.
        let ball = rapier3d::parry::shape::Ball::new(0.003);
        let cube = Cuboid::new(Vec3::splat(0.03));
        let pos12 = Pose::from_translation(Vec3::new(0.01, 0.0, 0.0325));
        let ours = MagnifiedDispatcher.contact(&pos12, &cube, &ball, 0.0).expect("supported").expect("touching");
        let theirs = DefaultQueryDispatcher.contact(&pos12, &cube, &ball, 0.0).expect("supported").expect("touching");
        assert_eq!(ours.dist, theirs.dist);
        assert!((ours.dist + 0.0005).abs() < 1e-6, "0.5 mm deep, got {}", ours.dist);
        assert!(magnified_pair(&cube, &ball).is_none());
        assert!(magnified_pair(&ball, &ball).is_none());
        assert!(magnified_pair(&cube, &cube).is_some());
        let (c, _) = disc();
        assert!(magnified_pair(&c, &cube).is_some());
    }

    /// A `gather` chip (2 x 2 x 1.2 cm) against another in 2000 poses (any
    /// yaw, tilted up to 46 degrees about any axis, centres up to 1.8 cm
    /// apart across and 1 cm up or down), each at least 0.5 mm deep by
    /// parry's separating-axis `contact`.
    fn chip_pairs() -> impl Iterator<Item = Pose> {
        let mut seed = 12345u64;
        let mut rnd = move || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            (seed >> 40) as f32 / (1u64 << 24) as f32
        };
        (0..2000).map(move |_| {
            let axis = Vec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalize_or(Vec3::X);
            let turn = Quat::from_axis_angle(axis, rnd() * 0.8) * Quat::from_rotation_z(rnd() * std::f32::consts::TAU);
            let at = Vec3::new((rnd() - 0.5) * 0.036, (rnd() - 0.5) * 0.036, (rnd() - 0.5) * 0.02);
            Pose::from_parts(at, turn)
        })
    }

    /// Counts the chip pairs whose deepest manifold point is more than 1 mm
    /// off the separating-axis depth, and how many pairs were compared.
    fn wrong_chip_manifolds<D: PersistentQueryDispatcher>(d: &D) -> (usize, usize) {
        let chip = Cuboid::new(Vec3::new(0.01, 0.01, 0.006));
        let mut compared = 0;
        let mut wrong = 0;
        for pos12 in chip_pairs() {
            let truth = DefaultQueryDispatcher.contact(&pos12, &chip, &chip, 0.0).expect("supported");
            let Some(truth) = truth.filter(|c| c.dist < -0.0005) else { continue };
            compared += 1;
            if deepest(d, &pos12, &chip, &chip).is_none_or(|got| (got - truth.dist).abs() > 0.001) {
                wrong += 1;
            }
        }
        (wrong, compared)
    }

    #[test]
    fn overlapping_chips_get_their_true_depth() {
        // parry's box-box manifold drops the crossings of the two faces'
        // edges wherever `closest_points_line2d`'s determinant, in m^4,
        // falls under f32::EPSILON: for 2 cm edges at any angle. Unmagnified,
        // over 200 of these pairs are more than 1 mm off, and a chip resting
        // tilted on another (as in the gather_hand_edges case) sinks into it
        // for good while its manifold says they barely touch. Magnified, at
        // most 4 pairs are still off: steeply tilted pairs whose
        // faces meet obliquely, where clipping one face against the other
        // in projection is itself an approximation, at any scale.
        let (parry_wrong, compared) = wrong_chip_manifolds(&DefaultQueryDispatcher);
        assert!(compared > 1800, "only {compared} of 2000 poses overlap");
        assert!(
            parry_wrong > 200,
            "parry alone got {parry_wrong} of {compared} wrong: is magnifying boxes still needed?"
        );
        let (wrong, _) = wrong_chip_manifolds(&MagnifiedDispatcher);
        assert!(
            wrong <= 4,
            "{wrong} of {compared} overlapping chip pairs got a manifold more than 1 mm off ({parry_wrong} unmagnified)"
        );
    }
}
