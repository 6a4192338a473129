struct TailParams {
    stage: u32,
    count: u32,
    k: u32,
    tree: u32,
}

struct BshNode {
    center: vec3<f32>,
    radius: f32,
    child: u32,
    next: u32,
    light: u32,
    extent: f32,
}

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const COUNT_TILES: u32 = 0u;
const COUNT_GROUP_TESTS: u32 = 1u;
const COUNT_CLUSTER_TESTS: u32 = 2u;
const COUNT_SPHERE_TESTS: u32 = 3u;
const COUNT_TESTED: u32 = 4u;
const COUNT_KEPT: u32 = 5u;
const COUNT_PIXELS: u32 = 6u;
const COUNT_FIELDS: u32 = 7u;
const DIRECT_COUNT_PIXELS: u32 = 0u;
const DIRECT_COUNT_CANDIDATES: u32 = 1u;
const DIRECT_COUNT_EVALUATIONS: u32 = 2u;
const DIRECT_COUNT_RAYS: u32 = 3u;
const DIRECT_COUNT_NODES: u32 = 4u;
const DIRECT_COUNT_FIELDS: u32 = 5u;
const MAP_CAMERA: u32 = 0u;
const MAP_PERSPECTIVE: u32 = 1u;
const MAP_ORTHOGRAPHIC: u32 = 2u;
const XI_STEP: f32 = 0.000000059604645f;
const PICK_STREAM: u32 = 2654435769u;
const TWO_PI: f32 = 6.2831855f;
const UNRANGED: f32 = 100000000000000000000000000000000000000f;
const CULL_RADIUS_SCALE: f32 = 1.000001f;
const SPHERE_PAD: f32 = 0.00000047683716f;
const SPHERE_HUGE: f32 = 340282350000000000000000000000000000000f;
const SPHERE_PAD_ABS: f32 = 0.000000000000000001f;
const CLUSTER: u32 = 64u;
const GROUP_SIDE: u32 = 8u;
const INV_PI: f32 = 0.31830987f;
const MIN_D2_: f32 = 0.000000000001f;
const MAX_INTENSITY: f32 = 72057594000000000f;
const BSH_NONE: u32 = 4294967295u;
const BSH_TAIL: u32 = 2147483648u;
const BSH_TAIL_BINS: u32 = 1024u;
const BSH_TAIL_MAX: u32 = 64u;
const RESERVOIR_FULL: u32 = 4294967295u;
const GGX_ALPHA_MIN: f32 = 0.001f;
const RANGE_SCALE_MAX: f32 = 64f;
const LIGHT_BVH_LEAF: u32 = 4294967295u;
const ONE_MINUS_EPSILON: f32 = 0.99999994f;
const F32_MAX: f32 = 340282350000000000000000000000000000000f;
const DEPTH_NONE: f32 = 1000000000000000000000000000000f;
const DEPTH_SIGMA: f32 = 0.05f;
const COVER_WEIGHT: f32 = 0.1f;
const ROULETTE_DEPTH: u32 = 2u;
const TEMPORAL_MAX_HISTORY: f32 = 32f;
const TEMPORAL_DEPTH_TOLERANCE: f32 = 0.01f;
const TEMPORAL_MOTION_DEPTH_TOLERANCE: f32 = 0.05f;
const TEMPORAL_NORMAL_COS: f32 = 0.9f;
const TEMPORAL_MIN_MOMENTS: f32 = 8f;
const TEMPORAL_CHANGED_HISTORY: f32 = 1f;
const TEMPORAL_CHANGE_LOW: f32 = 4f;
const TEMPORAL_CHANGE_HIGH: f32 = 8f;
const TEMPORAL_MIN_WEIGHT: f32 = 0.01f;
const BSH: u32 = 0u;
const BSH_TILE_DEPTH: u32 = 8u;
const BSH_TILE_SUBTREES: u32 = 256u;
const HIST: u32 = 0u;

@group(0) @binding(0) 
var<uniform> params: TailParams;
@group(0) @binding(1) 
var<storage> bounds: array<vec4<f32>>;
@group(0) @binding(2) 
var<storage> r2_2: array<f32>;
@group(0) @binding(3) 
var<storage, read_write> tail_hist: array<atomic<u32>>;
@group(0) @binding(4) 
var<storage, read_write> tail: array<atomic<u32>>;
@group(0) @binding(5) 
var<storage, read_write> bsh_nodes: array<BshNode>;

fn f32_to_bits(x: f32) -> u32 {
    return bitcast<u32>(x);
}

fn range_radius(extent: f32, r2_: f32) -> f32 {
    return (extent + sqrt(r2_));
}

fn bsh_tail_key(radius: f32) -> u32 {
    let _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
}

fn bsh_node(nodes: u32, i: u32) -> BshNode {
    let _e4 = bsh_nodes[i];
    return _e4;
}

fn bsh_in_tail(extent_1: f32, r2_1: f32, cut: u32) -> bool {
    let _e3 = range_radius(extent_1, r2_1);
    let _e4 = bsh_tail_key(_e3);
    return (_e4 >= cut);
}

fn bsh_rightmost_next(nodes_1: u32, i_1: u32) -> u32 {
    let _e2 = bsh_node(nodes_1, i_1);
    if (_e2.child == BSH_NONE) {
        return BSH_NONE;
    }
    let _e8 = bsh_node(nodes_1, _e2.child);
    return _e8.next;
}

fn bsh_tail_bin(hist: u32, b_1: u32) -> u32 {
    let _e4 = atomicLoad((&tail_hist[b_1]));
    return _e4;
}

