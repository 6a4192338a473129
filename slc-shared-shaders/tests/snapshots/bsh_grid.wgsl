struct GridParams {
    stage: u32,
    count: u32,
    levels: u32,
    capacity: u32,
    reach: f32,
    cells: u32,
    header: u32,
    fill: u32,
    entries: u32,
    least: u32,
    pad1_: u32,
    pad2_: u32,
}

struct BshNode {
    center: vec3<f32>,
    radius: f32,
    child: u32,
    next: u32,
    light: u32,
    extent: f32,
}

struct GridFrame {
    lo: vec3<f32>,
    nx: u32,
    hi: vec3<f32>,
    ny: u32,
    inv: vec3<f32>,
    nz: u32,
}

const LIGHT_POINT: u32 = 0u;
const LIGHT_SPOT: u32 = 1u;
const LIGHT_IES: u32 = 2u;
const LIGHT_TRIANGLE: u32 = 3u;
const LIGHT_VPL: u32 = 4u;
const NO_LIGHT: u32 = 4294967295u;
const GRID_HEADER: u32 = 32u;
const GRID_LEVELS_MAX: u32 = 8u;
const GRID_SORT_MAX: u32 = 1536u;
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
const GRID_ENTRIES_PER_LIGHT: u32 = 8u;
const LOBE_CONE_PAD: f32 = 1.001f;

@group(0) @binding(0) 
var<uniform> params: GridParams;
@group(0) @binding(1) 
var<storage> bsh_nodes: array<BshNode>;
@group(0) @binding(2) 
var<storage> grid_leaves: array<u32>;
@group(0) @binding(3) 
var<storage> grid_levels: array<GridFrame>;
@group(0) @binding(4) 
var<storage, read_write> grid: array<atomic<u32>>;
@group(0) @binding(5) 
var<storage, read_write> grid_fill: array<atomic<u32>>;
@group(0) @binding(6) 
var<storage, read_write> grid_entries: array<u32>;
var<workgroup> wg_sums: array<u32, 64>;
var<workgroup> wg_cell: array<u32, 1536>;
var<workgroup> wg_span: vec2<u32>;

fn to_u32_(x_1: f32) -> u32 {
    return u32(x_1);
}

fn add_wrap_u32_(a: u32, b: u32) -> u32 {
    return (a + b);
}

fn f32_from_bits(u: u32) -> f32 {
    return bitcast<f32>(u);
}

fn bsh_range_bound(node: BshNode) -> f32 {
    if (node.child == BSH_NONE) {
        return (node.radius - node.extent);
    }
    let _e8 = f32_from_bits(node.light);
    return _e8;
}

fn bsh_reach_bound(node_1: BshNode, w: f32) -> f32 {
    let _e5 = bsh_range_bound(node_1);
    return (node_1.extent + ((w * 1.001f) * _e5));
}

fn bsh_grid_budget(leaves: u32, cells: u32, least: u32) -> u32 {
    if (leaves > 536870911u) {
        return 4294967295u;
    }
    let e = (leaves * GRID_ENTRIES_PER_LIGHT);
    let _e8 = add_wrap_u32_(e, cells);
    return max(select(_e8, 4294967295u, (_e8 < e)), least);
}

fn bsh_grid_reach(node_2: BshNode, w_1: f32) -> f32 {
    if (w_1 > 1f) {
        let _e5 = bsh_reach_bound(node_2, w_1);
        return max(node_2.radius, _e5);
    }
    return node_2.radius;
}

fn bsh_grid_pad(reach: f32) -> f32 {
    if (reach > 10000000000000000000f) {
        return 340282350000000000000000000000000000000f;
    }
    return ((reach * 1.00001f) + 0.0000000000000000000001f);
}

fn bsh_grid_axis(v: f32, lo: f32, inv: f32, n: u32) -> u32 {
    let _e8 = to_u32_(max(((v - lo) * inv), 0f));
    return min(_e8, (n - 1u));
}

fn bsh_grid_radius(node_3: BshNode, w_2: f32) -> f32 {
    let _e2 = bsh_grid_reach(node_3, w_2);
    let _e3 = bsh_grid_pad(_e2);
    return _e3;
}

