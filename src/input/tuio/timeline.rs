//! What a TUIO tracker reported, packet by packet, with the time each
//! packet arrived, so that every physics step sees the hands at its own
//! time rather than whatever arrived last.
//!
//! The demo runs several catch-up steps per frame when frames are slow
//! (on lavapipe under load). Sampling the tracker once per frame would
//! make all of a frame's steps see one pose and the next frame's jump, as
//! with the mouse (see `sources.rs`). Between two
//! packets a hand moves on the straight line from one report to the next;
//! a hand that appears or vanishes does so at the packet that says so, on
//! its own step. Input is never extrapolated: past the last packet the
//! hands stay where it put them.

use super::decode::TuioState;
use crate::pipeline::surface::Hand;
use std::collections::VecDeque;

/// Reports older than this (s) behind the newest are dropped: a frame
/// never runs more than a few steps behind the wall clock, and the demo
/// caps its catch-up at well under a second.
const KEEP_S: f64 = 1.0;
/// At most this many reports are kept, whatever the sender's rate.
const KEEP_MAX: usize = 512;

/// The tracker's state after each packet, by arrival time (seconds, the
/// listener's clock).
#[derive(Debug, Clone, Default)]
pub struct Timeline {
    reports: VecDeque<(f64, TuioState)>,
}

impl Timeline {
    pub fn new() -> Self {
        Self::default()
    }

    /// Records the state after a packet that arrived at `at` (not
    /// decreasing).
    pub fn record(&mut self, at: f64, state: &TuioState) {
        self.reports.push_back((at, state.clone()));
        while self.reports.len() > KEEP_MAX || self.reports.front().is_some_and(|(t, _)| at - t > KEEP_S) {
            self.reports.pop_front();
        }
    }

    /// The hands on a table of [width, depth] metres at time `t`: those of
    /// the last report at or before `t`, each moved towards where the next
    /// report puts it by `t`'s share of the time between the two. Before
    /// the first report kept, the first report's hands.
    pub fn hands_at(&self, table: [f32; 2], t: f64) -> Vec<Hand> {
        let next = self.reports.partition_point(|(at, _)| *at <= t);
        let Some((t0, before)) = self.reports.get(next.saturating_sub(1)) else {
            return Vec::new();
        };
        let from = before.hands(table, t.max(*t0));
        match self.reports.get(next) {
            Some((t1, after)) if next > 0 && t1 > t0 => {
                let share = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0) as f32;
                let to = after.hands(table, *t1);
                from.into_iter()
                    .map(|h| match to.iter().find(|n| n.id == h.id) {
                        Some(n) => between(&h, n, share),
                        None => h,
                    })
                    .collect()
            }
            _ => from,
        }
    }
}

/// `a` moved `share` of the way to `b` (same hand): position, angle (the
/// short way round), spread and pressure; its kind, size and outline stay
/// `a`'s (a contour moves with its pose).
fn between(a: &Hand, b: &Hand, share: f32) -> Hand {
    let mix = |x: f32, y: f32| x + (y - x) * share;
    let mut turn = (b.pose.angle - a.pose.angle) % std::f32::consts::TAU;
    if turn > std::f32::consts::PI {
        turn -= std::f32::consts::TAU;
    } else if turn < -std::f32::consts::PI {
        turn += std::f32::consts::TAU;
    }
    let mut h = a.clone();
    h.pose.x = mix(a.pose.x, b.pose.x);
    h.pose.y = mix(a.pose.y, b.pose.y);
    h.pose.angle = a.pose.angle + turn * share;
    h.spread = mix(a.spread, b.spread);
    h.pressure = mix(a.pressure, b.pressure);
    h
}

#[cfg(test)]
mod tests {
    use super::*;
    use rosc::{OscBundle, OscMessage, OscPacket, OscTime, OscType, encoder};

    const TABLE: [f32; 2] = [1.0, 0.75];

