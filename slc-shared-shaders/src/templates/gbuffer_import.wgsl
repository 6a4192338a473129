{% include "header.wgsl" %}
// An engine's G-buffer textures into the buffers vpl_tiled and vpl_denoise
// read: position (xyz, w > 0 where a surface is) and unit normal facing the
// camera; depth is the distance from the eye. Clears the irradiance of every
// pixel, since vpl_tiled writes only pixels that see a surface.

@group(0) @binding(0) var<uniform> params: ImageParams;
@group(0) @binding(1) var position_tex: texture_2d<f32>;
@group(0) @binding(2) var normal_tex: texture_2d<f32>;
@group(0) @binding(3) var<storage, read_write> gb_position: array<vec4f>;
@group(0) @binding(4) var<storage, read_write> gb_normal: array<vec4f>;
@group(0) @binding(5) var<storage, read_write> irradiance: array<vec4f>;
// Declared because the shared library reads it; unused here, so not bound.
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= params.width || gid.y >= params.height {
        return;
    }
    let i = gid.y * params.width + gid.x;
    let texel = vec2i(i32(gid.x), i32(gid.y));
    let p = textureLoad(position_tex, texel, 0);
    let n = textureLoad(normal_tex, texel, 0).xyz;
    let len2 = dot(n, n);
    let valid = p.w > 0.0 && len2 > 0.0;
    let v = p.xyz - params.eye;
    gb_position[i] = vec4f(p.xyz, select(0.0, 1.0, valid));
    gb_normal[i] = select(vec4f(0.0, 0.0, 0.0, DEPTH_NONE), vec4f(n / sqrt(len2), sqrt(dot(v, v))), valid);
    irradiance[i] = vec4f(0.0);
}
