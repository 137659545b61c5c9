//! The demo's mouse mapping: a pure state machine from mouse events to the
//! hands touching the table, so the app only forwards events and the
//! mapping is unit-tested.
//!
//! | input | effect |
//! |---|---|
//! | left drag | a hand of the selected mode follows the cursor (default: one fingertip) |
//! | Shift + left drag | flat hand |
//! | Ctrl + left drag | side of the hand (edge) |
//! | Alt + left drag | two fingertips |
//! | wheel | rotates the hand under the cursor (and the next one) by 15° per notch |
//! | Shift + wheel | spreads / closes the fingers by 0.25 per notch (0..=3) |
//! | right click while dragging | pins the dragged hand where it is; the next left drag adds a second hand |
//! | right click, not dragging | lifts every pinned hand; with none pinned, pins a new hand at the cursor |
//! | cursor leaves the window | lifts the dragged hand (pinned hands stay) |
//!
//! The kind of a hand is fixed when its button goes down: letting go of
//! Shift in the middle of a drag does not turn a flat hand into a
//! fingertip, and the modifier is then free for Shift + wheel. When several
//! modifiers are held the first row of the table that matches wins.

use crate::pipeline::surface::{Hand, HandKind};

/// Modifier keys as the window system reports them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Modifiers {
    pub shift: bool,
    pub ctrl: bool,
    pub alt: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Button {
    Left,
    Right,
    Middle,
}

/// One input event, already converted to table metres by the app.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MouseEvent {
    /// The cursor is over this table point (metres).
    Moved([f32; 2]),
    Pressed(Button),
    Released(Button),
    /// Wheel turned by this many notches; positive = away from the user.
    Wheel(f32),
    /// The modifier keys changed.
    Modifiers(Modifiers),
    /// The hand kind chosen in the UI for a plain left drag.
    Mode(HandKind),
    /// The cursor left the window.
    Left,
}

/// Rotation per wheel notch, degrees.
pub const DEGREES_PER_NOTCH: f32 = 15.0;
/// Spread change per wheel notch.
pub const SPREAD_PER_NOTCH: f32 = 0.25;
/// Largest spread the wheel reaches.
pub const MAX_SPREAD: f32 = 3.0;

/// The state of the mouse mapping.
#[derive(Debug, Clone)]
pub struct Mouse {
    cursor: [f32; 2],
    modifiers: Modifiers,
    mode: HandKind,
    angle: f32,
    spread: f32,
    pressure: f32,
    active: Option<Hand>,
    pinned: Vec<Hand>,
    next_id: u32,
}

impl Default for Mouse {
    fn default() -> Self {
        Self::new()
    }
}

impl Mouse {
    /// Nothing touching; mode one fingertip; hands at full pressure.
    pub fn new() -> Self {
        Self {
            cursor: [0.0, 0.0],
            modifiers: Modifiers::default(),
            mode: HandKind::Fingertips(1),
            angle: 0.0,
            spread: 1.0,
            pressure: 1.0,
            active: None,
            pinned: Vec::new(),
            next_id: 1,
        }
    }

    /// The pressure given to new hands (0..=1).
    pub fn with_pressure(mut self, pressure: f32) -> Self {
        self.pressure = pressure.clamp(0.0, 1.0);
        self
    }

    pub fn handle(&mut self, event: MouseEvent) {
        match event {
            MouseEvent::Moved(p) => {
                self.cursor = p;
                if let Some(hand) = &mut self.active {
                    hand.pose.x = p[0];
                    hand.pose.y = p[1];
                }
            }
            MouseEvent::Pressed(Button::Left) => {
                if self.active.is_none() {
                    self.active = Some(self.new_hand());
                }
            }
            MouseEvent::Released(Button::Left) | MouseEvent::Left => self.active = None,
            MouseEvent::Pressed(Button::Right) => {
                if let Some(hand) = self.active.take() {
                    self.pinned.push(hand);
                } else if self.pinned.is_empty() {
                    let hand = self.new_hand();
                    self.pinned.push(hand);
                } else {
                    self.pinned.clear();
                }
            }
            MouseEvent::Pressed(_) | MouseEvent::Released(_) => {}
            MouseEvent::Wheel(notches) => {
                if !notches.is_finite() {
                    return;
                }
                if self.modifiers.shift {
                    self.spread = (self.spread + notches * SPREAD_PER_NOTCH).clamp(0.0, MAX_SPREAD);
                } else {
                    self.angle += (notches * DEGREES_PER_NOTCH).to_radians();
                }
                if let Some(hand) = &mut self.active {
                    hand.pose.angle = self.angle;
                    hand.spread = self.spread;
                }
            }
            MouseEvent::Modifiers(m) => self.modifiers = m,
            MouseEvent::Mode(kind) => self.mode = kind,
        }
    }

    /// Every hand on the table: pinned ones first, then the dragged one.
    pub fn hands(&self) -> Vec<Hand> {
        self.pinned.iter().chain(&self.active).cloned().collect()
    }

    /// The kind a left press would put down now.
    pub fn kind_for_press(&self) -> HandKind {
        let m = self.modifiers;
        if m.shift {
            HandKind::FlatHand
        } else if m.ctrl {
            HandKind::Edge
        } else if m.alt {
            HandKind::Fingertips(2)
        } else {
            self.mode
        }
    }

