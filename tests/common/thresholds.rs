//! Every physics bound the integration tests assert beyond the behaviour
//! suite's (whose checks live with its cases, `src/harness/behaviour/cases.rs`),
//! in one table: the bound, the value this build measures, and why the
//! bound sits where it does. A test asserts a threshold with
//! [`Threshold::check`], which prints the value it measured, so
//! `cargo test --release -- --nocapture | grep threshold` re-measures the
//! table. `tests/thresholds.rs` checks the table itself.

/// Which side of the bound a measured value must stay on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The value must stay below the bound (a largest allowed value).
    Below,
    /// The value must stay above the bound (a smallest required value).
    Above,
}

/// One physics bound asserted by the tests.
#[derive(Debug, Clone, Copy)]
pub struct Threshold {
    pub name: &'static str,
    pub side: Side,
    pub bound: f32,
    /// The worst value this build measures over every run asserted against it.
    pub measured: f32,
    pub unit: &'static str,
    /// Why the bound sits where it does: physics, the paper, or the
    /// measured value plus a stated margin.
    pub reason: &'static str,
}

impl Threshold {
    /// Whether `value` is on the bound's side of it (NaN never is).
    pub fn holds(&self, value: f32) -> bool {
        match self.side {
            Side::Below => value < self.bound,
            Side::Above => value > self.bound,
        }
    }

    /// Prints `value` (what `what` measured) and asserts it holds.
    pub fn check(&self, value: f32, what: &str) {
        let side = if self.side == Side::Below { "<" } else { ">" };
        println!(
            "threshold {}: {what}: {value:.5} {} (asserted {side} {}, table's measured {})",
            self.name, self.unit, self.bound, self.measured
        );
        assert!(
            self.holds(value),
            "{what}: {value} {} is not {side} {} ({}: {})",
            self.unit,
            self.bound,
            self.name,
            self.reason
        );
    }
}

/// Culling the particles that touch nothing movable, a hand edge pushing
/// the box: the culled and full paths' largest distance over the box's travel.
pub const CULL_EDGE_PUSH: Threshold = Threshold {
    name: "cull_edge_push",
    side: Side::Below,
    bound: 0.0037,
    measured: 0.00246,
    unit: "of the travel",
    reason: "a culled particle touches nothing movable, so the paths differ only by the order rapier meets the \
             box's contacts in (fewer bodies, another order): 0.4 mm of 17.3 cm measured; bound: measured plus half",
};

/// The same for a flat hand sweeping over the box, carrying it on the
/// friction of the few particles on its top.
pub const CULL_FLAT_HAND: Threshold = Threshold {
    name: "cull_flat_hand",
    side: Side::Below,
    bound: 0.0055,
    measured: 0.00366,
    unit: "of the travel",
    reason: "as the edge push, but the box rides on a few particles' friction, solved by 4 PGS iterations whose \
             answer depends on the contact order: 1.4 mm of 37.4 cm measured; bound: measured plus half",
};

/// Pooled against per-frame particles dragging the box: the paths' largest
/// distance over the box's travel.
pub const POOLED_PER_FRAME: Threshold = Threshold {
    name: "pooled_per_frame",
    side: Side::Below,
    bound: 0.0135,
    measured: 0.00904,
    unit: "of the travel",
    reason: "fresh per-frame contacts get no solver warm start, so their friction converges a little less and the \
             box lags: 0.9 mm of 9.4 cm measured; bound: measured plus half",
};

/// `tradeoff --quick`: where the culled run leaves the box, off where the
/// full run leaves it (its CSV's error column, two decimals).
pub const TRADEOFF_CULL: Threshold = Threshold {
    name: "tradeoff_cull",
    side: Side::Below,
    bound: 0.06,
    measured: 0.04,
    unit: "cm",
    reason: "culling drops only particles that cannot touch the box; the end point moves with the contact order \
             alone: 0.04 cm measured; bound: measured plus half (a real loss leaves the box centimetres behind)",
};

/// The stability cases but the pressed stack and the flung box: deepest
/// overlap between scene bodies.
pub const STABILITY_PENETRATION: Threshold = Threshold {
    name: "stability_penetration",
    side: Side::Below,
    bound: 0.0063,
    measured: 0.0042,
    unit: "m",
    reason: "rapier's soft contacts let bodies in by millimetres under load and push them out; the deepest, 4.2 mm, \
             is a ball flicked at 40 m/s into a wall; bound: measured plus half",
};

/// Five boxes stacked under a pressing flat hand: deepest overlap.
pub const STACK_PENETRATION: Threshold = Threshold {
    name: "stack_penetration",
    side: Side::Below,
    bound: 0.01,
    measured: 0.00989,
    unit: "m",
    reason: "the suite's stated stability limit, 1 cm (a third of a stacked box's 3 cm height: deeper reads as one \
             box sinking into another); Particle's hand presses five boxes' weight plus its own into the lowest \
             contacts and measures 9.9 mm, the closest any threshold comes to its bound",
};

/// Four joints pulling one box apart: deepest overlap when the last joint
/// slings the box into the rim wall.
pub const FLUNG_BOX_PENETRATION: Threshold = Threshold {
    name: "flung_box_penetration",
    side: Side::Below,
    bound: 0.016,
    measured: 0.01392,
    unit: "m",
    reason: "the box's corner reaches the rim wall at 0.5 m/s, 8 mm a step, and rapier's soft contact lets it in \
             for a step or two before pushing it out: two steps of its travel, 1.6 cm; measured 1.39 cm",
};

