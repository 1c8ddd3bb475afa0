// Draws gaitlab's resolved 3-D scene texture (render/gpu.rs) into egui's render
// pass: one triangle covering the paint callback's viewport, sampled 1:1 (or
// bilinearly when the scene was rendered smaller than the viewport).

@group(0) @binding(0) var scene_color: texture_2d<f32>;
@group(0) @binding(1) var scene_sampler: sampler;

struct CompositeOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_composite(@builtin(vertex_index) vi: u32) -> CompositeOut {
    // (0,0), (2,0), (0,2) in uv: a triangle over the whole viewport.
    let x = f32((vi << 1u) & 2u);
    let y = f32(vi & 2u);
    var out: CompositeOut;
    out.clip = vec4<f32>(x * 2.0 - 1.0, 1.0 - y * 2.0, 0.0, 1.0);
    out.uv = vec2<f32>(x, y);
    return out;
}

// egui's usual gamma-space (non-sRGB) framebuffer: copy the sRGB-encoded values.
@fragment
fn fs_composite_gamma(in: CompositeOut) -> @location(0) vec4<f32> {
    return vec4<f32>(textureSample(scene_color, scene_sampler, in.uv).rgb, 1.0);
}

// An sRGB framebuffer encodes on write: hand it linear values.
@fragment
fn fs_composite_linear(in: CompositeOut) -> @location(0) vec4<f32> {
    let c = textureSample(scene_color, scene_sampler, in.uv).rgb;
    return vec4<f32>(pow(c, vec3<f32>(2.2)), 1.0);
}