    pub fn mode(&self) -> HandKind {
        self.mode
    }

    pub fn cursor(&self) -> [f32; 2] {
        self.cursor
    }

    pub fn is_dragging(&self) -> bool {
        self.active.is_some()
    }

    pub fn pinned(&self) -> &[Hand] {
        &self.pinned
    }

    fn new_hand(&mut self) -> Hand {
        let id = self.next_id;
        self.next_id = self.next_id.wrapping_add(1);
        Hand::new(id, self.kind_for_press(), self.cursor[0], self.cursor[1])
            .with_angle(self.angle)
            .with_spread(self.spread)
            .with_pressure(self.pressure)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use MouseEvent::{Moved, Pressed, Released, Wheel};

    fn run(events: &[MouseEvent]) -> Mouse {
        let mut m = Mouse::new();
        for &e in events {
            m.handle(e);
        }
        m
    }

    #[test]
    fn left_drag_moves_one_fingertip_and_release_lifts_it() {
        let m = run(&[Moved([0.1, 0.2]), Pressed(Button::Left), Moved([0.15, 0.2])]);
        let hands = m.hands();
        assert_eq!(hands.len(), 1);
        assert_eq!(hands[0].kind, HandKind::Fingertips(1));
        assert_eq!([hands[0].pose.x, hands[0].pose.y], [0.15, 0.2]);
        let mut m = m;
        m.handle(Released(Button::Left));
        assert!(m.hands().is_empty());
        assert!(run(&[Moved([0.1, 0.2])]).hands().is_empty());
    }

    #[test]
    fn modifiers_choose_the_hand_at_press_time() {
        let with = |m: Modifiers| run(&[MouseEvent::Modifiers(m), Pressed(Button::Left)]).hands()[0].kind;
        let shift = Modifiers { shift: true, ..Modifiers::default() };
        let ctrl = Modifiers { ctrl: true, ..Modifiers::default() };
        let alt = Modifiers { alt: true, ..Modifiers::default() };
        assert_eq!(with(shift), HandKind::FlatHand);
        assert_eq!(with(ctrl), HandKind::Edge);
        assert_eq!(with(alt), HandKind::Fingertips(2));
        // Releasing the modifier mid-drag keeps the hand.
        let m = run(&[
            MouseEvent::Modifiers(shift),
            Pressed(Button::Left),
            MouseEvent::Modifiers(Modifiers::default()),
            Moved([0.0, 0.1]),
        ]);
        assert_eq!(m.hands()[0].kind, HandKind::FlatHand);
        // The UI mode applies without modifiers.
        let m = run(&[MouseEvent::Mode(HandKind::Forearm), Pressed(Button::Left)]);
        assert_eq!(m.hands()[0].kind, HandKind::Forearm);
    }

    #[test]
    fn wheel_rotates_and_shift_wheel_spreads() {
        let m = run(&[Pressed(Button::Left), Wheel(2.0)]);
        assert!((m.hands()[0].pose.angle.to_degrees() - 30.0).abs() < 1e-4);
        let shift = Modifiers { shift: true, ..Modifiers::default() };
        let m = run(&[
            MouseEvent::Mode(HandKind::Fingertips(2)),
            Pressed(Button::Left),
            MouseEvent::Modifiers(shift),
            Wheel(-10.0),
        ]);
        assert_eq!(m.hands()[0].spread, 0.0);
        assert_eq!(m.hands()[0].pose.angle, 0.0);
        // The angle carries over to the next hand.
        let m = run(&[Wheel(1.0), Pressed(Button::Left)]);
        assert!((m.hands()[0].pose.angle.to_degrees() - 15.0).abs() < 1e-4);
    }

    #[test]
    fn right_click_pins_one_hand_while_the_other_moves() {
        let mut m = run(&[
            Moved([-0.1, 0.0]),
            Pressed(Button::Left),
            Pressed(Button::Right),
            Released(Button::Right),
            Moved([-0.2, 0.0]),
            Released(Button::Left),
        ]);
        assert_eq!(m.hands().len(), 1);
        assert_eq!(m.hands()[0].pose.x, -0.1);
        for e in [Moved([0.1, 0.0]), Pressed(Button::Left), Moved([0.2, 0.05])] {
            m.handle(e);
        }
        let hands = m.hands();
        assert_eq!(hands.len(), 2);
        assert_ne!(hands[0].id, hands[1].id);
        assert_eq!([hands[0].pose.x, hands[1].pose.x], [-0.1, 0.2]);
        // Right click again (after the drag) releases the pinned hand.
        m.handle(Released(Button::Left));
        m.handle(Pressed(Button::Right));
        assert!(m.hands().is_empty());
        // With nothing pinned, a right click pins a new hand at the cursor.
        m.handle(Pressed(Button::Right));
        assert_eq!(m.pinned().len(), 1);
        assert_eq!(m.hands()[0].pose.x, 0.2);
    }

    #[test]
    fn leaving_the_window_lifts_only_the_dragged_hand() {
        let m = run(&[Pressed(Button::Right), Pressed(Button::Left), MouseEvent::Left, Wheel(f32::NAN)]);
        assert_eq!(m.hands().len(), 1);
        assert!(!m.is_dragging());
    }
}
