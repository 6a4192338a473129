struct GridParams {
    stage: u32,
    count: u32,
    levels: u32,
    capacity: u32,
    reach: f32,
    cells: u32,
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

fn grid_word(i: u32) -> u32 {
    let _e3 = atomicLoad((&grid[i]));
    return _e3;
}

fn grid_frame() -> GridFrame {
    var f_1: GridFrame;

    let _e3 = grid_word(0u);
    let _e6 = grid_word(1u);
    let _e9 = grid_word(2u);
    f_1.lo = vec3<f32>(bitcast<f32>(_e3), bitcast<f32>(_e6), bitcast<f32>(_e9));
    let _e14 = grid_word(3u);
    f_1.nx = _e14;
    let _e17 = grid_word(4u);
    let _e20 = grid_word(5u);
    let _e23 = grid_word(6u);
    f_1.hi = vec3<f32>(bitcast<f32>(_e17), bitcast<f32>(_e20), bitcast<f32>(_e23));
    let _e28 = grid_word(7u);
    f_1.ny = _e28;
    let _e31 = grid_word(8u);
    let _e34 = grid_word(9u);
    let _e37 = grid_word(10u);
    f_1.inv = vec3<f32>(bitcast<f32>(_e31), bitcast<f32>(_e34), bitcast<f32>(_e37));
    let _e42 = grid_word(11u);
    f_1.nz = _e42;
    let _e43 = f_1;
    return _e43;
}

fn grid_leaf(i_1: u32) -> u32 {
    let node_5 = grid_leaves[i_1];
    let _e7 = bsh_nodes[node_5].light;
    if ((_e7 & BSH_TAIL) != 0u) {
        return BSH_NONE;
    }
    return node_5;
}

fn cover_first(f_2: GridFrame, node_3: BshNode, r: f32) -> vec3<u32> {
    let c_3 = node_3.center;
    let _e11 = bsh_grid_axis((c_3.x - r), f_2.lo.x, f_2.inv.x, f_2.nx);
    let _e19 = bsh_grid_axis((c_3.y - r), f_2.lo.y, f_2.inv.y, f_2.ny);
    let _e27 = bsh_grid_axis((c_3.z - r), f_2.lo.z, f_2.inv.z, f_2.nz);
    return vec3<u32>(_e11, _e19, _e27);
}

fn cover_last(f_3: GridFrame, node_4: BshNode, r_1: f32) -> vec3<u32> {
    let c_4 = node_4.center;
    let _e11 = bsh_grid_axis((c_4.x + r_1), f_3.lo.x, f_3.inv.x, f_3.nx);
    let _e19 = bsh_grid_axis((c_4.y + r_1), f_3.lo.y, f_3.inv.y, f_3.ny);
    let _e27 = bsh_grid_axis((c_4.z + r_1), f_3.lo.z, f_3.inv.z, f_3.nz);
    return vec3<u32>(_e11, _e19, _e27);
}

@compute @workgroup_size(64, 1, 1) 
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    var sum: u32 = 0u;
    var c: u32;
    var start: u32 = 0u;
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
    let _e4 = params.stage;
    if (_e4 == 3u) {
        let _e7 = grid_frame();
        let cells_1 = ((_e7.nx * _e7.ny) * _e7.nz);
        let run = (((cells_1 + 64u) - 1u) / 64u);
        let a_1 = min((i_2 * run), cells_1);
        let b_1 = min((a_1 + run), cells_1);
        c = a_1;
        loop {
            let _e26 = c;
            if (_e26 < b_1) {
            } else {
                break;
            }
            {
                let _e28 = sum;
                let _e30 = c;
                let _e32 = atomicLoad((&grid_fill[_e30]));
                sum = (_e28 + _e32);
            }
            continuing {
                let _e35 = c;
                c = (_e35 + 1u);
            }
        }
        let _e39 = sum;
        wg_sums[i_2] = _e39;
        workgroupBarrier();
        loop {
            let _e44 = j;
            if (_e44 < i_2) {
            } else {
                break;
            }
            {
                let _e46 = start;
                let _e48 = j;
                let _e50 = wg_sums[_e48];
                start = (_e46 + _e50);
            }
            continuing {
                let _e53 = j;
                j = (_e53 + 1u);
            }
        }
        c_1 = a_1;
        loop {
            let _e56 = c_1;
            if (_e56 < b_1) {
            } else {
                break;
            }
            {
                let _e59 = c_1;
                let n_1 = atomicLoad((&grid_fill[_e59]));
                let _e64 = c_1;
                let _e67 = start;
                atomicStore((&grid[(GRID_HEADER + _e64)]), _e67);
                let _e69 = c_1;
                let _e71 = start;
                atomicStore((&grid_fill[_e69]), _e71);
                let _e72 = start;
                start = (_e72 + n_1);
            }
            continuing {
                let _e75 = c_1;
                c_1 = (_e75 + 1u);
            }
        }
        if ((i_2 + 1u) == 64u) {
            let _e85 = start;
            atomicStore((&grid[(GRID_HEADER + cells_1)]), _e85);
        }
        return;
    }
    let _e88 = params.stage;
    switch _e88 {
        case 0u: {
            let _e91 = params.count;
            if (i_2 >= _e91) {
                return;
            }
            let _e93 = grid_leaf(i_2);
            if (_e93 == BSH_NONE) {
                return;
            }
            let _e99 = atomicAdd((&grid[13]), 1u);
            let leaf = bsh_nodes[_e93];
            let _e105 = params.reach;
            let _e106 = bsh_grid_reach(leaf, _e105);
            let _e107 = bsh_grid_pad(_e106);
            loop {
                let _e110 = l;
                let _e113 = params.levels;
                if (_e110 < _e113) {
                } else {
                    break;
                }
                {
                    let _e116 = l;
                    let _e118 = grid_levels[_e116];
                    let _e119 = cover_last(_e118, leaf, _e107);
                    let _e121 = l;
                    let _e123 = grid_levels[_e121];
                    let _e124 = cover_first(_e123, leaf, _e107);
                    let d = ((_e119 - _e124) + vec3(1u));
                    let n_2 = ((d.x * d.y) * d.z);
                    let _e136 = l;
                    let at = (16u + (2u * _e136));
                    let _e141 = atomicAdd((&grid[at]), n_2);
                    if ((_e141 + n_2) < _e141) {
                        let _e149 = atomicAdd((&grid[(at + 1u)]), 1u);
                    }
                }
                continuing {
                    let _e151 = l;
                    l = (_e151 + 1u);
                }
            }
            return;
        }
        case 1u: {
            if (i_2 != 0u) {
                return;
            }
            let leaves_1 = atomicLoad((&grid[13]));
            let _e160 = params.levels;
            chosen = _e160;
            loop {
                let _e164 = l_1;
                let _e167 = params.levels;
                if (_e164 < _e167) {
                } else {
                    break;
                }
                {
                    let _e170 = l_1;
                    let f_4 = grid_levels[_e170];
                    let cells_2 = ((f_4.nx * f_4.ny) * f_4.nz);
                    let _e178 = bsh_grid_budget(leaves_1, cells_2);
                    let _e181 = params.capacity;
                    let budget = min(_e178, _e181);
                    let _e183 = chosen;
                    let _e186 = params.levels;
                    if (_e183 == _e186) {
                        let _e193 = l_1;
                        let _e197 = atomicLoad((&grid[(17u + (2u * _e193))]));
                        local = (_e197 == 0u);
                    } else {
                        local = false;
                    }
                    let _e201 = local;
                    if _e201 {
                        let _e207 = l_1;
                        let _e211 = atomicLoad((&grid[(16u + (2u * _e207))]));
                        local_1 = (_e211 <= budget);
                    } else {
                        local_1 = false;
                    }
                    let _e214 = local_1;
                    if _e214 {
                        let _e215 = l_1;
                        chosen = _e215;
                    }
                    let _e219 = l_1;
                    atomicStore((&grid[(16u + (2u * _e219))]), 0u);
                    let _e227 = l_1;
                    atomicStore((&grid[(17u + (2u * _e227))]), 0u);
                }
                continuing {
                    let _e233 = l_1;
                    l_1 = (_e233 + 1u);
                }
            }
            atomicStore((&grid[13]), 0u);
            let _e239 = chosen;
            let _e242 = params.levels;
            if (_e239 < _e242) {
                let _e245 = chosen;
                let _e247 = grid_levels[_e245];
                f = _e247;
            }
            let _e252 = f.lo.x;
            atomicStore((&grid[0]), bitcast<u32>(_e252));
            let _e258 = f.lo.y;
            atomicStore((&grid[1]), bitcast<u32>(_e258));
            let _e264 = f.lo.z;
            atomicStore((&grid[2]), bitcast<u32>(_e264));
            let _e269 = f.nx;
            atomicStore((&grid[3]), _e269);
            let _e274 = f.hi.x;
            atomicStore((&grid[4]), bitcast<u32>(_e274));
            let _e280 = f.hi.y;
            atomicStore((&grid[5]), bitcast<u32>(_e280));
            let _e286 = f.hi.z;
            atomicStore((&grid[6]), bitcast<u32>(_e286));
            let _e291 = f.ny;
            atomicStore((&grid[7]), _e291);
            let _e296 = f.inv.x;
            atomicStore((&grid[8]), bitcast<u32>(_e296));
            let _e302 = f.inv.y;
            atomicStore((&grid[9]), bitcast<u32>(_e302));
            let _e308 = f.inv.z;
            atomicStore((&grid[10]), bitcast<u32>(_e308));
            let _e313 = f.nz;
            atomicStore((&grid[11]), _e313);
            let _e318 = params.reach;
            atomicStore((&grid[12]), bitcast<u32>(_e318));
            return;
        }
        case 2u, 4u: {
            let _e322 = params.count;
            if (i_2 >= _e322) {
                return;
            }
            let _e324 = grid_frame();
            let _e325 = grid_leaf(i_2);
            if !((_e324.nx == 0u)) {
                local_2 = (_e325 == BSH_NONE);
            } else {
                local_2 = true;
            }
            let _e335 = local_2;
            if _e335 {
                return;
            }
            let leaf_1 = bsh_nodes[_e325];
            let _e341 = params.reach;
            let _e342 = bsh_grid_reach(leaf_1, _e341);
            let _e343 = bsh_grid_pad(_e342);
            let _e344 = cover_first(_e324, leaf_1, _e343);
            let _e345 = cover_last(_e324, leaf_1, _e343);
            z = _e344.z;
            loop {
                let _e348 = z;
                if (_e348 <= _e345.z) {
                } else {
                    break;
                }
                {
                    y = _e344.y;
                    loop {
                        let _e353 = y;
                        if (_e353 <= _e345.y) {
                        } else {
                            break;
                        }
                        {
                            x = _e344.x;
                            loop {
                                let _e358 = x;
                                if (_e358 <= _e345.x) {
                                } else {
                                    break;
                                }
                                {
                                    let _e361 = z;
                                    let _e364 = y;
                                    let _e368 = x;
                                    let c_5 = ((((_e361 * _e324.ny) + _e364) * _e324.nx) + _e368);
                                    let _e373 = atomicAdd((&grid_fill[c_5]), 1u);
                                    let _e376 = params.stage;
                                    if (_e376 == 4u) {
                                        grid_entries[_e373] = i_2;
                                    }
                                }
                                continuing {
                                    let _e382 = x;
                                    x = (_e382 + 1u);
                                }
                            }
                        }
                        continuing {
                            let _e385 = y;
                            y = (_e385 + 1u);
                        }
                    }
                }
                continuing {
                    let _e388 = z;
                    z = (_e388 + 1u);
                }
            }
            return;
        }
        default: {
            let _e390 = grid_frame();
            if (i_2 >= ((_e390.nx * _e390.ny) * _e390.nz)) {
                return;
            }
            atomicStore((&grid_fill[i_2]), 0u);
            let a_2 = atomicLoad((&grid[(GRID_HEADER + i_2)]));
            let b_2 = atomicLoad((&grid[((GRID_HEADER + i_2) + 1u)]));
            s = (a_2 + 1u);
            loop {
                let _e415 = s;
                if (_e415 < b_2) {
                } else {
                    break;
                }
                {
                    let _e418 = s;
                    let v_1 = grid_entries[_e418];
                    let _e421 = s;
                    c_2 = _e421;
                    loop {
                        let _e423 = c_2;
                        if (_e423 > a_2) {
                            let _e428 = c_2;
                            let _e432 = grid_entries[(_e428 - 1u)];
                            local_3 = (_e432 > v_1);
                        } else {
                            local_3 = false;
                        }
                        let _e435 = local_3;
                        if _e435 {
                        } else {
                            break;
                        }
                        {
                            let _e437 = c_2;
                            let _e440 = c_2;
                            let _e444 = grid_entries[(_e440 - 1u)];
                            grid_entries[_e437] = _e444;
                            let _e445 = c_2;
                            c_2 = (_e445 - 1u);
                        }
                    }
                    let _e449 = c_2;
                    grid_entries[_e449] = v_1;
                }
                continuing {
                    let _e452 = s;
                    s = (_e452 + 1u);
                }
            }
            s_1 = a_2;
            loop {
                let _e455 = s_1;
                if (_e455 < b_2) {
                } else {
                    break;
                }
                {
                    let _e458 = s_1;
                    let _e462 = s_1;
                    let _e464 = grid_entries[_e462];
                    let _e466 = grid_leaves[_e464];
                    grid_entries[_e458] = _e466;
                }
                continuing {
                    let _e468 = s_1;
                    s_1 = (_e468 + 1u);
                }
            }
            return;
        }
    }
}
