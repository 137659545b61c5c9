//! Contact tracking by overlap: persistent ids for the Joint and Proxy
//! techniques, which attach something to "the same finger" frame after
//! frame.
//!
//! # Rules
//!
//! Each contact of the previous frame is first moved by its velocity (its
//! predicted place), then compared with the blobs of the new frame by pixel
//! overlap (runs against runs, no label image).
//!
//! 1. **Continue.** A previous contact hands its id to the new blob it
//!    overlaps most. A blob claimed by exactly one previous contact takes
//!    its id.
//! 2. **Merge.** A blob claimed by several previous contacts takes the id of
//!    the *oldest* (earliest first seen; lower id on a tie). The others are
//!    remembered inside it, with where they were relative to its centroid.
//! 3. **Split.** When a previous contact overlaps several new blobs, the
//!    blobs and the identities it carried (its own and any merged into it)
//!    are paired by position, nearest first, within `max_jump_px`. So two
//!    fingers that touched and parted get their own ids back, each on its
//!    own side. The carried contact's own id always goes to one part (the
//!    one overlapping it most, if position did not place it); parts left
//!    over get new ids; identities left over stay merged in the part
//!    nearest to them.
//! 4. **Jump.** A blob overlapping nothing takes the id of the nearest
//!    previous contact that overlaps nothing either, if its predicted
//!    centroid is within `max_jump_px` (a fast flick can outrun overlap).
//! 5. **New / lost.** Any other blob gets a new id (ids are never reused);
//!    a previous contact matched by nothing is gone.
//!
//! Velocity is the weighted-centroid displacement since the previous frame,
//! except in a frame where the contact merged or split: then the centroid
//! jumps without anything moving, and the previous velocity carries over.
//!
//! A slow contact also gets a longer baseline for its flow: the frames over
//! which its outline moved at most a couple of pixels (see [`Tracked::baseline`]).

use std::collections::{HashSet, VecDeque};

use super::components::{BBox, Blob, Run};
use super::contact_id::ContactId;
use super::grid::BoxGrid;

/// [`BlobTracker`] settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlobTrackerParams {
    /// Furthest a contact may be from its predicted place and keep its id
    /// without overlap, or reclaim an id after a split; pixels.
    pub max_jump_px: f32,
    /// Blobs with major / minor axis below this are too round for their
    /// axis angle to mean anything: no rotation is reported for them.
    pub min_elongation: f32,
    /// Blobs at least this elongated have an axis steady enough to measure
    /// its turn from one frame to the next.
    pub steady_elongation: f32,
    /// Frames over which the axis of a blob at `min_elongation` is smoothed
    /// (the inverse of the share each frame's angle gets, see
    /// `SmoothedAxis`); fewer for longer blobs, down to one (no
    /// smoothing) at `steady_elongation`.
    pub max_turn_frames: usize,
    /// Most frames a slow contact's flow is measured over (see
    /// [`Tracked::baseline`]); 1 measures every flow from the previous
    /// frame alone.
    pub max_baseline_frames: usize,
    /// How far (px) any point of a contact may have moved over its flow's
    /// baseline: its centroid's travel plus its turn times its semi-major
    /// axis.
    pub baseline_px: f32,
}

impl Default for BlobTrackerParams {
    /// A fingertip's patch is 1.2 times as long as it is wide (`surface::hand`);
    /// on the default sensor it measures a little either side of that, and
    /// its axis angle jitters from frame to frame by several times the
    /// 0.017 rad a frame of two fingers twisting a quarter turn in 1.5 s.
    /// Reported only above 1.2, a twisting fingertip's turn would never be
    /// seen (`two_finger_twist`). From 1.08, smoothed over 12 frames
    /// (0.2 s), fewer for longer blobs, the twist turns further: frame by
    /// frame the jitter holds it back, and longer windows lag more
    /// (`surfacelab behaviours`). A flat hand (1.56), a forearm (3.67) or a
    /// hand's edge (6.29) is past 1.3, so its turn is measured frame by
    /// frame.
    ///
    /// Block matching errs by about 0.1 px at each outline point whatever
    /// the speed, against a small fraction of that for the tracked
    /// centroid, so a fingertip moving 0.1 px a frame would have particles
    /// jittering as fast as it moves. Over a baseline of
    /// k frames the same error is spread over k frames of motion. Up to 16
    /// frames (0.27 s at 60 Hz) while no point of the contact moved more
    /// than 2 px: the error is then at most a twentieth of the motion
    /// measured, and a contact that stops carries at most 2 px of its last
    /// motion into the flow. With `surfacelab behaviours` (twist, slow
    /// twist, pin and spin on the small box; default stride), baselines of
    /// up to 16 frames and 2 px turn the box markedly further than frame by
    /// frame; a 1 px threshold lets pin and spin on the one box slide its
    /// pinned point past the 2 cm limit. Other two-finger twists on the
    /// small box (fingers closer together, 0.8-3 s, both ways) turn it
    /// further with it too.
    fn default() -> Self {
        Self {
            max_jump_px: 40.0,
            min_elongation: 1.08,
            steady_elongation: 1.3,
            max_turn_frames: 12,
            max_baseline_frames: 16,
            baseline_px: 2.0,
        }
    }
}

