//! How much simulation a scene asks for, predicted before a step is taken.
//!
//! Every number in a scene can lie within its own bound while their product
//! does not: a 256-particle cloth is fine, 10 kHz physics is fine, and a
//! 90 s trial is fine, but together they are 230 million particle-steps,
//! hours of work with no end in sight. A scene is therefore also checked
//! against a bound on the work it implies, and refused (exit 2) with the
//! product and the bound named, so nothing a file asks for runs for hours
//! without a word.

use super::model::Scene;

/// Soft-body particle-steps (particles × steps, times the solver iterations
/// over the default 4) a scene may ask for. A cloth step under the Particle
/// technique, the costliest, takes 0.12 ms per particle at 256 particles and
/// 0.14 ms at 1,024 (`surfacelab run --task cloth.toml --technique particle
/// --gesture flatten` at 240 Hz on a 2-core VM: 15.2 s and 68.3 s for 480
/// steps), so ten million is about twenty minutes on one core. The built-in
/// cloth (256 particles, 60 Hz, 90 s) asks for 1.4 million.
pub const MAX_PARTICLE_STEPS: f64 = 1.0e7;

/// Rigid object-steps (objects × steps, times the solver iterations over
/// the default 4): the most objects a scene may have ([`super::bounds::MAX_OBJECTS`],
/// which stay within a real-time step) at the default 60 Hz for the longest
/// duration ([`super::bounds::DURATION_S`]), ten minutes of work.
pub const MAX_OBJECT_STEPS: f64 = 1000.0 * 60.0 * 600.0;

/// The solver iterations the work bounds are measured at.
const DEFAULT_ITERATIONS: usize = 4;

/// The work a scene asks for over a number of simulated seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Work {
    pub particles: usize,
    pub objects: usize,
    pub steps_per_s: f64,
    pub seconds: f32,
    /// Solver iterations over the default, at least 1.
    pub iterations: f32,
}

impl Work {
    /// `scene` run for `seconds`.
    pub fn of(scene: &Scene, seconds: f32) -> Work {
        let particles = scene.soft_bodies.iter().map(|b| b.resolution.iter().product::<usize>()).sum();
        let iterations = scene.physics.solver_iterations.max(DEFAULT_ITERATIONS) as f32 / DEFAULT_ITERATIONS as f32;
        // The rate as written (2000 Hz, not the 1999.9999 of 1 / dt in f32).
        let steps_per_s = (1000.0 / f64::from(scene.physics.dt)).round() / 1000.0;
        Work { particles, objects: scene.objects.len(), steps_per_s, seconds, iterations }
    }

    fn steps(&self) -> f64 {
        self.steps_per_s * f64::from(self.seconds) * f64::from(self.iterations)
    }

    /// `Err` with the product and its bound where the work is beyond what
    /// this program does in reasonable time; what to lower is named.
    pub fn check(&self) -> Result<(), String> {
        let iterations = if self.iterations > 1.0 {
            format!(" × {} (solver iterations over {DEFAULT_ITERATIONS})", self.iterations)
        } else {
            String::new()
        };
        let over = |count: usize, what: &str, bound: f64, minutes: u32, lower: &str| {
            let plural = if count == 1 { what.to_owned() } else { format!("{what}s") };
            let product = count as f64 * self.steps();
            (product > bound).then(|| {
                format!(
                    "{count} {plural} × {} Hz × {} s{iterations} = {} {what}-steps, above the bound of {} \
                     (about {minutes} minutes of work); lower {lower}, `physics.timestep_hz` or `time_limit_s`",
                    self.steps_per_s,
                    self.seconds,
                    thousands(product),
                    thousands(bound)
                )
            })
        };
        match over(self.particles, "particle", MAX_PARTICLE_STEPS, 20, "a soft body's `resolution`")
            .or_else(|| over(self.objects, "object", MAX_OBJECT_STEPS, 10, "the object `count`"))
        {
            Some(message) => Err(message),
            None => Ok(()),
        }
    }
}

/// 230400000 as 230,400,000.
fn thousands(v: f64) -> String {
    let digits = format!("{:.0}", v.round());
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn work(particles: usize, objects: usize, hz: f64, seconds: f32) -> Work {
        Work { particles, objects, steps_per_s: hz, seconds, iterations: 1.0 }
    }

    #[test]
    fn the_built_in_cloth_fits_and_the_same_cloth_at_10_khz_does_not() {
        assert_eq!(work(256, 0, 60.0, 90.0).check(), Ok(()));
        let e = work(256, 0, 10_000.0, 90.0).check().expect_err("hours of work");
        assert!(
            e.starts_with(
                "256 particles × 10000 Hz × 90 s = 230,400,000 particle-steps, above the bound of 10,000,000"
            ),
            "{e}"
        );
    }

    #[test]
    fn the_most_objects_fit_at_60_hz_for_the_longest_run_and_not_faster() {
        assert_eq!(work(0, 1000, 60.0, 600.0).check(), Ok(()));
        let e = work(0, 1000, 61.0, 600.0).check().expect_err("past the bound");
        assert!(e.contains("36,600,000 object-steps, above the bound of 36,000,000"), "{e}");
        let e = Work { iterations: 2.0, ..work(0, 1000, 60.0, 600.0) }.check().expect_err("8 iterations");
        assert!(e.contains(" × 2 (solver iterations over 4) = 72,000,000"), "{e}");
    }
}
