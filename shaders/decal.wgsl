// Pipeline "decal": flat marks painted on horizontal planes (targets,
// waypoints, zones, the finish): discs, rings, rectangles and outlines drawn
// as signed-distance shapes on instanced quads, lit and shadowed like the
// surface they lie on, alpha-blended, depth-tested but not depth-written.
// Prepended by frame.wgsl.

struct DecalIn {
    // x, y: centre; z: plane height; w: rotation about z (radians).
    @location(0) place: vec4<f32>,
    // x, y: half extents (x = radius for discs); z: stroke width (0 = filled);
    // w: 0 for a disc, 1 for a rectangle.
    @location(1) shape: vec4<f32>,
    @location(2) color: vec4<f32>,
};

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) local: vec2<f32>,
    @location(1) shape: vec4<f32>,
    @location(2) color: vec4<f32>,
    @location(3) shadow: vec3<f32>,
};

// Lifted above its plane so it wins the depth test against the surface it is
// painted on (0.4 mm: invisible at table scale, enough for a 32-bit depth).
const LIFT: f32 = 0.0004;

// Vertices per decal: four quads. A filled shape or a disc uses the first
// (the others collapse to nothing); a rectangle's outline is four strips
// along its edges, so the fragments inside it, which the outline's
// coverage discards anyway, are never shaded. On a software rasteriser a
// sorting zone's outline over the whole zone cost as much as its fill.
const VERTICES: u32 = 24u;

@vertex
fn vs_main(@builtin(vertex_index) index: u32, d: DecalIn) -> VsOut {
    let corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let half = select(d.shape.xx, d.shape.xy, d.shape.w > 0.5);
    // Room for half the stroke outside the edge and for antialiasing.
    let margin = 0.5 * d.shape.z + 0.003;
    let outer = half + vec2<f32>(margin);
    let inner = half - vec2<f32>(margin);
    let strips = d.shape.w > 0.5 && d.shape.z > 0.0 && inner.x > 0.0 && inner.y > 0.0;
    let quad = index / 6u;
    // The quad's corners [lo, hi] in the decal's frame.
    var lo = -outer;
    var hi = outer;
    if strips {
        switch quad {
            case 0u: { hi.y = -inner.y; }
            case 1u: { lo.y = inner.y; }
            case 2u: { lo.y = -inner.y; hi.y = inner.y; hi.x = -inner.x; }
            default: { lo.y = -inner.y; hi.y = inner.y; lo.x = inner.x; }
        }
    } else if quad > 0u {
        hi = lo;
    }
    let local = mix(lo, hi, corners[index % 6u]);
    let c = cos(d.place.w);
    let s = sin(d.place.w);
    let xy = d.place.xy + vec2<f32>(c * local.x - s * local.y, s * local.x + c * local.y);
    let world = vec3<f32>(xy, d.place.z + LIFT);
    var out: VsOut;
    out.clip = frame.view_proj * vec4<f32>(world, 1.0);
    out.local = local;
    out.shape = d.shape;
    out.color = d.color;
    out.shadow = shadow_coords(vec3<f32>(xy, d.place.z), vec3<f32>(0.0, 0.0, 1.0));
    return out;
}

// The shape's coverage of this pixel (0 outside, 1 inside, antialiased
// across its edge).
fn coverage(in: VsOut) -> f32 {
    let disc = length(in.local) - in.shape.x;
    let q = abs(in.local) - in.shape.xy;
    let rect = length(max(q, vec2<f32>(0.0))) + min(max(q.x, q.y), 0.0);
    var distance = select(disc, rect, in.shape.w > 0.5);
    // A stroke is centred on the edge, like an SVG stroke.
    distance = select(distance, abs(distance) - 0.5 * in.shape.z, in.shape.z > 0.0);
    let pixel = max(fwidth(distance), 1e-6);
    return clamp(0.5 - distance / pixel, 0.0, 1.0);
}

@fragment
fn fs_main(in: VsOut) -> @location(0) vec4<f32> {
    let coverage = coverage(in);
    if coverage <= 0.0 {
        discard;
    }
    // Matte: no highlight, so the lighting is ambient + shadowed Lambert.
    let up = vec3<f32>(0.0, 0.0, 1.0);
    let color = in.color.rgb * (ambient_light(up) + frame.light_color.rgb * direct_light(in.shadow, up));
    return output(color, in.color.a * coverage);
}

// `fs_main` where no shadow can fall (`render::shadow_regions`): the four
// lookups would each answer fully lit, so the colour is the same without them.
@fragment
fn fs_unshadowed(in: VsOut) -> @location(0) vec4<f32> {
    let coverage = coverage(in);
    if coverage <= 0.0 {
        discard;
    }
    let up = vec3<f32>(0.0, 0.0, 1.0);
    let direct = max(dot(up, frame.light_direction.xyz), 0.0);
    let color = in.color.rgb * (ambient_light(up) + frame.light_color.rgb * direct);
    return output(color, in.color.a * coverage);
}
