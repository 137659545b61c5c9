//! Every source of hands merged into one list per physics step: the mouse
//! (through [`Mouse`], as documented there), touch-screen fingers, a TUIO
//! tracker, and a gesture file replayed as live input (`--script`).
//!
//! Each source keeps its hand ids in its own range so two sources never
//! share an id: mouse ids count up from 1, touches use
//! [`TOUCH_ID_BASE`], scripts [`SCRIPT_ID_BASE`], TUIO the ranges of
//! [`crate::input::tuio`].

use super::tuio::TuioListener;
use crate::input::{Button, Gesture, Mouse, MouseEvent};
use crate::pipeline::surface::{Hand, HandKind};
use std::collections::VecDeque;

/// Hand-id range of touch-screen fingers.
pub const TOUCH_ID_BASE: u32 = 0x1000_0000;
/// Hand-id range of a replayed script.
pub const SCRIPT_ID_BASE: u32 = 0x6000_0000;
const ID_MASK: u32 = 0x0FFF_FFFF;

/// A gesture replayed as live input: its time 0 is the session time at
/// which it started.
#[derive(Debug, Clone)]
pub struct Script {
    pub gesture: Gesture,
    pub start: f64,
}

/// One input event as it arrived from the window system, before it is
/// applied.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SourceEvent {
    Mouse(MouseEvent),
    /// A finger went down on, or moved to, a table point.
    TouchAt(u64, [f32; 2]),
    /// A finger went up (or the touch was cancelled).
    TouchUp(u64),
}

/// All input sources.
///
/// Events are stamped with the wall-clock second they arrived
/// ([`Input::push`]), spread over the frame that delivered them together
/// ([`Input::spread`]), and applied when a physics step's own time reaches
/// them ([`Input::hands_at`]). A frame that runs several catch-up steps
/// therefore sees continuous motion, and a press or a release lands on its
/// own step. Sampling once per frame instead, at a slow frame rate, would
/// move the hand in only some steps, jumping centimetres at once, and a
/// Particle drag would barely move the box that the same drag, smoothed,
/// carries (`app::lab::tests::a_drag_at_8_fps_moves_the_box_as_far_as_at_60`).
#[derive(Debug, Default)]
pub struct Input {
    pub mouse: Mouse,
    /// Touch id (from the window system) and table point of each finger down.
    touches: Vec<(u64, [f32; 2])>,
    pub script: Option<Script>,
    pub tuio: Option<TuioListener>,
    /// Events not yet applied, in arrival order, with their wall time.
    pending: VecDeque<(f64, SourceEvent)>,
    /// Wall time and point of the last applied cursor move.
    cursor_from: Option<(f64, [f32; 2])>,
    /// Wall time and point of each finger's last applied move.
    touch_from: Vec<(u64, f64, [f32; 2])>,
    /// The latest stamp pushed.
    newest: f64,
    /// The instant wall time 0 stands for, once a window clock runs (see
    /// [`Input::set_clock`]): TUIO packets are timed by the real clock.
    clock: Option<std::time::Instant>,
}

impl Input {
    pub fn new(script: Option<Gesture>, tuio: Option<TuioListener>) -> Self {
        Self { script: script.map(|gesture| Script { gesture, start: 0.0 }), tuio, ..Self::default() }
    }

    /// An event that arrived at wall-clock second `at`. Times never go
    /// back: an event stamped before the last one counts as simultaneous.
    pub fn push(&mut self, at: f64, event: SourceEvent) {
        let at = if at.is_finite() { at.max(self.newest) } else { self.newest };
        self.newest = at;
        self.pending.push_back((at, event));
    }

    /// Spreads the events stamped in `(from, to]` evenly over that span,
    /// in their order: the k-th of n at `from + (to - from) k / n`.
    ///
    /// The demo calls it once a frame, over the time since the last frame.
    /// A window hears of input only between frames: the moves of a 60 ms
    /// software-rendered frame arrive together and would carry nearly one
    /// stamp, so the interpolated hand would stand still for most of the
    /// frame and then jump through the batch. Their order is known and
    /// their times are not; spread evenly, a steady drag stays steady, and
    /// a Particle drag carries the box as far as the drag's true timing
    /// does (`docs/design/demo-input-timing.md` has the measurements).
    /// Where the window hears each event as it comes (a fast frame, or one
    /// that waits for the next one), a stamp moves by less than a frame.
    pub fn spread(&mut self, from: f64, to: f64) {
        let n = self.pending.iter().filter(|p| p.0 > from && p.0 <= to).count();
        let mut k = 0;
        for p in self.pending.iter_mut().filter(|p| p.0 > from && p.0 <= to) {
            k += 1;
            p.0 = from + (to - from) * k as f64 / n as f64;
        }
    }

