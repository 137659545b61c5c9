//! The fixed physics timestep, independent of the frame rate: real time
//! accrues as debt, each session step pays one `dt` of it.
//!
//! A frame runs as many steps as the debt allows, at most `max_steps`; what
//! is left beyond one step is dropped, so a stall (a slow frame, a window
//! drag, a debugger) makes the simulation run slower than real time for a
//! moment instead of spiralling into ever longer catch-up frames.

/// Debt-based fixed-step clock.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clock {
    dt: f64,
    max_steps: u32,
    debt: f64,
    /// Real seconds dropped so far because the machine could not keep up.
    dropped: f64,
    /// Real seconds the last [`Clock::advance`] dropped.
    dropped_last: f64,
}

impl Clock {
    /// `dt` seconds per step (> 0), at most `max_steps` (>= 1) per frame.
    pub fn new(dt: f64, max_steps: u32) -> Self {
        Self { dt: dt.max(1e-6), max_steps: max_steps.max(1), debt: 0.0, dropped: 0.0, dropped_last: 0.0 }
    }

    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Adds `elapsed` real seconds; returns the number of steps due now.
    pub fn advance(&mut self, elapsed: f64) -> u32 {
        if elapsed.is_finite() && elapsed > 0.0 {
            self.debt += elapsed;
        }
        let due = (self.debt / self.dt).floor();
        let steps = due.min(f64::from(self.max_steps));
        self.debt -= steps * self.dt;
        self.dropped_last = (self.debt - self.dt).max(0.0);
        if self.dropped_last > 0.0 {
            self.dropped += self.dropped_last;
            self.debt = self.dt;
        }
        steps as u32
    }

    /// How many real seconds before now step `k` of the `due` steps the
    /// last [`Clock::advance`] asked for stands for. The last step stands
    /// for now less the debt still owed, the ones before it a step's length
    /// apart, so the steps of successive frames lie exactly `dt` apart in
    /// real time. When the last advance dropped time, its steps are spread
    /// evenly over the real time they covered, dropped part included.
    pub fn stood_for(&self, k: u32, due: u32) -> f64 {
        let spacing = if due > 0 { self.dt + self.dropped_last / f64::from(due) } else { self.dt };
        self.debt + f64::from(due.saturating_sub(k + 1)) * spacing
    }

    /// Forgets the debt (after a pause, so resuming does not catch up).
    pub fn clear(&mut self) {
        self.debt = 0.0;
        self.dropped_last = 0.0;
    }

    /// Real seconds the simulation has fallen behind in total.
    pub fn dropped(&self) -> f64 {
        self.dropped
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_follow_real_time_whatever_the_frame_rate() {
        for fps in [30.0, 60.0, 75.0, 144.0, 240.0] {
            let mut c = Clock::new(1.0 / 60.0, 4);
            let frames = (fps * 10.0) as usize;
            let steps: u32 = (0..frames).map(|_| c.advance(1.0 / fps)).sum();
            assert!((599..=601).contains(&steps), "{fps} fps: {steps} steps in 10 s");
            assert_eq!(c.dropped(), 0.0);
        }
    }

    /// Steps stand for real times exactly `dt` apart across frames of any
    /// length, so a steady drag moves the hand the same distance each step.
    #[test]
    fn steps_stand_for_times_a_step_apart_across_frames() {
        let dt = 1.0 / 60.0;
        let mut c = Clock::new(dt, 6);
        let (mut wall, mut times) = (0.0, Vec::new());
        for elapsed in [0.041, 0.063, 0.029, 0.077, 0.052, 0.018, 0.094, 0.035] {
            wall += elapsed;
            let due = c.advance(elapsed);
            times.extend((0..due).map(|k| wall - c.stood_for(k, due)));
        }
        assert!(times.len() > 20, "{} steps", times.len());
        for pair in times.windows(2) {
            assert!((pair[1] - pair[0] - dt).abs() < 1e-9, "steps {pair:?} are not {dt} s apart");
        }
        // A stall's steps spread over the real time they cover.
        let due = c.advance(1.0);
        let first = c.stood_for(0, due);
        assert!(first > 0.8 && c.stood_for(due - 1, due) <= dt + 1e-12, "{first}");
    }

    #[test]
    fn a_stall_is_dropped_not_caught_up() {
        let mut c = Clock::new(1.0 / 60.0, 4);
        assert_eq!(c.advance(2.0), 4);
        assert!(c.dropped() > 1.9);
        // One step of debt is kept; the next frame is ordinary again.
        assert_eq!(c.advance(1.0 / 60.0), 2);
        assert_eq!(c.advance(f64::NAN), 0);
    }
}
