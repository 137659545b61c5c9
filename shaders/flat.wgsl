// Pipeline "flat": flat-faced meshes — the table slab, boxes, the steering
// platform. They cover most of every frame, so this is the leanest lit
// shader: matte (no highlight), lighting constant per face and computed per
// vertex, one shadow tap (an edge < 1 mm wide). Round meshes use "mesh".
// (The table's grid and rim are drawn over it by the "grid" pipeline.)
// Prepended by frame.wgsl.

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) shadow: vec3<f32>,
    // Albedo times ambient light.
    @location(1) @interpolate(flat) ambient: vec3<f32>,
    // Albedo times unshadowed direct light.
    @location(2) @interpolate(flat) direct: vec3<f32>,
};

@vertex
fn vs_main(v: MeshVertex, i: ObjectInstance) -> VsOut {
    let model = mat4x4<f32>(i.model_0, i.model_1, i.model_2, i.model_3);
    let normal_matrix = mat3x3<f32>(i.normal_0.xyz, i.normal_1.xyz, i.normal_2.xyz);
    let world = model * vec4<f32>(v.position, 1.0);
    let n = normalize(normal_matrix * v.normal);
    var out: VsOut;
    out.clip = frame.view_proj * world;
    out.shadow = shadow_coords(world.xyz, n);
    out.ambient = i.color.rgb * ambient_light(n);
    out.direct = i.color.rgb * frame.light_color.rgb * max(dot(n, frame.light_direction.xyz), 0.0);
    return out;
}

@fragment
fn fs_main(in: VsOut) -> @location(0) vec4<f32> {
    let lit = shadowed(shadow_sharp(in.shadow));
    return output(in.ambient + in.direct * lit, 1.0);
}

// `fs_main` where no shadow can fall (`render::shadow_regions`): the lookup
// would answer fully lit, so the colour is the same without it.
@fragment
fn fs_unshadowed(in: VsOut) -> @location(0) vec4<f32> {
    return output(in.ambient + in.direct, 1.0);
}
