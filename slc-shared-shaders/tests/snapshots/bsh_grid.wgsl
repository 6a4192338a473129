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
    let _e9 = to_u32_(max(floor(((v - lo) * inv)), 0f));
    return min(_e9, (n - 1u));
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
    let node_3 = grid_leaves[i_1];
    let _e7 = bsh_nodes[node_3].light;
    if ((_e7 & BSH_TAIL) != 0u) {
        return BSH_NONE;
    }
    return node_3;
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
            let _e125 = bsh_grid_reach(leaf, _e124);
            let _e126 = bsh_grid_pad(_e125);
            loop {
                let _e129 = l;
                let _e132 = params.levels;
                if (_e129 < _e132) {
                } else {
                    break;
                }
                {
                    let _e135 = l;
                    let _e137 = grid_levels[_e135];
                    let _e139 = bsh_grid_last(_e137, leaf.center, _e126);
                    let _e141 = l;
                    let _e143 = grid_levels[_e141];
                    let _e145 = bsh_grid_first(_e143, leaf.center, _e126);
                    let d = ((_e139 - _e145) + vec3(1u));
                    let n_2 = ((d.x * d.y) * d.z);
                    let _e158 = l;
                    let at = ((h_1 + 16u) + (2u * _e158));
                    let _e163 = atomicAdd((&grid[at]), n_2);
                    if ((_e163 + n_2) < _e163) {
                        let _e171 = atomicAdd((&grid[(at + 1u)]), 1u);
                    }
                }
                continuing {
                    let _e173 = l;
                    l = (_e173 + 1u);
                }
            }
            return;
        }
        case 1u: {
            if (i_2 != 0u) {
                return;
            }
            let leaves_1 = atomicLoad((&grid[(h_1 + 13u)]));
            let _e184 = params.levels;
            chosen = _e184;
            loop {
                let _e188 = l_1;
                let _e191 = params.levels;
                if (_e188 < _e191) {
                } else {
                    break;
                }
                {
                    let _e194 = l_1;
                    let f_4 = grid_levels[_e194];
                    let cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    let _e202 = bsh_grid_budget(leaves_1, cells_2);
                    let _e205 = params.capacity;
                    let budget = min(_e202, _e205);
                    let _e210 = l_1;
                    let at_1 = ((h_1 + 16u) + (2u * _e210));
                    let _e213 = chosen;
                    let _e216 = params.levels;
                    if (_e213 == _e216) {
                        let _e224 = atomicLoad((&grid[(at_1 + 1u)]));
                        local = (_e224 == 0u);
                    } else {
                        local = false;
                    }
                    let _e228 = local;
                    if _e228 {
                        let _e233 = atomicLoad((&grid[at_1]));
                        local_1 = (_e233 <= budget);
                    } else {
                        local_1 = false;
                    }
                    let _e236 = local_1;
                    if _e236 {
                        let _e237 = l_1;
                        chosen = _e237;
                    }
                    atomicStore((&grid[at_1]), 0u);
                    atomicStore((&grid[(at_1 + 1u)]), 0u);
                }
                continuing {
                    let _e247 = l_1;
                    l_1 = (_e247 + 1u);
                }
            }
            atomicStore((&grid[(h_1 + 13u)]), 0u);
            let _e255 = chosen;
            let _e258 = params.levels;
            if (_e255 < _e258) {
                let _e261 = chosen;
                let _e263 = grid_levels[_e261];
                f = _e263;
            }
            let _e268 = f.lo.x;
            atomicStore((&grid[h_1]), bitcast<u32>(_e268));
            let _e276 = f.lo.y;
            atomicStore((&grid[(h_1 + 1u)]), bitcast<u32>(_e276));
            let _e284 = f.lo.z;
            atomicStore((&grid[(h_1 + 2u)]), bitcast<u32>(_e284));
            let _e291 = f.nx;
            atomicStore((&grid[(h_1 + 3u)]), _e291);
            let _e298 = f.hi.x;
            atomicStore((&grid[(h_1 + 4u)]), bitcast<u32>(_e298));
            let _e306 = f.hi.y;
            atomicStore((&grid[(h_1 + 5u)]), bitcast<u32>(_e306));
            let _e314 = f.hi.z;
            atomicStore((&grid[(h_1 + 6u)]), bitcast<u32>(_e314));
            let _e321 = f.ny;
            atomicStore((&grid[(h_1 + 7u)]), _e321);
            let _e328 = f.inv.x;
            atomicStore((&grid[(h_1 + 8u)]), bitcast<u32>(_e328));
            let _e336 = f.inv.y;
            atomicStore((&grid[(h_1 + 9u)]), bitcast<u32>(_e336));
            let _e344 = f.inv.z;
            atomicStore((&grid[(h_1 + 10u)]), bitcast<u32>(_e344));
            let _e351 = f.nz;
            atomicStore((&grid[(h_1 + 11u)]), _e351);
            let _e358 = params.reach;
            atomicStore((&grid[(h_1 + 12u)]), bitcast<u32>(_e358));
            return;
        }
        case 2u, 4u: {
            let _e362 = params.count;
            if (i_2 >= _e362) {
                return;
            }
            let _e364 = grid_frame(h_1);
            let _e365 = grid_leaf(i_2);
            if !((_e364.nx == 0u)) {
                local_2 = (_e365 == BSH_NONE);
            } else {
                local_2 = true;
            }
            let _e375 = local_2;
            if _e375 {
                return;
            }
            let leaf_1 = bsh_nodes[_e365];
            let _e381 = params.reach;
            let _e382 = bsh_grid_reach(leaf_1, _e381);
            let _e383 = bsh_grid_pad(_e382);
            let _e385 = bsh_grid_first(_e364, leaf_1.center, _e383);
            let _e387 = bsh_grid_last(_e364, leaf_1.center, _e383);
            z = _e385.z;
            loop {
                let _e390 = z;
                if (_e390 <= _e387.z) {
                } else {
                    break;
                }
                {
                    y = _e385.y;
                    loop {
                        let _e395 = y;
                        if (_e395 <= _e387.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e385.x;
                            loop {
                                let _e400 = x;
                                if (_e400 <= _e387.x) {
                                } else {
                                    break;
                                }
                                {
                                    let _e403 = z;
                                    let _e406 = y;
                                    let _e410 = x;
                                    let c_5 = ((((_e403 * _e364.ny) + _e406) * _e364.nx) + _e410);
                                    let _e415 = params.fill;
                                    let _e419 = atomicAdd((&grid_fill[(_e415 + c_5)]), 1u);
                                    let _e422 = params.stage;
                                    if (_e422 == 4u) {
                                        grid_entries[_e419] = i_2;
                                    }
                                }
                                continuing {
                                    let _e428 = x;
                                    x = (_e428 + 1u);
                                }
                            }
                        }
                        continuing {
                            let _e431 = y;
                            y = (_e431 + 1u);
                        }
                    }
                }
                continuing {
                    let _e434 = z;
                    z = (_e434 + 1u);
                }
            }
            return;
        }
        default: {
            let _e436 = grid_frame(h_1);
            if (i_2 >= ((_e436.nx * _e436.ny) * _e436.nz)) {
                return;
            }
            let _e446 = params.fill;
            atomicStore((&grid_fill[(_e446 + i_2)]), 0u);
            let a_2 = atomicLoad((&grid[(starts + i_2)]));
            let b_2 = atomicLoad((&grid[((starts + i_2) + 1u)]));
            s = (a_2 + 1u);
            loop {
                let _e463 = s;
                if (_e463 < b_2) {
                } else {
                    break;
                }
                {
                    let _e466 = s;
                    let v_1 = grid_entries[_e466];
                    let _e469 = s;
                    c_2 = _e469;
                    loop {
                        let _e471 = c_2;
                        if (_e471 > a_2) {
                            let _e476 = c_2;
                            let _e480 = grid_entries[(_e476 - 1u)];
                            local_3 = (_e480 > v_1);
                        } else {
                            local_3 = false;
                        }
                        let _e483 = local_3;
                        if _e483 {
                        } else {
                            break;
                        }
                        {
                            let _e485 = c_2;
                            let _e488 = c_2;
                            let _e492 = grid_entries[(_e488 - 1u)];
                            grid_entries[_e485] = _e492;
                            let _e493 = c_2;
                            c_2 = (_e493 - 1u);
                        }
                    }
                    let _e497 = c_2;
                    grid_entries[_e497] = v_1;
                }
                continuing {
                    let _e500 = s;
                    s = (_e500 + 1u);
                }
            }
            s_1 = a_2;
            loop {
                let _e503 = s_1;
                if (_e503 < b_2) {
                } else {
                    break;
                }
                {
                    let _e506 = s_1;
                    let _e510 = s_1;
                    let _e512 = grid_entries[_e510];
                    let _e514 = grid_leaves[_e512];
                    grid_entries[_e506] = _e514;
                }
                continuing {
                    let _e516 = s_1;
                    s_1 = (_e516 + 1u);
                }
            }
            return;
        }
    }
}
