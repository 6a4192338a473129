// Light evaluation for the light types this scene has (others compiled out).

/// RGB radiant intensity of `l` toward unit `w` (pointing away from the light).
fn light_intensity(l: GpuLight, w: vec3f) -> vec3f {
    switch l.kind {
{% if point %}
        case LIGHT_POINT: { return l.intensity; }
{% endif %}
{% if spot %}
        case LIGHT_SPOT: { return l.intensity * spot_falloff(dot(l.p1, w), l.a, l.b, l.p2.x); }
{% endif %}
{% if ies %}
        case LIGHT_IES: { return l.intensity * ies_light_candela(0u, l.ies_base, l.p1, l.p2, w); }
{% endif %}
{% if triangle %}
        case LIGHT_TRIANGLE: {
            return l.intensity * triangle_lobe(triangle_normal(l.p0, l.p1, l.p2), l.a, w);
        }
{% endif %}
{% if vpl %}
        case LIGHT_VPL: { return l.intensity * vpl_lobe(l.p1, w); }
{% endif %}
        default: { return vec3f(0.0); }
    }
}

/// The point of `l` that a connection goes to: its position, or a uniform
/// point on a triangle for `u1, u2 ∈ [0, 1)`.
fn light_point(l: GpuLight, u1: f32, u2: f32) -> vec3f {
{% if triangle %}
    if l.kind == LIGHT_TRIANGLE {
        return triangle_sample(l.p0, l.p1, l.p2, u1, u2);
    }
{% endif %}
    return l.p0;
}

/// Area of an area light (0 for point-like lights, which are delta lights).
fn light_area(l: GpuLight) -> f32 {
{% if triangle %}
    if l.kind == LIGHT_TRIANGLE {
        return l.a;
    }
{% endif %}
    return 0.0;
}

/// Unit normal of an area light (zero for point-like lights).
fn light_normal(l: GpuLight) -> vec3f {
{% if triangle %}
    if l.kind == LIGHT_TRIANGLE {
        return triangle_normal(l.p0, l.p1, l.p2);
    }
{% endif %}
    return vec3f(0.0);
}