    /// A TUIO 1.1 bundle: one source, the cursors alive at (x, y)
    /// normalised, frame `fseq`.
    fn cursors(fseq: i32, live: &[(i32, f32, f32)]) -> Vec<u8> {
        let msg = |args: Vec<OscType>| OscPacket::Message(OscMessage { addr: "/tuio/2Dcur".into(), args });
        let mut content = vec![msg(vec!["source".into(), "test@127.0.0.1".into()])];
        let mut alive: Vec<OscType> = vec!["alive".into()];
        alive.extend(live.iter().map(|c| OscType::Int(c.0)));
        content.push(msg(alive));
        for &(id, x, y) in live {
            content.push(msg(vec![
                "set".into(),
                id.into(),
                x.into(),
                y.into(),
                0.0f32.into(),
                0.0f32.into(),
                0.0f32.into(),
            ]));
        }
        content.push(msg(vec!["fseq".into(), fseq.into()]));
        let bundle = OscPacket::Bundle(OscBundle { timetag: OscTime { seconds: 0, fractional: 1 }, content });
        encoder::encode(&bundle).expect("encodes")
    }

    /// A timeline fed `packets` at their times.
    fn timeline(packets: &[(f64, Vec<u8>)]) -> Timeline {
        let mut state = TuioState::new();
        let mut line = Timeline::new();
        for (at, p) in packets {
            state.receive(p, *at).expect("a valid packet");
            line.record(*at, &state);
        }
        line
    }

    #[test]
    fn a_step_between_two_reports_sees_the_hand_on_the_line_between_them() {
        // Cursor 7 at x = 0.2 at t = 1.0 s, at x = 0.6 at t = 1.1 s (on a
        // 1 m table: -0.3 m and +0.1 m from the centre).
        let line = timeline(&[(1.0, cursors(1, &[(7, 0.2, 0.5)])), (1.1, cursors(2, &[(7, 0.6, 0.5)]))]);
        let x = |t: f64| line.hands_at(TABLE, t)[0].pose.x;
        assert!((x(1.0) - -0.3).abs() < 1e-5, "at the first report: {}", x(1.0));
        assert!((x(1.025) - -0.2).abs() < 1e-4, "a quarter of the way: {}", x(1.025));
        assert!((x(1.05) - -0.1).abs() < 1e-4, "half way: {}", x(1.05));
        assert!((x(1.1) - 0.1).abs() < 1e-5, "at the second report: {}", x(1.1));
        assert!((x(1.3) - 0.1).abs() < 1e-5, "never extrapolated past the last report: {}", x(1.3));
    }

    #[test]
    fn a_touch_and_a_lift_happen_at_the_report_that_says_so() {
        let line = timeline(&[
            (0.0, cursors(1, &[])),
            (0.2, cursors(2, &[(3, 0.5, 0.5)])),
            (0.4, cursors(3, &[(3, 0.5, 0.5), (4, 0.1, 0.1)])),
            (0.6, cursors(4, &[(4, 0.1, 0.1)])),
        ]);
        let count = |t: f64| line.hands_at(TABLE, t).len();
        assert_eq!(count(0.1), 0, "nothing down before the first touch is reported");
        assert_eq!(count(0.19), 0);
        assert_eq!(count(0.2), 1, "down at its own report");
        assert_eq!(count(0.39), 1, "the second finger is not down before its report");
        assert_eq!(count(0.4), 2);
        assert_eq!(count(0.59), 2, "the first finger lifts at its report, not before");
        assert_eq!(count(0.6), 1);
    }

    #[test]
    fn old_reports_are_dropped_and_an_early_time_sees_the_oldest_kept() {
        let packets: Vec<(f64, Vec<u8>)> =
            (0..200).map(|k| (f64::from(k) * 0.01, cursors(k + 1, &[(1, 0.5, 0.5)]))).collect();
        let line = timeline(&packets);
        assert!(line.reports.len() <= 101, "about a second of reports kept: {}", line.reports.len());
        assert_eq!(line.hands_at(TABLE, 0.0).len(), 1, "before the oldest kept report: its hands");
        assert!(Timeline::new().hands_at(TABLE, 1.0).is_empty(), "nothing reported, no hands");
    }

    #[test]
    fn turning_takes_the_short_way_round() {
        let a = Hand::new(1, crate::pipeline::surface::HandKind::FlatHand, 0.0, 0.0);
        let (mut from, mut to) = (a.clone(), a);
        from.pose.angle = 3.0;
        to.pose.angle = -3.0;
        let mid = between(&from, &to, 0.5);
        // 3.0 to -3.0 rad is 0.28 rad across pi, not 6 rad through 0.
        assert!((mid.pose.angle - (3.0 + 0.5 * (std::f32::consts::TAU - 6.0))).abs() < 1e-5, "{}", mid.pose.angle);
    }
}
