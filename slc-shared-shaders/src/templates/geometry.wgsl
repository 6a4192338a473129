// Shadow rays through the geometry BVH (bindings geo_nodes, geo_tris).

/// `true` when the open segment from `a` to `b` hits a triangle.
fn occluded(a: vec3f, b: vec3f) -> bool {
    let dv = b - a;
    let len = length(dv);
    if len <= 0.0 || arrayLength(&geo_nodes) == 0u {
        return false;
    }
    let d = dv / len;
    // A zero direction component would divide by zero: nudge it.
    let inv_d = 1.0 / select(d, vec3f(1e-30), abs(d) < vec3f(1e-30));
    let eps = 1e-4 * len;
    let t_max = len - eps;
    var stack: array<u32, 64>;
    var sp = 0u;
    var node = 0u;
    loop {
        let n = geo_nodes[node];
        if ray_aabb(a, inv_d, n.bmin, n.bmax, t_max) >= 0.0 {
            if n.count > 0u {
                for (var i = n.first; i < n.first + n.count; i++) {
                    let t = geo_tris[i];
                    if ray_triangle(a, d, t.v0, t.v1, t.v2, eps, t_max) > 0.0 {
                        return true;
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
    return false;
}
