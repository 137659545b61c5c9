//! Where the table's shadows can fall on screen, so that the table and the
//! decals painted on it look up the shadow map only there.
//!
//! On a software rasteriser a fragment's shadow lookup (a filtered depth
//! comparison, four of them for the soft-edged decals) is most of its cost,
//! and the table and its zones cover most of the frame; yet only the pixels
//! near an object can be in shadow. Everywhere else the lookup answers
//! "fully lit" (the shadow map holds only the casters), and a shader that
//! skips it computes the same colour bit for bit. So the view is cut into
//! disjoint rectangles ([`cells`]): those that may hold a shadow are drawn
//! with the shadowed shaders, the rest with their unshadowed twins
//! (`fs_unshadowed` in `shaders/flat.wgsl` and `shaders/decal.wgsl`). The
//! cells do not overlap, so each pixel is drawn once and the decals'
//! blending is unchanged. `docs/performance.md` (the demo window) has the
//! saving.
//!
//! A caster's shadow falls along the light, downwards: on any receiver
//! between its bottom and `floor` (the lowest receiver, the table top or a
//! lower decal) it lies inside the hull of its bounding box and that box
//! slid down the light to `floor`. Each box is first grown by
//! [`reach`]: how far sideways a lookup may land from the point it shades
//! (the filter taps and the normal offset of `shadow_coords` in
//! `shaders/frame.wgsl`), counted twice over.

use glam::{Mat4, Vec3};

use crate::render::bounds::{Aabb, mesh_half_extents};
use crate::render::draw_list::DrawList;

/// A rectangle of pixels: `min` inclusive, `max` exclusive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PixelRect {
    pub min: [u32; 2],
    pub max: [u32; 2],
}

impl PixelRect {
    pub fn width(&self) -> u32 {
        self.max[0] - self.min[0]
    }

    pub fn height(&self) -> u32 {
        self.max[1] - self.min[1]
    }

    fn is_empty(&self) -> bool {
        self.max[0] <= self.min[0] || self.max[1] <= self.min[1]
    }
}

/// How far (metres) a shadow lookup may land sideways from the point it
/// shades: the bilinear footprint (one texel), the outer PCF taps (`tap`),
/// and the normal offset (at most a texel and three taps).
pub fn reach(texel: f32, tap: f32) -> f32 {
    2.0 * texel + 4.0 * tap
}

/// The screen rectangles (pixels of a `size` view) that may show a shadow
/// on a receiver at or above `floor`: one per caster (objects and
/// deformables), grown by `margin` metres; they may overlap. The whole
/// view when a caster's shadow reaches behind the camera.
pub fn shadow_rects(
    list: &DrawList,
    view_proj: Mat4,
    size: [u32; 2],
    light: Vec3,
    floor: f32,
    margin: f32,
) -> Vec<PixelRect> {
    let whole = PixelRect { min: [0, 0], max: size };
    let mut boxes: Vec<Aabb> = list
        .objects
        .iter()
        .filter(|o| o.transform.is_finite())
        .map(|o| Aabb::of_transformed_box(o.transform, mesh_half_extents(o.mesh)))
        .collect();
    for d in &list.deformables {
        let mut b = Aabb::EMPTY;
        d.positions.iter().for_each(|&p| b.add_point(p));
        boxes.push(b);
    }
    let mut rects = Vec::new();
    for b in boxes.into_iter().filter(|b| !b.is_empty()) {
        let grown = Aabb { min: b.min - Vec3::splat(margin), max: b.max + Vec3::splat(margin) };
        match screen_rect(&grown, view_proj, size, light, floor) {
            Some(r) if !r.is_empty() => rects.push(r),
            Some(_) => {}
            None => return vec![whole],
        }
    }
    rects
}

/// The pixels covering `b` and `b` slid along `-light` down to `floor`;
/// `None` when a point is behind the camera (or the light is level).
fn screen_rect(b: &Aabb, view_proj: Mat4, size: [u32; 2], light: Vec3, floor: f32) -> Option<PixelRect> {
    if light.z <= 1e-3 {
        return None;
    }
    let (w, h) = (size[0] as f32, size[1] as f32);
    let (mut lo, mut hi) = ([f32::INFINITY; 2], [f32::NEG_INFINITY; 2]);
    for c in b.corners() {
        let drop = (c.z - floor).max(0.0) / light.z;
        for p in [c, c - light * drop] {
            let clip = view_proj * p.extend(1.0);
            if !clip.is_finite() || clip.w <= 1e-6 {
                return None;
            }
            let (x, y) = ((clip.x / clip.w * 0.5 + 0.5) * w, (0.5 - clip.y / clip.w * 0.5) * h);
            lo = [lo[0].min(x), lo[1].min(y)];
            hi = [hi[0].max(x), hi[1].max(y)];
        }
    }
    // A pixel of slack on each side for the rasteriser's rounding.
    let px = |v: f32, limit: u32| (v.clamp(0.0, limit as f32)) as u32;
    Some(PixelRect {
        min: [px(lo[0].floor() - 1.0, size[0]), px(lo[1].floor() - 1.0, size[1])],
        max: [px(hi[0].ceil() + 1.0, size[0]), px(hi[1].ceil() + 1.0, size[1])],
    })
}

