// Pipeline "mesh": lit, shadowed, instanced meshes — the objects (box,
// sphere, cylinder, capsule) and the deformables (drawn with an identity
// transform and culling off). Prepended by frame.wgsl.

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    // From the surface to the eye (for the highlight).
    @location(0) to_eye: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(3) params: vec4<f32>,
    @location(4) shadow: vec3<f32>,
};

@vertex
fn vs_main(v: MeshVertex, i: ObjectInstance) -> VsOut {
    let model = mat4x4<f32>(i.model_0, i.model_1, i.model_2, i.model_3);
    let normal_matrix = mat3x3<f32>(i.normal_0.xyz, i.normal_1.xyz, i.normal_2.xyz);
    let world = model * vec4<f32>(v.position, 1.0);
    var out: VsOut;
    out.clip = frame.view_proj * world;
    out.to_eye = frame.camera_position.xyz - world.xyz;
    out.normal = normalize(normal_matrix * v.normal);
    out.shadow = shadow_coords(world.xyz, out.normal);
    out.color = i.color;
    out.params = i.params;
    return out;
}

@fragment
fn fs_main(in: VsOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    // Deformables are double-sided: light the side facing the camera.
    let n = normalize(in.normal) * select(-1.0, 1.0, front);
    return output(shade(in.color.rgb, in.to_eye, in.shadow, n, in.params.y), 1.0);
}