fn bsh_tail_cut(hist_1: u32, k: u32) -> u32 {
    var b_2: u32 = BSH_TAIL_BINS;
    var sum: u32 = 0u;
    var local_2: bool;

    loop {
        let _e6 = b_2;
        if (_e6 > 0u) {
            let _e11 = sum;
            let _e12 = b_2;
            let _e15 = bsh_tail_bin(hist_1, (_e12 - 1u));
            local_2 = ((_e11 + _e15) <= k);
        } else {
            local_2 = false;
        }
        let _e19 = local_2;
        if _e19 {
        } else {
            break;
        }
        {
            let _e20 = sum;
            let _e21 = b_2;
            let _e24 = bsh_tail_bin(hist_1, (_e21 - 1u));
            sum = (_e20 + _e24);
            let _e26 = b_2;
            b_2 = (_e26 - 1u);
        }
    }
    let _e29 = b_2;
    return _e29;
}

fn tail_light(s_1: u32) -> u32 {
    let _e5 = atomicLoad((&tail[(2u + s_1)]));
    return _e5;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var local: bool;
    var b: u32;
    var a: u32 = 1u;
    var c: u32;
    var local_1: bool;
    var s: u32 = 0u;
    var n: u32 = 0u;

    let i_2 = gid.x;
    let _e4 = params.stage;
    switch _e4 {
        case 0u: {
            let _e7 = params.count;
            if (i_2 < _e7) {
                let _e13 = bounds[i_2].w;
                let _e16 = r2_2[i_2];
                let _e17 = range_radius(_e13, _e16);
                let _e18 = bsh_tail_key(_e17);
                let _e21 = atomicAdd((&tail_hist[_e18]), 1u);
                return;
            } else {
                return;
            }
        }
        case 1u: {
            if (i_2 == 0u) {
                let _e29 = params.k;
                let _e30 = bsh_tail_cut(HIST, _e29);
                atomicStore((&tail[0]), _e30);
                atomicStore((&tail[1]), 0u);
                return;
            } else {
                return;
            }
        }
        case 2u: {
            let _e36 = params.count;
            if (i_2 < _e36) {
                let _e43 = bounds[i_2].w;
                let _e46 = r2_2[i_2];
                let _e49 = atomicLoad((&tail[0]));
                let _e50 = bsh_in_tail(_e43, _e46, _e49);
                local = _e50;
            } else {
                local = false;
            }
            let _e52 = local;
            if _e52 {
                let _e58 = atomicAdd((&tail[1]), 1u);
                atomicStore((&tail[(2u + _e58)]), i_2);
                return;
            } else {
                return;
            }
        }
        default: {
            b = i_2;
            loop {
                let _e62 = b;
                if (_e62 < BSH_TAIL_BINS) {
                } else {
                    break;
                }
                {
                    let _e66 = b;
                    atomicStore((&tail_hist[_e66]), 0u);
                }
                continuing {
                    let _e69 = b;
                    b = (_e69 + 64u);
                }
            }
            if (i_2 != 0u) {
                return;
            }
            let count = atomicLoad((&tail[1]));
            loop {
                let _e79 = a;
                if (_e79 < count) {
                } else {
                    break;
                }
                {
                    let _e81 = a;
                    let _e82 = tail_light(_e81);
                    let _e83 = a;
                    c = _e83;
                    loop {
                        let _e85 = c;
                        if (_e85 > 0u) {
                            let _e90 = c;
                            let _e93 = tail_light((_e90 - 1u));
                            local_1 = (_e93 > _e82);
                        } else {
                            local_1 = false;
                        }
                        let _e96 = local_1;
                        if _e96 {
                        } else {
                            break;
                        }
                        {
                            let _e99 = c;
                            let _e102 = c;
                            let _e105 = tail_light((_e102 - 1u));
                            atomicStore((&tail[(2u + _e99)]), _e105);
                            let _e106 = c;
                            c = (_e106 - 1u);
                        }
                    }
                    let _e111 = c;
                    atomicStore((&tail[(2u + _e111)]), _e82);
                }
                continuing {
                    let _e115 = a;
                    a = (_e115 + 1u);
                }
            }
            loop {
                let _e119 = s;
                if (_e119 < count) {
                } else {
                    break;
                }
                {
                    let _e121 = s;
                    let _e122 = tail_light(_e121);
                    let b_3 = bounds[_e122];
                    let _e128 = params.tree;
                    let _e129 = s;
                    let _e134 = s;
                    let next = select(((_e128 + _e129) + 1u), BSH_NONE, ((_e134 + 1u) == count));
                    let _e142 = params.tree;
                    let _e143 = s;
                    let _e150 = r2_2[_e122];
                    let _e151 = range_radius(b_3.w, _e150);
                    bsh_nodes[(_e142 + _e143)] = BshNode(b_3.xyz, _e151, BSH_NONE, next, _e122, b_3.w);
                }
                continuing {
                    let _e156 = s;
                    s = (_e156 + 1u);
                }
            }
            let _e160 = params.tree;
            let first = select(_e160, BSH_NONE, (count == 0u));
            loop {
                let _e167 = n;
                if (_e167 != BSH_NONE) {
                } else {
                    break;
                }
                {
                    let _e171 = n;
                    bsh_nodes[_e171].next = first;
                }
                continuing {
                    let _e175 = n;
                    let _e176 = bsh_rightmost_next(BSH, _e175);
                    n = _e176;
                }
            }
            return;
        }
    }
}