/// A flat hand squishing the jelly block under Particle: the volume's
/// largest departure from its rest volume.
pub const SQUISHED_VOLUME_PARTICLE: Threshold = Threshold {
    name: "squished_volume_particle",
    side: Side::Below,
    bound: 0.06,
    measured: 0.0595,
    unit: "of the rest volume",
    reason: "a squashed jelly bulges instead of shrinking; line-of-sight particles do not hold the block's sides up \
             (Layer::Sight), so the hand presses its centre down by millimetres and it loses 5.95% at most; \
             bound: the stated 6%, a volume loss one can see beyond",
};

/// The same under Proxy, whose one cube presses the block's top flat.
pub const SQUISHED_VOLUME_PROXY: Threshold = Threshold {
    name: "squished_volume_proxy",
    side: Side::Below,
    bound: 0.02,
    measured: 0.0148,
    unit: "of the rest volume",
    reason: "one flat cube presses the block evenly and it bulges at its sides: 1.48% lost measured; bound: \
             measured plus a third",
};

/// Joint squeezing the jelly into the slot: the same departure.
pub const SQUEEZED_VOLUME: Threshold = Threshold {
    name: "squeezed_volume",
    side: Side::Below,
    bound: 0.015,
    measured: 0.0108,
    unit: "of the rest volume",
    reason: "the funnel squeezes the block's sides in and it bulges along the slot: 1.08% lost measured; bound: \
             measured plus two fifths",
};

/// The stability cases where hands press, pin, wedge or drag objects
/// slowly (stacks, a pinned box, a wedged capsule, a cambered card, the
/// steering cylinder between two hands, overlaps recovering, a light box on
/// a heavy one): the fastest any object moves.
pub const SPEED_HELD: Threshold = Threshold {
    name: "speed_held",
    side: Side::Below,
    bound: 0.18,
    measured: 0.1196,
    unit: "m/s",
    reason: "the hands here move at a few cm/s or hold still, and a stable solve moves nothing faster than about \
             that: 0.12 m/s measured (the top box of the pressed stack under Proxy); bound: measured plus half",
};

/// A contact beside the box that the box never meets (jumping, or lost and
/// found every other frame): the box's fastest motion.
pub const SPEED_AT_REST: Threshold = Threshold {
    name: "speed_at_rest",
    side: Side::Below,
    bound: 0.0004,
    measured: 0.00014,
    unit: "m/s",
    reason: "nothing pushes the box, so it only settles on the table: 0.14 mm/s measured; bound: under three \
             times that, where anything touching the box moves it at centimetres a second",
};

/// Two joints pulling one box apart until they break.
pub const SPEED_PULLED_APART: Threshold = Threshold {
    name: "speed_pulled_apart",
    side: Side::Below,
    bound: 3.0,
    measured: 1.98,
    unit: "m/s",
    reason: "when one stretched joint breaks, the other yanks the box (the paper's \"breaking joints fling \
             objects\"): 1.98 m/s measured; bound: measured plus half",
};

/// Four joints pulling one box apart: the last one slings it.
pub const SPEED_FLUNG_BOX: Threshold = Threshold {
    name: "speed_flung_box",
    side: Side::Below,
    bound: 5.0,
    measured: 3.28,
    unit: "m/s",
    reason: "the last of four stretched joints slings the box into the rim wall: 3.28 m/s measured; bound: \
             measured plus half",
};

/// A ball flicked at 40 m/s at a thin wall.
pub const SPEED_FLICKED_BALL: Threshold = Threshold {
    name: "speed_flicked_ball",
    side: Side::Below,
    bound: 41.0,
    measured: 39.94,
    unit: "m/s",
    reason: "the ball starts at 40 m/s and nothing adds speed to it (39.94 measured); 1 m/s above the launch \
             speed is energy the solver made",
};

/// The 20,000-particle flood on the sorting scene.
pub const SPEED_FLOOD: Threshold = Threshold {
    name: "speed_flood",
    side: Side::Below,
    bound: 0.5,
    measured: 0.18,
    unit: "m/s",
    reason: "the forearm and hands sway at up to 5 cm/s; ten times that is a solver under load flinging pieces. \
             0.18 m/s measured over the 300-step run (the 10,000-step run is not part of the default suite)",
};

/// A hand edge's push filmed by the synthetic infrared and depth cameras
/// and played back: the filmed run's largest gap from the gesture's path,
/// over the box's travel (Joint).
pub const FILMED_EDGE_PUSH: Threshold = Threshold {
    name: "filmed_edge_push",
    side: Side::Below,
    bound: 0.039,
    measured: 0.0259,
    unit: "of the travel",
    reason: "a filmed hand passes through the camera's blur, noise and rectification, so its contact lies \
             millimetres off the drawn one and the box is pushed a little differently: 4.4 mm of 17.1 cm at \
             worst (depth camera; infrared 0.8%); bound: measured plus half",
};

/// The same for a flat hand's sweep (Particle).
pub const FILMED_SWEEP: Threshold = Threshold {
    name: "filmed_sweep",
    side: Side::Below,
    bound: 0.078,
    measured: 0.0518,
    unit: "of the travel",
    reason: "as the edge push, and the box rides on the friction of the few particles on its top, which the \
             filmed outline places a little differently: 1.9 cm of 37.4 cm (depth camera; infrared 2.0%); \
             bound: measured plus half",
};

