struct GridStage {
    stage: u32,
    count: u32,
    levels: u32,
    moves: u32,
}

struct GridParams {
    capacity: u32,
    reach: f32,
    header: u32,
    fill: u32,
    entries: u32,
    least: u32,
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
const GRID_ENTRIES_PER_LIGHT: u32 = 8u;
const LOBE_CONE_PAD: f32 = 1.001f;

@group(0) @binding(0) 
var<uniform> params: GridStage;
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
@group(0) @binding(7) 
var<storage> grids: array<GridParams>;
var<workgroup> wg_sums: array<u32, 64>;
var<workgroup> wg_big: array<vec2<u32>, 64>;
var<workgroup> wg_bigs: atomic<u32>;
var<workgroup> wg_cell: array<u32, 1024>;

fn to_u32_(x: f32) -> u32 {
    return u32(x);
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
    let e_1 = (leaves * GRID_ENTRIES_PER_LIGHT);
    let _e8 = add_wrap_u32_(e_1, cells);
    return max(select(_e8, 4294967295u, (_e8 < e_1)), least);
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

fn bsh_grid_first(f: GridFrame, c: vec3<f32>, r: f32) -> vec3<u32> {
    let _e10 = bsh_grid_axis((c.x - r), f.lo.x, f.inv.x, f.nx);
    let _e18 = bsh_grid_axis((c.y - r), f.lo.y, f.inv.y, f.ny);
    let _e26 = bsh_grid_axis((c.z - r), f.lo.z, f.inv.z, f.nz);
    return vec3<u32>(_e10, _e18, _e26);
}

fn bsh_grid_last(f_1: GridFrame, c_1: vec3<f32>, r_1: f32) -> vec3<u32> {
    let _e10 = bsh_grid_axis((c_1.x + r_1), f_1.lo.x, f_1.inv.x, f_1.nx);
    let _e18 = bsh_grid_axis((c_1.y + r_1), f_1.lo.y, f_1.inv.y, f_1.ny);
    let _e26 = bsh_grid_axis((c_1.z + r_1), f_1.lo.z, f_1.inv.z, f_1.nz);
    return vec3<u32>(_e10, _e18, _e26);
}

fn grid_word(i: u32) -> u32 {
    let _e3 = atomicLoad((&grid[i]));
    return _e3;
}

fn grid_frame(h: u32) -> GridFrame {
    var f_2: GridFrame;

    let _e3 = grid_word(h);
    let _e7 = grid_word((h + 1u));
    let _e11 = grid_word((h + 2u));
    f_2.lo = vec3<f32>(bitcast<f32>(_e3), bitcast<f32>(_e7), bitcast<f32>(_e11));
    let _e17 = grid_word((h + 3u));
    f_2.nx = _e17;
    let _e21 = grid_word((h + 4u));
    let _e25 = grid_word((h + 5u));
    let _e29 = grid_word((h + 6u));
    f_2.hi = vec3<f32>(bitcast<f32>(_e21), bitcast<f32>(_e25), bitcast<f32>(_e29));
    let _e35 = grid_word((h + 7u));
    f_2.ny = _e35;
    let _e39 = grid_word((h + 8u));
    let _e43 = grid_word((h + 9u));
    let _e47 = grid_word((h + 10u));
    f_2.inv = vec3<f32>(bitcast<f32>(_e39), bitcast<f32>(_e43), bitcast<f32>(_e47));
    let _e53 = grid_word((h + 11u));
    f_2.nz = _e53;
    let _e54 = f_2;
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

fn cell_key(big: bool, a_1: u32, j: u32) -> u32 {
    if big {
        let _e6 = grid_entries[(a_1 + j)];
        return _e6;
    }
    let _e9 = wg_cell[j];
    return _e9;
}

fn set_cell_key(big_1: bool, a_2: u32, j_1: u32, v_1: u32) {
    if big_1 {
        grid_entries[(a_2 + j_1)] = v_1;
        return;
    } else {
        wg_cell[j_1] = v_1;
        return;
    }
}

fn sort_together(b_1: u32, li_1: u32) {
    var j_2: u32;
    var p: u32 = 1u;
    var k: u32 = 2u;
    var h_1: u32;
    var t: u32;
    var j_3: u32;

    let _e4 = workgroupUniformLoad((&wg_big[b_1]));
    let a_3 = _e4.x;
    let n_1 = (_e4.y - _e4.x);
    let big_2 = (n_1 > GRID_SORT_MAX);
    if !(big_2) {
        j_2 = li_1;
        loop {
            let _e13 = j_2;
            if (_e13 < n_1) {
            } else {
                break;
            }
            {
                let _e16 = j_2;
                let _e19 = j_2;
                let _e22 = grid_entries[(a_3 + _e19)];
                wg_cell[_e16] = _e22;
            }
            continuing {
                let _e23 = j_2;
                j_2 = (_e23 + 64u);
            }
        }
    }
    loop {
        let _e28 = p;
        if (_e28 < n_1) {
        } else {
            break;
        }
        {
            let _e30 = p;
            p = (_e30 << 1u);
        }
    }
    workgroupBarrier();
    loop {
        let _e35 = k;
        let _e36 = p;
        if (_e35 <= _e36) {
        } else {
            break;
        }
        {
            let _e38 = k;
            h_1 = (_e38 >> 1u);
            loop {
                let _e42 = h_1;
                if (_e42 > 0u) {
                } else {
                    break;
                }
                {
                    t = li_1;
                    loop {
                        let _e46 = t;
                        let _e47 = p;
                        if (_e46 < (_e47 >> 1u)) {
                        } else {
                            break;
                        }
                        {
                            let _e51 = t;
                            let _e52 = h_1;
                            let _e59 = t;
                            let _e60 = h_1;
                            let i_4 = (((_e51 & ~((_e52 - 1u))) << 1u) | (_e59 & (_e60 - 1u)));
                            let _e65 = h_1;
                            let _e67 = k;
                            let _e71 = h_1;
                            let _e72 = k;
                            let o = select((i_4 | _e65), (i_4 ^ (_e67 - 1u)), (_e71 == (_e72 >> 1u)));
                            if (o < n_1) {
                                let _e78 = cell_key(big_2, a_3, i_4);
                                let _e79 = cell_key(big_2, a_3, o);
                                if (_e79 < _e78) {
                                    set_cell_key(big_2, a_3, i_4, _e79);
                                    set_cell_key(big_2, a_3, o, _e78);
                                }
                            }
                        }
                        continuing {
                            let _e81 = t;
                            t = (_e81 + 64u);
                        }
                    }
                    workgroupBarrier();
                    storageBarrier();
                }
                continuing {
                    let _e84 = h_1;
                    h_1 = (_e84 >> 1u);
                }
            }
        }
        continuing {
            let _e87 = k;
            k = (_e87 << 1u);
        }
    }
    j_3 = li_1;
    loop {
        let _e91 = j_3;
        if (_e91 < n_1) {
        } else {
            break;
        }
        {
            let _e94 = j_3;
            let _e98 = j_3;
            let _e99 = cell_key(big_2, a_3, _e98);
            let _e101 = grid_leaves[_e99];
            grid_entries[(a_3 + _e94)] = _e101;
        }
        continuing {
            let _e102 = j_3;
            j_3 = (_e102 + 64u);
        }
    }
    workgroupBarrier();
    return;
}

fn sort_cells(g: GridParams, first: u32, li_2: u32) {
    var span: vec2<u32> = vec2(0u);
    var s: u32;
    var moves: u32 = 0u;
    var local: bool;
    var c_2: u32;
    var local_1: bool;
    var e: u32;
    var b_2: u32 = 0u;

    let starts = (g.header + GRID_HEADER);
    let _e7 = grid_frame(g.header);
    let cell = (first + li_2);
    if (cell < ((_e7.nx * _e7.ny) * _e7.nz)) {
        let _e21 = atomicLoad((&grid[(starts + cell)]));
        let _e27 = atomicLoad((&grid[((starts + cell) + 1u)]));
        span = vec2<u32>(_e21, _e27);
        atomicStore((&grid_fill[(g.fill + cell)]), 0u);
    }
    if (li_2 == 0u) {
        atomicStore((&wg_bigs), 0u);
    }
    workgroupBarrier();
    let _e39 = span.x;
    s = (_e39 + 1u);
    loop {
        let _e45 = s;
        let _e47 = span.y;
        if (_e45 < _e47) {
            let _e51 = moves;
            let _e54 = params.moves;
            local = (_e51 < _e54);
        } else {
            local = false;
        }
        let _e57 = local;
        if _e57 {
        } else {
            break;
        }
        {
            let _e59 = s;
            let v_2 = grid_entries[_e59];
            let _e62 = s;
            c_2 = _e62;
            loop {
                let _e64 = c_2;
                let _e66 = span.x;
                if (_e64 > _e66) {
                    let _e71 = c_2;
                    let _e75 = grid_entries[(_e71 - 1u)];
                    local_1 = (_e75 > v_2);
                } else {
                    local_1 = false;
                }
                let _e78 = local_1;
                if _e78 {
                } else {
                    break;
                }
                {
                    let _e80 = c_2;
                    let _e83 = c_2;
                    let _e87 = grid_entries[(_e83 - 1u)];
                    grid_entries[_e80] = _e87;
                    let _e88 = c_2;
                    c_2 = (_e88 - 1u);
                }
            }
            let _e92 = c_2;
            grid_entries[_e92] = v_2;
            let _e94 = moves;
            let _e95 = s;
            let _e96 = c_2;
            moves = (_e94 + (_e95 - _e96));
            let _e99 = s;
            s = (_e99 + 1u);
        }
    }
    let _e102 = s;
    let _e104 = span.y;
    if (_e102 < _e104) {
        let _e109 = atomicAdd((&wg_bigs), 1u);
        let _e111 = span;
        wg_big[_e109] = _e111;
    } else {
        let _e113 = span.x;
        e = _e113;
        loop {
            let _e115 = e;
            let _e117 = span.y;
            if (_e115 < _e117) {
            } else {
                break;
            }
            {
                let _e120 = e;
                let _e124 = e;
                let _e126 = grid_entries[_e124];
                let _e128 = grid_leaves[_e126];
                grid_entries[_e120] = _e128;
            }
            continuing {
                let _e130 = e;
                e = (_e130 + 1u);
            }
        }
    }
    storageBarrier();
    let _e133 = workgroupUniformLoad((&wg_bigs));
    loop {
        let _e136 = b_2;
        if (_e136 < _e133) {
        } else {
            break;
        }
        {
            let _e138 = b_2;
            sort_together(_e138, li_2);
        }
        continuing {
            let _e140 = b_2;
            b_2 = (_e140 + 1u);
        }
    }
    return;
}

fn count_levels(g_1: GridParams, i_2: u32) {
    var l: u32 = 0u;

    let _e4 = params.count;
    if (i_2 >= _e4) {
        return;
    }
    let h_2 = g_1.header;
    let _e7 = grid_leaf(i_2);
    if (_e7 == BSH_NONE) {
        return;
    }
    let _e15 = atomicAdd((&grid[(h_2 + 13u)]), 1u);
    let leaf = bsh_nodes[_e7];
    let _e20 = bsh_grid_radius(leaf, g_1.reach);
    loop {
        let _e23 = l;
        let _e26 = params.levels;
        if (_e23 < _e26) {
        } else {
            break;
        }
        {
            let _e29 = l;
            let _e31 = grid_levels[_e29];
            let _e33 = bsh_grid_last(_e31, leaf.center, _e20);
            let _e35 = l;
            let _e37 = grid_levels[_e35];
            let _e39 = bsh_grid_first(_e37, leaf.center, _e20);
            let d = ((_e33 - _e39) + vec3(1u));
            let n_2 = ((d.x * d.y) * d.z);
            let _e52 = l;
            let at = ((h_2 + 16u) + (2u * _e52));
            let _e57 = atomicAdd((&grid[at]), n_2);
            if ((_e57 + n_2) < _e57) {
                let _e65 = atomicAdd((&grid[(at + 1u)]), 1u);
            }
        }
        continuing {
            let _e67 = l;
            l = (_e67 + 1u);
        }
    }
    return;
}

fn choose_level(g_2: GridParams) {
    var chosen: u32;
    var l_1: u32 = 0u;
    var local_2: bool;
    var local_3: bool;
    var f_3: GridFrame;

    let h_3 = g_2.header;
    let leaves_1 = atomicLoad((&grid[(h_3 + 13u)]));
    let _e9 = params.levels;
    chosen = _e9;
    loop {
        let _e13 = l_1;
        let _e16 = params.levels;
        if (_e13 < _e16) {
        } else {
            break;
        }
        {
            let _e19 = l_1;
            let f_4 = grid_levels[_e19];
            let cells_1 = ((f_4.nx * f_4.ny) * f_4.nz);
            let _e28 = bsh_grid_budget(leaves_1, cells_1, g_2.least);
            let budget = min(_e28, g_2.capacity);
            let _e34 = l_1;
            let at_1 = ((h_3 + 16u) + (2u * _e34));
            let _e37 = chosen;
            let _e40 = params.levels;
            if (_e37 == _e40) {
                let _e48 = atomicLoad((&grid[(at_1 + 1u)]));
                local_2 = (_e48 == 0u);
            } else {
                local_2 = false;
            }
            let _e52 = local_2;
            if _e52 {
                let _e57 = atomicLoad((&grid[at_1]));
                local_3 = (_e57 <= budget);
            } else {
                local_3 = false;
            }
            let _e60 = local_3;
            if _e60 {
                let _e61 = l_1;
                chosen = _e61;
            }
            atomicStore((&grid[at_1]), 0u);
            atomicStore((&grid[(at_1 + 1u)]), 0u);
        }
        continuing {
            let _e71 = l_1;
            l_1 = (_e71 + 1u);
        }
    }
    atomicStore((&grid[(h_3 + 13u)]), 0u);
    let _e79 = chosen;
    let _e82 = params.levels;
    if (_e79 < _e82) {
        let _e85 = chosen;
        let _e87 = grid_levels[_e85];
        f_3 = _e87;
    }
    let _e92 = f_3.lo.x;
    atomicStore((&grid[h_3]), bitcast<u32>(_e92));
    let _e100 = f_3.lo.y;
    atomicStore((&grid[(h_3 + 1u)]), bitcast<u32>(_e100));
    let _e108 = f_3.lo.z;
    atomicStore((&grid[(h_3 + 2u)]), bitcast<u32>(_e108));
    let _e115 = f_3.nx;
    atomicStore((&grid[(h_3 + 3u)]), _e115);
    let _e122 = f_3.hi.x;
    atomicStore((&grid[(h_3 + 4u)]), bitcast<u32>(_e122));
    let _e130 = f_3.hi.y;
    atomicStore((&grid[(h_3 + 5u)]), bitcast<u32>(_e130));
    let _e138 = f_3.hi.z;
    atomicStore((&grid[(h_3 + 6u)]), bitcast<u32>(_e138));
    let _e145 = f_3.ny;
    atomicStore((&grid[(h_3 + 7u)]), _e145);
    let _e152 = f_3.inv.x;
    atomicStore((&grid[(h_3 + 8u)]), bitcast<u32>(_e152));
    let _e160 = f_3.inv.y;
    atomicStore((&grid[(h_3 + 9u)]), bitcast<u32>(_e160));
    let _e168 = f_3.inv.z;
    atomicStore((&grid[(h_3 + 10u)]), bitcast<u32>(_e168));
    let _e175 = f_3.nz;
    atomicStore((&grid[(h_3 + 11u)]), _e175);
    atomicStore((&grid[(h_3 + 12u)]), bitcast<u32>(g_2.reach));
    return;
}

fn fill_cells(g_3: GridParams, i_3: u32, scatter: bool) {
    var local_4: bool;
    var z: u32;
    var y: u32;
    var x_1: u32;

    let _e5 = params.count;
    if (i_3 >= _e5) {
        return;
    }
    let _e8 = grid_frame(g_3.header);
    let _e9 = grid_leaf(i_3);
    if !((_e8.nx == 0u)) {
        local_4 = (_e9 == BSH_NONE);
    } else {
        local_4 = true;
    }
    let _e19 = local_4;
    if _e19 {
        return;
    }
    let leaf_1 = bsh_nodes[_e9];
    let _e24 = bsh_grid_radius(leaf_1, g_3.reach);
    let _e26 = bsh_grid_first(_e8, leaf_1.center, _e24);
    let _e28 = bsh_grid_last(_e8, leaf_1.center, _e24);
    z = _e26.z;
    loop {
        let _e31 = z;
        if (_e31 <= _e28.z) {
        } else {
            break;
        }
        {
            y = _e26.y;
            loop {
                let _e36 = y;
                if (_e36 <= _e28.y) {
                } else {
                    break;
                }
                {
                    x_1 = _e26.x;
                    loop {
                        let _e41 = x_1;
                        if (_e41 <= _e28.x) {
                        } else {
                            break;
                        }
                        {
                            let _e44 = z;
                            let _e47 = y;
                            let _e51 = x_1;
                            let c_5 = ((((_e44 * _e8.ny) + _e47) * _e8.nx) + _e51);
                            let _e58 = atomicAdd((&grid_fill[(g_3.fill + c_5)]), 1u);
                            if scatter {
                                grid_entries[_e58] = i_3;
                            }
                        }
                        continuing {
                            let _e62 = x_1;
                            x_1 = (_e62 + 1u);
                        }
                    }
                }
                continuing {
                    let _e65 = y;
                    y = (_e65 + 1u);
                }
            }
        }
        continuing {
            let _e68 = z;
            z = (_e68 + 1u);
        }
    }
    return;
}

fn scan_starts(g_4: GridParams, li_3: u32) {
    var sum: u32 = 0u;
    var c_3: u32;
    var start: u32;
    var j_4: u32 = 0u;
    var c_4: u32;

    let starts_1 = (g_4.header + GRID_HEADER);
    let _e6 = grid_frame(g_4.header);
    let cells_2 = ((_e6.nx * _e6.ny) * _e6.nz);
    let run = (((cells_2 + 64u) - 1u) / 64u);
    let a_4 = min((li_3 * run), cells_2);
    let b_3 = min((a_4 + run), cells_2);
    c_3 = a_4;
    loop {
        let _e25 = c_3;
        if (_e25 < b_3) {
        } else {
            break;
        }
        {
            let _e27 = sum;
            let _e30 = c_3;
            let _e33 = atomicLoad((&grid_fill[(g_4.fill + _e30)]));
            sum = (_e27 + _e33);
        }
        continuing {
            let _e36 = c_3;
            c_3 = (_e36 + 1u);
        }
    }
    let _e40 = sum;
    wg_sums[li_3] = _e40;
    workgroupBarrier();
    start = g_4.entries;
    loop {
        let _e45 = j_4;
        if (_e45 < li_3) {
        } else {
            break;
        }
        {
            let _e47 = start;
            let _e49 = j_4;
            let _e51 = wg_sums[_e49];
            start = (_e47 + _e51);
        }
        continuing {
            let _e54 = j_4;
            j_4 = (_e54 + 1u);
        }
    }
    c_4 = a_4;
    loop {
        let _e57 = c_4;
        if (_e57 < b_3) {
        } else {
            break;
        }
        {
            let _e61 = c_4;
            let n_3 = atomicLoad((&grid_fill[(g_4.fill + _e61)]));
            let _e66 = c_4;
            let _e69 = start;
            atomicStore((&grid[(starts_1 + _e66)]), _e69);
            let _e72 = c_4;
            let _e75 = start;
            atomicStore((&grid_fill[(g_4.fill + _e72)]), _e75);
            let _e76 = start;
            start = (_e76 + n_3);
        }
        continuing {
            let _e79 = c_4;
            c_4 = (_e79 + 1u);
        }
    }
    if ((li_3 + 1u) == 64u) {
        let _e88 = start;
        atomicStore((&grid[(starts_1 + cells_2)]), _e88);
        return;
    } else {
        return;
    }
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    let g_5 = grids[wid.z];
    let _e10 = params.stage;
    switch _e10 {
        case 0u: {
            count_levels(g_5, gid.x);
            return;
        }
        case 1u: {
            if (li == 0u) {
                choose_level(g_5);
                return;
            } else {
                return;
            }
        }
        case 3u: {
            scan_starts(g_5, li);
            return;
        }
        case 5u: {
            sort_cells(g_5, (((wid.y * groups.x) + wid.x) * 64u), li);
            return;
        }
        default: {
            let _e24 = params.stage;
            fill_cells(g_5, gid.x, (_e24 == 4u));
            return;
        }
    }
}