impl BlobTrackerParams {
    /// Frames over which to smooth the axis of a blob this elongated: from
    /// `max_turn_frames` at `min_elongation` down to one at
    /// `steady_elongation`, in proportion.
    fn turn_frames(&self, elongation: f32) -> usize {
        let span = (self.steady_elongation - self.min_elongation).max(f32::EPSILON);
        let roundness = ((self.steady_elongation - elongation) / span).clamp(0.0, 1.0);
        1 + (roundness * (self.max_turn_frames.max(1) - 1) as f32).round() as usize
    }
}

/// A contact's principal-axis angle, smoothed over its last frames: each
/// frame moves it by a share of the way to the angle measured (the axis
/// turn between them). The turn reported is how far it moved, so the turns
/// of a contact add up to how far its smoothed axis turned, whatever the
/// share from frame to frame: they never drift from the axis itself (a
/// pinch's fingertips, not turning, would add up a turn of their own if
/// each frame's turn were a mean over a window whose length followed the
/// blob's jittering elongation).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct SmoothedAxis(Option<f32>);

impl SmoothedAxis {
    /// Takes this frame's axis angle (defined modulo pi) with weight
    /// `share` in `(0, 1]`; returns the turn (0 on the first angle).
    fn update(&mut self, angle: f32, share: f32) -> f32 {
        match self.0 {
            None => {
                self.0 = Some(angle);
                0.0
            }
            Some(was) => {
                let turn = share * axis_turn(was, angle);
                self.0 = Some(was + turn);
                turn
            }
        }
    }
}

/// A contact's last centroids and turns, newest last, for as long as it
/// continued as one contact: the motion over its flow's baseline.
#[derive(Debug, Clone, Default, PartialEq)]
struct Path {
    /// Weighted centroid (px) and the turn reported that frame (rad).
    steps: VecDeque<([f32; 2], f32)>,
}

impl Path {
    /// Adds this frame's centroid and turn, keeping `keep` steps.
    fn push(&mut self, centroid: [f32; 2], turn: f32, keep: usize) {
        if self.steps.len() >= keep.max(1) {
            self.steps.pop_front();
        }
        self.steps.push_back((centroid, turn));
    }

    /// The longest baseline, up to `max` frames, over which no point within
    /// `radius` (px) of the centroid moved more than `reach` (px) from where
    /// it is now; with the centroid's motion and the turn over it. At least
    /// one frame, whose motion is `velocity` and `rotation` themselves.
    fn baseline(&self, max: usize, radius: f32, reach: f32, velocity: [f32; 2], rotation: f32) -> (u32, [f32; 2], f32) {
        let mut best = (1, velocity, rotation);
        let Some(&(now, _)) = self.steps.back() else { return best };
        let mut turned = 0.0f32;
        for (k, &(was, _)) in self.steps.iter().rev().enumerate().skip(1).take(max) {
            // The turn of frame `k` frames back ends at that step's successor.
            turned += self.steps[self.steps.len() - k].1;
            let moved = [now[0] - was[0], now[1] - was[1]];
            if moved[0].hypot(moved[1]) + turned.abs() * radius > reach {
                break;
            }
            if k >= 2 {
                best = (k as u32, moved, turned);
            }
        }
        best
    }
}

/// What tracking says about one blob of the current frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tracked {
    pub id: ContactId,
    /// Weighted-centroid motion, pixels per frame.
    pub velocity: [f32; 2],
    /// Turn of the principal axis since the previous frame, radians per
    /// frame in image orientation (positive = clockwise on screen), of the
    /// axis smoothed for blobs under [`BlobTrackerParams::steady_elongation`]
    /// (see `SmoothedAxis`); 0 for blobs under
    /// [`BlobTrackerParams::min_elongation`] and in frames where the contact
    /// merged or split.
    pub rotation: f32,
    /// Too round for its turn to show in its image (elongation under
    /// [`BlobTrackerParams::steady_elongation`]): the flow along its outline
    /// gets its turn from `rotation` (see `BlockMatcher::flow_at_turning`).
    pub round: bool,
    /// Frames since the id was first seen (0 = new this frame).
    pub age: u32,
    /// Frames its flow is measured over: the most, up to
    /// [`BlobTrackerParams::max_baseline_frames`], over which none of its
    /// points moved more than [`BlobTrackerParams::baseline_px`]; 1 for a
    /// contact moving a pixel a frame or more, and where it merged or split.
    pub baseline: u32,
    /// Its centroid's motion (px) and turn (rad) over `baseline` frames:
    /// `velocity` and `rotation` when that is one.
    pub baseline_motion: [f32; 2],
    pub baseline_turn: f32,
}

