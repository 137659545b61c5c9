//! TUIO: the protocol touch tables and trackers speak. [`decode`] turns
//! packets into hands (pure), [`listener`] owns the UDP socket and the clock.

mod decode;
mod listener;
mod timeline;

pub use decode::*;
pub use listener::*;
pub use timeline::Timeline;
