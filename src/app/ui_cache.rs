//! The side panel drawn once and reused while it does not change.
//!
//! On a software rasteriser egui's own drawing is a large part of a frame:
//! at 1280x800 on lavapipe the panel's thousands of triangles (text is two
//! per glyph, plus anti-aliasing feathers) take about as much of the
//! frame's GPU time as the 3D table (measured with `scripts/demo-fps.sh`).
//! Yet from one frame to the next the panel is usually pixel for pixel the
//! same. So egui's output is cut in two: the leading primitives that lie
//! wholly outside the table view (the panel) are drawn into a texture of
//! the window's size, again only when they differ from the last ones drawn;
//! every frame copies that texture's panel part and the table view into the
//! window and draws only the rest (hand outlines, banners, popups) live.

use egui::epaint::{ClippedPrimitive, Primitive};
use egui::{Rect, Vec2};

/// How many leading primitives can be cached: those before the first one
/// that reaches into `view` (points). Order is kept, so anything drawn
/// after a live primitive stays live and overlaps come out as egui meant.
/// A primitive reaches into the view when the part of its mesh inside its
/// clip rectangle overlaps the view by more than half a point (the
/// anti-aliasing feather of a panel edge does not count: the view's copy
/// covers it).
pub fn cacheable_prefix(primitives: &[ClippedPrimitive], view: Rect) -> usize {
    let inner = view.shrink2(Vec2::splat(0.5));
    primitives
        .iter()
        .position(|p| match &p.primitive {
            Primitive::Mesh(m) => {
                let drawn = m.calc_bounds().intersect(p.clip_rect);
                drawn.is_positive() && drawn.intersects(inner) && drawn.intersect(inner).is_positive()
            }
            // A callback may draw anything anywhere.
            Primitive::Callback(_) => true,
        })
        .unwrap_or(primitives.len())
}

/// Whether two lists of primitives draw the same pixels (same meshes, same
/// clip rectangles, same textures; callbacks never compare equal).
pub fn same_primitives(a: &[ClippedPrimitive], b: &[ClippedPrimitive]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| {
            x.clip_rect == y.clip_rect
                && match (&x.primitive, &y.primitive) {
                    (Primitive::Mesh(m), Primitive::Mesh(n)) => m == n,
                    _ => false,
                }
        })
}

/// The up to four rectangles of `window` outside `view` (pixels, min
/// inclusive, max exclusive, as `[x, y, width, height]`): left and right
/// strips at full height, top and bottom between them.
pub fn outside(window: [u32; 2], view: [u32; 4]) -> Vec<[u32; 4]> {
    let [w, h] = window;
    let x0 = view[0].min(w);
    let y0 = view[1].min(h);
    let x1 = (view[0] + view[2]).clamp(x0, w);
    let y1 = (view[1] + view[3]).clamp(y0, h);
    [[0, 0, x0, h], [x1, 0, w - x1, h], [x0, 0, x1 - x0, y0], [x0, y1, x1 - x0, h - y1]]
        .into_iter()
        .filter(|r| r[2] > 0 && r[3] > 0)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::epaint::{Mesh, Vertex};
    use egui::{Color32, Pos2, TextureId, pos2};

    fn quad(min: Pos2, max: Pos2, clip: Rect) -> ClippedPrimitive {
        let mut m = Mesh::with_texture(TextureId::default());
        for p in [min, pos2(max.x, min.y), max, pos2(min.x, max.y)] {
            m.vertices.push(Vertex { pos: p, uv: Pos2::ZERO, color: Color32::WHITE });
        }
        m.indices = vec![0, 1, 2, 0, 2, 3];
        ClippedPrimitive { clip_rect: clip, primitive: Primitive::Mesh(m) }
    }

    #[test]
    fn the_panel_before_the_first_view_primitive_is_cached() {
        let screen = Rect::from_min_max(Pos2::ZERO, pos2(1280.0, 800.0));
        let view = Rect::from_min_max(pos2(320.0, 0.0), pos2(1280.0, 800.0));
        let panel_bg = quad(Pos2::ZERO, pos2(320.3, 800.0), screen); // feathered edge
        let label = quad(pos2(10.0, 10.0), pos2(200.0, 30.0), screen);
        // A mesh reaching over the view but clipped to the panel stays cacheable.
        let clipped = quad(pos2(10.0, 40.0), pos2(900.0, 60.0), Rect::from_min_max(Pos2::ZERO, pos2(320.0, 800.0)));
        let outline = quad(pos2(600.0, 300.0), pos2(700.0, 400.0), screen);
        let late_label = quad(pos2(10.0, 700.0), pos2(200.0, 720.0), screen);
        let prims = vec![panel_bg.clone(), label.clone(), clipped, outline, late_label];
        assert_eq!(cacheable_prefix(&prims, view), 3);
        assert_eq!(cacheable_prefix(&prims[..3], view), 3);
        assert_eq!(cacheable_prefix(&prims[3..], view), 0);
        assert!(same_primitives(&prims[..2], &[panel_bg.clone(), label]));
        let moved = quad(pos2(10.0, 11.0), pos2(200.0, 31.0), screen);
        assert!(!same_primitives(&prims[..2], &[panel_bg, moved]));
    }

    #[test]
    fn outside_the_view_is_covered_exactly_once() {
        for (window, view) in
            [([1280, 800], [320, 0, 960, 800]), ([1000, 700], [300, 20, 600, 650]), ([640, 480], [0, 0, 640, 480])]
        {
            let rects = outside(window, view);
            let mut covered = vec![0u8; (window[0] * window[1]) as usize];
            for r in rects.iter().chain(std::iter::once(&view)) {
                for y in r[1]..r[1] + r[3] {
                    for x in r[0]..r[0] + r[2] {
                        covered[(y * window[0] + x) as usize] += 1;
                    }
                }
            }
            assert!(covered.iter().all(|&c| c == 1), "{window:?} {view:?}: {rects:?}");
        }
    }
}