/// An identity carried by a (merged) contact.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Identity {
    id: ContactId,
    birth: u64,
    /// Its last own centroid relative to the carrying contact's centroid.
    offset: [f32; 2],
}

/// A contact of the previous frame.
#[derive(Debug, Clone, PartialEq)]
struct Live {
    id: ContactId,
    birth: u64,
    centroid: [f32; 2],
    velocity: [f32; 2],
    /// Its principal-axis angle, smoothed; unset for a round blob.
    axis: SmoothedAxis,
    path: Path,
    bbox: BBox,
    runs: Vec<Run>,
    /// Identities merged in this contact, its own included; empty when it
    /// is a single contact.
    members: Vec<Identity>,
}

impl Live {
    fn predicted(&self) -> [f32; 2] {
        [self.centroid[0] + self.velocity[0], self.centroid[1] + self.velocity[1]]
    }

    /// The identities it carries, its own first when single.
    fn identities(&self) -> Vec<Identity> {
        if self.members.is_empty() {
            vec![Identity { id: self.id, birth: self.birth, offset: [0.0, 0.0] }]
        } else {
            self.members.clone()
        }
    }
}

/// The result for one new blob while the frame is being resolved.
#[derive(Debug, Clone)]
struct Assignment {
    id: ContactId,
    birth: u64,
    velocity: [f32; 2],
    /// Its smoothed axis so far, when the contact continued without a
    /// topology change (else unset).
    axis: SmoothedAxis,
    /// Its path so far, carried with the axis.
    path: Path,
    members: Vec<Identity>,
}

impl Assignment {
    /// A blob that continues previous contact `p` alone: same id, history
    /// and members; its velocity is how far the centroid moved.
    fn continuing(p: &Live, centroid: [f32; 2]) -> Self {
        Assignment {
            id: p.id,
            birth: p.birth,
            velocity: [centroid[0] - p.centroid[0], centroid[1] - p.centroid[1]],
            axis: p.axis,
            path: p.path.clone(),
            members: p.members.clone(),
        }
    }
}

/// Keeps contact ids from frame to frame.
#[derive(Debug, Clone, Default)]
pub struct BlobTracker {
    params: BlobTrackerParams,
    live: Vec<Live>,
    next_id: u32,
    frame: u64,
}

fn distance(a: [f32; 2], b: [f32; 2]) -> f32 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Pixels shared by `a` moved by `shift` and `b`; both sorted by row, then
/// column.
fn overlap(a: &[Run], shift: [i32; 2], b: &[Run]) -> u32 {
    let (Some(af), Some(al), Some(bf), Some(bl)) = (a.first(), a.last(), b.first(), b.last()) else {
        return 0;
    };
    // Only the rows both cover: a small blob against a huge one (a frame
    // of speckle) then costs the small one's rows, not the huge one's.
    let (a_first, a_last) = (i64::from(af.y) + i64::from(shift[1]), i64::from(al.y) + i64::from(shift[1]));
    let (lo, hi) = (a_first.max(i64::from(bf.y)), a_last.min(i64::from(bl.y)));
    if lo > hi {
        return 0;
    }
    let a = &a[a.partition_point(|r| i64::from(r.y) + i64::from(shift[1]) < lo)..];
    let a = &a[..a.partition_point(|r| i64::from(r.y) + i64::from(shift[1]) <= hi)];
    let b = &b[b.partition_point(|r| i64::from(r.y) < lo)..];
    let b = &b[..b.partition_point(|r| i64::from(r.y) <= hi)];
    let (mut i, mut j, mut total) = (0, 0, 0i64);
    while i < a.len() && j < b.len() {
        let ay = i64::from(a[i].y) + i64::from(shift[1]);
        let by = i64::from(b[j].y);
        match ay.cmp(&by) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                let a0 = i64::from(a[i].x0) + i64::from(shift[0]);
                let a1 = i64::from(a[i].x1) + i64::from(shift[0]);
                let (b0, b1) = (i64::from(b[j].x0), i64::from(b[j].x1));
                total += (a1.min(b1) - a0.max(b0)).max(0);
                if a1 < b1 {
                    i += 1;
                } else {
                    j += 1;
                }
            }
        }
    }
    total as u32
}

