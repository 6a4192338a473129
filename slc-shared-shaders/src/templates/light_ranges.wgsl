{% include "header.wgsl" %}
// Per record of the direct pass: every light's threshold range r_t² (from
// its peak, ε and the exposure with stochastic culling; +∞ otherwise) and
// random range r² (r_t²/(1−ξ) with ξ = xi_for(seed, frame, light), the CPU's
// numbers; a clamp range R² or +∞ otherwise), computed on the device from the
// record's own parameters just before the record shades with them.
{{ engine }}

{{ bindings }}

@compute @workgroup_size({{ wg }})
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let i = gid.x;
    if i >= params.light_count {
        return;
    }
    let rt = record_rt2(peaks[i].xyz, params.slc, params.mode, params.exposure, params.error_bound, params.unculled);
    rt2[i] = rt;
    r2[i] = record_r2(rt, params.slc, params.fixed_r2, xi_for(params.seed, params.frame, i));
}