    /// Applies every event that arrived by wall time `wall`.
    pub fn apply_until(&mut self, wall: f64) {
        while let Some(&(at, event)) = self.pending.front() {
            if at > wall {
                break;
            }
            self.pending.pop_front();
            match event {
                SourceEvent::Mouse(e) => {
                    if let MouseEvent::Moved(p) = e {
                        self.cursor_from = Some((at, p));
                    }
                    self.mouse.handle(e);
                }
                SourceEvent::TouchAt(id, p) => {
                    self.touch_at(id, p);
                    self.touch_from.retain(|t| t.0 != id);
                    self.touch_from.push((id, at, p));
                }
                SourceEvent::TouchUp(id) => {
                    self.touch_up(id);
                    self.touch_from.retain(|t| t.0 != id);
                }
            }
        }
    }

    /// A finger went down on, or moved to, a table point (applied now).
    pub fn touch_at(&mut self, id: u64, at: [f32; 2]) {
        match self.touches.iter_mut().find(|t| t.0 == id) {
            Some(t) => t.1 = at,
            None => self.touches.push((id, at)),
        }
    }

    /// A finger went up (or the touch was cancelled), applied now.
    pub fn touch_up(&mut self, id: u64) {
        self.touches.retain(|t| t.0 != id);
    }

    /// Whether finger `id` is down once every event so far is applied.
    pub fn touching(&self, id: u64) -> bool {
        let pending = self.pending.iter().rev().find_map(|&(_, e)| match e {
            SourceEvent::TouchAt(i, _) if i == id => Some(true),
            SourceEvent::TouchUp(i) if i == id => Some(false),
            _ => None,
        });
        pending.unwrap_or_else(|| self.touches.iter().any(|t| t.0 == id))
    }

    /// Whether the script has hands to come at session time `t`.
    pub fn script_running(&self, t: f64) -> bool {
        self.script.as_ref().is_some_and(|s| t - s.start <= s.gesture.duration())
    }

    /// The hands on the table at session time `t`, on a table of `table`
    /// = [width, depth] metres, as the events applied so far leave them.
    pub fn hands(&self, t: f64, table: [f32; 2]) -> Vec<Hand> {
        self.merge(self.mouse.hands(), self.touches.iter().copied(), t, None, table)
    }

    /// Wall time 0 is `origin`: from now on a TUIO tracker's hands are
    /// taken at each step's own wall time, between the packets that
    /// arrived before and after it, rather than as they are now.
    pub fn set_clock(&mut self, origin: std::time::Instant) {
        self.clock = Some(origin);
    }

    /// The instant wall time `wall` stands for: from the window's clock
    /// (see [`Input::set_clock`]), or now when none runs yet.
    pub fn instant_at(&self, wall: f64) -> std::time::Instant {
        match self.clock {
            Some(origin) => origin + std::time::Duration::from_secs_f64(wall.max(0.0)),
            None => std::time::Instant::now(),
        }
    }

    /// The hands at wall time `wall` (session time `t`) for one physics
    /// step: events up to `wall` applied, and a dragged hand or a finger
    /// placed on the straight line between its last move and its next
    /// one, at `wall`'s share of the way. Without a next move yet, it stays
    /// where the last one put it: input is never extrapolated.
    pub fn hands_at(&mut self, wall: f64, t: f64, table: [f32; 2]) -> Vec<Hand> {
        self.apply_until(wall);
        let mouse = match (self.cursor_from, self.next_move(wall, None)) {
            (Some(from), Some(to)) if self.mouse.is_dragging() => {
                let mut m = self.mouse.clone();
                m.handle(MouseEvent::Moved(between(from, to, wall)));
                m.hands()
            }
            _ => self.mouse.hands(),
        };
        let touches: Vec<(u64, [f32; 2])> = self
            .touches
            .iter()
            .map(|&(id, p)| {
                let from = self.touch_from.iter().find(|f| f.0 == id).map(|f| (f.1, f.2));
                match (from, self.next_move(wall, Some(id))) {
                    (Some(from), Some(to)) => (id, between(from, to, wall)),
                    _ => (id, p),
                }
            })
            .collect();
        self.merge(mouse, touches.into_iter(), t, Some(wall), table)
    }

