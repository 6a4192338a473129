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
const GRID_HEADER: u32 = 32u;
const GRID_LEVELS_MAX: u32 = 8u;
const GRIDS_MAX: u32 = 3u;
const GRID_SORT_MOVES: u32 = 1024u;
const GRID_SORT_MAX: u32 = 1024u;
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
const XI_ROTATED: u32 = 2147483648u;
const XI_BITS_SHIFT: u32 = 26u;
const XI_INDEX_MASK: u32 = 67108863u;
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
const REUSE_TRUST_SCALE: f32 = 64f;
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
const BSH_TAIL_CHUNK: u32 = 32u;

@group(0) @binding(0) 
var<uniform> params: TailParams;
@group(0) @binding(1) 
var<storage> bounds: array<vec4<f32>>;
@group(0) @binding(2) 
var<storage> r2_3: array<f32>;
@group(0) @binding(3) 
var<storage, read_write> tail_hist: array<atomic<u32>>;
@group(0) @binding(4) 
var<storage, read_write> tail: array<atomic<u32>>;
@group(0) @binding(5) 
var<storage, read_write> bsh_nodes: array<BshNode>;
var<workgroup> wg_bins: array<u32, 1024>;
var<workgroup> wg_chunks: array<u32, 32>;

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
    var c_2: u32;

    let _e2 = bsh_node(nodes_1, i_1);
    if (_e2.child == BSH_NONE) {
        return BSH_NONE;
    }
    c_2 = _e2.child;
    loop {
        let _e9 = c_2;
        let _e10 = bsh_node(nodes_1, _e9);
        if (_e10.next != _e2.next) {
        } else {
            break;
        }
        {
            let _e14 = c_2;
            let _e15 = bsh_node(nodes_1, _e14);
            c_2 = _e15.next;
        }
    }
    let _e17 = c_2;
    return _e17;
}

fn bsh_tail_leaf(slot: BshNode, bound: vec4<f32>, r2_2: f32, li: u32, next: u32) -> BshNode {
    var leaf: BshNode;

    leaf = slot;
    leaf.center = vec3<f32>(bound.x, bound.y, bound.z);
    let _e13 = range_radius(bound.w, r2_2);
    leaf.radius = _e13;
    leaf.child = BSH_NONE;
    leaf.next = next;
    leaf.light = li;
    leaf.extent = bound.w;
    let _e20 = leaf;
    return _e20;
}

fn bsh_tail_bin(hist: u32, b_3: u32) -> u32 {
    let _e4 = wg_bins[b_3];
    return _e4;
}

fn bsh_tail_chunk(hist_1: u32, c_3: u32) -> u32 {
    let _e4 = wg_chunks[c_3];
    return _e4;
}

fn bsh_tail_cut(hist_2: u32, k: u32) -> u32 {
    var c_4: u32 = 32u;
    var sum_1: u32 = 0u;
    var local_2: bool;
    var b_4: u32;
    var local_3: bool;

    loop {
        let _e6 = c_4;
        if (_e6 > 0u) {
            let _e11 = sum_1;
            let _e12 = c_4;
            let _e15 = bsh_tail_chunk(hist_2, (_e12 - 1u));
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
            let _e20 = sum_1;
            let _e21 = c_4;
            let _e24 = bsh_tail_chunk(hist_2, (_e21 - 1u));
            sum_1 = (_e20 + _e24);
            let _e26 = c_4;
            c_4 = (_e26 - 1u);
        }
    }
    let _e29 = c_4;
    b_4 = (_e29 * BSH_TAIL_CHUNK);
    let _e33 = b_4;
    let _e34 = b_4;
    let end = (_e33 - min(_e34, BSH_TAIL_CHUNK));
    loop {
        let _e38 = b_4;
        if (_e38 > end) {
            let _e42 = sum_1;
            let _e43 = b_4;
            let _e46 = bsh_tail_bin(hist_2, (_e43 - 1u));
            local_3 = ((_e42 + _e46) <= k);
        } else {
            local_3 = false;
        }
        let _e50 = local_3;
        if _e50 {
        } else {
            break;
        }
        {
            let _e51 = sum_1;
            let _e52 = b_4;
            let _e55 = bsh_tail_bin(hist_2, (_e52 - 1u));
            sum_1 = (_e51 + _e55);
            let _e57 = b_4;
            b_4 = (_e57 - 1u);
        }
    }
    let _e60 = b_4;
    return _e60;
}

