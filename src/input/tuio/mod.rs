//! TUIO: the protocol touch tables and trackers speak. `decode` turns
//! packets into hands (pure; TUIO 1.1 there, 2.0 in `tuio2`), `listener`
//! owns the UDP socket and the clock; `protocol` holds what both
//! versions share.

mod decode;
mod listener;
mod protocol;
mod timeline;
mod tuio2;

pub use decode::*;
pub use listener::*;
pub use protocol::{MAX_BUNDLE_DEPTH, STALE_AFTER_S, TuioError, TuioStats};
pub use timeline::Timeline;
pub use tuio2::{Bounds, Pointer, Skeleton, Span, TUIO2_ID_BASE, Token};