fn boxes_meet(a: BBox, shift: [i32; 2], b: BBox) -> bool {
    let (ax0, ax1) = (i64::from(a.x0) + i64::from(shift[0]), i64::from(a.x1) + i64::from(shift[0]));
    let (ay0, ay1) = (i64::from(a.y0) + i64::from(shift[1]), i64::from(a.y1) + i64::from(shift[1]));
    ax0 <= i64::from(b.x1) && i64::from(b.x0) <= ax1 && ay0 <= i64::from(b.y1) && i64::from(b.y0) <= ay1
}

/// Difference of two axis angles (defined modulo pi), in `(-pi/2, pi/2]`.
fn axis_turn(from: f32, to: f32) -> f32 {
    use std::f32::consts::{FRAC_PI_2, PI};
    let mut d = (to - from).rem_euclid(PI);
    if d > FRAC_PI_2 {
        d -= PI;
    }
    d
}

impl BlobTracker {
    pub fn new(params: BlobTrackerParams) -> Self {
        Self { params, live: Vec::new(), next_id: 1, frame: 0 }
    }

    pub fn params(&self) -> BlobTrackerParams {
        self.params
    }

    /// Forgets every contact (ids keep counting up).
    pub fn reset(&mut self) {
        self.live.clear();
    }

    fn new_id(&mut self) -> ContactId {
        let id = self.next_id.max(1);
        self.next_id = id.wrapping_add(1);
        ContactId::new(id)
    }

    /// Assigns ids to this frame's blobs, in their order.
    pub fn update(&mut self, blobs: &[Blob]) -> Vec<Tracked> {
        self.frame += 1;
        let prev = std::mem::take(&mut self.live);
        let m = Matching::new(&prev, blobs);
        let mut out: Vec<Option<Assignment>> = vec![None; blobs.len()];
        continue_and_merge(&prev, blobs, &m, &mut out);
        self.split(&prev, blobs, &m, &mut out);
        jump(&prev, blobs, &m, self.params.max_jump_px, &mut out);
        self.remember(blobs, out)
    }

    /// Rule 3: splits. Each part of a contact that split takes the identity
    /// (of the contact or of one merged into it) predicted nearest to it;
    /// the contact's own id survives in some part; identities no part took
    /// stay merged in the nearest part.
    fn split(&mut self, prev: &[Live], blobs: &[Blob], m: &Matching, out: &mut [Option<Assignment>]) {
        let (frame, gate) = (self.frame, self.params.max_jump_px);
        let centroid = |j: usize| blobs[j].weighted_centroid;
        // Ids in use, built only if a merge and a split meet in one frame.
        let mut taken: Option<HashSet<ContactId>> = None;
        for (i, p) in prev.iter().enumerate() {
            if m.split_parts[i].is_empty() {
                continue;
            }
            let main = m.best[i].filter(|&b| m.owners[b].len() == 1);
            let parts: Vec<usize> = main.into_iter().chain(m.split_parts[i].iter().copied()).collect();
            let mut identities = p.identities();
            if main.is_none() {
                // The main part merged with others this same frame and keeps
                // that result; the other parts draw from what is left.
                let taken = taken.get_or_insert_with(|| {
                    out.iter().flatten().flat_map(|a| a.members.iter().map(|m| m.id).chain([a.id])).collect()
                });
                identities.retain(|m| !taken.contains(&m.id));
            }
            let at = p.predicted();
            let place = |m: &Identity| [at[0] + m.offset[0], at[1] + m.offset[1]];
            let mut pairs: Vec<(f32, usize, usize)> = Vec::new();
            for (k, &j) in parts.iter().enumerate() {
                for (n, m) in identities.iter().enumerate() {
                    let d = distance(centroid(j), place(m));
                    if d <= gate {
                        pairs.push((d, k, n));
                    }
                }
            }
            pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
            let mut part_identity: Vec<Option<usize>> = vec![None; parts.len()];
            let mut identity_part: Vec<Option<usize>> = vec![None; identities.len()];
            for (_, k, n) in pairs {
                if part_identity[k].is_none() && identity_part[n].is_none() {
                    part_identity[k] = Some(n);
                    identity_part[n] = Some(k);
                }
            }
            // The carried contact's own id must survive in some part.
            if main.is_some()
                && let Some(own) = identities.iter().position(|m| m.id == p.id)
                && identity_part[own].is_none()
            {
                let overlap_of = |j: usize| m.overlaps[i].iter().find(|&&(k, _)| k == j).map_or(0, |&(_, a)| a);
                if let Some(k) =
                    (0..parts.len()).filter(|&k| part_identity[k].is_none()).max_by_key(|&k| overlap_of(parts[k]))
                {
                    part_identity[k] = Some(own);
                    identity_part[own] = Some(k);
                }
            }
            let mut assigned: Vec<Assignment> = part_identity
                .iter()
                .map(|taken| match *taken {
                    Some(n) => Assignment {
                        id: identities[n].id,
                        birth: identities[n].birth,
                        velocity: p.velocity,
                        axis: SmoothedAxis::default(),
                        path: Path::default(),
                        members: Vec::new(),
                    },
                    None => self.fresh(frame),
                })
                .collect();
            // Identities no part took stay merged in the nearest part.
            for (n, m) in identities.iter().enumerate() {
                if identity_part[n].is_some() {
                    continue;
                }
                let spot = place(m);
                if let Some(k) = (0..parts.len())
                    .min_by(|&a, &b| distance(centroid(parts[a]), spot).total_cmp(&distance(centroid(parts[b]), spot)))
                {
                    let c = centroid(parts[k]);
                    let a = &mut assigned[k];
                    if a.members.is_empty() {
                        a.members.push(Identity { id: a.id, birth: a.birth, offset: [0.0, 0.0] });
                    }
                    a.members.push(Identity { offset: [spot[0] - c[0], spot[1] - c[1]], ..*m });
                }
            }
            for (k, a) in assigned.into_iter().enumerate() {
                if let Some(taken) = &mut taken {
                    taken.insert(a.id);
                }
                out[parts[k]] = Some(a);
            }
        }
    }

