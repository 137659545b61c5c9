//! A uniform grid over the table plane of the rigid scene objects' AABBs,
//! so a contact's ray tests the few objects near it and not every object on
//! the table.
//!
//! rapier's own broad phase also holds the technique's particles, which sit
//! exactly where contact rays go, so scene queries keep their own list of
//! scene colliders (see `World::cast_ray`). Scanning that list is linear in
//! the objects: at 10,000 boxes the AABB tests of the contact rays were the
//! frame's largest cost (`surfacelab bench --point objects=10000` under
//! `perf`). The grid returns a superset of the colliders a ray can touch, in
//! the list's own order, so a cast answers exactly what the scan did.

use glam::Vec2;
use rapier3d::parry::bounding_volume::Aabb;
use rapier3d::parry::query::Ray;

/// Below this many objects a scan is as fast as the grid.
const MIN_OBJECTS: usize = 64;
/// Slack (m) added round every query box: a candidate too many is free, one
/// too few would change an answer.
const SLACK: f32 = 1e-3;

/// Grid cells over the objects' xy extent, each listing the objects (as
/// indices into the scene collider list) whose AABB overlaps it.
#[derive(Debug, Clone, Default)]
pub(super) struct SceneIndex {
    /// Indices of the colliders every query tests: the table and its walls.
    always: Vec<u32>,
    grid: Option<Grid>,
}

#[derive(Debug, Clone)]
struct Grid {
    lo: Vec2,
    cell: f32,
    cols: usize,
    rows: usize,
    /// `starts[k]..starts[k + 1]` of `members` are cell `k`'s objects.
    starts: Vec<u32>,
    members: Vec<u32>,
    /// The objects' lowest and highest z.
    z: (f32, f32),
}

impl SceneIndex {
    /// Indexes `colliders`: `(is an object, world AABB)` in list order.
    pub fn new(colliders: impl Iterator<Item = (bool, Aabb)> + Clone) -> SceneIndex {
        let objects = colliders.clone().filter(|(is_object, _)| *is_object).count();
        if objects < MIN_OBJECTS {
            return SceneIndex::default();
        }
        let mut always = Vec::new();
        let mut boxes = Vec::with_capacity(objects);
        for (i, (is_object, aabb)) in colliders.enumerate() {
            if is_object { boxes.push((i as u32, aabb)) } else { always.push(i as u32) }
        }
        SceneIndex { always, grid: Some(Grid::new(&boxes)) }
    }

    /// The colliders (list indices, ascending) whose AABB may meet `ray`
    /// within `max_toi`; `None`: every collider (no grid).
    pub fn along_ray(&self, ray: &Ray, max_toi: f32) -> Option<Vec<u32>> {
        let grid = self.grid.as_ref()?;
        let mut out = self.always.clone();
        if let Some((lo, hi)) = grid.ray_extent(ray, max_toi) {
            grid.collect(lo, hi, &mut out);
        }
        Some(ascending(out))
    }
}

/// The entries of a collider list a query tests, in list order: all of
/// them, or the ones the grid picked.
pub(super) struct SceneColliders<'a, T> {
    list: &'a [T],
    picked: Option<std::vec::IntoIter<u32>>,
    next: usize,
}

impl<'a, T> SceneColliders<'a, T> {
    pub fn new(list: &'a [T], picked: Option<Vec<u32>>) -> Self {
        SceneColliders { list, picked: picked.map(Vec::into_iter), next: 0 }
    }
}

impl<'a, T> Iterator for SceneColliders<'a, T> {
    type Item = &'a T;

    fn next(&mut self) -> Option<&'a T> {
        if let Some(picked) = &mut self.picked {
            return picked.next().map(|i| &self.list[i as usize]);
        }
        self.next += 1;
        self.list.get(self.next - 1)
    }
}

/// Sorted and without repeats: list order, each collider once.
fn ascending(mut v: Vec<u32>) -> Vec<u32> {
    v.sort_unstable();
    v.dedup();
    v
}

impl Grid {
    /// About one object per cell, no cell smaller than the largest object's
    /// footprint would make a typical object span more than four.
    fn new(boxes: &[(u32, Aabb)]) -> Grid {
        let (mut lo, mut hi) = (Vec2::splat(f32::MAX), Vec2::splat(f32::MIN));
        let (mut z_lo, mut z_hi) = (f32::MAX, f32::MIN);
        let mut widest = 0.0f32;
        for (_, b) in boxes {
            lo = lo.min(Vec2::new(b.mins.x, b.mins.y));
            hi = hi.max(Vec2::new(b.maxs.x, b.maxs.y));
            z_lo = z_lo.min(b.mins.z);
            z_hi = z_hi.max(b.maxs.z);
            widest = widest.max((b.maxs.x - b.mins.x).max(b.maxs.y - b.mins.y));
        }
        let extent = (hi - lo).max(Vec2::splat(1e-3));
        let cell = (extent.x * extent.y / boxes.len() as f32).sqrt().max(widest).max(1e-3);
        let cols = ((extent.x / cell).ceil() as usize).max(1);
        let rows = ((extent.y / cell).ceil() as usize).max(1);
        let mut grid = Grid { lo, cell, cols, rows, starts: Vec::new(), members: Vec::new(), z: (z_lo, z_hi) };
        // Counting sort of (cell, object) pairs into one flat array.
        let mut counts = vec![0u32; cols * rows + 1];
        for (_, b) in boxes {
            for k in grid.cells_of(b) {
                counts[k + 1] += 1;
            }
        }
        for k in 1..counts.len() {
            counts[k] += counts[k - 1];
        }
        let mut fill = counts.clone();
        let mut members = vec![0; counts[cols * rows] as usize];
        for (i, b) in boxes {
            for k in grid.cells_of(b) {
                members[fill[k] as usize] = *i;
                fill[k] += 1;
            }
        }
        grid.members = members;
        grid.starts = counts;
        grid
    }