/// The view of `size` pixels cut into disjoint rectangles, each with
/// whether it lies in one of `regions` (which may overlap): horizontal
/// bands between the regions' top and bottom edges, each cut at the sides
/// of the regions it crosses; neighbours alike are joined, across a band
/// and down from band to band. Together the cells cover every pixel exactly
/// once; with no regions there is one cell, the view.
pub fn cells(size: [u32; 2], regions: &[PixelRect]) -> Vec<(PixelRect, bool)> {
    let mut ys: Vec<u32> = vec![0, size[1]];
    for r in regions {
        ys.extend([r.min[1].min(size[1]), r.max[1].min(size[1])]);
    }
    ys.sort_unstable();
    ys.dedup();
    let mut out: Vec<(PixelRect, bool)> = Vec::new();
    // Where the previous band's cells start in `out`.
    let mut previous = 0..0;
    for band in ys.windows(2) {
        let (y0, y1) = (band[0], band[1]);
        let mut inside: Vec<(u32, u32)> = regions
            .iter()
            .filter(|r| r.min[1] <= y0 && y1 <= r.max[1])
            .map(|r| (r.min[0].min(size[0]), r.max[0].min(size[0])))
            .filter(|(a, b)| a < b)
            .collect();
        inside.sort_unstable();
        let mut row: Vec<(u32, u32, bool)> = Vec::new();
        let mut push = |x0: u32, x1: u32, shadowed: bool| match row.last_mut() {
            _ if x0 >= x1 => {}
            Some(last) if last.2 == shadowed && last.1 == x0 => last.1 = x1,
            _ => row.push((x0, x1, shadowed)),
        };
        let mut x = 0;
        for (a, b) in inside {
            push(x, a.max(x), false);
            push(a.max(x), b, true);
            x = x.max(b);
        }
        push(x, size[0], false);
        let same = out[previous.clone()].len() == row.len()
            && out[previous.clone()]
                .iter()
                .zip(&row)
                .all(|((r, s), (x0, x1, t))| r.min[0] == *x0 && r.max[0] == *x1 && s == t);
        if same {
            out[previous.clone()].iter_mut().for_each(|(r, _)| r.max[1] = y1);
        } else {
            previous = out.len()..out.len() + row.len();
            out.extend(row.into_iter().map(|(x0, x1, s)| (PixelRect { min: [x0, y0], max: [x1, y1] }, s)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::samples;

    fn rect(x0: u32, y0: u32, x1: u32, y1: u32) -> PixelRect {
        PixelRect { min: [x0, y0], max: [x1, y1] }
    }

    /// How many cells cover each pixel, and whether the shadowed ones are
    /// exactly the pixels of the regions.
    fn check_cover(size: [u32; 2], regions: &[PixelRect]) {
        let cells = cells(size, regions);
        for y in 0..size[1] {
            for x in 0..size[0] {
                let hits: Vec<bool> = cells
                    .iter()
                    .filter(|(r, _)| (r.min[0]..r.max[0]).contains(&x) && (r.min[1]..r.max[1]).contains(&y))
                    .map(|&(_, s)| s)
                    .collect();
                assert_eq!(hits.len(), 1, "pixel ({x}, {y}) covered {} times", hits.len());
                let in_region =
                    regions.iter().any(|r| (r.min[0]..r.max[0]).contains(&x) && (r.min[1]..r.max[1]).contains(&y));
                assert_eq!(hits[0], in_region, "pixel ({x}, {y})");
            }
        }
    }

    #[test]
    fn cells_cover_every_pixel_once() {
        check_cover([20, 15], &[]);
        check_cover([20, 15], &[rect(0, 0, 20, 15)]);
        check_cover([20, 15], &[rect(2, 3, 8, 9), rect(10, 1, 14, 4), rect(12, 6, 20, 15)]);
        // Overlapping, nested, touching, and past the view's edge.
        let overlapping =
            [rect(2, 2, 6, 6), rect(5, 5, 9, 9), rect(3, 3, 4, 4), rect(9, 0, 11, 3), rect(15, 10, 30, 20)];
        check_cover([20, 15], &overlapping);
        // Overlapping regions in the same columns: three bands, one row of
        // three cells.
        let stacked = cells([10, 10], &[rect(2, 0, 5, 6), rect(2, 3, 5, 10)]);
        assert_eq!(stacked.len(), 3, "{stacked:?}");
    }

    #[test]
    fn a_casters_shadow_lies_in_its_rectangle() {
        let list = samples::positioning();
        let size = [640, 480];
        let camera = crate::render::camera::CameraMatrices::for_draw_list(&list, size);
        let light = crate::render::light::light_direction();
        let rects = shadow_rects(&list, camera.view_proj, size, light, 0.0, 0.0);
        assert!(!rects.is_empty() && rects.iter().all(|r| r.width() < size[0]), "{rects:?}");
        // Each caster's top corners, dropped along the light onto the table.
        for o in &list.objects {
            for c in Aabb::of_transformed_box(o.transform, mesh_half_extents(o.mesh)).corners() {
                let on_table = c - light * (c.z / light.z);
                let clip = camera.view_proj * on_table.extend(1.0);
                let x = ((clip.x / clip.w * 0.5 + 0.5) * size[0] as f32) as u32;
                let y = ((0.5 - clip.y / clip.w * 0.5) * size[1] as f32) as u32;
                assert!(
                    rects.iter().any(|r| (r.min[0]..r.max[0]).contains(&x) && (r.min[1]..r.max[1]).contains(&y)),
                    "shadow point ({x}, {y}) outside {rects:?}"
                );
            }
        }
    }
}