    /// A new contact's assignment, born this frame.
    fn fresh(&mut self, frame: u64) -> Assignment {
        Assignment {
            id: self.new_id(),
            birth: frame,
            velocity: [0.0, 0.0],
            axis: SmoothedAxis::default(),
            path: Path::default(),
            members: Vec::new(),
        }
    }

    /// Rule 5: blobs still unassigned are new contacts; then remember this
    /// frame's contacts for the next.
    fn remember(&mut self, blobs: &[Blob], mut out: Vec<Option<Assignment>>) -> Vec<Tracked> {
        let frame = self.frame;
        let mut result = Vec::with_capacity(blobs.len());
        for (j, blob) in blobs.iter().enumerate() {
            let a = match out[j].take() {
                Some(a) => a,
                None => self.fresh(frame),
            };
            let elongation = blob.ellipse.elongation();
            let mut axis = a.axis;
            let rotation = if elongation >= self.params.min_elongation {
                axis.update(blob.ellipse.angle, 1.0 / self.params.turn_frames(elongation) as f32)
            } else {
                axis = SmoothedAxis::default();
                0.0
            };
            let members = if a.members.len() > 1 { a.members } else { Vec::new() };
            let round = elongation < self.params.steady_elongation;
            let mut path = a.path;
            path.push(blob.weighted_centroid, rotation, self.params.max_baseline_frames + 1);
            let (baseline, baseline_motion, baseline_turn) = path.baseline(
                self.params.max_baseline_frames,
                blob.ellipse.semi_axes[0],
                self.params.baseline_px,
                a.velocity,
                rotation,
            );
            result.push(Tracked {
                id: a.id,
                velocity: a.velocity,
                rotation,
                round,
                age: (frame - a.birth) as u32,
                baseline,
                baseline_motion,
                baseline_turn,
            });
            self.live.push(Live {
                id: a.id,
                birth: a.birth,
                centroid: blob.weighted_centroid,
                velocity: a.velocity,
                axis,
                path,
                bbox: blob.bbox,
                runs: blob.runs.clone(),
                members,
            });
        }
        result
    }
}

/// How last frame's contacts, each moved by its velocity, overlap this
/// frame's blobs.
struct Matching {
    /// Per previous contact: the blobs it overlaps, with the overlap (px).
    overlaps: Vec<Vec<(usize, u32)>>,
    /// Per previous contact: the blob it overlaps most.
    best: Vec<Option<usize>>,
    /// Per blob: the previous contacts whose best it is.
    owners: Vec<Vec<usize>>,
    /// Per previous contact: blobs nobody claimed that it overlaps most,
    /// the parts a split produced.
    split_parts: Vec<Vec<usize>>,
}