    /// The cells an AABB's footprint overlaps.
    fn cells_of(&self, b: &Aabb) -> impl Iterator<Item = usize> {
        let (lo, hi) = (Vec2::new(b.mins.x, b.mins.y), Vec2::new(b.maxs.x, b.maxs.y));
        grid_cells(lo, hi, self.lo, self.cell, self.cols, self.rows)
    }

    /// Appends the objects of every cell the box `lo..hi` (grown by the
    /// slack) overlaps.
    fn collect(&self, lo: Vec2, hi: Vec2, out: &mut Vec<u32>) {
        let slack = Vec2::splat(SLACK);
        for k in grid_cells(lo - slack, hi + slack, self.lo, self.cell, self.cols, self.rows) {
            out.extend_from_slice(&self.members[self.starts[k] as usize..self.starts[k + 1] as usize]);
        }
    }

    /// The xy box of the part of `ray` (within `max_toi`) that lies between
    /// the objects' lowest and highest z; `None` when it misses that slab.
    fn ray_extent(&self, ray: &Ray, max_toi: f32) -> Option<(Vec2, Vec2)> {
        let (o, d) = (ray.origin, ray.dir);
        let (z_lo, z_hi) = (self.z.0 - SLACK, self.z.1 + SLACK);
        let (t0, t1) = if d.z == 0.0 {
            if o.z < z_lo || o.z > z_hi {
                return None;
            }
            (0.0, max_toi)
        } else {
            let (a, b) = ((z_lo - o.z) / d.z, (z_hi - o.z) / d.z);
            (a.min(b).max(0.0), a.max(b).min(max_toi))
        };
        // NaN (a ray with no direction) fails this too.
        if t0.partial_cmp(&t1).is_none_or(|o| o == std::cmp::Ordering::Greater) {
            return None;
        }
        let p = Vec2::new(o.x + d.x * t0, o.y + d.y * t0);
        let q = Vec2::new(o.x + d.x * t1, o.y + d.y * t1);
        Some((p.min(q), p.max(q)))
    }
}

/// Cell indices (row-major) of the cells the box `lo..hi` overlaps, clamped
/// to the grid; nothing for a box wholly off it or not finite.
fn grid_cells(lo: Vec2, hi: Vec2, origin: Vec2, cell: f32, cols: usize, rows: usize) -> impl Iterator<Item = usize> {
    let span = |a: f32, b: f32, o: f32, n: usize| {
        let (a, b) = ((a - o) / cell, (b - o) / cell);
        if !(a.is_finite() && b.is_finite()) || b < 0.0 || a >= n as f32 {
            return 0..0;
        }
        (a.floor().max(0.0) as usize)..((b.floor() as usize).min(n - 1) + 1)
    };
    let (cx, cy) = (span(lo.x, hi.x, origin.x, cols), span(lo.y, hi.y, origin.y, rows));
    cy.flat_map(move |r| cx.clone().map(move |c| r * cols + c))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;
    use rapier3d::parry::query::RayCast;

    fn aabb(x: f32, y: f32, half: f32) -> Aabb {
        Aabb::new(Vec3::new(x - half, y - half, 0.0), Vec3::new(x + half, y + half, 2.0 * half))
    }

    /// A 20 × 20 grid of 1 cm boxes at 2.5 cm pitch, after a table slab.
    fn boxes() -> Vec<(bool, Aabb)> {
        let table = Aabb::new(Vec3::new(-1.0, -1.0, -0.03), Vec3::new(1.0, 1.0, 0.0));
        std::iter::once((false, table))
            .chain((0..400).map(|i| (true, aabb((i % 20) as f32 * 0.025, (i / 20) as f32 * 0.025, 0.005))))
            .collect()
    }

    #[test]
    fn every_ray_gets_every_collider_its_scan_would_hit() {
        let list = boxes();
        let index = SceneIndex::new(list.iter().copied());
        assert!(index.grid.is_some());
        let mut fewer = 0;
        // Rays straight down, and from an eye above at slants, over the grid.
        for k in 0..2000 {
            let (u, v) = ((k % 50) as f32 * 0.011 - 0.03, (k / 50) as f32 * 0.0137 - 0.03);
            let origin = if k % 2 == 0 { Vec3::new(u, v, 1.0) } else { Vec3::new(0.2, -0.5, 0.8) };
            let target = Vec3::new(u, v, 0.0);
            let ray = Ray::new(origin, target - origin);
            let out = index.along_ray(&ray, 100.0).expect("a grid");
            let scan: Vec<u32> = (0..list.len() as u32)
                .filter(|&i| list[i as usize].1.cast_local_ray(&ray, 100.0, true).is_some())
                .collect();
            assert!(scan.iter().all(|i| out.contains(i)), "ray {k}: {scan:?} not in {out:?}");
            assert!(out.windows(2).all(|w| w[0] < w[1]), "ascending and unique");
            fewer += usize::from(out.len() < 40);
        }
        assert!(fewer > 1900, "the grid narrows most rays to a few objects: {fewer} of 2000");
    }

    #[test]
    fn few_objects_are_scanned() {
        let list: Vec<(bool, Aabb)> = boxes().into_iter().take(10).collect();
        let index = SceneIndex::new(list.iter().copied());
        let down = Ray::new(Vec3::new(5.0, 5.0, 1.0), Vec3::new(0.0, 0.0, -1.0));
        assert_eq!(index.along_ray(&down, 1.0), None, "no grid: the caller scans");
        let all = SceneIndex::new(boxes().into_iter());
        assert_eq!(all.along_ray(&down, 1.0), Some(vec![0]), "off the objects only the table is left");
    }
}
