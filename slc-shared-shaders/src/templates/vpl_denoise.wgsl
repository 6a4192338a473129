{% include "header.wgsl" %}
// Cross-bilateral denoise of the VPL irradiance over the {{ period }}×{{ period }}
// interleaving window (one pixel of every VPL subset), weighted by the
// core's bilateral_weight on normal and depth, widened to twice the period
// where a VPL subset is missing from the window; the CPU's filter, per pixel.
// Normal and depth come from vpl_tiled's guide: the G-buffer as gbuffer_at
// reads it (unit normal and distance from the eye; a zero normal and
// DEPTH_NONE where no surface is), one texel per tap.

{{ bindings }}

const PERIOD: u32 = {{ period }}u;


/// Weighted irradiance sum, total weight and the number of neighbours
/// heavier than COVER_WEIGHT over the `size × size` window around pixel
/// (x, y), for a pixel with normal `n` and depth `z`.
struct Window {
    sum: vec3f,
    weight: f32,
    covered: u32,
}

fn window_sum(x: u32, y: u32, size: u32, n: vec3f, z: f32, inv: f32) -> Window {
    let w = params.width;
    let h = params.height;
    let x0 = window_start(x, size);
    let x1 = window_end(x, size, w);
    let y0 = window_start(y, size);
    let y1 = window_end(y, size, h);
    var win: Window;
    win.sum = vec3f(0.0);
    win.weight = 0.0;
    win.covered = 0u;
    for (var yy = y0; yy < y1; yy++) {
        for (var xx = x0; xx < x1; xx++) {
            let j = yy * w + xx;
            // The neighbour's surface (DEPTH_NONE where none is).
            let g = guide[j];
            let wgt = bilateral_weight(n, g.xyz, z, g.w, inv);
            win.sum += irradiance[j].xyz * wgt;
            win.weight += wgt;
            win.covered += select(0u, 1u, wgt > COVER_WEIGHT);
        }
    }
    return win;
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
    let g = guide[i];
    // No surface: a zero normal.
    if all(g.xyz == vec3f(0.0)) {
        filtered[i] = vec4f(0.0, 0.0, 0.0, e.w);
        return;
    }
    let n = g.xyz;
    let z = g.w;
    let inv = inv_sigma_z(z);
    var s = window_sum(gid.x, gid.y, PERIOD, n, z, inv);
    // A VPL subset is missing (an edge, a corner, the border): the doubled
    // window brings it in (the CPU filter's rule).
    if misses_subset(s.covered, PERIOD) {
        s = window_sum(gid.x, gid.y, wide_window(PERIOD), n, z, inv);
    }
    filtered[i] = vec4f(filtered_irradiance(e.xyz, s.sum, s.weight), e.w);
}