/// A fingertip dragging a box 10 cm (`fingertip_drag`), every technique and
/// Hybrid, pooled or per-frame: how far the box moves along the drag.
pub const DRAG_TRAVEL_LEAST: Threshold = Threshold {
    name: "drag_travel_least",
    side: Side::Above,
    bound: 0.08,
    measured: 0.0939,
    unit: "m",
    reason: "the behaviour suite's drag threshold, 0.8 of the finger's 10 cm: springs lag and particles slip a little, \
             and a box left further behind is not dragged; 9.39 cm measured (Joint)",
};

/// The same drag: the box does not overshoot the finger.
pub const DRAG_TRAVEL_MOST: Threshold = Threshold {
    name: "drag_travel_most",
    side: Side::Below,
    bound: 0.11,
    measured: 0.0957,
    unit: "m",
    reason: "the finger stops after 10 cm; a box that slides on a centimetre past it has been flung, not dragged; \
             9.57 cm measured (Proxy)",
};

/// The same drag: how far the box strays across it.
pub const DRAG_DRIFT: Threshold = Threshold {
    name: "drag_drift",
    side: Side::Below,
    bound: 0.0004,
    measured: 0.00027,
    unit: "m",
    reason: "the drag runs straight along x over a box centred on it, so only contact noise pushes it sideways: \
             0.27 mm measured (Joint); bound: measured plus half",
};

/// The same drag: deepest overlap between scene bodies.
pub const DRAG_PENETRATION: Threshold = Threshold {
    name: "drag_penetration",
    side: Side::Below,
    bound: 0.00029,
    measured: 0.00019,
    unit: "m",
    reason: "a fingertip presses a 200 g box with little more than its own weight, which rapier's contacts hold \
             within a fraction of a millimetre: 0.19 mm measured (Particle); bound: measured plus half",
};

/// A hand edge sweeping three boxes 24 cm (Particle, Joint): the least
/// any box moves.
pub const SWEEP_BOXES_MOVED: Threshold = Threshold {
    name: "sweep_boxes_moved",
    side: Side::Above,
    bound: 0.098,
    measured: 0.147,
    unit: "m",
    reason: "the edge carries all three boxes together: 14.7 cm measured (Joint); bound: measured less a third",
};

/// The same sweep: the spread of the three boxes' travel.
pub const SWEEP_BOXES_SPREAD: Threshold = Threshold {
    name: "sweep_boxes_spread",
    side: Side::Below,
    bound: 0.0023,
    measured: 0.00151,
    unit: "m",
    reason: "one straight edge pushes the three boxes' faces together, so they move as one: 1.5 mm measured \
             (Particle); bound: measured plus half",
};

/// The same sweep under Proxy: the middle box, under the edge's centre.
pub const SWEEP_PROXY_PUSHED: Threshold = Threshold {
    name: "sweep_proxy_pushed",
    side: Side::Above,
    bound: 0.02,
    measured: 0.0319,
    unit: "m",
    reason: "Proxy's one cube at the blob centre pushes the box it meets and turns it aside into its neighbour: \
             3.19 cm measured; bound: measured less a third, rounded to 2 cm",
};

/// The same sweep under Proxy: the box left furthest behind.
pub const SWEEP_PROXY_LEFT: Threshold = Threshold {
    name: "sweep_proxy_left",
    side: Side::Below,
    bound: 0.0019,
    measured: 0.00127,
    unit: "m",
    reason: "the paper's known weakness: one proxy at the blob centre misses the outer boxes, and the one left \
             behind moves only where its neighbour nudges it: 1.3 mm measured; bound: measured plus half",
};

/// Two fingers twisting a small box 90 degrees, every technique: its turn.
pub const TWIST_YAW_LEAST: Threshold = Threshold {
    name: "twist_yaw_least",
    side: Side::Above,
    bound: 45.0,
    measured: 81.6,
    unit: "degrees",
    reason: "the paper's twist turns the box with the fingers; half of their 90 degrees is where a box that slips \
             under them starts: 81.6 measured (Proxy)",
};

/// The same twist: the box does not overshoot the fingers.
pub const TWIST_YAW_MOST: Threshold = Threshold {
    name: "twist_yaw_most",
    side: Side::Below,
    bound: 100.0,
    measured: 90.37,
    unit: "degrees",
    reason: "the fingers stop at 90 degrees; 10 more is a box flung round, not turned: 90.4 measured (Particle)",
};

/// The same twist: how far the box's centre moves.
pub const TWIST_SHIFT: Threshold = Threshold {
    name: "twist_shift",
    side: Side::Below,
    bound: 0.0007,
    measured: 0.00047,
    unit: "m",
    reason: "the fingers turn about the box's centre, so it turns in place: 0.47 mm measured (Joint); bound: \
             measured plus half",
};

/// Two fingertips' joints pulling one box apart, 26 cm each way in 1 s:
/// the box's fastest motion.
pub const PULL_APART_SPEED: Threshold = Threshold {
    name: "pull_apart_speed",
    side: Side::Below,
    bound: 2.9,
    measured: 1.94,
    unit: "m/s",
    reason: "the stretched joints fight over the box and jerk it: 1.94 m/s measured; bound: measured plus half",
};

/// The same pull: deepest overlap between scene bodies.
pub const PULL_APART_PENETRATION: Threshold = Threshold {
    name: "pull_apart_penetration",
    side: Side::Below,
    bound: 0.0018,
    measured: 0.00122,
    unit: "m",
    reason: "the joints hold the box up off the table more than they press it: 1.2 mm measured; bound: measured \
             plus half",
};

