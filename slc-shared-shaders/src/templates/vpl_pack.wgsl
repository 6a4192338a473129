{% include "header.wgsl" %}
// VPLs from {% if source == "rsm" %}a reflective shadow map (one per texel){% else %}an engine's VPL buffer{% endif %} into vpl_tiled's light
// buffer: subset after subset ({{ period }}x{{ period }} interleaving{% if source == "rsm" %}, each subset's image in map
// order: interleave_slot{% else %}: interleave_slot_linear{% endif %}), flux scaled by the period squared, each VPL's ξ id,
// r_t² (SLC) or the fixed r² (clamp). Invocation q takes {% if source == "rsm" %}texel
// (map_x(q), map_y(q)) of the RSM's map order{% else %}record q{% endif %} and writes where its VPL went into
// near_slots[q]: the near field's clusters (vpl_near) are runs of 64.
// Slots no VPL fills (a subset's padding) keep the zero flux the buffer was
// created with.

const P: u32 = {{ period }}u;

{{ bindings }}

@compute @workgroup_size(CLUSTER)
fn main(@builtin(global_invocation_id) gid: vec3u) {
    let q = gid.x;
    if q >= params.count {
        return;
    }
{% if source == "rsm" %}
    let tx = map_x(q, params.size);
    let ty = map_y(q, params.size);
    let i = ty * params.size + tx;
    let texel = vec2i(i32(tx), i32(ty));
    var p = textureLoad(rsm_position, texel, 0).xyz;
    var normal = textureLoad(rsm_normal, texel, 0).xyz;
    var flux = textureLoad(rsm_flux, texel, 0).xyz;
    let slot = interleave_slot(tx, ty, params.size, P);
{% else %}
    let i = q;
    let r = records[i];
    var p = r.position;
    var normal = r.normal;
    var flux = r.flux;
    let slot = interleave_slot_linear(i, params.per_subset, P);
{% endif %}
    // A texel or record no light constructor would accept (NaN, ∞,
    // negative or too bright) is skipped: zero flux at the origin.
    if !vpl_record_ok(p, normal, flux) {
        p = vec3f(0.0);
        normal = vec3f(0.0);
        flux = vec3f(0.0);
    }
    flux *= params.scale;
    lights[slot] = GpuLight(p, LIGHT_VPL, normal, 0.0, vec3f(0.0), 0.0, flux, 0u);
    ids[slot] = i;
    let slc = params.slc != 0u;
    rt2[slot] = select(0.0, vpl_rt2(flux, params.exposure, params.error_bound, params.mode), slc);
    r2[slot] = select(params.fixed_r2, 0.0, slc);
    near_slots[q] = slot;
}
