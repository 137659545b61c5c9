//! What a scripted participant learns: payoff estimates of each manner per
//! context, one rule for every technique.
//!
//! **Context** = the goal's kind (positioning, sorting, steering, other) ×
//! the cluster band of the object about to be moved (1 object, 2–3, 4 or
//! more bound for the same destination within a hand's width). The
//! technique is *not* part of the context: the participant learns from what
//! happens under their hands, and what it learned under one technique
//! carries into the next (as it does for people), so technique order
//! matters and the Latin square balances it.
//!
//! **Payoff** of one episode (touch to lift) = (progress − penalties) /
//! duration, in m/s, where progress is the drop in the summed distance of
//! all open objects to their goals, a re-grip (the objects stopped
//! following) costs [`REGRIP_PENALTY_M`] and a drop (a restart)
//! [`DROP_PENALTY_M`].
//!
//! **Update**: a recency-weighted mean, `Q += ALPHA · (payoff − Q)`, so
//! estimates follow the technique now in use within a few episodes.
//!
//! **Choice**: ε-greedy over the manners the situation allows. Practice
//! trials explore with [`EXPLORE_PRACTICE`], measured trials with
//! [`EXPLORE_MEASURED`]. Priors are optimistic (above what most manners
//! turn out to pay), so a greedy participant still tries each manner once
//! per context before settling.
//!
//! **Priors** (the same for everyone): the participant's habitual fingertip
//! drag (index finger, or two fingers for the participants whose skill says
//! so) starts at [`PRIOR_HABIT`], every other manner at [`PRIOR_OTHER`]. So
//! a fresh participant begins with the finger, as people do on a touch
//! screen, and moves to other manners only after the finger disappoints.

use super::manner::Manner;
use crate::scene::Goal;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Step size of the payoff estimates: an episode's payoff moves the
/// estimate 30% of the way (about three episodes to follow a change).
pub const ALPHA: f32 = 0.3;
/// Exploration during practice trials: one choice in three is random.
pub const EXPLORE_PRACTICE: f32 = 0.3;
/// Exploration during measured trials: one in twenty.
pub const EXPLORE_MEASURED: f32 = 0.05;
/// Prior payoff of the habitual fingertip drag (m/s).
pub const PRIOR_HABIT: f32 = 0.2;
/// Prior payoff of every other manner (m/s): below the habit, above what a
/// manner that fails pays, so each is tried once the habit disappoints.
pub const PRIOR_OTHER: f32 = 0.15;
/// A re-grip costs as much as losing this much progress (m).
pub const REGRIP_PENALTY_M: f32 = 0.03;
/// A drop (task restart) costs as much as losing this much progress (m).
pub const DROP_PENALTY_M: f32 = 0.3;

/// The situation a payoff is learned for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Context {
    /// 0 positioning, 1 sorting, 2 steering, 3 any other goal.
    pub goal: u8,
    /// 0: one object; 1: 2–3; 2: 4 or more.
    pub cluster_band: u8,
}

impl Context {
    pub fn new(goal: &Goal, cluster: usize) -> Context {
        let goal = match goal {
            Goal::Positioning { .. } => 0,
            Goal::Sorting { .. } => 1,
            Goal::Steering(_) => 2,
            _ => 3,
        };
        let cluster_band = match cluster {
            0 | 1 => 0,
            2 | 3 => 1,
            _ => 2,
        };
        Context { goal, cluster_band }
    }

    fn slot(self) -> usize {
        usize::from(self.goal.min(3)) * 3 + usize::from(self.cluster_band.min(2))
    }
}

const CONTEXTS: usize = 12;

/// One participant's payoff estimates; carried from trial to trial.
#[derive(Debug, Clone, PartialEq)]
pub struct Learner {
    q: [[f32; Manner::ALL.len()]; CONTEXTS],
    tries: [[u32; Manner::ALL.len()]; CONTEXTS],
}

impl Learner {
    /// A fresh participant whose habitual drag is `habit`.
    pub fn new(habit: Manner) -> Learner {
        let mut row = [PRIOR_OTHER; Manner::ALL.len()];
        row[habit.index()] = PRIOR_HABIT;
        Learner { q: [row; CONTEXTS], tries: [[0; Manner::ALL.len()]; CONTEXTS] }
    }

    /// The payoff estimate of `manner` in `context` (m/s).
    pub fn estimate(&self, context: Context, manner: Manner) -> f32 {
        self.q[context.slot()][manner.index()]
    }

    /// Episodes of `manner` seen in `context`.
    pub fn tries(&self, context: Context, manner: Manner) -> u32 {
        self.tries[context.slot()][manner.index()]
    }

