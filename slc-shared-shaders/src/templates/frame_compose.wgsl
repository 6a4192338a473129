{% include "header.wgsl" %}
// The VPL frame's composition into the HDR target ({{ out_format }}):
// `L_e + ρ/π · (E_direct + E_indirect)` per G-buffer pixel (material from
// the normal's w), zero where no surface; alpha 1.

@group(0) @binding(0) var<uniform> image: ImageParams;
@group(0) @binding(1) var position_tex: texture_2d<f32>;
@group(0) @binding(2) var normal_tex: texture_2d<f32>;
@group(0) @binding(3) var indirect_tex: texture_2d<f32>;
@group(0) @binding(4) var<storage, read> direct: array<vec4f>;
@group(0) @binding(5) var<storage, read> materials: array<GpuMaterial>;
@group(0) @binding(6) var out_tex: texture_storage_2d<{{ out_format }}, write>;
// Declared because the shared library reads it; unused here, so not bound.
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= image.width || gid.y >= image.height {
        return;
    }
    let i = gid.y * image.width + gid.x;
    let texel = vec2i(i32(gid.x), i32(gid.y));
    var radiance = vec3f(0.0);
    if textureLoad(position_tex, texel, 0).w > 0.0 {
        let m = materials[u32(textureLoad(normal_tex, texel, 0).w)];
        radiance = diffuse_radiance(m.albedo, m.emission, direct[i].xyz + textureLoad(indirect_tex, texel, 0).xyz);
    }
    textureStore(out_tex, texel, vec4f(radiance, 1.0));
}
