{% include "header.wgsl" %}
{% include "lights.wgsl" %}
// The VPL frame's raster passes over the scene's triangles: `vs_main` with
// `fs_gbuffer` (the camera's G-buffer), `fs_rsm` (the primary light's
// reflective shadow map) or `fs_shadow` (its shadow map). Normals are the shading normal on the side the
// viewer (camera or light) sees, as the CPU's ray casting makes them.

{{ bindings }}

struct VsOut {
    @builtin(position) clip: vec4f,
    @location(0) world: vec3f,
    @location(1) normal: vec3f,
    @location(2) @interpolate(flat) geo: vec3f,
    @location(3) @interpolate(flat) material: u32,
}

@vertex
fn vs_main(@location(0) position: vec3f, @location(1) material: u32, @location(2) normal: vec3f, @location(3) geo: vec3f) -> VsOut {
    let m = mat4x4f(params.c0, params.c1, params.c2, params.c3);
    return VsOut(m * vec4f(position, 1.0), position, normal, geo, material);
}

/// The shading normal at a fragment seen along `dir` (the interpolated
/// vertex normal is the barycentric sum `shading_normal` takes).
fn seen_normal(v: VsOut, dir: vec3f) -> vec3f {
    return shading_normal(v.normal, vec3f(0.0), vec3f(0.0), vec3f(1.0, 0.0, 0.0), face_against(v.geo, dir));
}

struct GbufferOut {
    /// World position, w = 1.
    @location(0) position: vec4f,
    /// Unit normal facing the camera, w = material index.
    @location(1) normal: vec4f,
}

@fragment
fn fs_gbuffer(v: VsOut) -> GbufferOut {
    let n = seen_normal(v, v.world - params.origin);
    return GbufferOut(vec4f(v.world, 1.0), vec4f(n, f32(v.material)));
}

struct RsmOut {
    /// World position, w = 1.
    @location(0) position: vec4f,
    /// Unit normal facing the light.
    @location(1) normal: vec4f,
    /// Reflected flux: incident flux of the texel × albedo.
    @location(2) flux: vec4f,
}

@fragment
fn fs_rsm(v: VsOut) -> RsmOut {
    var dir = params.axis;
    var incident = params.light.intensity * params.texel;
    if params.mode == MAP_PERSPECTIVE {
        dir = normalize(v.world - params.origin);
        incident = light_intensity(params.light, dir) * rsm_texel_solid_angle(params.texel, dot(dir, params.axis));
    }
    let albedo = materials[v.material].albedo;
    return RsmOut(vec4f(v.world, 1.0), vec4f(seen_normal(v, dir), 0.0), vec4f(incident * albedo, 0.0));
}

/// Distance along the light's ray: from the light (perspective) or from
/// the map's plane (orthographic).
@fragment
fn fs_shadow(v: VsOut) -> @location(0) vec4f {
    return vec4f(light_map_depth(v.world - params.origin, params.axis, params.mode == MAP_PERSPECTIVE), 0.0, 0.0, 0.0);
}
