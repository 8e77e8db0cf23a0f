// Copies the offscreen scene image into egui's render pass (the viewport is the 3D
// view's rectangle, set by egui before `paint`).

@group(0) @binding(0) var scene_image: texture_2d<f32>;
@group(0) @binding(1) var scene_sampler: sampler;

struct BlitOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_blit(@builtin(vertex_index) index: u32) -> BlitOut {
    let xy = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u)) * 2.0 - 1.0;
    var out: BlitOut;
    out.clip = vec4<f32>(xy, 0.0, 1.0);
    out.uv = vec2<f32>(xy.x * 0.5 + 0.5, 0.5 - xy.y * 0.5);
    return out;
}

// For a non-sRGB target (the browser): the image is already gamma-encoded.
@fragment
fn fs_blit(in: BlitOut) -> @location(0) vec4<f32> {
    return vec4<f32>(textureSample(scene_image, scene_sampler, in.uv).rgb, 1.0);
}

// For an sRGB target (some desktops): the GPU encodes, so hand it linear values.
@fragment
fn fs_blit_to_linear(in: BlitOut) -> @location(0) vec4<f32> {
    let c = textureSample(scene_image, scene_sampler, in.uv).rgb;
    return vec4<f32>(pow(c, vec3<f32>(2.2)), 1.0);
}
