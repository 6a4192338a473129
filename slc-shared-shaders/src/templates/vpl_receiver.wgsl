// The receiver an invocation of vpl_tiled or vpl_near shades, and its sums
// (module-scope, so cluster_cull.wgsl's shade_list reaches them): the
// pixel's surface from the G-buffer, read once by load_receiver, which also
// counts the shaded pixel in the counting variant and returns the box of
// the workgroup's surfaces (uniform: it decides the culling).

var<private> pos: vec3f;
/// Unit normal; zero where no surface is.
var<private> nrm: vec3f;
/// Distance from the eye (DEPTH_NONE where no surface is): with `nrm`, the
/// denoise's guide (vpl_tiled writes it).
var<private> eye_distance: f32;
var<private> valid: bool;
var<private> e: vec3f;
var<private> kept: u32;
{% if glossy %}
var<private> s: vec3f;
var<private> g: Glossy;
{% endif %}

/// Loads pixel `pix` (when `inside` the image) into the receiver and
/// returns the workgroup's box of surfaces; every invocation calls it.
fn load_receiver(li: u32, pix: u32, inside: bool) -> WorkgroupBox {
    var p = vec4f(0.0);
    eye_distance = DEPTH_NONE;
    if inside {
        let gb = gbuffer_at(pix);
        p = gb.position;
        nrm = gb.normal.xyz;
        eye_distance = gb.normal.w;
    }
    pos = p.xyz;
    valid = inside && p.w > 0.0;
{% if glossy %}
    if valid {
        g = glossy_at(pix, pos);
    }
{% endif %}
{% if counters %}
    counts_begin(li);
    if valid {
        count_one(COUNT_PIXELS);
    }
{% endif %}
    return workgroup_box(li, pos, valid);
}

{% if counters %}
/// Counts the receiver's kept lights and adds the workgroup's counts to
/// `counters`; every invocation calls it last.
fn count_receiver(li: u32) {
    if valid {
        count_add(COUNT_KEPT, kept);
    }
    counts_end(li);
}
{% endif %}