/// A ball thrown by a fingertip's joint: the held point's velocity one
/// frame after the lift, off the hand's (0.38 m/s at the ball's top).
pub const RELEASE_VELOCITY: Threshold = Threshold {
    name: "release_velocity",
    side: Side::Below,
    bound: 0.2,
    measured: 0.128,
    unit: "of the hand's speed",
    reason: "a released spring leaves the held point with about the hand's speed, plus what the spring stretched to \
             catch up: 12.8% measured; bound: 20%, about measured plus half",
};

/// The same throw: the held point's sideways speed one frame after the lift.
pub const RELEASE_SIDEWAYS: Threshold = Threshold {
    name: "release_sideways",
    side: Side::Below,
    bound: 2e-6,
    measured: 0.0,
    unit: "m/s",
    reason: "the hand moves along x over a ball centred on its path, so nothing acts across it: exactly 0 measured; \
             bound: numerically zero",
};

/// A flat hand whose centroid lies beside the ball under centroid
/// hit-testing: how far the ball moves along the hand's path.
pub const CENTROID_MISS: Threshold = Threshold {
    name: "centroid_miss",
    side: Side::Below,
    bound: 2e-6,
    measured: 0.0,
    unit: "m",
    reason: "the hit test at the centroid finds nothing and the hand's other points are not used, so nothing \
             touches the ball (the paper's point-based limit): exactly 0 measured; bound: numerically zero",
};

/// Two flat hands that grasped and carried the box under Hybrid, opened:
/// the box's speed after the release.
pub const GRASP_RELEASED_SPEED: Threshold = Threshold {
    name: "grasp_released_speed",
    side: Side::Below,
    bound: 2e-6,
    measured: 1.1e-8,
    unit: "m/s",
    reason: "opening hands drop their grips and the table's friction stops the box within the settle time: \
             1.1e-8 m/s measured; bound: numerically zero",
};

/// The same grasp under Proxy: how far the box moves.
pub const PROXY_GRASP_MISS: Threshold = Threshold {
    name: "proxy_grasp_miss",
    side: Side::Below,
    bound: 2e-6,
    measured: 1.8e-8,
    unit: "m",
    reason: "a flat hand's proxy is one body at the palm's centre, 7.5 cm from the box, and never touches it: \
             1.8e-8 m measured (the box settling); bound: numerically zero",
};

/// Culling's comparison runs (edge push, flat hand sweep): the box's
/// travel, so that the path comparison is about a moved box.
pub const CULL_TRAVEL: Threshold = Threshold {
    name: "cull_travel",
    side: Side::Above,
    bound: 0.115,
    measured: 0.1728,
    unit: "m",
    reason: "the edge pushes the box 17.3 cm (the sweep 37 cm); bound: measured less a third",
};

/// The same runs: the culled run's simulated particle-frames over the
/// sensed ones.
pub const CULL_KEPT: Threshold = Threshold {
    name: "cull_kept",
    side: Side::Below,
    bound: 0.43,
    measured: 0.289,
    unit: "of the sensed particle-frames",
    reason: "most of a hand's particles land on the bare table away from the box and are culled: 28.9% kept \
             measured (edge push); bound: measured plus half",
};

/// Culled particle-frames over a run, the edge push and the sweep.
pub const CULLED_PARTICLES: Threshold = Threshold {
    name: "culled_particles",
    side: Side::Above,
    bound: 5700.0,
    measured: 8547.0,
    unit: "particle-frames",
    reason: "the hand's particles away from the box: 8,547 culled measured (edge push); bound: measured less a third",
};

/// Two hands gathering on the positioning, sorting and steering tasks,
/// every built-in technique: the fastest object.
pub const STUDY_TASK_SPEED: Threshold = Threshold {
    name: "study_task_speed",
    side: Side::Below,
    bound: 2.0,
    measured: 1.36,
    unit: "m/s",
    reason: "the hands sweep at tens of cm/s and shove pieces into each other; 1.36 m/s measured (positioning, \
             Direct Force); bound: measured plus half",
};

/// The same runs: deepest overlap between scene bodies.
pub const STUDY_TASK_PENETRATION: Threshold = Threshold {
    name: "study_task_penetration",
    side: Side::Below,
    bound: 0.0143,
    measured: 0.00952,
    unit: "m",
    reason: "pieces squeezed between two closing hands press into each other under rapier's soft contacts: 9.5 mm \
             measured (positioning, Direct Force); bound: measured plus half",
};

/// A flat hand slid 15 cm with its fingers over a ball and its centroid
/// beside it, outline hit-testing: how far Joint carries the ball.
pub const OUTLINE_JOINT_CARRY: Threshold = Threshold {
    name: "outline_joint_carry",
    side: Side::Above,
    bound: 0.12,
    measured: 0.174,
    unit: "m",
    reason: "Joint holds the ball under the fingers and carries it at least 80% of the hand's 15 cm; 17.4 cm \
             measured (the ball rolls on after the hand stops)",
};

/// The same under Proxy, whose cube on the ball rolls it along.
pub const OUTLINE_PROXY_ROLL: Threshold = Threshold {
    name: "outline_proxy_roll",
    side: Side::Above,
    bound: 0.088,
    measured: 0.132,
    unit: "m",
    reason: "the cube rides the ball's top and rolls it ahead of the hand: 13.2 cm measured; bound: measured less \
             a third",
};