fn bsh_grid_first(f_1: GridFrame, c_2: vec3<f32>, r: f32) -> vec3<u32> {
    let _e10 = bsh_grid_axis((c_2.x - r), f_1.lo.x, f_1.inv.x, f_1.nx);
    let _e18 = bsh_grid_axis((c_2.y - r), f_1.lo.y, f_1.inv.y, f_1.ny);
    let _e26 = bsh_grid_axis((c_2.z - r), f_1.lo.z, f_1.inv.z, f_1.nz);
    return vec3<u32>(_e10, _e18, _e26);
}

fn bsh_grid_last(f_2: GridFrame, c_3: vec3<f32>, r_1: f32) -> vec3<u32> {
    let _e10 = bsh_grid_axis((c_3.x + r_1), f_2.lo.x, f_2.inv.x, f_2.nx);
    let _e18 = bsh_grid_axis((c_3.y + r_1), f_2.lo.y, f_2.inv.y, f_2.ny);
    let _e26 = bsh_grid_axis((c_3.z + r_1), f_2.lo.z, f_2.inv.z, f_2.nz);
    return vec3<u32>(_e10, _e18, _e26);
}

fn grid_word(i: u32) -> u32 {
    let _e3 = atomicLoad((&grid[i]));
    return _e3;
}

fn grid_frame(h: u32) -> GridFrame {
    var f_3: GridFrame;

    let _e3 = grid_word(h);
    let _e7 = grid_word((h + 1u));
    let _e11 = grid_word((h + 2u));
    f_3.lo = vec3<f32>(bitcast<f32>(_e3), bitcast<f32>(_e7), bitcast<f32>(_e11));
    let _e17 = grid_word((h + 3u));
    f_3.nx = _e17;
    let _e21 = grid_word((h + 4u));
    let _e25 = grid_word((h + 5u));
    let _e29 = grid_word((h + 6u));
    f_3.hi = vec3<f32>(bitcast<f32>(_e21), bitcast<f32>(_e25), bitcast<f32>(_e29));
    let _e35 = grid_word((h + 7u));
    f_3.ny = _e35;
    let _e39 = grid_word((h + 8u));
    let _e43 = grid_word((h + 9u));
    let _e47 = grid_word((h + 10u));
    f_3.inv = vec3<f32>(bitcast<f32>(_e39), bitcast<f32>(_e43), bitcast<f32>(_e47));
    let _e53 = grid_word((h + 11u));
    f_3.nz = _e53;
    let _e54 = f_3;
    return _e54;
}

fn grid_leaf(i_1: u32) -> u32 {
    let node_4 = grid_leaves[i_1];
    let _e7 = bsh_nodes[node_4].light;
    if ((_e7 & BSH_TAIL) != 0u) {
        return BSH_NONE;
    }
    return node_4;
}

