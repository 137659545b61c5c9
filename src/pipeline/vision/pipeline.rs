//! The vision pipeline: one contact image in, contacts and moving outline
//! points out, with the time each stage took.
//!
//! Stage order: threshold -> components -> tracking -> Sobel -> flow.
//! Tracking runs before flow (the paper has them side by side) because its
//! per-contact motion is the flow search's guess: a flick moving 20 px per
//! frame is then found with a 3 px search radius instead of a 20 px one
//! (45x fewer candidates), and the guess resolves the aperture problem
//! along straight outlines.

use std::collections::VecDeque;
use std::ops::Range;
use std::time::Instant;

use crate::pipeline::surface::ContactImage;

use super::components::{Blob, find_blobs_in_rows};
use super::contact_id::ContactId;
use super::flow::BlockMatcher;
use super::interest::FlowInterest;
use super::sobel::find_edges;
use super::threshold::{Mask, threshold_rows};
use super::tracking::{BlobTracker, BlobTrackerParams};

/// Pipeline settings. The defaults suit the default sensor (640 x 480 over
/// 1.0 x 0.75 m, 1.56 mm pixels) and the rasterizer's 4 px soft edge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VisionParams {
    /// Grey level at and above which a pixel is touching. 48 (19% of full
    /// scale): a light touch at pressure 0.4 still shows (its outline sits
    /// about a pixel inside the drawn shape), and sensor noise of up to
    /// +-40 never does.
    pub threshold: u8,
    /// Blobs smaller than this many pixels are noise (a fingertip is ~90).
    pub min_area: u32,
    /// Gradient magnitude (grey levels per pixel) at and above which a
    /// pixel is on an outline. A full-pressure soft edge rises ~64 grey/px;
    /// 12 keeps the outline of a touch down to pressure ~0.2 while leaving
    /// out the flat inside of a contact, where noise alone makes gradients.
    pub edge_threshold: f32,
    /// Report every `stride`-th column and row of the outline (a grid
    /// anchored at pixel 0, so still contacts keep their points). The soft
    /// edge is a band about 4 px wide: at 3 a flat hand gives a few hundred
    /// points, about one per 2 mm of outline; 2 gives about twice as many
    /// and 1 about nine times, with flow cost and particle count in
    /// proportion (`cargo bench --bench vision`). 3 is what keeps two flat
    /// hands within the vision stage's 0.5 ms budget.
    pub stride: usize,
    /// Side of the block matched for flow, pixels (odd). 7 spans the
    /// 4 px soft edge with texture to spare on both sides.
    pub block_size: usize,
    /// Flow search radius around the tracked motion's prediction, pixels.
    /// 3 covers a fingertip spinning or accelerating by 3 px per frame
    /// beyond what tracking predicted.
    pub search_radius: usize,
    /// See [`BlobTrackerParams::max_jump_px`].
    pub max_jump_px: f32,
}

impl Default for VisionParams {
    fn default() -> Self {
        Self {
            threshold: 48,
            min_area: 6,
            edge_threshold: 12.0,
            stride: 3,
            block_size: 7,
            search_radius: 3,
            max_jump_px: BlobTrackerParams::default().max_jump_px,
        }
    }
}

/// A tracked contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    /// Stable across frames (see `tracking` for the rules).
    pub id: ContactId,
    pub blob: Blob,
    /// Weighted-centroid motion, pixels per frame.
    pub velocity_px: [f32; 2],
    /// Principal-axis turn, radians per frame, image orientation (negate
    /// for the table); smoothed over frames for nearly round blobs, 0 for
    /// round ones (see `Tracked::rotation`).
    pub rotation_rad: f32,
    /// Frames since the contact appeared (0 = new).
    pub age_frames: u32,
}

/// A point of a contact's outline with its motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeSample {
    /// Pixel position `[column, row]` (integers at pixel centres).
    pub px: [f32; 2],
    /// Image motion at this point since the previous frame, pixels per
    /// frame: the content here was at `px - flow_px` one frame ago. Zero on
    /// a contact's first frame.
    pub flow_px: [f32; 2],
    /// Gradient magnitude, grey levels per pixel.
    pub magnitude: f32,
    /// Grey level at the point.
    pub grey: u8,
    pub contact_id: ContactId,
    /// Whether `flow_px` was measured: false where the frame's
    /// [`FlowInterest`] asked for none (it is then zero).
    pub has_flow: bool,
}

/// Microseconds spent in each stage of one `process` call.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StageTimings {
    pub threshold_us: f64,
    pub components_us: f64,
    pub tracking_us: f64,
    pub sobel_us: f64,
    pub flow_us: f64,
    /// Everything, including keeping a copy of the frame for the next flow.
    pub total_us: f64,
}

/// The result of one frame.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VisionFrame {
    pub contacts: Vec<Contact>,
    pub edges: Vec<EdgeSample>,
    pub timings: StageTimings,
}

