// slc-bevy's two small kernels around slc's direct pass.
//
// `unpack`: Bevy 0.20's deferred G-buffer (Rgba32Uint, packed by
// bevy_pbr::deferred::functions::deferred_gbuffer_from_pbr_input) into the
// textures slc's direct pass reads: world normal (xyz), linear base colour
// (rgb), and (unused, perceptual roughness, metallic, reflectance). Unlit
// pixels get a zero normal (slc adds nothing there). The unpacking follows
// bevy_pbr's pbr_input_from_deferred_gbuffer: base colour stored as
// pow(rgb, 1/2.2) in 8 bits, props = (reflectance, metallic, occlusion,
// clearcoat), the normal octahedral in 2 x 12 bits, flags in the top byte.
//
// `fullscreen` + `composite`: adds slc's radiance into Bevy's HDR view
// target (additive blending).

@group(0) @binding(0) var gbuffer: texture_2d<u32>;
@group(0) @binding(1) var normal_out: texture_storage_2d<rgba16float, write>;
@group(0) @binding(2) var base_out: texture_storage_2d<rgba16float, write>;
@group(0) @binding(3) var material_out: texture_storage_2d<rgba16float, write>;
@group(0) @binding(4) var radiance: texture_2d<f32>;

// bevy_pbr::deferred::types: DEFERRED_FLAGS_UNLIT_BIT.
const UNLIT: u32 = 1u;

// bevy_render::utils::octahedral_decode_signed.
fn octahedral_decode_signed(v: vec2f) -> vec3f {
    var n = vec3f(v.xy, 1.0 - abs(v.x) - abs(v.y));
    let t = saturate(-n.z);
    let w = select(vec2f(t), vec2f(-t), n.xy >= vec2f(0.0));
    n = vec3f(n.xy + w, n.z);
    return normalize(n);
}

@compute @workgroup_size(8, 8)
fn unpack(@builtin(global_invocation_id) gid: vec3u) {
    let size = textureDimensions(gbuffer);
    if gid.x >= size.x || gid.y >= size.y {
        return;
    }
    let texel = vec2i(gid.xy);
    let g = textureLoad(gbuffer, texel, 0);
    let flags = (g.a >> 24u) & 0xFFu;
    let base_rough = unpack4x8unorm(g.r);
    let props = unpack4x8unorm(g.b);
    let oct = vec2f(f32(g.a & 0xFFFu), f32((g.a >> 12u) & 0xFFFu)) / 4095.0;
    var n = octahedral_decode_signed(oct * 2.0 - 1.0);
    if (flags & UNLIT) != 0u || all(g == vec4u(0u)) {
        n = vec3f(0.0);
    }
    textureStore(normal_out, texel, vec4f(n, 0.0));
    textureStore(base_out, texel, vec4f(pow(base_rough.rgb, vec3f(2.2)), 1.0));
    textureStore(material_out, texel, vec4f(0.0, base_rough.a, props.g, props.r));
}

struct Fullscreen {
    @builtin(position) position: vec4f,
}

@vertex
fn fullscreen(@builtin(vertex_index) i: u32) -> Fullscreen {
    let uv = vec2f(f32(i >> 1u), f32(i & 1u)) * 2.0;
    return Fullscreen(vec4f(uv * vec2f(2.0, -2.0) + vec2f(-1.0, 1.0), 0.0, 1.0));
}

@fragment
fn composite(in: Fullscreen) -> @location(0) vec4f {
    return vec4f(textureLoad(radiance, vec2i(in.position.xy), 0).rgb, 0.0);
}
