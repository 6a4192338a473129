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
    pad0_: u32,
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

fn bsh_grid_budget(leaves: u32, cells: u32) -> u32 {
    if (leaves > 536870911u) {
        return 4294967295u;
    }
    let e = (leaves * GRID_ENTRIES_PER_LIGHT);
    let _e7 = add_wrap_u32_(e, cells);
    return select(_e7, 4294967295u, (_e7 < e));
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

fn bsh_grid_first(f_1: GridFrame, c_3: vec3<f32>, r: f32) -> vec3<u32> {
    let _e10 = bsh_grid_axis((c_3.x - r), f_1.lo.x, f_1.inv.x, f_1.nx);
    let _e18 = bsh_grid_axis((c_3.y - r), f_1.lo.y, f_1.inv.y, f_1.ny);
    let _e26 = bsh_grid_axis((c_3.z - r), f_1.lo.z, f_1.inv.z, f_1.nz);
    return vec3<u32>(_e10, _e18, _e26);
}

fn bsh_grid_last(f_2: GridFrame, c_4: vec3<f32>, r_1: f32) -> vec3<u32> {
    let _e10 = bsh_grid_axis((c_4.x + r_1), f_2.lo.x, f_2.inv.x, f_2.nx);
    let _e18 = bsh_grid_axis((c_4.y + r_1), f_2.lo.y, f_2.inv.y, f_2.ny);
    let _e26 = bsh_grid_axis((c_4.z + r_1), f_2.lo.z, f_2.inv.z, f_2.nz);
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

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
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
    var s: u32;
    var c_2: u32;
    var local_3: bool;
    var s_1: u32;

    let i_2 = gid.x;
    let h_1 = params.header;
    let starts = (h_1 + GRID_HEADER);
    let _e9 = params.stage;
    if (_e9 == 3u) {
        let _e12 = grid_frame(h_1);
        let cells_1 = ((_e12.nx * _e12.ny) * _e12.nz);
        let run = (((cells_1 + 64u) - 1u) / 64u);
        let a_1 = min((i_2 * run), cells_1);
        let b_1 = min((a_1 + run), cells_1);
        c = a_1;
        loop {
            let _e31 = c;
            if (_e31 < b_1) {
            } else {
                break;
            }
            {
                let _e33 = sum;
                let _e37 = params.fill;
                let _e38 = c;
                let _e41 = atomicLoad((&grid_fill[(_e37 + _e38)]));
                sum = (_e33 + _e41);
            }
            continuing {
                let _e44 = c;
                c = (_e44 + 1u);
            }
        }
        let _e48 = sum;
        wg_sums[i_2] = _e48;
        workgroupBarrier();
        let _e51 = params.entries;
        start = _e51;
        loop {
            let _e55 = j;
            if (_e55 < i_2) {
            } else {
                break;
            }
            {
                let _e57 = start;
                let _e59 = j;
                let _e61 = wg_sums[_e59];
                start = (_e57 + _e61);
            }
            continuing {
                let _e64 = j;
                j = (_e64 + 1u);
            }
        }
        c_1 = a_1;
        loop {
            let _e67 = c_1;
            if (_e67 < b_1) {
            } else {
                break;
            }
            {
                let _e72 = params.fill;
                let _e73 = c_1;
                let n_1 = atomicLoad((&grid_fill[(_e72 + _e73)]));
                let _e78 = c_1;
                let _e81 = start;
                atomicStore((&grid[(starts + _e78)]), _e81);
                let _e85 = params.fill;
                let _e86 = c_1;
                let _e89 = start;
                atomicStore((&grid_fill[(_e85 + _e86)]), _e89);
                let _e90 = start;
                start = (_e90 + n_1);
            }
            continuing {
                let _e93 = c_1;
                c_1 = (_e93 + 1u);
            }
        }
        if ((i_2 + 1u) == 64u) {
            let _e102 = start;
            atomicStore((&grid[(starts + cells_1)]), _e102);
        }
        return;
    }
    let _e105 = params.stage;
    switch _e105 {
        case 0u: {
            let _e108 = params.count;
            if (i_2 >= _e108) {
                return;
            }
            let _e110 = grid_leaf(i_2);
            if (_e110 == BSH_NONE) {
                return;
            }
            let _e118 = atomicAdd((&grid[(h_1 + 13u)]), 1u);
            let leaf = bsh_nodes[_e110];
            let _e124 = params.reach;
            let _e125 = bsh_grid_radius(leaf, _e124);
            loop {
                let _e128 = l;
                let _e131 = params.levels;
                if (_e128 < _e131) {
                } else {
                    break;
                }
                {
                    let _e134 = l;
                    let _e136 = grid_levels[_e134];
                    let _e138 = bsh_grid_last(_e136, leaf.center, _e125);
                    let _e140 = l;
                    let _e142 = grid_levels[_e140];
                    let _e144 = bsh_grid_first(_e142, leaf.center, _e125);
                    let d = ((_e138 - _e144) + vec3(1u));
                    let n_2 = ((d.x * d.y) * d.z);
                    let _e157 = l;
                    let at = ((h_1 + 16u) + (2u * _e157));
                    let _e162 = atomicAdd((&grid[at]), n_2);
                    if ((_e162 + n_2) < _e162) {
                        let _e170 = atomicAdd((&grid[(at + 1u)]), 1u);
                    }
                }
                continuing {
                    let _e172 = l;
                    l = (_e172 + 1u);
                }
            }
            return;
        }
        case 1u: {
            if (i_2 != 0u) {
                return;
            }
            let leaves_1 = atomicLoad((&grid[(h_1 + 13u)]));
            let _e183 = params.levels;
            chosen = _e183;
            loop {
                let _e187 = l_1;
                let _e190 = params.levels;
                if (_e187 < _e190) {
                } else {
                    break;
                }
                {
                    let _e193 = l_1;
                    let f_4 = grid_levels[_e193];
                    let cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    let _e201 = bsh_grid_budget(leaves_1, cells_2);
                    let _e204 = params.capacity;
                    let budget = min(_e201, _e204);
                    let _e209 = l_1;
                    let at_1 = ((h_1 + 16u) + (2u * _e209));
                    let _e212 = chosen;
                    let _e215 = params.levels;
                    if (_e212 == _e215) {
                        let _e223 = atomicLoad((&grid[(at_1 + 1u)]));
                        local = (_e223 == 0u);
                    } else {
                        local = false;
                    }
                    let _e227 = local;
                    if _e227 {
                        let _e232 = atomicLoad((&grid[at_1]));
                        local_1 = (_e232 <= budget);
                    } else {
                        local_1 = false;
                    }
                    let _e235 = local_1;
                    if _e235 {
                        let _e236 = l_1;
                        chosen = _e236;
                    }
                    atomicStore((&grid[at_1]), 0u);
                    atomicStore((&grid[(at_1 + 1u)]), 0u);
                }
                continuing {
                    let _e246 = l_1;
                    l_1 = (_e246 + 1u);
                }
            }
            atomicStore((&grid[(h_1 + 13u)]), 0u);
            let _e254 = chosen;
            let _e257 = params.levels;
            if (_e254 < _e257) {
                let _e260 = chosen;
                let _e262 = grid_levels[_e260];
                f = _e262;
            }
            let _e267 = f.lo.x;
            atomicStore((&grid[h_1]), bitcast<u32>(_e267));
            let _e275 = f.lo.y;
            atomicStore((&grid[(h_1 + 1u)]), bitcast<u32>(_e275));
            let _e283 = f.lo.z;
            atomicStore((&grid[(h_1 + 2u)]), bitcast<u32>(_e283));
            let _e290 = f.nx;
            atomicStore((&grid[(h_1 + 3u)]), _e290);
            let _e297 = f.hi.x;
            atomicStore((&grid[(h_1 + 4u)]), bitcast<u32>(_e297));
            let _e305 = f.hi.y;
            atomicStore((&grid[(h_1 + 5u)]), bitcast<u32>(_e305));
            let _e313 = f.hi.z;
            atomicStore((&grid[(h_1 + 6u)]), bitcast<u32>(_e313));
            let _e320 = f.ny;
            atomicStore((&grid[(h_1 + 7u)]), _e320);
            let _e327 = f.inv.x;
            atomicStore((&grid[(h_1 + 8u)]), bitcast<u32>(_e327));
            let _e335 = f.inv.y;
            atomicStore((&grid[(h_1 + 9u)]), bitcast<u32>(_e335));
            let _e343 = f.inv.z;
            atomicStore((&grid[(h_1 + 10u)]), bitcast<u32>(_e343));
            let _e350 = f.nz;
            atomicStore((&grid[(h_1 + 11u)]), _e350);
            let _e357 = params.reach;
            atomicStore((&grid[(h_1 + 12u)]), bitcast<u32>(_e357));
            return;
        }
        case 2u, 4u: {
            let _e361 = params.count;
            if (i_2 >= _e361) {
                return;
            }
            let _e363 = grid_frame(h_1);
            let _e364 = grid_leaf(i_2);
            if !((_e363.nx == 0u)) {
                local_2 = (_e364 == BSH_NONE);
            } else {
                local_2 = true;
            }
            let _e374 = local_2;
            if _e374 {
                return;
            }
            let leaf_1 = bsh_nodes[_e364];
            let _e380 = params.reach;
            let _e381 = bsh_grid_radius(leaf_1, _e380);
            let _e383 = bsh_grid_first(_e363, leaf_1.center, _e381);
            let _e385 = bsh_grid_last(_e363, leaf_1.center, _e381);
            z = _e383.z;
            loop {
                let _e388 = z;
                if (_e388 <= _e385.z) {
                } else {
                    break;
                }
                {
                    y = _e383.y;
                    loop {
                        let _e393 = y;
                        if (_e393 <= _e385.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e383.x;
                            loop {
                                let _e398 = x;
                                if (_e398 <= _e385.x) {
                                } else {
                                    break;
                                }
                                {
                                    let _e401 = z;
                                    let _e404 = y;
                                    let _e408 = x;
                                    let c_5 = ((((_e401 * _e363.ny) + _e404) * _e363.nx) + _e408);
                                    let _e413 = params.fill;
                                    let _e417 = atomicAdd((&grid_fill[(_e413 + c_5)]), 1u);
                                    let _e420 = params.stage;
                                    if (_e420 == 4u) {
                                        grid_entries[_e417] = i_2;
                                    }
                                }
                                continuing {
                                    let _e426 = x;
                                    x = (_e426 + 1u);
                                }
                            }
                        }
                        continuing {
                            let _e429 = y;
                            y = (_e429 + 1u);
                        }
                    }
                }
                continuing {
                    let _e432 = z;
                    z = (_e432 + 1u);
                }
            }
            return;
        }
        default: {
            let _e434 = grid_frame(h_1);
            if (i_2 >= ((_e434.nx * _e434.ny) * _e434.nz)) {
                return;
            }
            let _e444 = params.fill;
            atomicStore((&grid_fill[(_e444 + i_2)]), 0u);
            let a_2 = atomicLoad((&grid[(starts + i_2)]));
            let b_2 = atomicLoad((&grid[((starts + i_2) + 1u)]));
            s = (a_2 + 1u);
            loop {
                let _e461 = s;
                if (_e461 < b_2) {
                } else {
                    break;
                }
                {
                    let _e464 = s;
                    let v_1 = grid_entries[_e464];
                    let _e467 = s;
                    c_2 = _e467;
                    loop {
                        let _e469 = c_2;
                        if (_e469 > a_2) {
                            let _e474 = c_2;
                            let _e478 = grid_entries[(_e474 - 1u)];
                            local_3 = (_e478 > v_1);
                        } else {
                            local_3 = false;
                        }
                        let _e481 = local_3;
                        if _e481 {
                        } else {
                            break;
                        }
                        {
                            let _e483 = c_2;
                            let _e486 = c_2;
                            let _e490 = grid_entries[(_e486 - 1u)];
                            grid_entries[_e483] = _e490;
                            let _e491 = c_2;
                            c_2 = (_e491 - 1u);
                        }
                    }
                    let _e495 = c_2;
                    grid_entries[_e495] = v_1;
                }
                continuing {
                    let _e498 = s;
                    s = (_e498 + 1u);
                }
            }
            s_1 = a_2;
            loop {
                let _e501 = s_1;
                if (_e501 < b_2) {
                } else {
                    break;
                }
                {
                    let _e504 = s_1;
                    let _e508 = s_1;
                    let _e510 = grid_entries[_e508];
                    let _e512 = grid_leaves[_e510];
                    grid_entries[_e504] = _e512;
                }
                continuing {
                    let _e514 = s_1;
                    s_1 = (_e514 + 1u);
                }
            }
            return;
        }
    }
}
