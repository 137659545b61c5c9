// Pipeline "feedback": the technique's lines (joints) and cubes (proxies,
// particles), drawn after everything else in two passes: parts hidden behind
// geometry faintly (x-ray, `frame.options.y` opacity), visible parts solid.
// Lines are screen-space quads of a fixed pixel width. Prepended by frame.wgsl.

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

struct LineIn {
    // xyz: end point; w: width in pixels (same in `b`).
    @location(0) a: vec4<f32>,
    @location(1) b: vec4<f32>,
    @location(2) color: vec4<f32>,
};

// Clip-space position of a point pulled 1 mm towards the eye, so a line lying
// on a surface is drawn in front of it rather than z-fighting with it.
fn clip_towards_eye(p: vec3<f32>) -> vec4<f32> {
    let lifted = p + normalize(frame.camera_position.xyz - p) * 0.001;
    return frame.view_proj * vec4<f32>(lifted, 1.0);
}

@vertex
fn vs_line(@builtin(vertex_index) index: u32, line: LineIn) -> VsOut {
    var ca = clip_towards_eye(line.a.xyz);
    var cb = clip_towards_eye(line.b.xyz);
    // Clip the segment against a plane just in front of the eye so the
    // perspective divide below stays finite.
    let w_min = 1e-4;
    if ca.w < w_min {
        ca = mix(ca, cb, (w_min - ca.w) / (cb.w - ca.w));
    } else if cb.w < w_min {
        cb = mix(cb, ca, (w_min - cb.w) / (ca.w - cb.w));
    }
    let half_viewport = 0.5 * frame.viewport.xy;
    let sa = ca.xy / ca.w * half_viewport;
    let sb = cb.xy / cb.w * half_viewport;
    let delta = sb - sa;
    let along = select(vec2<f32>(1.0, 0.0), normalize(delta), length(delta) > 1e-4);
    let across = vec2<f32>(-along.y, along.x);
    // Two triangles; x: which end, y: which side.
    let corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let corner = corners[index];
    let half_width = 0.5 * line.a.w;
    var clip = select(ca, cb, corner.x > 0.5);
    // Square caps: extend each end by half the width.
    let offset_px = across * corner.y * half_width + along * (corner.x * 2.0 - 1.0) * half_width;
    clip = vec4<f32>(clip.xy + offset_px / half_viewport * clip.w, clip.zw);
    var out: VsOut;
    out.clip = clip;
    out.color = line.color;
    return out;
}

struct CubeIn {
    // xyz: centre; w: half the side.
    @location(2) center_half: vec4<f32>,
    @location(3) color: vec4<f32>,
};

@vertex
fn vs_cube(v: MeshVertex, cube: CubeIn) -> VsOut {
    // The unit box has side 1: scale by the full side.
    let world = cube.center_half.xyz + v.position * (2.0 * cube.center_half.w);
    // Unshadowed, mostly flat shading: the faces stay distinguishable but
    // the colour stays close to the caller's.
    let facing = max(dot(v.normal, frame.light_direction.xyz), 0.0);
    var out: VsOut;
    out.clip = frame.view_proj * vec4<f32>(world, 1.0);
    out.color = vec4<f32>(cube.color.rgb * (0.6 + 0.4 * facing), cube.color.a);
    return out;
}

@fragment
fn fs_visible(in: VsOut) -> @location(0) vec4<f32> {
    return output(in.color.rgb, in.color.a);
}

@fragment
fn fs_hidden(in: VsOut) -> @location(0) vec4<f32> {
    return output(in.color.rgb, in.color.a * frame.options.y);
}
