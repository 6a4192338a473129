// The talk's stackless BSH traversal ("Improving tree traversal & shading")
// feeding a k-slot reservoir (Algorithm R): no shading inside the loop, and
// storage and the later shading loop bounded by K.

const K: u32 = {{ k }}u;

/// Lights held by the reservoir and the number of in-range lights seen.
struct Picks {
    light: array<u32, K>,
    n: u32,
}

/// Lights whose range sphere contains `x`, streamed through the reservoir;
/// `seed` drives the reservoir's random choices.
fn bsh_collect(x: vec3f, seed: u32) -> Picks {
    var picks: Picks;
    picks.n = 0u;
    var h = seed;
    var i = select(BSH_NONE, 0u, arrayLength(&bsh_nodes) > 0u);
    loop {
        if i == BSH_NONE {
            break;
        }
        let node = bsh_nodes[i];
        if sphere_contains_point(node.center, node.radius, x) {
            if node.child == BSH_NONE {
                if picks.n < 4294967295u {
                    picks.n += 1u;
                    h = pcg_hash(h);
                    let hi = h;
                    h = pcg_hash(h);
                    let slot = reservoir_slot(picks.n, K, hi, h);
                    if slot < K {
                        picks.light[slot] = node.light;
                    }
                }
                i = node.next;
            } else {
                i = node.child;
            }
        } else {
            i = node.next;
        }
    }
    return picks;
}

/// One reservoir pick connected to the shading point `x` (normal `n`).
struct Connection {
    /// Irradiance the pick adds at `x`, with the 1/p and reservoir weights
    /// (zero when the RR test at the sampled point fails, the light is
    /// behind `x`, or the shadow ray is blocked).
    e: vec3f,
    /// The sampled point on the light.
    y: vec3f,
    /// Cosine at `x` toward `y`.
    cos_x: f32,
}

/// Samples pick `li` at `(u1, u2)`, applies the RR test with the light's own
/// range at the sampled point's distance, casts the shadow ray (offset `eps`
/// along `n`) and weights by `1/p` and the reservoir weight `w_res`.
fn connect(li: u32, x: vec3f, n: vec3f, w_res: f32, u1: f32, u2: f32, eps: f32) -> Connection {
    var c: Connection;
    c.e = vec3f(0.0);
    let l = lights[li];
    c.y = light_point(l, u1, u2);
    let v = x - c.y;
    let d2 = dot(v, v);
    if !slc_keep(r2[li], d2) || d2 <= 0.0 {
        return c;
    }
    let w = v / sqrt(d2);
    c.cos_x = -dot(n, w);
    if c.cos_x <= 0.0 || occluded(x + n * eps, c.y) {
        return c;
    }
    c.e = light_intensity(l, w) * (c.cos_x * inverse_square(d2) * slc_weight(rt2[li], d2) * w_res);
    return c;
}
