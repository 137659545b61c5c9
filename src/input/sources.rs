//! Every source of hands merged into one list per physics step: the mouse
//! (through [`Mouse`], as documented there), touch-screen fingers, a TUIO
//! tracker, and a gesture file replayed as live input (`--script`).
//!
//! Each source keeps its hand ids in its own range so two sources never
//! share an id: mouse ids count up from 1, touches use
//! [`TOUCH_ID_BASE`], scripts [`SCRIPT_ID_BASE`], TUIO the ranges of
//! [`crate::input::tuio`].

use super::tuio::TuioListener;
use crate::input::{Gesture, Mouse};
use crate::pipeline::surface::{Hand, HandKind};

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

/// All input sources.
#[derive(Debug, Default)]
pub struct Input {
    pub mouse: Mouse,
    /// Touch id (from the window system) and table point of each finger down.
    touches: Vec<(u64, [f32; 2])>,
    pub script: Option<Script>,
    pub tuio: Option<TuioListener>,
}

impl Input {
    pub fn new(script: Option<Gesture>, tuio: Option<TuioListener>) -> Self {
        Self { script: script.map(|gesture| Script { gesture, start: 0.0 }), tuio, ..Self::default() }
    }

    /// A finger went down on, or moved to, a table point.
    pub fn touch_at(&mut self, id: u64, at: [f32; 2]) {
        match self.touches.iter_mut().find(|t| t.0 == id) {
            Some(t) => t.1 = at,
            None => self.touches.push((id, at)),
        }
    }

    /// A finger went up (or the touch was cancelled).
    pub fn touch_up(&mut self, id: u64) {
        self.touches.retain(|t| t.0 != id);
    }

    pub fn touching(&self, id: u64) -> bool {
        self.touches.iter().any(|t| t.0 == id)
    }

    /// Whether the script has hands to come at session time `t`.
    pub fn script_running(&self, t: f64) -> bool {
        self.script.as_ref().is_some_and(|s| t - s.start <= s.gesture.duration())
    }

    /// The hands on the table at session time `t`, on a table of `table`
    /// = [width, depth] metres.
    pub fn hands(&self, t: f64, table: [f32; 2]) -> Vec<Hand> {
        let mut hands = self.mouse.hands();
        hands.extend(
            self.touches
                .iter()
                .map(|&(id, [x, y])| Hand::new(TOUCH_ID_BASE | (id as u32 & ID_MASK), HandKind::Fingertips(1), x, y)),
        );
        if let Some(s) = &self.script {
            hands.extend(s.gesture.sample(t - s.start).into_iter().map(|mut h| {
                h.id = SCRIPT_ID_BASE | (h.id & ID_MASK);
                h
            }));
        }
        if let Some(tuio) = &self.tuio {
            hands.extend(tuio.hands(table));
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
        m.handle(crate::input::MouseEvent::Pressed(crate::input::Button::Left));
        m.hands().last().copied()
    }
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
}