/// A light fingertip sliding 8 cm over a 6 cm ball, 24 ways (Particle,
/// Hybrid): the least the ball rolls forward.
pub const LIGHT_TOUCH_ROLL: Threshold = Threshold {
    name: "light_touch_roll",
    side: Side::Above,
    bound: 0.04,
    measured: 0.0783,
    unit: "m",
    reason: "the behaviour suite's threshold for a light touch, 4 cm: half the finger's travel, where a ball rolled \
             back into the particles falls short; 7.83 cm measured (Hybrid)",
};

/// A fingertip dragging the small box 10 cm from anywhere on its top, 36
/// ways (Particle, Hybrid): the shortest drag.
pub const DRAG_ANYWHERE: Threshold = Threshold {
    name: "drag_anywhere",
    side: Side::Above,
    bound: 0.08,
    measured: 0.0946,
    unit: "m",
    reason: "the behaviour suite's threshold for a hand dragging what it sticks to: 0.8 of its 10 cm; 9.46 cm \
             measured (Hybrid, along y from 2 cm off centre)",
};

/// A flat hand resting on a ball and sliding 30 cm (Particle resting, and
/// Particle and Hybrid landed 2 cm off the ball's centre): the ball's
/// travel over the hand's.
pub const BALL_ROLLED_LEAST: Threshold = Threshold {
    name: "ball_rolled_least",
    side: Side::Above,
    bound: 0.3,
    measured: 0.515,
    unit: "of the hand's travel",
    reason: "a ball driven at its top by a sliding palm rolls about half the palm's travel (its centre moves at \
             half its top's speed); the behaviour suite's band is 0.3 to 0.75; 0.515 measured (Hybrid)",
};

/// The same: the ball is rolled, not pushed along.
pub const BALL_ROLLED_MOST: Threshold = Threshold {
    name: "ball_rolled_most",
    side: Side::Below,
    bound: 0.75,
    measured: 0.564,
    unit: "of the hand's travel",
    reason: "the top of the suite's band (0.3 to 0.75) round half the hand's travel; a ball pushed at its equator \
             goes nearly all the way; 0.564 measured (resting Particle)",
};

/// The same slide with the paper's particles, whose sides rise from the
/// table behind the ball.
pub const BALL_PUSHED_UNRESTING: Threshold = Threshold {
    name: "ball_pushed_unresting",
    side: Side::Above,
    bound: 0.85,
    measured: 0.939,
    unit: "of the hand's travel",
    reason: "the trailing edge's capsules meet the ball at its equator and push it at the hand's speed: 0.939 \
             measured; bound: well above the rolling band's 0.75, where a push and a roll part",
};

/// Pin and spin on the small box, a fingertip circling 90 degrees round a
/// pinned one, with sticking particles: the box's turn.
pub const PIN_SPIN_STICKING: Threshold = Threshold {
    name: "pin_spin_sticking",
    side: Side::Above,
    bound: 85.0,
    measured: 90.4,
    unit: "degrees",
    reason: "a sticking skin turns the box with the finger, the paper's Figure 2: the full 90 degrees, less 5 for \
             the start's lag; 90.4 measured",
};

/// The same without sticking: the turn falls short.
pub const PIN_SPIN_SLIDING: Threshold = Threshold {
    name: "pin_spin_sliding",
    side: Side::Below,
    bound: 80.0,
    measured: 73.8,
    unit: "degrees",
    reason: "particles matching only the finger's speed never make up the lag, and the finger slides: 73.8 \
             measured; bound: 10 degrees short of the finger's 90",
};

/// A fingertip pad dragging the steering cylinder 20 cm by its top: how
/// far it moves.
pub const PAD_DRAG_MOVED: Threshold = Threshold {
    name: "pad_drag_moved",
    side: Side::Above,
    bound: 0.15,
    measured: 0.200,
    unit: "m",
    reason: "the behaviour suite's threshold, 15 of the finger's 20 cm; 20.0 cm measured",
};

/// The same drag: the cylinder's largest tilt.
pub const PAD_DRAG_TILT: Threshold = Threshold {
    name: "pad_drag_tilt",
    side: Side::Below,
    bound: 1.5,
    measured: 1.01,
    unit: "degrees",
    reason: "the pad's press behind the axis holds the cylinder upright while its base slides: 1.0 degree \
             measured; bound: measured plus half (a tipping cylinder passes 15)",
};

/// Pin and spin on the small box, pooled and fresh pads: the box's
/// deepest contact with the table.
pub const PAD_SINK: Threshold = Threshold {
    name: "pad_sink",
    side: Side::Below,
    bound: 0.0013,
    measured: 0.00084,
    unit: "m",
    reason: "a pad's many contacts solved to convergence press the box with little more than its weight: 0.84 \
             mm measured (fresh pads); bound: measured plus half (unconverged pads sink it centimetres)",
};

/// The same runs: the box's turn.
pub const PAD_TURN: Threshold = Threshold {
    name: "pad_turn",
    side: Side::Above,
    bound: 45.0,
    measured: 74.1,
    unit: "degrees",
    reason: "the pin and spin gesture turns the box 90 degrees; at least half of it: 74.1 measured (fresh pads)",
};

/// A fingertip landing on the steering platform behind the cylinder and
/// sliding 14 cm through its place (Particle, Hybrid): the cylinder's travel.
pub const PUSH_FROM_BEHIND: Threshold = Threshold {
    name: "push_from_behind",
    side: Side::Above,
    bound: 0.05,
    measured: 0.0625,
    unit: "m",
    reason: "the behaviour suite's side pushes, 5 cm: a fingertip resting on the cylinder's top instead barely \
             moves it; 6.25 cm measured (Hybrid)",
};

