//! Fixed-length arrays read from files with their length checked. The TOML
//! reader fills a `[f32; 2]` from the first two entries of a longer array
//! and drops the rest without a word, so `size = [1.0, 0.75, 0.3]` would
//! pass as a two-number size. A field read with [`exactly`] is refused
//! instead: "expected an array of 2 values, found 3", with the file, line
//! and field the reader adds. Part of `files`, it depends on nothing in
//! the crate; every layer's file format may use it.
//!
//! ```text
//! #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
//! pub step: Option<[f32; 2]>,
//! ```

use serde::de::{DeserializeOwned, Error as _};
use serde::{Deserialize, Deserializer};
use toml::Spanned;

/// `[T; N]` read from an array of exactly `N` entries.
pub(crate) struct Exact<T, const N: usize>([T; N]);

impl<'de, T: DeserializeOwned, const N: usize> Deserialize<'de> for Exact<T, N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let entries = Vec::<T>::deserialize(d)?;
        let found = entries.len();
        <[T; N]>::try_from(entries)
            .map(Exact)
            .map_err(|_| D::Error::custom(format_args!("expected an array of {N} values, found {found}")))
    }
}

/// A field type whose fixed-length arrays, however nested in `Vec`,
/// `Option` and `Spanned`, are read with their length checked.
pub(crate) trait Exactly: Sized {
    /// What serde reads: the same shape, each array an [`Exact`].
    type Wire: DeserializeOwned;
    fn from_wire(wire: Self::Wire) -> Self;
}

impl<T: DeserializeOwned, const N: usize> Exactly for [T; N] {
    type Wire = Exact<T, N>;
    fn from_wire(wire: Exact<T, N>) -> Self {
        wire.0
    }
}

impl<E: Exactly> Exactly for Vec<E> {
    type Wire = Vec<E::Wire>;
    fn from_wire(wire: Self::Wire) -> Self {
        wire.into_iter().map(E::from_wire).collect()
    }
}

impl<E: Exactly> Exactly for Option<E> {
    type Wire = Option<E::Wire>;
    fn from_wire(wire: Self::Wire) -> Self {
        wire.map(E::from_wire)
    }
}

impl<E: Exactly> Exactly for Spanned<E> {
    type Wire = Spanned<E::Wire>;
    fn from_wire(wire: Self::Wire) -> Self {
        let span = wire.span();
        Spanned::new(span, E::from_wire(wire.into_inner()))
    }
}

/// `deserialize_with` for any [`Exactly`] field (add `default` on an
/// `Option`, which serde otherwise treats as optional only without it).
pub(crate) fn exactly<'de, D: Deserializer<'de>, T: Exactly>(d: D) -> Result<T, D::Error> {
    T::Wire::deserialize(d).map(T::from_wire)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, Deserialize)]
    struct Row {
        #[serde(deserialize_with = "exactly")]
        size: [f32; 2],
        #[serde(default, deserialize_with = "exactly")]
        step: Option<Spanned<[f64; 3]>>,
        #[serde(default, deserialize_with = "exactly")]
        ring: Vec<Vec<[f64; 2]>>,
    }

    #[test]
    fn the_right_lengths_read_as_arrays() {
        let row: Row =
            toml::from_str("size = [1.0, 0.75]\nstep = [1, 2, 3]\nring = [[[0, 0], [1, 0], [0, 1]]]").expect("valid");
        assert_eq!(row.size, [1.0, 0.75]);
        let step = row.step.expect("step");
        assert_eq!((*step.get_ref(), step.span()), ([1.0, 2.0, 3.0], 26..35));
        assert_eq!(row.ring, [[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]]);
        let row: Row = toml::from_str("size = [1, 2]").expect("the rest is optional");
        assert!(row.step.is_none() && row.ring.is_empty());
    }

    #[test]
    fn a_longer_or_shorter_array_is_refused_at_its_line() {
        for (text, found) in [
            ("size = [1.0, 0.75, 0.3]", "found 3"),
            ("size = [1.0]", "found 1"),
            ("size = [1, 2]\nstep = [1, 2, 3, 4]", "found 4"),
            ("size = [1, 2]\nring = [[[0, 0], [1, 0, 5]]]", "found 3"),
        ] {
            let e = toml::from_str::<Row>(text).expect_err(text).to_string();
            assert!(e.contains("expected an array of") && e.contains(found), "{text}: {e}");
            let line = text.lines().count();
            assert!(e.contains(&format!("line {line}")), "{text}: {e}");
        }
    }
}
