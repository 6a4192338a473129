{% include "header.wgsl" %}
// Cross-bilateral denoise of the VPL irradiance over the {{ period }}×{{ period }}
// interleaving window (one pixel of every VPL subset), weighted by the
// core's bilateral_weight on normal and depth; the CPU's filter, per pixel.

@group(0) @binding(0) var<uniform> params: VplParams;
@group(0) @binding(1) var<storage, read> gb_position: array<vec4f>;
@group(0) @binding(2) var<storage, read> gb_normal: array<vec4f>;
@group(0) @binding(3) var<storage, read> irradiance: array<vec4f>;
@group(0) @binding(4) var<storage, read_write> filtered: array<vec4f>;
@group(1) @binding(0) var<storage, read> slc_table: array<f32>;

const PERIOD: u32 = {{ period }}u;

/// Depth of pixel `i` (`gb_normal.w`), 1e30 where there is no surface.
fn depth_of(i: u32) -> f32 {
    return select(1e30, gb_normal[i].w, gb_position[i].w > 0.0);
}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let w = params.width;
    let h = params.height;
    if gid.x >= w || gid.y >= h {
        return;
    }
    let i = gid.y * w + gid.x;
    let e = irradiance[i];
    if gb_position[i].w <= 0.0 {
        filtered[i] = vec4f(0.0, 0.0, 0.0, e.w);
        return;
    }
    let n = gb_normal[i].xyz;
    let z = depth_of(i);
    let inv = 1.0 / (DEPTH_SIGMA * z);
    let half = PERIOD / 2u;
    let x0 = max(gid.x, half) - half;
    let x1 = min(gid.x + PERIOD - half, w);
    let y0 = max(gid.y, half) - half;
    let y1 = min(gid.y + PERIOD - half, h);
    var sum = vec3f(0.0);
    var sw = 0.0;
    for (var y = y0; y < y1; y++) {
        for (var x = x0; x < x1; x++) {
            let j = y * w + x;
            let wgt = bilateral_weight(n, gb_normal[j].xyz, z, depth_of(j), inv);
            sum += irradiance[j].xyz * wgt;
            sw += wgt;
        }
    }
    filtered[i] = vec4f(select(e.xyz, sum / sw, sw > 0.0), e.w);
}