impl Matching {
    fn new(prev: &[Live], blobs: &[Blob]) -> Matching {
        // The grid keeps this linear in the number of blobs.
        let grid = BoxGrid::new(&blobs.iter().map(|b| as_box(b.bbox, [0, 0])).collect::<Vec<_>>());
        let mut near = Vec::new();
        let mut overlaps: Vec<Vec<(usize, u32)>> = Vec::with_capacity(prev.len());
        let mut overlapped_by: Vec<Vec<(usize, u32)>> = vec![Vec::new(); blobs.len()];
        for (i, p) in prev.iter().enumerate() {
            let shift = [p.velocity[0].round() as i32, p.velocity[1].round() as i32];
            grid.query(as_box(p.bbox, [i64::from(shift[0]), i64::from(shift[1])]), &mut near);
            let found: Vec<(usize, u32)> = near
                .iter()
                .map(|&j| j as usize)
                .filter(|&j| boxes_meet(p.bbox, shift, blobs[j].bbox))
                .map(|j| (j, overlap(&p.runs, shift, &blobs[j].runs)))
                .filter(|&(_, a)| a > 0)
                .collect();
            for &(j, a) in &found {
                overlapped_by[j].push((i, a));
            }
            overlaps.push(found);
        }
        let best: Vec<Option<usize>> = overlaps
            .iter()
            .map(|o| o.iter().max_by_key(|&&(j, a)| (a, std::cmp::Reverse(j))).map(|&(j, _)| j))
            .collect();
        let mut owners: Vec<Vec<usize>> = vec![Vec::new(); blobs.len()];
        for (i, b) in best.iter().enumerate() {
            if let Some(j) = *b {
                owners[j].push(i);
            }
        }
        let mut split_parts: Vec<Vec<usize>> = vec![Vec::new(); prev.len()];
        for j in (0..blobs.len()).filter(|&j| owners[j].is_empty()) {
            let parent = overlapped_by[j].iter().max_by_key(|&&(i, a)| (a, std::cmp::Reverse(i)));
            if let Some(&(i, _)) = parent {
                split_parts[i].push(j);
            }
        }
        Matching { overlaps, best, owners, split_parts }
    }
}

/// A bounding box as grid coordinates, moved by `shift` pixels.
fn as_box(b: BBox, shift: [i64; 2]) -> [i64; 4] {
    [i64::from(b.x0) + shift[0], i64::from(b.y0) + shift[1], i64::from(b.x1) + shift[0], i64::from(b.y1) + shift[1]]
}

/// Rules 1 and 2: a blob that one previous contact overlaps most continues
/// it; one that several do merges them, keeping the oldest id and the
/// others as members at their predicted offsets.
fn continue_and_merge(prev: &[Live], blobs: &[Blob], m: &Matching, out: &mut [Option<Assignment>]) {
    let centroid = |j: usize| blobs[j].weighted_centroid;
    for (j, (slot, owners)) in out.iter_mut().zip(&m.owners).enumerate() {
        let Some(keeper) = owners.iter().copied().min_by_key(|&i| (prev[i].birth, prev[i].id)) else {
            continue;
        };
        let p = &prev[keeper];
        *slot = Some(if owners.len() == 1 {
            Assignment::continuing(p, centroid(j))
        } else {
            let c = centroid(j);
            let members = owners
                .iter()
                .flat_map(|&i| {
                    let o = &prev[i];
                    let at = o.predicted();
                    o.identities().into_iter().map(move |m| Identity {
                        offset: [at[0] + m.offset[0] - c[0], at[1] + m.offset[1] - c[1]],
                        ..m
                    })
                })
                .collect();
            Assignment {
                id: p.id,
                birth: p.birth,
                velocity: p.velocity,
                axis: SmoothedAxis::default(),
                path: Path::default(),
                members,
            }
        });
    }
}

