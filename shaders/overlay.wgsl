// Pipeline "overlay": the sensed contact image as a translucent dark "hand
// shadow" where the hands touch the glass: drawn after the objects without a
// depth test, so a fingertip on a box stays visible over the box. Row 0 of the
// image is the far edge (+y), column 0 the left edge (-x). Only the part of
// the table where the image is non-zero is drawn. Prepended by frame.wgsl.

@group(1) @binding(0) var contact_image: texture_2d<f32>;
@group(1) @binding(1) var contact_sampler: sampler;

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

// Above the decals' lift so the shadow darkens them too.
const LIFT: f32 = 0.0008;

// The drawn part of the image, in texture coordinates: xy = min, zw = max.
struct RegionIn {
    @location(0) uv_rect: vec4<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) index: u32, region: RegionIn) -> VsOut {
    let corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let uv = mix(region.uv_rect.xy, region.uv_rect.zw, corners[index]);
    let xy = vec2<f32>(uv.x - 0.5, 0.5 - uv.y) * 2.0 * frame.table.xy;
    var out: VsOut;
    out.clip = frame.view_proj * vec4<f32>(xy, LIFT, 1.0);
    out.uv = uv;
    return out;
}

@fragment
fn fs_main(in: VsOut) -> @location(0) vec4<f32> {
    let contact = textureSample(contact_image, contact_sampler, in.uv).r;
    // Blending keeps (1 - alpha) of the table: make that the linear share.
    let alpha = 1.0 - stored_factor(1.0 - frame.overlay_tint.a * contact);
    return output(frame.overlay_tint.rgb, alpha);
}
