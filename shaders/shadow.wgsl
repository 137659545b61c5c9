// Pipeline "shadow": depth of every shadow caster seen from the light,
// rendered into the shadow map before the main pass. Depth only (no
// fragment stage). Prepended by frame.wgsl.

@vertex
fn vs_main(v: MeshVertex, i: ObjectInstance) -> @builtin(position) vec4<f32> {
    let model = mat4x4<f32>(i.model_0, i.model_1, i.model_2, i.model_3);
    return frame.light_view_proj * model * vec4<f32>(v.position, 1.0);
}
