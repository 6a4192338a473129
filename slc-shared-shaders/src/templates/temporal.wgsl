{% include "header.wgsl" %}
// Temporal accumulation of a per-pixel signal (slc-core's temporal module,
// as slc-cpu's Temporal runs it): the history reprojected with the previous
// view-projection{% if motion %} (here: the engine's motion vectors){% endif %}, its four bilinear taps kept where they saw this surface,
// the change test and the moving average; the result into out_tex
// ({{ out_format }}) and the next frame's history.

{{ bindings }}
{% include "gbuffer_read.wgsl" %}

@compute @workgroup_size({{ tile }}, {{ tile }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    if gid.x >= view.width || gid.y >= view.height {
        return;
    }
    let texel = vec2i(i32(gid.x), i32(gid.y));
    let g = gbuffer_at(gid.y * view.width + gid.x);
    let c = textureLoad(signal_tex, texel, 0).xyz;
    if g.position.w <= 0.0 {
        textureStore(out_tex, texel, vec4f(c, 0.0));
        textureStore(next_value, texel, vec4f(c, 0.0));
        textureStore(next_noise, texel, vec4f(0.0));
        textureStore(next_surface, texel, vec4f(0.0));
        return;
    }
    let p = g.position.xyz;
    let n = g.normal.xyz;
    var hv = vec4f(0.0);
    var hn = vec4f(0.0);
{% if motion %}
    let motion = textureLoad(motion_tex, texel, 0).xy;
    let q = reproject_motion(f32(gid.x), f32(gid.y), motion.x, motion.y, f32(view.width), f32(view.height));
{% else %}
    let q = reproject(params.c0, params.c1, params.c2, params.c3, p, f32(view.width), f32(view.height));
{% endif %}
    if params.has_history == 1u {
{% if motion %}
        let d = length(p - view.eye);
{% else %}
        let d = length(p - params.prev_eye);
{% endif %}
        var v = vec4f(0.0);
        var m = vec4f(0.0);
        var weight = 0.0;
        for (var k = 0u; k < 4u; k++) {
            let tap = history_tap(q, k, f32(view.width), f32(view.height));
            if tap.w > 0.0 {
                let t = vec2i(i32(tap.x), i32(tap.y));
                let tv = textureLoad(hist_value, t, 0);
                let ts = textureLoad(hist_surface, t, 0);
                let tn = textureLoad(hist_noise, t, 0);
{% if motion %}
                let w = history_tap_weight_motion(tap.z, n, ts.xyz, d, tn.z, tv.w);
{% else %}
                let w = history_tap_weight(tap.z, n, ts.xyz, p, ts.w, d, tv.w);
{% endif %}
                v += tv * w;
                m += tn * w;
                weight += w;
            }
        }
        hv = history_mean(v, weight);
        hn = history_mean(m, weight);
    }
    let value = temporal_color(c, hv, hn.y, hn.x, params.max_history);
    textureStore(out_tex, texel, value);
    textureStore(next_value, texel, value);
    textureStore(next_noise, texel, temporal_moments(c, hn.x, hn.y, hv.w, value.w, length(p - view.eye)));
    textureStore(next_surface, texel, vec4f(n, dot(n, p)));
}
