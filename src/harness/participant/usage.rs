//! What one trial's participant did with each manner: time spent in it and
//! the net progress it made (progress minus penalties, m). Written to the
//! `manners` column of `trials.csv` as `name:time_s:net_m` items joined by
//! `;` (in [`Manner::ALL`] order), from which `strategies.csv` is built.

use super::manner::Manner;

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Usage {
    time_s: [f32; Manner::ALL.len()],
    net_m: [f32; Manner::ALL.len()],
}

impl Usage {
    pub fn add(&mut self, manner: Manner, time_s: f32, net_m: f32) {
        self.time_s[manner.index()] += time_s.max(0.0);
        self.net_m[manner.index()] += net_m;
    }

    /// The manner used for the most time (the first on a tie), if any.
    pub fn main(&self) -> Option<Manner> {
        let (k, t) = self.time_s.iter().enumerate().fold((0, 0.0f32), |b, (k, &t)| if t > b.1 { (k, t) } else { b });
        (t > 0.0).then_some(Manner::ALL[k])
    }

    /// `(manner, time_s, net_m)` of every manner used.
    pub fn used(&self) -> impl Iterator<Item = (Manner, f32, f32)> + '_ {
        Manner::ALL
            .into_iter()
            .enumerate()
            .filter(|(k, _)| self.time_s[*k] > 0.0)
            .map(|(k, m)| (m, self.time_s[k], self.net_m[k]))
    }

    /// The `manners` column, e.g. `fingertip_1:12.50:0.800;flat_hand:3.50:0.200`.
    pub fn to_column(&self) -> String {
        self.used().map(|(m, t, n)| format!("{}:{t:.2}:{n:.3}", m.name())).collect::<Vec<_>>().join(";")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn main_manner_and_column() {
        let mut u = Usage::default();
        assert_eq!(u.main(), None);
        assert_eq!(u.to_column(), "");
        u.add(Manner::FlatHand, 3.5, 0.2);
        u.add(Manner::Fingertips(1), 10.0, 0.5);
        u.add(Manner::Fingertips(1), 2.5, 0.3);
        assert_eq!(u.main(), Some(Manner::Fingertips(1)));
        assert_eq!(u.to_column(), "fingertip_1:12.50:0.800;flat_hand:3.50:0.200");
    }
}
