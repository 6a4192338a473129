{% include "header.wgsl" %}
// Cross-bilateral denoise of the VPL irradiance over the {{ period }}×{{ period }}
// interleaving window (one pixel of every VPL subset), weighted by the
// core's bilateral_weight on normal and depth, widened to twice the period
// where a VPL subset is missing from the window; the CPU's filter, per pixel.
//
// The workgroup first decodes its tile and the widened window's apron
// (SIDE × SIDE pixels) into workgroup memory, once per pixel: the windows
// then read normal, depth and irradiance from there, not from the G-buffer
// (an unprojection and three loads per neighbour, 64 to 256 neighbours per
// pixel at period 8). Same neighbours, same order, same sums as reading in
// place.

{{ bindings }}
{% include "gbuffer_read.wgsl" %}

const PERIOD: u32 = {{ period }}u;
const TILE: u32 = {{ tile }}u;
/// Pixels the widened window reaches left of (and above) its pixel:
/// ⌊wide_window(P)/2⌋ = P.
const APRON: u32 = {{ period }}u;
/// Side of the decoded square: the tile and the widened window's reach
/// either side (P before, P − 1 after).
const SIDE: u32 = {{ tile }}u + 2u * {{ period }}u - 1u;

/// Per decoded pixel: unit normal (xyz) and eye distance (w; DEPTH_NONE
/// where there is no surface), and the irradiance's channels.
var<workgroup> wg_surface: array<vec4f, SIDE * SIDE>;
var<workgroup> wg_red: array<f32, SIDE * SIDE>;
var<workgroup> wg_green: array<f32, SIDE * SIDE>;
var<workgroup> wg_blue: array<f32, SIDE * SIDE>;

/// Weighted irradiance sum, total weight and the number of neighbours
/// heavier than COVER_WEIGHT over the `size × size` window around pixel
/// (x, y), for a pixel with normal `n` and depth `z`.
struct Window {
    sum: vec3f,
    weight: f32,
    covered: u32,
}

/// The window's sums from the decoded square whose first pixel is `origin`.
fn window_sum(x: u32, y: u32, size: u32, origin: vec2u, n: vec3f, z: f32, inv: f32) -> Window {
    let x0 = window_start(x, size);
    let x1 = window_end(x, size, params.width);
    let y0 = window_start(y, size);
    let y1 = window_end(y, size, params.height);
    var win: Window;
    win.sum = vec3f(0.0);
    win.weight = 0.0;
    win.covered = 0u;
    for (var yy = y0; yy < y1; yy++) {
        for (var xx = x0; xx < x1; xx++) {
            let k = (yy - origin.y) * SIDE + (xx - origin.x);
            let s = wg_surface[k];
            let wgt = bilateral_weight(n, s.xyz, z, s.w, inv);
            win.sum += vec3f(wg_red[k], wg_green[k], wg_blue[k]) * wgt;
            win.weight += wgt;
            win.covered += select(0u, 1u, wgt > COVER_WEIGHT);
        }
    }
    return win;
}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(
    @builtin(global_invocation_id) gid: vec3u,
    @builtin(workgroup_id) wid: vec3u,
    @builtin(local_invocation_id) local: vec3u,
    @builtin(local_invocation_index) lid: u32,
) {
    let w = params.width;
    let h = params.height;
    // The square's first pixel, APRON before the tile (it may lie outside
    // the image: those entries are never read, as windows stop at its edges).
    let corner = vec2i(wid.xy * TILE) - vec2i(i32(APRON));
    for (var k = lid; k < SIDE * SIDE; k += TILE * TILE) {
        let p = corner + vec2i(i32(k % SIDE), i32(k / SIDE));
        var s = vec4f(0.0, 0.0, 0.0, DEPTH_NONE);
        var e = vec3f(0.0);
        if p.x >= 0 && p.y >= 0 && u32(p.x) < w && u32(p.y) < h {
            let j = u32(p.y) * w + u32(p.x);
            s = gbuffer_at(j).normal;
            e = irradiance[j].xyz;
        }
        wg_surface[k] = s;
        wg_red[k] = e.x;
        wg_green[k] = e.y;
        wg_blue[k] = e.z;
    }
    workgroupBarrier();
    if gid.x >= w || gid.y >= h {
        return;
    }
    let i = gid.y * w + gid.x;
    let e = irradiance[i];
    // `corner` as u32 (wrapping below 0): `xx - origin.x` wraps back.
    let origin = vec2u(corner);
    let own = wg_surface[(local.y + APRON) * SIDE + local.x + APRON];
    if own.w >= DEPTH_NONE {
        filtered[i] = vec4f(0.0, 0.0, 0.0, e.w);
        return;
    }
    let n = own.xyz;
    let z = own.w;
    let inv = inv_sigma_z(z);
    var s = window_sum(gid.x, gid.y, PERIOD, origin, n, z, inv);
    // A VPL subset is missing (an edge, a corner, the border): the doubled
    // window brings it in (the CPU filter's rule).
    if misses_subset(s.covered, PERIOD) {
        s = window_sum(gid.x, gid.y, wide_window(PERIOD), origin, n, z, inv);
    }
    filtered[i] = vec4f(filtered_irradiance(e.xyz, s.sum, s.weight), e.w);
}
