//! Built-in shapes for scene files and the built-in scenes: the unit
//! sphere as a subdivided icosahedron with smooth (radial) vertex normals,
//! and midpoint subdivision of triangles (no file I/O: built without the
//! `io` feature too).

use crate::scene::{Camera, Material, PrimaryLight, Scene};
use glam::Vec3;

/// The unit sphere at the origin: an icosahedron whose triangles are split
/// into four `levels` times, every vertex pushed onto the sphere;
/// `20·4^levels` triangles wound counter-clockwise seen from outside, with
/// radial vertex normals, one Lambertian grey material.
pub fn sphere(levels: u32) -> Scene {
    let t = (1.0 + 5f32.sqrt()) / 2.0;
    let v = [
        Vec3::new(-1.0, t, 0.0),
        Vec3::new(1.0, t, 0.0),
        Vec3::new(-1.0, -t, 0.0),
        Vec3::new(1.0, -t, 0.0),
        Vec3::new(0.0, -1.0, t),
        Vec3::new(0.0, 1.0, t),
        Vec3::new(0.0, -1.0, -t),
        Vec3::new(0.0, 1.0, -t),
        Vec3::new(t, 0.0, -1.0),
        Vec3::new(t, 0.0, 1.0),
        Vec3::new(-t, 0.0, -1.0),
        Vec3::new(-t, 0.0, 1.0),
    ];
    let faces: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let base: Vec<[Vec3; 3]> = faces.iter().map(|f| f.map(|i| v[i].normalize())).collect();
    let triangles: Vec<[Vec3; 3]> =
        subdivide(&base, levels).into_iter().map(|t| t.map(Vec3::normalize)).collect();
    let normals = triangles.clone();
    Scene {
        name: "sphere".into(),
        material_of: vec![0; triangles.len()],
        triangles,
        normals,
        materials: vec![Material::lambertian(Vec3::splat(0.8), Vec3::ZERO)],
        camera: Camera {
            position: Vec3::new(0.0, 0.0, 4.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov_deg: 40.0,
        },
        primary: PrimaryLight::Directional { direction: -Vec3::Y, irradiance: Vec3::ONE },
        unsupported: Vec::new(),
    }
}

/// Splits every triangle into four at its edge midpoints, `levels` times.
pub fn subdivide(tris: &[[Vec3; 3]], levels: u32) -> Vec<[Vec3; 3]> {
    split_midpoints(tris, levels, |a, b| (a + b) * 0.5)
}

/// The vertex normals of [`subdivide`]d triangles (same order): each new
/// vertex gets the normalised mean of its edge's two normals.
pub fn subdivide_normals(normals: &[[Vec3; 3]], levels: u32) -> Vec<[Vec3; 3]> {
    split_midpoints(normals, levels, |a, b| (a + b).try_normalize().unwrap_or(a))
}

fn split_midpoints(
    tris: &[[Vec3; 3]],
    levels: u32,
    mid: impl Fn(Vec3, Vec3) -> Vec3,
) -> Vec<[Vec3; 3]> {
    let mut cur = tris.to_vec();
    for _ in 0..levels {
        let mut next = Vec::with_capacity(cur.len() * 4);
        for [a, b, c] in cur {
            let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
            next.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        cur = next;
    }
    cur
}

#[cfg(test)]
mod tests {
    #[test]
    fn sphere_is_closed_outward_and_round() {
        let s = super::sphere(3);
        assert_eq!(s.triangles.len(), 20 * 64);
        s.validate().unwrap();
        let mut area = 0.0;
        for (i, t) in s.triangles.iter().enumerate() {
            assert!(t.iter().all(|p| (p.length() - 1.0).abs() < 1e-6));
            // Outward winding: the geometric normal points away from the centre.
            assert!(s.geometric_normal(i).dot(t[0] + t[1] + t[2]) > 0.0, "triangle {i} faces in");
            area += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).length();
        }
        // The inscribed polyhedron's area approaches 4π from below.
        assert!(
            area < 4.0 * std::f32::consts::PI && area > 0.99 * 4.0 * std::f32::consts::PI,
            "{area}"
        );
    }
}