    /// ε-greedy among `options` (ties to the first listed).
    pub fn choose(&self, context: Context, options: &[Manner], explore: f32, rng: &mut ChaCha8Rng) -> Option<Manner> {
        let first = *options.first()?;
        if rng.random::<f32>() < explore {
            return Some(options[rng.random_range(0..options.len())]);
        }
        Some(
            options
                .iter()
                .copied()
                .fold(first, |best, m| if self.estimate(context, m) > self.estimate(context, best) { m } else { best }),
        )
    }

    /// Learns from one episode's payoff.
    pub fn update(&mut self, context: Context, manner: Manner, payoff: f32) {
        if !payoff.is_finite() {
            return;
        }
        let q = &mut self.q[context.slot()][manner.index()];
        *q += ALPHA * (payoff - *q);
        self.tries[context.slot()][manner.index()] += 1;
    }
}

/// An episode's progress less its penalties (m).
pub fn net_progress(progress_m: f32, regrips: u32, drops: u32) -> f32 {
    progress_m - REGRIP_PENALTY_M * regrips as f32 - DROP_PENALTY_M * drops as f32
}

/// An episode's payoff (m/s): see the module doc.
pub fn payoff(progress_m: f32, regrips: u32, drops: u32, duration_s: f32) -> f32 {
    net_progress(progress_m, regrips, drops) / duration_s.max(0.25)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    fn ctx() -> Context {
        Context { goal: 1, cluster_band: 1 }
    }

    #[test]
    fn a_fresh_participant_uses_the_habit_then_leaves_it_when_it_fails() {
        let mut l = Learner::new(Manner::Fingertips(1));
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let options = [Manner::Fingertips(1), Manner::FlatHand, Manner::EdgeSweep];
        assert_eq!(l.choose(ctx(), &options, 0.0, &mut rng), Some(Manner::Fingertips(1)));
        // The finger achieves 2 cm/s: after a few episodes it falls below
        // the untried manners' prior, which are tried next.
        for _ in 0..3 {
            l.update(ctx(), Manner::Fingertips(1), 0.02);
        }
        assert!(l.estimate(ctx(), Manner::Fingertips(1)) < PRIOR_OTHER);
        assert_eq!(l.choose(ctx(), &options, 0.0, &mut rng), Some(Manner::FlatHand));
        // The flat hand pays 10 cm/s, the sweep nothing: the hand wins.
        for _ in 0..5 {
            l.update(ctx(), Manner::FlatHand, 0.10);
            l.update(ctx(), Manner::EdgeSweep, 0.0);
        }
        assert_eq!(l.choose(ctx(), &options, 0.0, &mut rng), Some(Manner::FlatHand));
        // Another context learned nothing.
        let other = Context { goal: 0, cluster_band: 0 };
        assert_eq!(l.choose(other, &options, 0.0, &mut rng), Some(Manner::Fingertips(1)));
        assert_eq!(l.tries(ctx(), Manner::FlatHand), 5);
    }

    #[test]
    fn recency_weighted_mean_converges_to_the_payoff() {
        let mut l = Learner::new(Manner::Fingertips(1));
        for _ in 0..40 {
            l.update(ctx(), Manner::PushEdge, 0.07);
        }
        assert!((l.estimate(ctx(), Manner::PushEdge) - 0.07).abs() < 1e-4);
        l.update(ctx(), Manner::PushEdge, f32::NAN);
        assert!((l.estimate(ctx(), Manner::PushEdge) - 0.07).abs() < 1e-4, "a NaN payoff is ignored");
    }

    #[test]
    fn exploration_picks_every_option_sometimes() {
        let l = Learner::new(Manner::Fingertips(1));
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let options = [Manner::Fingertips(1), Manner::Pinch, Manner::PushEdge];
        let mut seen = [0; 3];
        for _ in 0..300 {
            let m = l.choose(ctx(), &options, 1.0, &mut rng).expect("some");
            seen[options.iter().position(|o| *o == m).expect("listed")] += 1;
        }
        assert!(seen.iter().all(|&n| n > 60), "{seen:?}");
    }

    #[test]
    fn penalties_lower_the_payoff() {
        assert!((payoff(0.5, 0, 0, 5.0) - 0.1).abs() < 1e-6);
        assert!((payoff(0.5, 1, 0, 5.0) - 0.094).abs() < 1e-6);
        assert!(payoff(0.5, 0, 1, 5.0) < payoff(0.5, 5, 0, 5.0));
    }
}