/// Rule 4: jumps. A blob still unassigned takes the id of a previous
/// contact that overlaps nothing now and is predicted within `gate` pixels,
/// nearest pairs first.
fn jump(prev: &[Live], blobs: &[Blob], m: &Matching, gate: f32, out: &mut [Option<Assignment>]) {
    let centroid = |j: usize| blobs[j].weighted_centroid;
    let orphans: Vec<usize> = (0..blobs.len()).filter(|&j| out[j].is_none()).collect();
    let lost: Vec<usize> = (0..prev.len()).filter(|&i| m.overlaps[i].is_empty()).collect();
    let spot = |c: [f32; 2], r: f32| {
        [(c[0] - r).floor() as i64, (c[1] - r).floor() as i64, (c[0] + r).ceil() as i64, (c[1] + r).ceil() as i64]
    };
    let lost_grid = BoxGrid::new(&lost.iter().map(|&i| spot(prev[i].predicted(), 0.0)).collect::<Vec<_>>());
    let mut near = Vec::new();
    let mut pairs: Vec<(f32, usize, usize)> = Vec::new();
    for &j in &orphans {
        lost_grid.query(spot(centroid(j), gate), &mut near);
        for &n in &near {
            let i = lost[n as usize];
            let d = distance(centroid(j), prev[i].predicted());
            if d <= gate {
                pairs.push((d, j, i));
            }
        }
    }
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
    let mut used = vec![false; prev.len()];
    for (_, j, i) in pairs {
        if out[j].is_none() && !used[i] {
            used[i] = true;
            let p = &prev[i];
            out[j] = Some(Assignment::continuing(p, centroid(j)));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::surface::ContactImage;
    use crate::pipeline::vision::{find_blobs, threshold};

    /// Blobs of filled squares of side `s` centred at the given points.
    fn squares(centres: &[[i32; 2]], s: i32) -> Vec<Blob> {
        let mut img = ContactImage::new(100, 60);
        for c in centres {
            for y in c[1] - s / 2..c[1] - s / 2 + s {
                for x in c[0] - s / 2..c[0] - s / 2 + s {
                    img.pixels[(y * 100 + x) as usize] = 200;
                }
            }
        }
        find_blobs(&img, &threshold(&img, 1), 1)
    }

    #[test]
    fn moving_contact_keeps_its_id_and_speed() {
        let mut t = BlobTracker::new(BlobTrackerParams::default());
        let a = t.update(&squares(&[[20, 30]], 8));
        let b = t.update(&squares(&[[23, 30]], 8));
        assert_eq!(a[0].id, b[0].id);
        assert_eq!(b[0].velocity, [3.0, 0.0]);
        assert_eq!(b[0].age, 1);
        // Faster than its own size: prediction keeps the overlap.
        let c = t.update(&squares(&[[26, 30]], 8));
        let d = t.update(&squares(&[[40, 30]], 8));
        assert_eq!(c[0].id, d[0].id);
        // Lifted, then a new touch: a new id.
        assert!(t.update(&[]).is_empty());
        let e = t.update(&squares(&[[40, 30]], 8));
        assert_ne!(e[0].id, d[0].id);
        assert_eq!(e[0].age, 0);
    }

    #[test]
    fn merge_keeps_the_older_id_and_split_restores_both() {
        let mut t = BlobTracker::new(BlobTrackerParams::default());
        let old = t.update(&squares(&[[30, 30]], 8))[0].id;
        let ab = t.update(&squares(&[[30, 30], [50, 30]], 8));
        let young = ab[1].id;
        assert_ne!(old, young);
        t.update(&squares(&[[34, 30], [46, 30]], 8));
        let merged = t.update(&squares(&[[37, 30], [43, 30]], 8));
        assert_eq!(merged.len(), 1);
        assert_eq!(merged[0].id, old);
        t.update(&squares(&[[37, 30], [43, 30]], 8));
        let apart = t.update(&squares(&[[33, 30], [47, 30]], 8));
        assert_eq!(apart.len(), 2);
        assert_eq!(apart[0].id, old);
        assert_eq!(apart[1].id, young);
    }

    #[test]
    fn split_restores_ids_on_the_right_side_whatever_the_sizes() {
        let mut t = BlobTracker::new(BlobTrackerParams::default());
        let both = t.update(&squares(&[[30, 30], [50, 30]], 8));
        let (left, right) = (both[0].id, both[1].id);
        t.update(&squares(&[[37, 30], [43, 30]], 8));
        // The right-hand part is the bigger one; ids must still follow sides.
        let mut img = ContactImage::new(100, 60);
        for y in 26..34 {
            for x in 29..35 {
                img.pixels[y * 100 + x] = 200;
            }
            for x in 42..56 {
                img.pixels[y * 100 + x] = 200;
            }
        }
        let apart = t.update(&find_blobs(&img, &threshold(&img, 1), 1));
        assert_eq!((apart[0].id, apart[1].id), (left, right));
    }

    #[test]
    fn splitting_a_single_contact_gives_a_new_id_to_the_smaller_part() {
        let mut t = BlobTracker::new(BlobTrackerParams::default());
        let one = t.update(&squares(&[[30, 30]], 20))[0].id;
        let parts = t.update(&squares(&[[26, 30], [36, 30]], 6));
        assert_eq!(parts.len(), 2);
        assert!(parts.iter().any(|p| p.id == one));
        assert!(parts.iter().any(|p| p.id != one && p.age == 0));
    }

    #[test]
    fn a_smoothed_axis_turns_through_the_half_turn() {
        use std::f32::consts::{FRAC_PI_2, PI};
        let mut axis = SmoothedAxis::default();
        // An axis turning 0.1 rad a frame through pi/2, where the angle the
        // moments give jumps from just under pi/2 to just over -pi/2.
        let angle = |k: usize| (FRAC_PI_2 - 0.25 + 0.1 * k as f32 + FRAC_PI_2).rem_euclid(PI) - FRAC_PI_2;
        assert_eq!(axis.update(angle(0), 1.0), 0.0);
        for k in 1..6 {
            let turn = axis.update(angle(k), 1.0);
            assert!((turn - 0.1).abs() < 1e-5, "frame {k}: {turn}");
        }
    }

    #[test]
    fn rounder_blobs_smooth_their_axis_over_more_frames() {
        let p = BlobTrackerParams::default();
        assert_eq!(p.turn_frames(p.min_elongation), p.max_turn_frames);
        assert_eq!(p.turn_frames(p.steady_elongation), 1);
        assert_eq!(p.turn_frames(3.0), 1);
        let mid = p.turn_frames(0.5 * (p.min_elongation + p.steady_elongation));
        assert!(mid > 1 && mid < p.max_turn_frames, "{mid}");
    }

    #[test]
    fn smoothing_removes_the_jitter_of_a_round_blob_and_never_drifts() {
        // The axis of a fingertip-like blob: turning 0.017 rad a frame with
        // 0.08 rad of alternating jitter, as measured on the default sensor.
        let rate = 0.017;
        let jittered = |k: usize| rate * k as f32 + if k.is_multiple_of(2) { 0.08 } else { -0.08 };
        let (mut raw, mut smooth) = (SmoothedAxis::default(), SmoothedAxis::default());
        let (mut raw_err, mut smooth_err) = (0.0f32, 0.0f32);
        let mut total = 0.0;
        for k in 0..120 {
            let (r, s) = (raw.update(jittered(k), 1.0), smooth.update(jittered(k), 1.0 / 12.0));
            total += s;
            if k >= 60 {
                raw_err = raw_err.max((r - rate).abs());
                smooth_err = smooth_err.max((s - rate).abs());
            }
        }
        // Frame by frame the jitter (0.16 rad) swamps the turn; smoothed
        // over 12 frames the turn is within 0.015 rad a frame of the truth.
        assert!(raw_err > 0.1, "{raw_err}");
        assert!(smooth_err < 0.015, "{smooth_err}");
        // The turns add up to the axis's own turn (less its lag): they do
        // not drift, whatever the share from frame to frame.
        let mut varying = SmoothedAxis::default();
        let mut sum = 0.0;
        for k in 0..200usize {
            sum += varying.update(if k.is_multiple_of(2) { 0.08 } else { -0.08 }, 1.0 / (1 + k % 12) as f32);
        }
        assert!(sum.abs() <= 0.16, "a still axis turned {sum} rad in all");
        let axis_turned = rate * 119.0;
        assert!((total - axis_turned).abs() < rate * 12.0 + 0.16, "{total} against {axis_turned}");
    }

    /// A path along x at `speed` px a frame, turning `turn` rad a frame.
    fn path(frames: usize, speed: f32, turn: f32) -> Path {
        let mut p = Path::default();
        for k in 0..frames {
            p.push([10.0 + speed * k as f32, 20.0], if k == 0 { 0.0 } else { turn }, 17);
        }
        p
    }

    #[test]
    fn a_slow_contact_gets_the_longest_baseline_within_two_pixels() {
        let (reach, max) = (2.0, 16);
        // 0.1 px a frame: all 16 frames kept (1.6 px in all).
        let (k, moved, turned) = path(30, 0.1, 0.0).baseline(max, 5.0, reach, [0.1, 0.0], 0.0);
        assert_eq!(k, 16);
        assert!((moved[0] - 1.6).abs() < 1e-4 && moved[1] == 0.0 && turned == 0.0, "{moved:?} {turned}");
        // 0.75 px a frame: two frames (1.5 px); three would be 2.25.
        let (k, moved, _) = path(30, 0.75, 0.0).baseline(max, 5.0, reach, [0.75, 0.0], 0.0);
        assert_eq!((k, moved[0]), (2, 1.5));
        // 3 px a frame: the frame's own velocity and turn, as given.
        assert_eq!(path(30, 3.0, 0.01).baseline(max, 5.0, reach, [3.0, 0.0], 0.01), (1, [3.0, 0.0], 0.01));
        // Still, but turning 0.05 rad a frame with points 10 px out: 0.5 px
        // a frame at its rim, so four frames, and the turn over them.
        let (k, _, turned) = path(30, 0.0, 0.05).baseline(max, 10.0, reach, [0.0, 0.0], 0.05);
        assert_eq!(k, 4);
        assert!((turned - 0.2).abs() < 1e-5, "{turned}");
        // A contact seen for three frames: at most two frames back.
        assert_eq!(path(3, 0.1, 0.0).baseline(max, 5.0, reach, [0.1, 0.0], 0.0).0, 2);
    }

    #[test]
    fn axis_turn_wraps() {
        use std::f32::consts::PI;
        assert!((axis_turn(1.5, -1.5) - (PI - 3.0)).abs() < 1e-6);
        assert!((axis_turn(0.1, 0.3) - 0.2).abs() < 1e-6);
    }
}
