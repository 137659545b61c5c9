// Pipeline "grid": markings on the table top — a faint grid, one line every
// few centimetres, and a darker rim like a display's bezel — drawn as
// instanced strips that darken what is below them (multiplicative blending),
// so they stay under shadows, decals and objects without costing the whole
// table a pattern evaluation per pixel. Prepended by frame.wgsl.

struct StripIn {
    // xy: one end on the table; z: height; w: half width (pixels or metres).
    @location(0) a: vec4<f32>,
    // xy: the other end; z: 1 when the width is in pixels; w: darkness (0..1).
    @location(1) b: vec4<f32>,
};

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    // -1..1 across the strip.
    @location(0) across: f32,
    @location(1) @interpolate(flat) darkness: f32,
};

// Above the table top, below the decals' lift.
const LIFT: f32 = 0.0002;

@vertex
fn vs_main(@builtin(vertex_index) index: u32, strip: StripIn) -> VsOut {
    let corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let corner = corners[index];
    let z = strip.a.z + LIFT;
    let end = select(strip.a.xy, strip.b.xy, corner.x > 0.5);
    var clip: vec4<f32>;
    if strip.b.z > 0.5 {
        // Width in pixels: widen in screen space, 1 px wider for antialiasing.
        let ca = frame.view_proj * vec4<f32>(strip.a.xy, z, 1.0);
        let cb = frame.view_proj * vec4<f32>(strip.b.xy, z, 1.0);
        let half_viewport = 0.5 * frame.viewport.xy;
        let dir = normalize((cb.xy / cb.w - ca.xy / ca.w) * half_viewport);
        let normal = vec2<f32>(-dir.y, dir.x);
        clip = select(ca, cb, corner.x > 0.5);
        let offset_px = normal * corner.y * (strip.a.w + 1.0);
        clip = vec4<f32>(clip.xy + offset_px / half_viewport * clip.w, clip.zw);
    } else {
        let dir = normalize(strip.b.xy - strip.a.xy);
        let normal = vec2<f32>(-dir.y, dir.x);
        clip = frame.view_proj * vec4<f32>(end + normal * corner.y * strip.a.w, z, 1.0);
    }
    var out: VsOut;
    out.clip = clip;
    out.across = corner.y;
    out.darkness = strip.b.w;
    return out;
}

@fragment
fn fs_main(in: VsOut) -> @location(0) vec4<f32> {
    // Coverage of the strip in this pixel, antialiased across its width.
    let d = abs(in.across);
    let coverage = clamp((1.0 - d) / max(fwidth(d), 1e-6) + 0.5, 0.0, 1.0);
    // Multiplied into the target (src * dst): 1 leaves it, 1 - darkness darkens.
    return vec4<f32>(vec3<f32>(stored_factor(1.0 - in.darkness * coverage)), 1.0);
}