/// A frame kept for the flow of later ones.
#[derive(Debug, Clone)]
struct PastFrame {
    image: ContactImage,
    /// The rows it may have lit (black elsewhere).
    lit: Range<usize>,
}

/// Runs the stages frame after frame, keeping what flow and tracking need
/// from earlier frames.
#[derive(Debug, Clone)]
pub struct Pipeline {
    params: VisionParams,
    matcher: BlockMatcher,
    tracker: BlobTracker,
    /// The last frames, newest last: as many as a slow contact's flow
    /// baseline may span (see `Tracked::baseline`).
    past: VecDeque<PastFrame>,
    mask: Mask,
    /// The rows the previous frame may have lit (see [`Pipeline::process_rows`]).
    lit: Range<usize>,
}

impl Default for Pipeline {
    fn default() -> Self {
        Self::new(VisionParams::default())
    }
}

fn micros(since: Instant) -> f64 {
    since.elapsed().as_secs_f64() * 1e6
}

impl Pipeline {
    pub fn new(params: VisionParams) -> Self {
        Self {
            params,
            matcher: BlockMatcher::new(params.block_size, params.search_radius),
            tracker: BlobTracker::new(BlobTrackerParams {
                max_jump_px: params.max_jump_px,
                ..BlobTrackerParams::default()
            }),
            past: VecDeque::new(),
            mask: Mask::default(),
            lit: 0..usize::MAX,
        }
    }

    pub fn params(&self) -> VisionParams {
        self.params
    }

    /// Forgets the earlier frames and every contact.
    pub fn reset(&mut self) {
        self.tracker.reset();
        self.past.clear();
        self.lit = 0..usize::MAX;
    }

    /// Analyses one frame, measuring flow at every outline point.
    pub fn process(&mut self, image: &ContactImage) -> VisionFrame {
        self.process_with(image, &FlowInterest::All)
    }

    /// Analyses one frame, measuring flow only where `interest` asks.
    pub fn process_with(&mut self, image: &ContactImage, interest: &FlowInterest) -> VisionFrame {
        self.process_rows(image, 0..image.height, interest)
    }

    /// [`Self::process_with`] for an image that is black outside `rows` (as
    /// [`crate::pipeline::surface::rasterize_rows`] returns them). Thresholding,
    /// labelling and keeping the previous frame then touch only those rows
    /// and the previous frame's: the same result as `process_with`, without
    /// passes over empty glass.
    pub fn process_rows(&mut self, image: &ContactImage, rows: Range<usize>, interest: &FlowInterest) -> VisionFrame {
        let start = Instant::now();
        let changed = union(&rows, &self.lit, image.height);
        self.lit = rows.clone();
        let mut timings = StageTimings::default();
        let p = self.params;

        let t = Instant::now();
        threshold_rows(image, p.threshold, &mut self.mask, changed.clone());
        timings.threshold_us = micros(t);

        let t = Instant::now();
        // Level 0 lights every pixel, wherever the hands are.
        let scan = if p.threshold == 0 { 0..image.height } else { rows };
        let blobs = find_blobs_in_rows(image, &self.mask, p.min_area, scan);
        timings.components_us = micros(t);

        let t = Instant::now();
        let tracked = self.tracker.update(&blobs);
        timings.tracking_us = micros(t);

        let t = Instant::now();
        let outline = find_edges(image, &blobs, p.edge_threshold, p.stride);
        timings.sobel_us = micros(t);

        let t = Instant::now();
        if self.past.back().is_some_and(|q| q.image.width != image.width || q.image.height != image.height) {
            self.past.clear();
        }
        let past = &self.past;
        let edges = outline
            .iter()
            .map(|e| {
                let (blob, track) = (&blobs[e.blob], &tracked[e.blob]);
                let px = [e.x as f32, e.y as f32];
                // The flow's baseline: one frame, or several for a slow
                // contact (see `Tracked::baseline`), as far as frames are kept.
                let (frames, motion, turn) = if (track.baseline as usize) <= past.len() {
                    (track.baseline, track.baseline_motion, track.baseline_turn)
                } else {
                    (1, track.velocity, track.rotation)
                };
                let (flow_px, has_flow) = match past.len().checked_sub(frames as usize).map(|i| &past[i].image) {
                    Some(prev) if track.age > 0 => {
                        let guess = rigid_guess(px, blob.weighted_centroid, motion, turn);
                        let k = frames as f32;
                        let per_frame = if frames == 1 { guess } else { [guess[0] / k, guess[1] / k] };
                        if interest.wants(px, per_frame, p.search_radius as f32) {
                            // A round contact's turn does not show in its
                            // image: the flow takes it from the tracker.
                            let hidden_turn = if track.round {
                                let moved = rigid_guess(px, blob.weighted_centroid, motion, 0.0);
                                [guess[0] - moved[0], guess[1] - moved[1]]
                            } else {
                                [0.0, 0.0]
                            };
                            let flow = self.matcher.flow_at_turning(prev, image, [e.x, e.y], guess, hidden_turn);
                            let flow = flow.map(|f| if frames == 1 { f } else { [f[0] / k, f[1] / k] });
                            (flow.unwrap_or([0.0, 0.0]), true)
                        } else {
                            ([0.0, 0.0], false)
                        }
                    }
                    _ => ([0.0, 0.0], interest.wants(px, [0.0, 0.0], p.search_radius as f32)),
                };
                EdgeSample {
                    px,
                    flow_px,
                    has_flow,
                    magnitude: e.magnitude,
                    grey: image.pixels[e.y as usize * image.width + e.x as usize],
                    contact_id: track.id,
                }
            })
            .collect();
        timings.flow_us = micros(t);

        let lit = self.lit.clone();
        self.keep(image, &lit, &changed);
        let contacts = blobs
            .into_iter()
            .zip(tracked)
            .map(|(blob, t)| Contact {
                id: t.id,
                blob,
                velocity_px: t.velocity,
                rotation_rad: t.rotation,
                age_frames: t.age,
            })
            .collect();
        timings.total_us = micros(start);
        VisionFrame { contacts, edges, timings }
    }
}

