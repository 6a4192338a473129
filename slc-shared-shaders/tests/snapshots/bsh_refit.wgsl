struct RefitParams {
    first: u32,
    count: u32,
    pad0_: u32,
    pad1_: u32,
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

@group(0) @binding(0) 
var<uniform> params: RefitParams;
@group(0) @binding(1) 
var<storage> order: array<u32>;
@group(0) @binding(2) 
var<storage> bounds: array<vec4<f32>>;
@group(0) @binding(3) 
var<storage> r2_4: array<f32>;
@group(0) @binding(4) 
var<storage, read_write> bsh_nodes: array<BshNode>;
@group(0) @binding(5) 
var<storage> tail: array<u32>;

fn f32_from_bits(u: u32) -> f32 {
    return bitcast<f32>(u);
}

fn f32_to_bits(x: f32) -> u32 {
    return bitcast<u32>(x);
}

fn sphere_pad(r: f32, c: vec3<f32>) -> f32 {
    return (((r + max(abs(c.x), max(abs(c.y), abs(c.z)))) * SPHERE_PAD) + SPHERE_PAD_ABS);
}

fn sphere_union(c1_: vec3<f32>, r1_: f32, c2_: vec3<f32>, r2_: f32) -> vec4<f32> {
    var local: bool;

    let v = (c2_ - c1_);
    let d = sqrt(dot(v, v));
    let _e8 = sphere_pad(r1_, c1_);
    if (r1_ >= ((d + r2_) + _e8)) {
        return vec4<f32>(c1_.x, c1_.y, c1_.z, r1_);
    }
    let _e16 = sphere_pad(r2_, c2_);
    if (r2_ >= ((d + r1_) + _e16)) {
        return vec4<f32>(c2_.x, c2_.y, c2_.z, r2_);
    }
    if !((d >= SPHERE_HUGE)) {
        local = ((0.5f * ((d + r1_) + r2_)) >= SPHERE_HUGE);
    } else {
        local = true;
    }
    let _e35 = local;
    if _e35 {
        return vec4<f32>(c1_.x, c1_.y, c1_.z, SPHERE_HUGE);
    }
    if (abs((r1_ - r2_)) >= d) {
        if (r1_ >= r2_) {
            let rn = max(r1_, (d + r2_));
            let _e50 = sphere_pad(rn, c1_);
            return vec4<f32>(c1_.x, c1_.y, c1_.z, (rn + _e50));
        }
        let rm = max(r2_, (d + r1_));
        let _e58 = sphere_pad(rm, c2_);
        return vec4<f32>(c2_.x, c2_.y, c2_.z, (rm + _e58));
    }
    let r0_ = (0.5f * ((d + r1_) + r2_));
    let c_2 = (c1_ + (v * ((r0_ - r1_) / d)));
    let e1_ = (c_2 - c1_);
    let e2_ = (c_2 - c2_);
    let r_1 = max(r0_, max((sqrt(dot(e1_, e1_)) + r1_), (sqrt(dot(e2_, e2_)) + r2_)));
    let _e82 = sphere_pad(r_1, c_2);
    return vec4<f32>(c_2.x, c_2.y, c_2.z, (r_1 + _e82));
}

fn range_radius(extent: f32, r2_1: f32) -> f32 {
    return (extent + sqrt(r2_1));
}

fn bsh_tail_key(radius: f32) -> u32 {
    let _e1 = f32_to_bits(radius);
    return ((_e1 & 2147483647u) >> 21u);
}

fn bsh_range_bound(node: BshNode) -> f32 {
    if (node.child == BSH_NONE) {
        return (node.radius - node.extent);
    }
    let _e8 = f32_from_bits(node.light);
    return _e8;
}

fn bsh_node(nodes: u32, i: u32) -> BshNode {
    let _e4 = bsh_nodes[i];
    return _e4;
}

fn bsh_in_tail(extent_1: f32, r2_2: f32, cut: u32) -> bool {
    let _e3 = range_radius(extent_1, r2_2);
    let _e4 = bsh_tail_key(_e3);
    return (_e4 >= cut);
}

fn bsh_leaf_refitted(node_1: BshNode, bound: vec4<f32>, r2_3: f32, cut_1: u32) -> BshNode {
    var leaf: BshNode;

    let _e5 = bsh_in_tail(bound.w, r2_3, cut_1);
    leaf = node_1;
    leaf.center = vec3<f32>(bound.x, bound.y, bound.z);
    let _e16 = range_radius(bound.w, select(r2_3, 0f, _e5));
    leaf.radius = _e16;
    leaf.extent = bound.w;
    leaf.light = ((node_1.light & 2147483647u) | select(0u, BSH_TAIL, _e5));
    let _e27 = leaf;
    return _e27;
}

fn bsh_pair_sphere(left: BshNode, right: BshNode) -> vec4<f32> {
    let _e6 = sphere_union(left.center, left.radius, right.center, right.radius);
    return _e6;
}

fn bsh_pair_extent(left_1: BshNode, right_1: BshNode, center: vec3<f32>) -> f32 {
    let vl = (left_1.center - center);
    let vr = (right_1.center - center);
    let a = max((sqrt(dot(vl, vl)) + left_1.extent), (sqrt(dot(vr, vr)) + right_1.extent));
    let _e16 = sphere_pad(a, center);
    return (a + _e16);
}

fn bsh_pair_range(left_2: BshNode, right_2: BshNode) -> f32 {
    let _e2 = bsh_range_bound(left_2);
    let _e3 = bsh_range_bound(right_2);
    return max(_e2, _e3);
}

fn bsh_inner_refitted(node_2: BshNode, left_3: BshNode, right_3: BshNode) -> BshNode {
    var inner: BshNode;

    let _e3 = bsh_pair_sphere(left_3, right_3);
    inner = node_2;
    inner.center = vec3<f32>(_e3.x, _e3.y, _e3.z);
    inner.radius = _e3.w;
    let _e14 = inner.center;
    let _e15 = bsh_pair_extent(left_3, right_3, _e14);
    inner.extent = _e15;
    let _e17 = bsh_pair_range(left_3, right_3);
    let _e18 = f32_to_bits(_e17);
    inner.light = _e18;
    let _e19 = inner;
    return _e19;
}

fn bsh_family_refitted(nodes_1: u32, node_3: BshNode) -> BshNode {
    var acc: BshNode;
    var c_1: u32;

    let _e3 = bsh_node(nodes_1, node_3.child);
    let _e5 = bsh_node(nodes_1, _e3.next);
    let _e6 = bsh_inner_refitted(node_3, _e3, _e5);
    acc = _e6;
    c_1 = _e5.next;
    loop {
        let _e10 = c_1;
        if (_e10 != node_3.next) {
        } else {
            break;
        }
        {
            let _e13 = c_1;
            let _e14 = bsh_node(nodes_1, _e13);
            let _e15 = acc;
            let _e16 = acc;
            let _e17 = bsh_inner_refitted(_e15, _e16, _e14);
            acc = _e17;
            c_1 = _e14.next;
        }
    }
    let _e19 = acc;
    return _e19;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let _e4 = params.count;
    if (gid.x >= _e4) {
        return;
    }
    let _e9 = params.first;
    let i_1 = order[(_e9 + gid.x)];
    let node_4 = bsh_nodes[i_1];
    if (node_4.child == BSH_NONE) {
        let li = (node_4.light & 2147483647u);
        let _e27 = bounds[li];
        let _e30 = r2_4[li];
        let _e33 = tail[0];
        let _e34 = bsh_leaf_refitted(node_4, _e27, _e30, _e33);
        bsh_nodes[i_1] = _e34;
        return;
    }
    let _e38 = bsh_family_refitted(BSH, node_4);
    bsh_nodes[i_1] = _e38;
    return;
}