fn sort_cell(cell: u32, li_1: u32) {
    var span: vec2<u32> = vec2(0u);
    var s: u32;
    var c_4: u32;
    var local_3: bool;
    var s_1: u32;
    var j_1: u32;
    var j_2: u32;
    var below: u32;
    var m: u32;

    let _e4 = params.header;
    let starts = (_e4 + GRID_HEADER);
    if (li_1 == 0u) {
        let _e11 = params.header;
        let _e12 = grid_frame(_e11);
        if (cell < ((_e12.nx * _e12.ny) * _e12.nz)) {
            let _e25 = atomicLoad((&grid[(starts + cell)]));
            let _e31 = atomicLoad((&grid[((starts + cell) + 1u)]));
            span = vec2<u32>(_e25, _e31);
            let _e36 = params.fill;
            atomicStore((&grid_fill[(_e36 + cell)]), 0u);
        }
        let _e41 = span;
        wg_span = _e41;
    }
    let _e43 = workgroupUniformLoad((&wg_span));
    let a_1 = _e43.x;
    let n_1 = (_e43.y - _e43.x);
    if (n_1 > GRID_SORT_MAX) {
        if (li_1 == 0u) {
            s = (a_1 + 1u);
            loop {
                let _e55 = s;
                if (_e55 < (a_1 + n_1)) {
                } else {
                    break;
                }
                {
                    let _e59 = s;
                    let v_1 = grid_entries[_e59];
                    let _e62 = s;
                    c_4 = _e62;
                    loop {
                        let _e64 = c_4;
                        if (_e64 > a_1) {
                            let _e69 = c_4;
                            let _e73 = grid_entries[(_e69 - 1u)];
                            local_3 = (_e73 > v_1);
                        } else {
                            local_3 = false;
                        }
                        let _e76 = local_3;
                        if _e76 {
                        } else {
                            break;
                        }
                        {
                            let _e78 = c_4;
                            let _e81 = c_4;
                            let _e85 = grid_entries[(_e81 - 1u)];
                            grid_entries[_e78] = _e85;
                            let _e86 = c_4;
                            c_4 = (_e86 - 1u);
                        }
                    }
                    let _e90 = c_4;
                    grid_entries[_e90] = v_1;
                }
                continuing {
                    let _e93 = s;
                    s = (_e93 + 1u);
                }
            }
            s_1 = a_1;
            loop {
                let _e96 = s_1;
                if (_e96 < (a_1 + n_1)) {
                } else {
                    break;
                }
                {
                    let _e100 = s_1;
                    let _e104 = s_1;
                    let _e106 = grid_entries[_e104];
                    let _e108 = grid_leaves[_e106];
                    grid_entries[_e100] = _e108;
                }
                continuing {
                    let _e110 = s_1;
                    s_1 = (_e110 + 1u);
                }
            }
        }
        return;
    }
    j_1 = li_1;
    loop {
        let _e113 = j_1;
        if (_e113 < n_1) {
        } else {
            break;
        }
        {
            let _e116 = j_1;
            let _e119 = j_1;
            let _e122 = grid_entries[(a_1 + _e119)];
            wg_cell[_e116] = _e122;
        }
        continuing {
            let _e123 = j_1;
            j_1 = (_e123 + 64u);
        }
    }
    workgroupBarrier();
    j_2 = li_1;
    loop {
        let _e127 = j_2;
        if (_e127 < n_1) {
        } else {
            break;
        }
        {
            let _e130 = j_2;
            let v_2 = wg_cell[_e130];
            below = 0u;
            m = 0u;
            loop {
                let _e137 = m;
                if (_e137 < n_1) {
                } else {
                    break;
                }
                {
                    let _e139 = below;
                    let _e143 = m;
                    let _e145 = wg_cell[_e143];
                    below = (_e139 + select(0u, 1u, (_e145 < v_2)));
                }
                continuing {
                    let _e150 = m;
                    m = (_e150 + 1u);
                }
            }
            let _e153 = below;
            let _e158 = grid_leaves[v_2];
            grid_entries[(a_1 + _e153)] = _e158;
        }
        continuing {
            let _e159 = j_2;
            j_2 = (_e159 + 64u);
        }
    }
    return;
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    var sum: u32 = 0u;
    var c: u32;
    var start: u32;
    var j: u32 = 0u;
    var c_1: u32;
    var l: u32 = 0u;
    var chosen: u32;
    var l_1: u32 = 0u;
    var local: bool;
    var local_1: bool;
    var f: GridFrame;
    var local_2: bool;
    var z: u32;
    var y: u32;
    var x: u32;

    let _e6 = params.stage;
    if (_e6 == 5u) {
        sort_cell(((wid.y * groups.x) + wid.x), li);
        return;
    }
    let i_2 = gid.x;
    let h_1 = params.header;
    let starts_1 = (h_1 + GRID_HEADER);
    let _e22 = params.stage;
    if (_e22 == 3u) {
        let _e25 = grid_frame(h_1);
        let cells_1 = ((_e25.nx * _e25.ny) * _e25.nz);
        let run = (((cells_1 + 64u) - 1u) / 64u);
        let a_2 = min((i_2 * run), cells_1);
        let b_1 = min((a_2 + run), cells_1);
        c = a_2;
        loop {
            let _e44 = c;
            if (_e44 < b_1) {
            } else {
                break;
            }
            {
                let _e46 = sum;
                let _e50 = params.fill;
                let _e51 = c;
                let _e54 = atomicLoad((&grid_fill[(_e50 + _e51)]));
                sum = (_e46 + _e54);
            }
            continuing {
                let _e57 = c;
                c = (_e57 + 1u);
            }
        }
        let _e61 = sum;
        wg_sums[i_2] = _e61;
        workgroupBarrier();
        let _e64 = params.entries;
        start = _e64;
        loop {
            let _e68 = j;
            if (_e68 < i_2) {
            } else {
                break;
            }
            {
                let _e70 = start;
                let _e72 = j;
                let _e74 = wg_sums[_e72];
                start = (_e70 + _e74);
            }
            continuing {
                let _e77 = j;
                j = (_e77 + 1u);
            }
        }
        c_1 = a_2;
        loop {
            let _e80 = c_1;
            if (_e80 < b_1) {
            } else {
                break;
            }
            {
                let _e85 = params.fill;
                let _e86 = c_1;
                let n_2 = atomicLoad((&grid_fill[(_e85 + _e86)]));
                let _e91 = c_1;
                let _e94 = start;
                atomicStore((&grid[(starts_1 + _e91)]), _e94);
                let _e98 = params.fill;
                let _e99 = c_1;
                let _e102 = start;
                atomicStore((&grid_fill[(_e98 + _e99)]), _e102);
                let _e103 = start;
                start = (_e103 + n_2);
            }
            continuing {
                let _e106 = c_1;
                c_1 = (_e106 + 1u);
            }
        }
        if ((i_2 + 1u) == 64u) {
            let _e115 = start;
            atomicStore((&grid[(starts_1 + cells_1)]), _e115);
        }
        return;
    }
    let _e118 = params.stage;
    switch _e118 {
        case 0u: {
            let _e121 = params.count;
            if (i_2 >= _e121) {
                return;
            }
            let _e123 = grid_leaf(i_2);
            if (_e123 == BSH_NONE) {
                return;
            }
            let _e131 = atomicAdd((&grid[(h_1 + 13u)]), 1u);
            let leaf = bsh_nodes[_e123];
            let _e137 = params.reach;
            let _e138 = bsh_grid_radius(leaf, _e137);
            loop {
                let _e141 = l;
                let _e144 = params.levels;
                if (_e141 < _e144) {
                } else {
                    break;
                }
                {
                    let _e147 = l;
                    let _e149 = grid_levels[_e147];
                    let _e151 = bsh_grid_last(_e149, leaf.center, _e138);
                    let _e153 = l;
                    let _e155 = grid_levels[_e153];
                    let _e157 = bsh_grid_first(_e155, leaf.center, _e138);
                    let d = ((_e151 - _e157) + vec3(1u));
                    let n_3 = ((d.x * d.y) * d.z);
                    let _e170 = l;
                    let at = ((h_1 + 16u) + (2u * _e170));
                    let _e175 = atomicAdd((&grid[at]), n_3);
                    if ((_e175 + n_3) < _e175) {
                        let _e183 = atomicAdd((&grid[(at + 1u)]), 1u);
                    }
                }
                continuing {
                    let _e185 = l;
                    l = (_e185 + 1u);
                }
            }
            return;
        }
        case 1u: {
            if (i_2 != 0u) {
                return;
            }
            let leaves_1 = atomicLoad((&grid[(h_1 + 13u)]));
            let _e196 = params.levels;
            chosen = _e196;
            loop {
                let _e200 = l_1;
                let _e203 = params.levels;
                if (_e200 < _e203) {
                } else {
                    break;
                }
                {
                    let _e206 = l_1;
                    let f_4 = grid_levels[_e206];
                    let cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    let _e216 = params.least;
                    let _e217 = bsh_grid_budget(leaves_1, cells_2, _e216);
                    let _e220 = params.capacity;
                    let budget = min(_e217, _e220);
                    let _e225 = l_1;
                    let at_1 = ((h_1 + 16u) + (2u * _e225));
                    let _e228 = chosen;
                    let _e231 = params.levels;
                    if (_e228 == _e231) {
                        let _e239 = atomicLoad((&grid[(at_1 + 1u)]));
                        local = (_e239 == 0u);
                    } else {
                        local = false;
                    }
                    let _e243 = local;
                    if _e243 {
                        let _e248 = atomicLoad((&grid[at_1]));
                        local_1 = (_e248 <= budget);
                    } else {
                        local_1 = false;
                    }
                    let _e251 = local_1;
                    if _e251 {
                        let _e252 = l_1;
                        chosen = _e252;
                    }
                    atomicStore((&grid[at_1]), 0u);
                    atomicStore((&grid[(at_1 + 1u)]), 0u);
                }
                continuing {
                    let _e262 = l_1;
                    l_1 = (_e262 + 1u);
                }
            }
            atomicStore((&grid[(h_1 + 13u)]), 0u);
            let _e270 = chosen;
            let _e273 = params.levels;
            if (_e270 < _e273) {
                let _e276 = chosen;
                let _e278 = grid_levels[_e276];
                f = _e278;
            }
            let _e283 = f.lo.x;
            atomicStore((&grid[h_1]), bitcast<u32>(_e283));
            let _e291 = f.lo.y;
            atomicStore((&grid[(h_1 + 1u)]), bitcast<u32>(_e291));
            let _e299 = f.lo.z;
            atomicStore((&grid[(h_1 + 2u)]), bitcast<u32>(_e299));
            let _e306 = f.nx;
            atomicStore((&grid[(h_1 + 3u)]), _e306);
            let _e313 = f.hi.x;
            atomicStore((&grid[(h_1 + 4u)]), bitcast<u32>(_e313));
            let _e321 = f.hi.y;
            atomicStore((&grid[(h_1 + 5u)]), bitcast<u32>(_e321));
            let _e329 = f.hi.z;
            atomicStore((&grid[(h_1 + 6u)]), bitcast<u32>(_e329));
            let _e336 = f.ny;
            atomicStore((&grid[(h_1 + 7u)]), _e336);
            let _e343 = f.inv.x;
            atomicStore((&grid[(h_1 + 8u)]), bitcast<u32>(_e343));
            let _e351 = f.inv.y;
            atomicStore((&grid[(h_1 + 9u)]), bitcast<u32>(_e351));
            let _e359 = f.inv.z;
            atomicStore((&grid[(h_1 + 10u)]), bitcast<u32>(_e359));
            let _e366 = f.nz;
            atomicStore((&grid[(h_1 + 11u)]), _e366);
            let _e373 = params.reach;
            atomicStore((&grid[(h_1 + 12u)]), bitcast<u32>(_e373));
            return;
        }
        case 2u, 4u: {
            let _e377 = params.count;
            if (i_2 >= _e377) {
                return;
            }
            let _e379 = grid_frame(h_1);
            let _e380 = grid_leaf(i_2);
            if !((_e379.nx == 0u)) {
                local_2 = (_e380 == BSH_NONE);
            } else {
                local_2 = true;
            }
            let _e390 = local_2;
            if _e390 {
                return;
            }
            let leaf_1 = bsh_nodes[_e380];
            let _e396 = params.reach;
            let _e397 = bsh_grid_radius(leaf_1, _e396);
            let _e399 = bsh_grid_first(_e379, leaf_1.center, _e397);
            let _e401 = bsh_grid_last(_e379, leaf_1.center, _e397);
            z = _e399.z;
            loop {
                let _e404 = z;
                if (_e404 <= _e401.z) {
                } else {
                    break;
                }
                {
                    y = _e399.y;
                    loop {
                        let _e409 = y;
                        if (_e409 <= _e401.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e399.x;
                            loop {
                                let _e414 = x;
                                if (_e414 <= _e401.x) {
                                } else {
                                    break;
                                }
                                {
                                    let _e417 = z;
                                    let _e420 = y;
                                    let _e424 = x;
                                    let c_5 = ((((_e417 * _e379.ny) + _e420) * _e379.nx) + _e424);
                                    let _e429 = params.fill;
                                    let _e433 = atomicAdd((&grid_fill[(_e429 + c_5)]), 1u);
                                    let _e436 = params.stage;
                                    if (_e436 == 4u) {
                                        grid_entries[_e433] = i_2;
                                    }
                                }
                                continuing {
                                    let _e442 = x;
                                    x = (_e442 + 1u);
                                }
                            }
                        }
                        continuing {
                            let _e445 = y;
                            y = (_e445 + 1u);
                        }
                    }
                }
                continuing {
                    let _e448 = z;
                    z = (_e448 + 1u);
                }
            }
            return;
        }
        default: {
            return;
        }
    }
}
