//! What every command that simulates for a while shares: the work bound
//! checked before the first step ([`check_work`]), and a replay that says
//! how far it has come and stops cleanly at Ctrl-C
//! ([`replay_showing_progress`]).

use crate::input::Gesture;
use crate::scene;
use crate::session::Session;
use std::time::{Duration, Instant};

/// Refuses a run or a picture whose simulated seconds, longer than the
/// scene's own time limit (which loading it checked), ask for more work than this program
/// does in reasonable time ([`scene::Work`]).
pub fn check_work(scene: &scene::Scene, seconds: f64) -> Result<(), super::Failure> {
    let seconds = seconds as f32;
    if seconds <= scene.time_limit_s {
        return Ok(());
    }
    scene::Work::of(scene, seconds)
        .check()
        .map_err(|m| super::Failure::bad_input(anyhow::anyhow!("{}: {seconds} s of simulation: {m}", scene.origin)))
}

/// The exit status of a command stopped by Ctrl-C (128 + SIGINT, as a shell
/// reports a process the signal ended), after what it has is written.
pub const EXIT_INTERRUPTED: u8 = 130;

/// How often a long replay says how far it has come (wall time).
const PROGRESS_EVERY: Duration = Duration::from_secs(2);

/// Where a replay ends: [`Session::replay_until`]'s rule for a gesture (the
/// last step that starts half a step before `until`), or, with no gesture,
/// every step that starts before `until`, as `screenshot` has always
/// stepped a scene left alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Until {
    Gesture(f64),
    Before(f64),
}

impl Until {
    fn seconds(self) -> f64 {
        match self {
            Until::Gesture(t) | Until::Before(t) => t,
        }
    }

    fn goes_on(self, session: &Session) -> bool {
        match self {
            Until::Gesture(t) => session.time() + 0.5 * f64::from(session.world().dt()) < t,
            Until::Before(t) => session.time() < t,
        }
    }
}

/// Replays `gesture` step by step as [`Session::replay_until`] does, the
/// same steps with the same hands, saying on standard error how far it has
/// come every [`PROGRESS_EVERY`] (a dense cloth or a high physics rate can
/// take minutes) and stopping cleanly at Ctrl-C. `Some((time reached,
/// until))` when stopped.
pub fn replay_showing_progress(
    session: &mut Session,
    gesture: &Gesture,
    until: Until,
    command: &str,
    at_stop: &str,
) -> anyhow::Result<Option<(f64, f64)>> {
    use std::sync::atomic::{AtomicBool, Ordering};
    let stop = std::sync::Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    // Without a handler (another one is installed) Ctrl-C ends the process as usual.
    let _ = ctrlc::set_handler(move || flag.store(true, Ordering::Relaxed));
    let end = until.seconds();
    let start = Instant::now();
    let mut next_note = start + PROGRESS_EVERY;
    let mut steps = 0_u64;
    while until.goes_on(session) {
        let hands = gesture.sample(session.time());
        session.step(&hands)?;
        steps += 1;
        // The clock and the flag every few steps: cheap beside a step.
        if !steps.is_multiple_of(8) {
            continue;
        }
        if stop.load(Ordering::Relaxed) {
            eprintln!(
                "surfacelab {command}: stopped by Ctrl-C at {:.2} s of {end:.2} s; it {at_stop} as things are",
                session.time()
            );
            return Ok(Some((session.time(), end)));
        }
        let now = Instant::now();
        if now >= next_note {
            let done = session.time() / end;
            let left = start.elapsed().as_secs_f64() * (1.0 - done) / done.max(1e-9);
            eprintln!(
                "surfacelab {command}: {:.1} of {end:.1} s simulated ({:.0}%), about {left:.0} s left; Ctrl-C stops and {at_stop}",
                session.time(),
                100.0 * done
            );
            next_note = now + PROGRESS_EVERY;
        }
    }
    Ok(None)
}