/// A fingertip pushing a 50 g box into a 400 g one, 20 cm in 2 s
/// (Particle, Hybrid): the least either box moves.
pub const CHAIN_PUSH: Threshold = Threshold {
    name: "chain_push",
    side: Side::Above,
    bound: 0.12,
    measured: 0.133,
    unit: "m",
    reason: "the finger reaches the small box after 1.5 cm and pushes both on; a finger passing through the small \
             box leaves it behind; 13.3 cm measured (Particle, whose pile projection moves the small box back \
             into the finger); bound: 12 cm, within a tenth of it",
};

/// Two flat hands closing on the small box and carrying it 15 cm
/// (Hybrid): its travel over the carry.
pub const GRASP_CARRIED: Threshold = Threshold {
    name: "grasp_carried",
    side: Side::Above,
    bound: 0.9,
    measured: 0.979,
    unit: "of the carry",
    reason: "a grasp, by the definition `tests/hybrid.rs` gives it: the object travels at least 90% of the hands' \
             carry; 0.979 measured",
};

/// The same carry: the box's largest distance from the hands' midpoint.
pub const GRASP_LAG: Threshold = Threshold {
    name: "grasp_lag",
    side: Side::Below,
    bound: 0.0032,
    measured: 0.0021,
    unit: "m",
    reason: "persistent grips hold the box between the hands: 2.1 mm measured; bound: measured plus half",
};

/// A flat hand landing half over the small box (Hybrid): how far its
/// grips shove the box.
pub const GRIP_SHOVE: Threshold = Threshold {
    name: "grip_shove",
    side: Side::Below,
    bound: 0.00003,
    measured: 1.9e-5,
    unit: "m",
    reason: "grips are made only on fixed ground, none inside the box, which only settles: 19 µm measured; \
             bound: measured plus half",
};

/// The same: the box's speed at the end, with the hand on the table.
pub const GRIP_SHOVE_SPEED: Threshold = Threshold {
    name: "grip_shove_speed",
    side: Side::Below,
    bound: 0.0003,
    measured: 1.94e-4,
    unit: "m/s",
    reason: "nothing pushes the box and it settles: 0.19 mm/s measured; bound: measured plus half",
};

/// A hand edge's push filmed by the infrared camera and streamed as YUYV
/// (Particle): the box's travel.
pub const CAMERA_EDGE_PUSH_TRAVEL: Threshold = Threshold {
    name: "camera_edge_push_travel",
    side: Side::Above,
    bound: 0.116,
    measured: 0.1745,
    unit: "m",
    reason: "the filmed push moves the box 17.5 cm; bound: measured less a third",
};

/// A flat hand's sweep filmed by the depth camera and streamed as Z16
/// (Particle): the box's travel.
pub const CAMERA_SWEEP_TRAVEL: Threshold = Threshold {
    name: "camera_sweep_travel",
    side: Side::Above,
    bound: 0.25,
    measured: 0.3814,
    unit: "m",
    reason: "the filmed sweep carries the box 38.1 cm; bound: measured less a third",
};

/// A contact ray landing on a cloth: the named particle's distance from
/// the hit, on the table.
pub const CLOTH_RAY_PARTICLE: Threshold = Threshold {
    name: "cloth_ray_particle",
    side: Side::Below,
    bound: 0.012,
    measured: 0.00975,
    unit: "m",
    reason: "the ray lands midway between two rows of particles 2 cm apart, so the nearest lies 1 cm away: 9.75 \
             mm measured; bound: half the spacing plus 2 mm",
};

/// A light box resting on a 3 mm cloth: its centre's height.
pub const BOX_ON_CLOTH_HEIGHT: Threshold = Threshold {
    name: "box_on_cloth_height",
    side: Side::Above,
    bound: 0.0135,
    measured: 0.016,
    unit: "m",
    reason: "on the bare table the box's centre is 1 cm up; the cloth lifts it by its 3 mm thickness and more; \
             below 1.35 cm the box sinks through it; 1.60 cm measured",
};

/// One flat hand dragging the paper sheet 20 cm (Particle, Proxy, Joint):
/// the sheet's travel.
pub const SHEET_DRAGGED: Threshold = Threshold {
    name: "sheet_dragged",
    side: Side::Above,
    bound: 0.11,
    measured: 0.170,
    unit: "m",
    reason: "the hand carries the sheet most of its 20 cm: 17.0 cm measured (Proxy); bound: measured less a third",
};

/// A flat hand landing on the sleeping sheet and sliding 10 cm (every
/// technique): the sheet's travel.
pub const SLEEPING_SHEET_DRAGGED: Threshold = Threshold {
    name: "sleeping_sheet_dragged",
    side: Side::Above,
    bound: 0.053,
    measured: 0.0789,
    unit: "m",
    reason: "the hand wakes the sheet and drags it: 7.89 cm measured (Proxy); bound: measured less a third",
};

/// Cloth under a flat hand (Proxy) circling at 3 cm/s for 10,000 steps:
/// the fastest particle.
pub const CLOTH_TOP_SPEED: Threshold = Threshold {
    name: "cloth_top_speed",
    side: Side::Below,
    bound: 0.44,
    measured: 0.29,
    unit: "m/s",
    reason: "the hand moves at 3 cm/s and the cloth's particles ring a little under its proxy: 0.29 m/s \
             measured; bound: measured plus half",
};

