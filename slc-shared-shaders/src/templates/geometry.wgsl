{% if ray_query %}
// Shadow rays as the adapter's ray queries through the occluders'
// acceleration structure (binding geo_tlas; Features::ray_query).
{% else %}
// Ray casting through the geometry BVH (bindings geo_nodes, geo_tris): one
// stack traversal serves closest-hit and shadow (any-hit) rays.
{% endif %}

{% if counters and kernel == "direct_light" %}
/// The counting variant's tallies of this invocation: shadow rays cast and
/// the BVH nodes they visited.
var<private> rays_cast: u32;
var<private> nodes_visited: u32;

{% endif %}
{% if ray_query %}
/// `true` when the ray `o + t·d`, `t ∈ (t_min, t_max)`, hits a triangle of
/// `geo_tlas` (any hit; triangles are opaque and two-sided, as `trace`'s).
fn ray_query_hits(o: vec3f, d: vec3f, t_min: f32, t_max: f32) -> bool {
    var rq: ray_query;
    let flags = RAY_FLAG_TERMINATE_ON_FIRST_HIT | RAY_FLAG_FORCE_OPAQUE;
    // Cull mask: every bit, so every instance whatever its mask.
    rayQueryInitialize(&rq, geo_tlas, RayDesc(flags, ~0u, t_min, t_max, o, d));
    rayQueryProceed(&rq);
    return rayQueryGetCommittedIntersection(&rq).kind != RAY_QUERY_INTERSECTION_NONE;
}
{% else %}
/// A ray hit: distance `t` and triangle index (in `geo_tris`), or
/// `tri = NO_LIGHT` for a miss.
struct GeoHit {
    t: f32,
    tri: u32,
}

/// The closest triangle hit along `o + t·d` (unit `d`) with
/// `t ∈ (t_min, t_max)`, or with `any_hit` the first one found.
fn trace(o: vec3f, d: vec3f, t_min: f32, t_max: f32, any_hit: bool) -> GeoHit {
    var hit: GeoHit;
    hit.t = t_max;
    hit.tri = NO_LIGHT;
    if arrayLength(&geo_nodes) == 0u {
        return hit;
    }
    let inv_d = ray_inverse3(d);
    var stack: array<u32, 64>;
    var sp = 0u;
    var node = 0u;
    loop {
        let n = geo_nodes[node];
{% if counters and kernel == "direct_light" %}
        nodes_visited += 1u;
{% endif %}
        if ray_aabb(o, inv_d, n.bmin, n.bmax, hit.t) >= 0.0 {
            if n.count > 0u {
                for (var i = n.first; i < n.first + n.count; i++) {
                    let t = geo_tris[i];
                    let th = ray_triangle(o, d, t.v0, t.v1, t.v2, t_min, hit.t);
                    if th > 0.0 {
                        hit.t = th;
                        hit.tri = i;
                        if any_hit {
                            return hit;
                        }
                    }
                }
            } else {
                if sp < 64u {
                    stack[sp] = n.first + 1u;
                    sp += 1u;
                }
                node = n.first;
                continue;
            }
        }
        if sp == 0u {
            break;
        }
        sp -= 1u;
        node = stack[sp];
    }
    return hit;
}
{% endif %}

/// `true` when the open segment from `a` to `b` hits a triangle (a relative
/// epsilon keeps the end points' own surfaces out).
fn occluded(a: vec3f, b: vec3f) -> bool {
    let dv = b - a;
    let len = length(dv);
    if len <= 0.0 {
        return false;
    }
    let eps = shadow_margin(len);
{% if counters and kernel == "direct_light" %}
    rays_cast += 1u;
{% endif %}
{% if ray_query %}
    return ray_query_hits(a, dv / len, eps, len - eps);
{% else %}
    return trace(a, dv / len, eps, len - eps, true).tri != NO_LIGHT;
{% endif %}
}