    /// The first pending move after `wall` of the cursor (`None`) or of
    /// finger `touch`; a lift before it ends the search.
    fn next_move(&self, wall: f64, touch: Option<u64>) -> Option<(f64, [f32; 2])> {
        for &(at, e) in self.pending.iter().filter(|p| p.0 > wall) {
            match (touch, e) {
                (None, SourceEvent::Mouse(MouseEvent::Moved(p))) => return Some((at, p)),
                (None, SourceEvent::Mouse(MouseEvent::Released(Button::Left) | MouseEvent::Left)) => return None,
                (Some(id), SourceEvent::TouchAt(i, p)) if i == id => return Some((at, p)),
                (Some(id), SourceEvent::TouchUp(i)) if i == id => return None,
                _ => {}
            }
        }
        None
    }

    fn merge(
        &self,
        mut hands: Vec<Hand>,
        touches: impl Iterator<Item = (u64, [f32; 2])>,
        t: f64,
        wall: Option<f64>,
        table: [f32; 2],
    ) -> Vec<Hand> {
        hands.extend(
            touches.map(|(id, [x, y])| Hand::new(TOUCH_ID_BASE | (id as u32 & ID_MASK), HandKind::Fingertips(1), x, y)),
        );
        if let Some(s) = &self.script {
            hands.extend(s.gesture.sample(t - s.start).into_iter().map(|mut h| {
                h.id = SCRIPT_ID_BASE | (h.id & ID_MASK);
                h
            }));
        }
        if let Some(tuio) = &self.tuio {
            match (self.clock, wall) {
                (Some(origin), Some(wall)) => {
                    hands.extend(tuio.hands_at(table, origin + std::time::Duration::from_secs_f64(wall.max(0.0))));
                }
                _ => hands.extend(tuio.hands(table)),
            }
        }
        hands
    }

    /// The hand a left press would put down at the cursor now: the mouse
    /// model's own answer, from a copy of it.
    pub fn press_preview(&self) -> Option<Hand> {
        if self.mouse.is_dragging() {
            return None;
        }
        let mut m = self.mouse.clone();
        m.handle(MouseEvent::Pressed(Button::Left));
        m.hands().pop()
    }
}

