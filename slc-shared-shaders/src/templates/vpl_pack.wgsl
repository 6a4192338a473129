{% include "header.wgsl" %}
// VPLs from {% if source == "rsm" %}a reflective shadow map (one per texel){% else %}an engine's VPL buffer{% endif %} into vpl_tiled's light
// buffer: subset after subset ({{ period }}x{{ period }} interleaving), flux scaled by
// the period squared, each VPL's ξ id, r_t² (SLC) or the fixed r² (clamp).
// For the near field (vpl_near): workgroup b packs near block b ({% if source == "rsm" %}an 8x8
// patch of texels{% else %}64 consecutive records{% endif %}), writes where each of its VPLs went
// (near_slots, in near-block order) and the box of their positions.

const P: u32 = {{ period }}u;

{{ bindings }}

const BOX_THREADS: u32 = NEAR_BLOCK;
{% include "workgroup_box.wgsl" %}

@compute @workgroup_size(NEAR_BLOCK)
fn main(@builtin(global_invocation_id) gid: vec3u, @builtin(workgroup_id) wg: vec3u, @builtin(local_invocation_index) li: u32) {
    // Near-block order: VPL q of the dispatch.
    let q = gid.x;
    let inside = q < params.count;
    var position = vec3f(0.0);
    var lit = false;
    if inside {
{% if source == "rsm" %}
        let tx = near_block_tx(q, params.size);
        let ty = near_block_ty(q, params.size);
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
        position = p;
        flux *= params.scale;
        lights[slot] = GpuLight(position, LIGHT_VPL, normal, 0.0, vec3f(0.0), 0.0, flux, 0u);
        ids[slot] = i;
        let slc = params.slc != 0u;
        rt2[slot] = select(0.0, vpl_rt2(flux, params.exposure, params.error_bound, params.mode), slc);
        r2[slot] = select(params.fixed_r2, 0.0, slc);
        near_slots[q] = slot;
        lit = any(flux != vec3f(0.0));
    }
    let block = workgroup_box(li, position, lit);
    if li == 0u && inside {
        near_boxes[wg.x] = GpuNearBox(block.lo, 0.0, block.hi, 0.0);
    }
}