fn tail_light(s_1: u32) -> u32 {
    let _e5 = atomicLoad((&tail[(2u + s_1)]));
    return _e5;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var b: u32;
    var c: u32;
    var sum: u32;
    var b_1: u32;
    var local: bool;
    var b_2: u32;
    var a: u32 = 1u;
    var c_1: u32;
    var local_1: bool;
    var s: u32 = 0u;
    var n: u32 = 0u;

    let i_2 = gid.x;
    let _e4 = params.stage;
    if (_e4 == 1u) {
        b = i_2;
        loop {
            let _e8 = b;
            if (_e8 < BSH_TAIL_BINS) {
            } else {
                break;
            }
            {
                let _e12 = b;
                let _e15 = b;
                let _e17 = atomicLoad((&tail_hist[_e15]));
                wg_bins[_e12] = _e17;
            }
            continuing {
                let _e18 = b;
                b = (_e18 + 64u);
            }
        }
        workgroupBarrier();
        c = i_2;
        loop {
            let _e22 = c;
            if (_e22 < 32u) {
            } else {
                break;
            }
            {
                sum = 0u;
                b_1 = 0u;
                loop {
                    let _e29 = b_1;
                    if (_e29 < BSH_TAIL_CHUNK) {
                    } else {
                        break;
                    }
                    {
                        let _e32 = sum;
                        let _e34 = c;
                        let _e37 = b_1;
                        let _e40 = wg_bins[((_e34 * BSH_TAIL_CHUNK) + _e37)];
                        sum = (_e32 + _e40);
                    }
                    continuing {
                        let _e43 = b_1;
                        b_1 = (_e43 + 1u);
                    }
                }
                let _e46 = c;
                let _e48 = sum;
                wg_chunks[_e46] = _e48;
            }
            continuing {
                let _e49 = c;
                c = (_e49 + 64u);
            }
        }
        workgroupBarrier();
        if (i_2 == 0u) {
            let _e59 = params.k;
            let _e60 = bsh_tail_cut(HIST, _e59);
            atomicStore((&tail[0]), _e60);
            atomicStore((&tail[1]), 0u);
        }
        return;
    }
    let _e66 = params.stage;
    switch _e66 {
        case 0u: {
            let _e69 = params.count;
            if (i_2 < _e69) {
                let _e75 = bounds[i_2].w;
                let _e78 = r2_3[i_2];
                let _e79 = range_radius(_e75, _e78);
                let _e80 = bsh_tail_key(_e79);
                let _e83 = atomicAdd((&tail_hist[_e80]), 1u);
                return;
            } else {
                return;
            }
        }
        case 2u: {
            let _e86 = params.count;
            if (i_2 < _e86) {
                let _e93 = bounds[i_2].w;
                let _e96 = r2_3[i_2];
                let _e99 = atomicLoad((&tail[0]));
                let _e100 = bsh_in_tail(_e93, _e96, _e99);
                local = _e100;
            } else {
                local = false;
            }
            let _e102 = local;
            if _e102 {
                let _e108 = atomicAdd((&tail[1]), 1u);
                atomicStore((&tail[(2u + _e108)]), i_2);
                return;
            } else {
                return;
            }
        }
        default: {
            b_2 = i_2;
            loop {
                let _e112 = b_2;
                if (_e112 < BSH_TAIL_BINS) {
                } else {
                    break;
                }
                {
                    let _e116 = b_2;
                    atomicStore((&tail_hist[_e116]), 0u);
                }
                continuing {
                    let _e119 = b_2;
                    b_2 = (_e119 + 64u);
                }
            }
            if (i_2 != 0u) {
                return;
            }
            let count = atomicLoad((&tail[1]));
            loop {
                let _e129 = a;
                if (_e129 < count) {
                } else {
                    break;
                }
                {
                    let _e131 = a;
                    let _e132 = tail_light(_e131);
                    let _e133 = a;
                    c_1 = _e133;
                    loop {
                        let _e135 = c_1;
                        if (_e135 > 0u) {
                            let _e140 = c_1;
                            let _e143 = tail_light((_e140 - 1u));
                            local_1 = (_e143 > _e132);
                        } else {
                            local_1 = false;
                        }
                        let _e146 = local_1;
                        if _e146 {
                        } else {
                            break;
                        }
                        {
                            let _e149 = c_1;
                            let _e152 = c_1;
                            let _e155 = tail_light((_e152 - 1u));
                            atomicStore((&tail[(2u + _e149)]), _e155);
                            let _e156 = c_1;
                            c_1 = (_e156 - 1u);
                        }
                    }
                    let _e161 = c_1;
                    atomicStore((&tail[(2u + _e161)]), _e132);
                }
                continuing {
                    let _e165 = a;
                    a = (_e165 + 1u);
                }
            }
            loop {
                let _e169 = s;
                if (_e169 < count) {
                } else {
                    break;
                }
                {
                    let _e171 = s;
                    let _e172 = tail_light(_e171);
                    let _e175 = params.tree;
                    let _e176 = s;
                    let at = (_e175 + _e176);
                    let _e181 = s;
                    let next_1 = select((at + 1u), BSH_NONE, ((_e181 + 1u) == count));
                    let _e190 = bsh_nodes[at];
                    let _e193 = bounds[_e172];
                    let _e196 = r2_3[_e172];
                    let _e197 = bsh_tail_leaf(_e190, _e193, _e196, _e172, next_1);
                    bsh_nodes[at] = _e197;
                }
                continuing {
                    let _e199 = s;
                    s = (_e199 + 1u);
                }
            }
            let _e203 = params.tree;
            let first = select(_e203, BSH_NONE, (count == 0u));
            loop {
                let _e210 = n;
                if (_e210 != BSH_NONE) {
                } else {
                    break;
                }
                {
                    let _e214 = n;
                    let _e215 = bsh_rightmost_next(BSH, _e214);
                    let _e217 = n;
                    bsh_nodes[_e217].next = first;
                    n = _e215;
                }
            }
            return;
        }
    }
}
