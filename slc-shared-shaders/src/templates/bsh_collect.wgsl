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