/// Cloth under a flat hand (Proxy) circling for 10,000 steps: the lowest
/// particle's centre.
pub const CLOTH_LOWEST: Threshold = Threshold {
    name: "cloth_lowest",
    side: Side::Above,
    bound: 0.0017,
    measured: 0.00251,
    unit: "m",
    reason: "the cloth's 3 mm contact skin holds its particles' centres millimetres up, and the hand's proxy \
             presses them to 2.5 mm measured; a particle through the table reads below zero; bound: measured \
             less a third",
};

/// A flat hand squishing the jelly block (Particle, Proxy): how far it
/// presses the block's centre down.
pub const SQUISH_PRESS: Threshold = Threshold {
    name: "squish_press",
    side: Side::Above,
    bound: 0.0013,
    measured: 0.002,
    unit: "m",
    reason: "the hand's weight presses the 1.8 cm-high centre down by millimetres: 2.0 mm measured under Proxy's \
             flat cube, 4.4 mm under Particle's; bound: measured less a third",
};

/// Two forearms sweeping the forty pieces together (Particle): the share
/// inside the goal circle.
pub const GATHERED: Threshold = Threshold {
    name: "gathered",
    side: Side::Above,
    bound: 0.775,
    measured: 1.0,
    unit: "of the pieces",
    reason: "at least 80% (32 of 40; the bound lies between 31 and 32) gathered; all 40 measured",
};

/// A ball rolling at 0.5 m/s meets a flat hand laid on its path (Particle,
/// Proxy): how far it rolls on.
pub const BALL_STOPPED_TRAVEL: Threshold = Threshold {
    name: "ball_stopped_travel",
    side: Side::Below,
    bound: 0.023,
    measured: 0.0154,
    unit: "m",
    reason: "Particle's many particles hold the ball still (0.5 mm); Proxy's single cube on its top lets it rock \
             and roll on 1.54 cm; bound: measured plus half",
};

/// The same under Particle: the ball's speed at the end.
pub const BALL_STOPPED_SPEED: Threshold = Threshold {
    name: "ball_stopped_speed",
    side: Side::Below,
    bound: 0.00016,
    measured: 1.04e-4,
    unit: "m/s",
    reason: "many particles on the ball hold it at rest: 0.10 mm/s measured; bound: measured plus half",
};

/// A fingertip pressing one end of a card across a ridge (Particle,
/// Proxy): the card's largest tilt.
pub const CARD_TILT: Threshold = Threshold {
    name: "card_tilt",
    side: Side::Above,
    bound: 5.0,
    measured: 5.03,
    unit: "degrees",
    reason: "a card tipping on its 12 mm ridge until its pressed end meets the table tilts 11.5 degrees; 5, under \
             half of that, is a tip one sees; 5.03 measured (Particle), the closest a lower bound comes to \
             its measured value",
};

/// The cloth task's rumpled cloth at rest: the share of its flat area
/// it covers.
pub const RUMPLED_COVER_LEAST: Threshold = Threshold {
    name: "rumpled_cover_least",
    side: Side::Above,
    bound: 0.5,
    measured: 0.640,
    unit: "of its flat area",
    reason: "the scene's creases are the cloth's rest shape and it covers about 0.64 of its area; the band 0.5 to \
             0.75 is a cloth visibly rumpled but not balled up",
};

/// The same: the rumpled cloth does not fall flat.
pub const RUMPLED_COVER_MOST: Threshold = Threshold {
    name: "rumpled_cover_most",
    side: Side::Below,
    bound: 0.75,
    measured: 0.640,
    unit: "of its flat area",
    reason: "the top of the band round the 0.64 the creases give: above it the wrinkles have fallen out",
};

/// The same: the rumpled cloth's highest particle.
pub const RUMPLED_RIDGE: Threshold = Threshold {
    name: "rumpled_ridge",
    side: Side::Above,
    bound: 0.034,
    measured: 0.0505,
    unit: "m",
    reason: "the creases hold ridges centimetres high: 5.05 cm measured; bound: measured less a third",
};

/// Two flat hands smoothing the rumpled cloth (every technique): the cover
/// gained.
pub const SMOOTHED_GAIN: Threshold = Threshold {
    name: "smoothed_gain",
    side: Side::Above,
    bound: 0.073,
    measured: 0.109,
    unit: "of its flat area",
    reason: "every technique smooths it some: 0.109 gained measured (Joint, the least); bound: measured less a \
             third",
};

/// The same: the smoothed cloth's cover.
pub const SMOOTHED_STRETCH: Threshold = Threshold {
    name: "smoothed_stretch",
    side: Side::Below,
    bound: 1.15,
    measured: 0.974,
    unit: "of its flat area",
    reason: "smoothing may stretch the sheet a little, since warp and weft share the creases' plasticity; 15% \
             more than its flat area is a cloth pulled out of shape; 0.974 measured (Particle)",
};

/// Five fingertips closing on a flat cloth (Proxy, Joint): its cover a
/// second after the hand lifts.
pub const CRUMPLED_COVER: Threshold = Threshold {
    name: "crumpled_cover",
    side: Side::Below,
    bound: 0.96,
    measured: 0.948,
    unit: "of its flat area",
    reason: "the grasp bunches the cloth and its creases hold, so it covers less than flat; 0.96 is a fold one \
             sees; 0.948 measured (Joint)",
};

/// A flat hand sliding 20 cm at 0.4 m/s over the paper, Direct Force:
/// the sheet's travel.
pub const DIRECT_SHEET_DRAGGED: Threshold = Threshold {
    name: "direct_sheet_dragged",
    side: Side::Above,
    bound: 0.035,
    measured: 0.0532,
    unit: "m",
    reason: "kinetic friction from the fast hand drags the sheet: 5.32 cm measured; bound: measured less a third",
};

