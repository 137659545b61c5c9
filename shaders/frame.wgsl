// Shared prelude of every pipeline's shader (prepended by `pipelines.rs`):
// the per-frame uniforms, the shadow-map lookup and the lighting model, so the
// table, the objects and the decals painted on them are lit identically.
// Coordinates: metres, z up, table top at z = 0.

struct Frame {
    view_proj: mat4x4<f32>,
    light_view_proj: mat4x4<f32>,
    // xyz: the eye.
    camera_position: vec4<f32>,
    // xyz: unit vector towards the (directional) light.
    light_direction: vec4<f32>,
    // rgb: direct light; ambient comes from a sky/ground hemisphere.
    light_color: vec4<f32>,
    sky_color: vec4<f32>,
    ground_color: vec4<f32>,
    // x: one shadow-map texel in metres, y: PCF tap spacing in uv units,
    // z: how much of the direct light a shadow removes (1 = all),
    // w: PCF tap spacing in metres.
    shadow: vec4<f32>,
    // width, height, 1/width, 1/height in pixels.
    viewport: vec4<f32>,
    // x, y: half width and half depth of the table.
    table: vec4<f32>,
    // rgb: colour of the contact overlay ("hand shadow"); a: its opacity at full contact.
    overlay_tint: vec4<f32>,
    // x: 1 when the target is not sRGB and the shader must encode;
    // y: opacity of feedback hidden behind geometry.
    options: vec4<f32>,
};

// A mesh vertex (`render::Vertex`, locations 0..=1): every lit mesh, the
// shadow casters and the feedback cubes share it.
struct MeshVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

// An object instance (`render::ObjectInstance`, locations 2..=10), read by
// the "mesh", "flat" and "shadow" pipelines from one instance buffer; each
// reads the fields it needs.
struct ObjectInstance {
    @location(2) model_0: vec4<f32>,
    @location(3) model_1: vec4<f32>,
    @location(4) model_2: vec4<f32>,
    @location(5) model_3: vec4<f32>,
    // Inverse-transpose of the model's upper 3x3 (non-uniform scales).
    @location(6) normal_0: vec4<f32>,
    @location(7) normal_1: vec4<f32>,
    @location(8) normal_2: vec4<f32>,
    @location(9) color: vec4<f32>,
    // y: specular strength (x, z, w unused).
    @location(10) params: vec4<f32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var shadow_map: texture_depth_2d;
@group(0) @binding(2) var shadow_sampler: sampler_comparison;

// Where `world` falls in the shadow map: xy = uv, z = depth to compare.
// Called per vertex: the light's projection is orthographic (affine), so
// interpolating these coordinates across a triangle is exact, and fragments
// are spared a matrix product (which costs more than the lookup on lavapipe).
fn shadow_coords(world: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    // Normal offset: look up a point off the surface so it does not shadow
    // itself (acne) without a large depth bias (peter-panning). The PCF taps
    // reach `frame.shadow.w` sideways, where a surface tilted away from the
    // light lies deeper; the offset grows with that tilt.
    let n_dot_l = clamp(dot(normal, frame.light_direction.xyz), 0.0, 1.0);
    let offset = frame.shadow.x + frame.shadow.w * (1.0 + 2.0 * (1.0 - n_dot_l));
    let clip = frame.light_view_proj * vec4<f32>(world + normal * offset, 1.0);
    return vec3<f32>(clip.x * 0.5 + 0.5, 0.5 - clip.y * 0.5, clip.z);
}

// 1 inside the shadow map; outside it (beyond the fitted scene) nothing
// casts a shadow.
fn in_shadow_map(c: vec3<f32>) -> bool {
    return all(abs(c.xy - 0.5) <= vec2<f32>(0.5)) && c.z <= 1.0;
}

// Fraction of direct light reaching the point with shadow coordinates `c`
// (1 = fully lit): four hardware-filtered (2x2) comparisons around it, a
// soft 4x4-texel PCF. For small surfaces (objects, decals).
fn shadow_soft(c: vec3<f32>) -> f32 {
    let d = frame.shadow.y;
    var lit = textureSampleCompareLevel(shadow_map, shadow_sampler, c.xy + vec2<f32>(-d, -d), c.z);
    lit += textureSampleCompareLevel(shadow_map, shadow_sampler, c.xy + vec2<f32>(d, -d), c.z);
    lit += textureSampleCompareLevel(shadow_map, shadow_sampler, c.xy + vec2<f32>(-d, d), c.z);
    lit += textureSampleCompareLevel(shadow_map, shadow_sampler, c.xy + vec2<f32>(d, d), c.z);
    return select(1.0, 0.25 * lit, in_shadow_map(c));
}

// One hardware-filtered comparison: a shadow edge one texel (< 1 mm) wide.
// For the table, which covers most of the frame.
fn shadow_sharp(c: vec3<f32>) -> f32 {
    return select(1.0, textureSampleCompareLevel(shadow_map, shadow_sampler, c.xy, c.z), in_shadow_map(c));
}

// Share of the direct light left by shadowing (shadows are not black).
fn shadowed(lit: f32) -> f32 {
    return 1.0 - frame.shadow.z * (1.0 - lit);
}

// Direct light reaching a surface with normal `n` whose shadow coordinates
// are `c`: Lambert times shadow.
fn direct_light(c: vec3<f32>, n: vec3<f32>) -> f32 {
    return max(dot(n, frame.light_direction.xyz), 0.0) * shadowed(shadow_soft(c));
}

// Ambient from a sky/ground hemisphere.
fn ambient_light(n: vec3<f32>) -> vec3<f32> {
    return mix(frame.ground_color.rgb, frame.sky_color.rgb, n.z * 0.5 + 0.5);
}

// Hemisphere ambient + shadowed Lambert + a small Blinn-Phong highlight
// (exponent 64 by repeated squaring: `pow` is slow on CPU rasterisers).
// `to_eye` need not be normalised.
fn shade(albedo: vec3<f32>, to_eye: vec3<f32>, shadow: vec3<f32>, n: vec3<f32>, specular: f32) -> vec3<f32> {
    let direct = direct_light(shadow, n);
    let h = normalize(frame.light_direction.xyz + normalize(to_eye));
    var s = max(dot(n, h), 0.0);
    s *= s;
    s *= s;
    s *= s;
    s *= s;
    s *= s;
    s *= s;
    let highlight = specular * s * min(4.0 * direct, 1.0);
    return albedo * (ambient_light(n) + frame.light_color.rgb * direct) + frame.light_color.rgb * highlight;
}

fn linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let lo = c * 12.92;
    let hi = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(hi, lo, c <= vec3<f32>(0.0031308));
}

// A factor that scales linear colour (a multiplicative blend, the
// transmittance 1 - alpha of a dark overlay), as it should be applied to
// the values the target stores: unchanged for sRGB targets; for targets the
// shader encodes, scaling by f^(1/2.4) matches scaling linear values by f
// (exactly for dark-to-mid tones, within a few levels elsewhere).
fn stored_factor(f: f32) -> f32 {
    return select(f, pow(max(f, 0.0), 1.0 / 2.4), frame.options.x > 0.5);
}

// Colours are computed in linear space; sRGB targets encode on write, other
// targets (some window surfaces) need it done here.
fn output(color: vec3<f32>, alpha: f32) -> vec4<f32> {
    let c = clamp(color, vec3<f32>(0.0), vec3<f32>(1.0));
    if frame.options.x > 0.5 {
        return vec4<f32>(linear_to_srgb(c), alpha);
    }
    return vec4<f32>(c, alpha);
}
