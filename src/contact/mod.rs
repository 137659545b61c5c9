//! Pure 2D contact geometry after Cheng et al. 2016 (entrance blocks), with no world and no GPU.

mod brute_force;
mod cached;
mod circle;
mod concave;
mod entrance_block;
mod error;
mod json_query;
mod line_index;
mod local_walk;
mod overlapping;
mod polygon;
mod query;
mod random_polygon;
mod report;
mod scaling;
mod separated;
#[cfg(test)]
mod test_support;
mod tolerance;
mod vec2;

pub use brute_force::{brute_force_report, brute_force_report_at, valid_covers};
pub use cached::CachedBlock;
pub use circle::{CircleFit, discretization_error, discretize_circle, segments_for_error};
pub use concave::{MAX_CONCAVE_VERTICES, SimplePolygon, UnionBlock};
pub use entrance_block::{ContactEdge, CoverKind, EntranceBlock, pair_tolerance};
pub use error::{ContactError, PolygonError};
pub use json_query::answer_json;
pub use polygon::ConvexPolygon;
pub use query::contact_report;
pub use random_polygon::random_ellipse;
pub use report::{ContactReport, Feature, Features, Relation};
pub use scaling::log_log_slope;
pub use tolerance::{scale_tolerance, tight_tolerance};
pub use vec2::Vec2;
