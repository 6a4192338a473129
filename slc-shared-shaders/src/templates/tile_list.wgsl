// vpl_tiled's light list for cluster_cull.wgsl: one list of MAX_TILE_LIGHTS
// light slots that every invocation of the tile shades (the including
// kernel defines MAX_TILE_LIGHTS, at least CLUSTER, and
// fn shade_list(count: u32), which shades tile_lights[..count]).

var<workgroup> tile_lights: array<u32, MAX_TILE_LIGHTS>;
var<workgroup> list_count: atomic<u32>;

fn list_clear(li: u32) {
    if li == 0u {
        atomicStore(&list_count, 0u);
    }
}

fn list_full() -> bool {
    return workgroupUniformLoad(&list_count) + CLUSTER > MAX_TILE_LIGHTS;
}

fn list_add(slot: u32, p: vec3f, radius: f32) {
    tile_lights[atomicAdd(&list_count, 1u)] = slot;
}

fn list_shade() {
    shade_list(workgroupUniformLoad(&list_count));
}