/// The point `wall`'s share of the way from one stamped point to the next.
fn between(from: (f64, [f32; 2]), to: (f64, [f32; 2]), wall: f64) -> [f32; 2] {
    let span = to.0 - from.0;
    let s = if span > 0.0 { ((wall - from.0) / span).clamp(0.0, 1.0) as f32 } else { 1.0 };
    [from.1[0] + (to.1[0] - from.1[0]) * s, from.1[1] + (to.1[1] - from.1[1]) * s]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{Button, MouseEvent};

    #[test]
    fn sources_merge_with_distinct_ids() {
        let text = "format = \"surfacelab-gesture\"\nversion = 1\n[[hands]]\nid = 1\nkind = \"edge\"\nkeys = [{ t = 0.0, pos = [0.1, 0.0] }, { t = 1.0, pos = [0.2, 0.0] }]\n";
        let gesture = Gesture::from_str(text, "test").expect("parses");
        let mut input = Input::new(Some(gesture), None);
        input.mouse.handle(MouseEvent::Moved([0.0, 0.1]));
        input.mouse.handle(MouseEvent::Pressed(Button::Left));
        input.touch_at(1, [-0.1, 0.0]);
        input.touch_at(1, [-0.2, 0.0]);
        let hands = input.hands(0.5, [1.0, 0.75]);
        assert_eq!(hands.len(), 3);
        let mut ids: Vec<u32> = hands.iter().map(|h| h.id).collect();
        ids.dedup();
        assert_eq!(ids.len(), 3);
        assert_eq!(hands[1].pose.x, -0.2);
        assert!((hands[2].pose.x - 0.15).abs() < 1e-6);
        assert!(input.script_running(0.5) && !input.script_running(1.5));
        input.touch_up(1);
        assert_eq!(input.hands(2.0, [1.0, 0.75]).len(), 1);
    }

    #[test]
    fn preview_is_the_hand_a_press_would_make() {
        let mut input = Input::default();
        input.mouse.handle(MouseEvent::Mode(HandKind::Forearm));
        input.mouse.handle(MouseEvent::Wheel(2.0));
        input.mouse.handle(MouseEvent::Moved([0.1, 0.1]));
        let p = input.press_preview().expect("not dragging");
        assert_eq!(p.kind, HandKind::Forearm);
        assert!((p.pose.angle.to_degrees() - 30.0).abs() < 1e-3);
        assert!(input.mouse.hands().is_empty(), "the preview touches nothing");
        input.mouse.handle(MouseEvent::Pressed(Button::Left));
        assert!(input.press_preview().is_none());
    }

    #[test]
    fn a_drag_between_stamped_moves_is_interpolated_at_each_step() {
        let mut input = Input::default();
        input.push(0.0, SourceEvent::Mouse(MouseEvent::Moved([0.0, 0.0])));
        input.push(0.03, SourceEvent::Mouse(MouseEvent::Pressed(Button::Left)));
        input.push(0.1, SourceEvent::Mouse(MouseEvent::Moved([0.1, -0.05])));
        let table = [1.0, 0.75];
        // The press lands on its own step, not on the frame's first.
        assert!(input.hands_at(0.02, 0.0, table).is_empty());
        let at = |input: &mut Input, wall: f64| {
            let h = input.hands_at(wall, 0.0, table);
            assert_eq!(h.len(), 1, "one hand at {wall}");
            [h[0].pose.x, h[0].pose.y]
        };
        // From the cursor's last move (0 s, the origin) to the next (0.1 s).
        let p = at(&mut input, 0.05);
        assert!((p[0] - 0.05).abs() < 1e-6 && (p[1] + 0.025).abs() < 1e-6, "{p:?}");
        let p = at(&mut input, 0.1);
        assert_eq!(p, [0.1, -0.05]);
        // No move to come: the hand stays where the last one put it.
        assert_eq!(at(&mut input, 0.2), [0.1, -0.05]);
        input.push(0.25, SourceEvent::Mouse(MouseEvent::Released(Button::Left)));
        assert_eq!(at(&mut input, 0.24), [0.1, -0.05]);
        assert!(input.hands_at(0.26, 0.0, table).is_empty());
    }

    /// Moves a slow frame delivered together are spread over the frame, in
    /// their order, so the hand moves steadily through them.
    #[test]
    fn a_batch_of_moves_is_spread_over_its_frame() {
        let mut input = Input::default();
        input.push(0.0, SourceEvent::Mouse(MouseEvent::Moved([0.0, 0.0])));
        input.push(0.0, SourceEvent::Mouse(MouseEvent::Pressed(Button::Left)));
        input.apply_until(0.0);
        for (i, x) in [0.01, 0.02, 0.03, 0.04].into_iter().enumerate() {
            input.push(0.099 + 0.0001 * i as f64, SourceEvent::Mouse(MouseEvent::Moved([x, 0.0])));
        }
        input.spread(0.0, 0.1);
        let table = [1.0, 0.75];
        for (wall, x) in [(0.0125, 0.005), (0.025, 0.01), (0.05, 0.02), (0.0875, 0.035), (0.1, 0.04)] {
            let h = input.hands_at(wall, 0.0, table);
            assert!((h[0].pose.x - x).abs() < 1e-6, "at {wall} s: {} m, not {x}", h[0].pose.x);
        }
        // One event alone keeps the end of its span.
        input.push(0.13, SourceEvent::Mouse(MouseEvent::Released(Button::Left)));
        input.spread(0.1, 0.15);
        assert_eq!(input.hands_at(0.149, 0.0, table).len(), 1);
        assert!(input.hands_at(0.15, 0.0, table).is_empty());
    }

    #[test]
    fn touches_are_stamped_and_interpolated_too() {
        let mut input = Input::default();
        input.push(1.0, SourceEvent::TouchAt(7, [0.0, 0.0]));
        input.push(1.2, SourceEvent::TouchAt(7, [0.2, 0.0]));
        assert!(input.touching(7), "pending events count");
        let table = [1.0, 0.75];
        assert!(input.hands_at(0.9, 0.0, table).is_empty());
        let h = input.hands_at(1.05, 0.0, table);
        assert!((h[0].pose.x - 0.05).abs() < 1e-6, "{:?}", h[0].pose);
        input.push(1.3, SourceEvent::TouchUp(7));
        assert!(!input.touching(7));
        assert_eq!(input.hands_at(1.25, 0.0, table)[0].pose.x, 0.2);
        assert!(input.hands_at(1.3, 0.0, table).is_empty());
        // A stamp from the past counts as simultaneous with the newest.
        input.push(0.5, SourceEvent::TouchAt(8, [0.1, 0.1]));
        assert!(input.hands_at(1.3, 0.0, table).len() == 1);
    }
}
