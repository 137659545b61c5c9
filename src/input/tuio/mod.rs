//! TUIO: the protocol touch tables and trackers speak. [`decode`] turns
//! packets into hands (pure; TUIO 1.1 there, 2.0 in [`tuio2`]), [`listener`]
//! owns the UDP socket and the clock.

mod decode;
mod listener;
mod timeline;
mod tuio2;

pub use decode::*;
pub use listener::*;
pub use timeline::Timeline;
pub use tuio2::{Bounds, Pointer, Skeleton, Span, TUIO2_ID_BASE, Token};