impl Pipeline {
    /// Keeps `image` (lit only in `rows`; `changed` covers those and the
    /// previous frame's) for the flow of the frames to come, in the buffer
    /// of the oldest frame kept once there are enough.
    fn keep(&mut self, image: &ContactImage, rows: &Range<usize>, changed: &Range<usize>) {
        let depth = self.tracker.params().max_baseline_frames.max(1);
        let reuse = if self.past.len() >= depth { self.past.pop_front() } else { None };
        let frame = match reuse {
            Some(mut old) if old.image.width == image.width && old.image.height == image.height => {
                // Outside both its lit rows and these, both frames are black.
                let (w, copy) = (image.width, union(changed, &old.lit, image.height));
                old.image.pixels[copy.start * w..copy.end * w]
                    .copy_from_slice(&image.pixels[copy.start * w..copy.end * w]);
                old.lit = rows.clone();
                old
            }
            _ => PastFrame { image: image.clone(), lit: rows.clone() },
        };
        self.past.push_back(frame);
    }
}

/// The rows in either range, clamped to `height` (empty ranges add nothing).
fn union(a: &Range<usize>, b: &Range<usize>, height: usize) -> Range<usize> {
    let clamp = |r: &Range<usize>| r.start.min(height)..r.end.min(height);
    match (clamp(a), clamp(b)) {
        (a, b) if a.is_empty() => b,
        (a, b) if b.is_empty() => a,
        (a, b) => a.start.min(b.start)..a.end.max(b.end),
    }
}

/// The flow at `px` if its contact moved rigidly: translated by `velocity`
/// and turned by `rotation` about its centroid `c`. The point was at
/// `c - velocity + R(-rotation) (px - c)` in the previous frame.
pub fn rigid_guess(px: [f32; 2], c: [f32; 2], velocity: [f32; 2], rotation: f32) -> [f32; 2] {
    let (sin, cos) = (-rotation).sin_cos();
    let r = [px[0] - c[0], px[1] - c[1]];
    let back = [cos * r[0] - sin * r[1], sin * r[0] + cos * r[1]];
    let was = [c[0] - velocity[0] + back[0], c[1] - velocity[1] + back[1]];
    [px[0] - was[0], px[1] - was[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rigid_guess_of_a_pure_turn() {
        // A quarter turn clockwise on screen about the origin moves (10, 0)
        // to (0, 10): the point now at (0, 10) came from (10, 0).
        let g = rigid_guess([0.0, 10.0], [0.0, 0.0], [0.0, 0.0], std::f32::consts::FRAC_PI_2);
        assert!((g[0] + 10.0).abs() < 1e-4 && (g[1] - 10.0).abs() < 1e-4, "{g:?}");
        assert_eq!(rigid_guess([5.0, 5.0], [1.0, 1.0], [2.0, -1.0], 0.0), [2.0, -1.0]);
    }

    #[test]
    fn degenerate_frames() {
        let mut p = Pipeline::default();
        for (w, h) in [(0, 0), (1, 1), (3, 1), (1, 3), (4, 2), (2, 5)] {
            let f = p.process(&ContactImage::new(w, h));
            assert!(f.contacts.is_empty());
            let white = ContactImage::from_pixels(w, h, vec![255; w * h]).expect("sized");
            let f = p.process(&white);
            // Below `min_area` (6) a white frame is noise.
            assert_eq!(f.contacts.len(), usize::from(w * h >= 6));
        }
    }
}
