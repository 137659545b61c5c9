//! Contact-image analysis: threshold, connected components, Sobel outlines, block-matching flow and contact tracking.

mod components;
mod contact_id;
mod contour;
mod flow;
mod grid;
mod hull;
mod interest;
mod pipeline;
mod sobel;
mod threshold;
mod tracking;

pub use components::{BBox, Blob, Ellipse, Run, find_blobs, find_blobs_in_rows};
pub use contact_id::ContactId;
pub use contour::trace_contour;
pub use flow::{BlockMatcher, MAX_BLOCK};
pub use hull::{convex_hull, signed_area};
pub use interest::{ConvexRegion, FlowInterest};
pub use pipeline::{Contact, EdgeSample, Pipeline, StageTimings, VisionFrame, VisionParams, rigid_guess};
pub use sobel::{EDGE_PAD, EdgePixel, find_edges, gradient_magnitude, sobel_at};
pub use threshold::{Mask, threshold, threshold_into, threshold_rows};
pub use tracking::{BlobTracker, BlobTrackerParams, Tracked};