/// The jelly resting across the tops of slot walls 4 cm apart: its
/// centre's height.
pub const PERCHED_JELLY_HEIGHT: Threshold = Threshold {
    name: "perched_jelly_height",
    side: Side::Above,
    bound: 0.07,
    measured: 0.097,
    unit: "m",
    reason: "the jelly stays perched on the walls, its centre 9.7 cm up; one fallen into the slot sits far below \
             7 cm",
};

/// The demo's own mouse under Xvfb (real X events through xdotool): a
/// fingertip pressed on the centre of `one_box`'s box, moved 200 px right
/// in 60 moves over 1.5 s, held 0.5 s and released. The box's travel over
/// the cursor's, Particle, Proxy and Hybrid, at the demo's own frame rate
/// and at `--max-fps 15`.
pub const DEMO_MOUSE_DRAG: Threshold = Threshold {
    name: "demo_mouse_drag",
    side: Side::Above,
    bound: 0.70,
    measured: 0.908,
    unit: "of the cursor's travel",
    reason: "a drag the hand follows carries the box most of the way: the fingertip slips while the box speeds up, \
             then holds it; 0.908 the least measured (Proxy), 0.92-0.98 the rest; the pressed point starts at the box \
             centre, so a box that loses its finger stops before 0.5 (7 cm of a 21 cm drag) and fails",
};

/// [`DEMO_MOUSE_DRAG`] under Joint: the anchor holds the box to the
/// cursor, so only the spring's lag is lost.
pub const DEMO_MOUSE_DRAG_JOINT: Threshold = Threshold {
    name: "demo_mouse_drag_joint",
    side: Side::Above,
    bound: 0.90,
    measured: 0.957,
    unit: "of the cursor's travel",
    reason: "the joint's spring carries the box with the cursor and lets it settle after the release; 0.957 the \
             least measured; 0.90 leaves the spring's last centimetre",
};

/// The whole table, for `tests/thresholds.rs`.
pub const ALL: &[Threshold] = &[
    CULL_EDGE_PUSH,
    CULL_FLAT_HAND,
    POOLED_PER_FRAME,
    TRADEOFF_CULL,
    STABILITY_PENETRATION,
    STACK_PENETRATION,
    FLUNG_BOX_PENETRATION,
    SQUISHED_VOLUME_PARTICLE,
    SQUISHED_VOLUME_PROXY,
    SQUEEZED_VOLUME,
    SPEED_HELD,
    SPEED_AT_REST,
    SPEED_PULLED_APART,
    SPEED_FLUNG_BOX,
    SPEED_FLICKED_BALL,
    SPEED_FLOOD,
    FILMED_EDGE_PUSH,
    FILMED_SWEEP,
    DRAG_TRAVEL_LEAST,
    DRAG_TRAVEL_MOST,
    DRAG_DRIFT,
    DRAG_PENETRATION,
    SWEEP_BOXES_MOVED,
    SWEEP_BOXES_SPREAD,
    SWEEP_PROXY_PUSHED,
    SWEEP_PROXY_LEFT,
    TWIST_YAW_LEAST,
    TWIST_YAW_MOST,
    TWIST_SHIFT,
    PULL_APART_SPEED,
    PULL_APART_PENETRATION,
    RELEASE_VELOCITY,
    CULL_TRAVEL,
    CULL_KEPT,
    CULLED_PARTICLES,
    STUDY_TASK_SPEED,
    STUDY_TASK_PENETRATION,
    OUTLINE_JOINT_CARRY,
    OUTLINE_PROXY_ROLL,
    LIGHT_TOUCH_ROLL,
    DRAG_ANYWHERE,
    BALL_ROLLED_LEAST,
    BALL_ROLLED_MOST,
    BALL_PUSHED_UNRESTING,
    PIN_SPIN_STICKING,
    PIN_SPIN_SLIDING,
    PAD_DRAG_MOVED,
    PAD_DRAG_TILT,
    PAD_SINK,
    PAD_TURN,
    PUSH_FROM_BEHIND,
    CHAIN_PUSH,
    GRASP_CARRIED,
    GRASP_LAG,
    GRIP_SHOVE,
    GRIP_SHOVE_SPEED,
    CAMERA_EDGE_PUSH_TRAVEL,
    CAMERA_SWEEP_TRAVEL,
    CLOTH_RAY_PARTICLE,
    BOX_ON_CLOTH_HEIGHT,
    SHEET_DRAGGED,
    SLEEPING_SHEET_DRAGGED,
    CLOTH_TOP_SPEED,
    CLOTH_LOWEST,
    SQUISH_PRESS,
    GATHERED,
    BALL_STOPPED_TRAVEL,
    BALL_STOPPED_SPEED,
    CARD_TILT,
    RUMPLED_COVER_LEAST,
    RUMPLED_COVER_MOST,
    RUMPLED_RIDGE,
    SMOOTHED_GAIN,
    SMOOTHED_STRETCH,
    CRUMPLED_COVER,
    DIRECT_SHEET_DRAGGED,
    PERCHED_JELLY_HEIGHT,
    RELEASE_SIDEWAYS,
    CENTROID_MISS,
    GRASP_RELEASED_SPEED,
    PROXY_GRASP_MISS,
    DEMO_MOUSE_DRAG,
    DEMO_MOUSE_DRAG_JOINT,
];
