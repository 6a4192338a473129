{% include "header.wgsl" %}
// The indirect irradiance (rgb, lights kept in w) into an engine's storage
// texture ({{ out_format }}); zero where the G-buffer has no surface.

@group(0) @binding(0) var<uniform> params: ImageParams;
@group(0) @binding(1) var<storage, read> gb_position: array<vec4f>;
@group(0) @binding(2) var<storage, read> irradiance: array<vec4f>;
@group(0) @binding(3) var out_tex: texture_storage_2d<{{ out_format }}, write>;
// Declared because the shared library reads it; unused here, so not bound.
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= params.width || gid.y >= params.height {
        return;
    }
    let i = gid.y * params.width + gid.x;
    let e = select(vec4f(0.0), irradiance[i], gb_position[i].w > 0.0);
    textureStore(out_tex, vec2i(i32(gid.x), i32(gid.y)), e);
}
