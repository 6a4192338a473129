//! The built-in Cornell box (no file needed), and a many-light variant of it.

use crate::scene::{Camera, Material, PrimaryLight, Scene};
use glam::Vec3;

impl Scene {
    /// The built-in Cornell box, from the measurements published by the
    /// Cornell Program of Computer Graphics ("Cornell Box Data"), converted
    /// from millimetres to metres, with the reflectances of McGuire's
    /// Computer Graphics Archive version. The primary light is a spot at the
    /// ceiling light's centre pointing down; its peak intensity is that of the
    /// measured light (radiance `(17, 12, 4)` times its 0.130 × 0.105 m area).
    pub fn cornell_box() -> Scene {
        let mm = |x: f32, y: f32, z: f32| Vec3::new(x, y, z) * 0.001;
        let white = Material::lambertian(Vec3::new(0.725, 0.71, 0.68), Vec3::ZERO);
        let red = Material::lambertian(Vec3::new(0.63, 0.065, 0.05), Vec3::ZERO);
        let green = Material::lambertian(Vec3::new(0.14, 0.45, 0.091), Vec3::ZERO);
        let light = Material::lambertian(Vec3::splat(0.78), Vec3::new(17.0, 12.0, 4.0));
        let quads: [([[f32; 3]; 4], u32); 16] = [
            // Floor, ceiling, back wall (white), right wall (green), left wall (red).
            ([[552.8, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 559.2], [549.6, 0.0, 559.2]], 0),
            (
                [
                    [556.0, 548.8, 0.0],
                    [556.0, 548.8, 559.2],
                    [0.0, 548.8, 559.2],
                    [0.0, 548.8, 0.0],
                ],
                0,
            ),
            (
                [
                    [549.6, 0.0, 559.2],
                    [0.0, 0.0, 559.2],
                    [0.0, 548.8, 559.2],
                    [556.0, 548.8, 559.2],
                ],
                0,
            ),
            ([[0.0, 0.0, 559.2], [0.0, 0.0, 0.0], [0.0, 548.8, 0.0], [0.0, 548.8, 559.2]], 2),
            (
                [
                    [552.8, 0.0, 0.0],
                    [549.6, 0.0, 559.2],
                    [556.0, 548.8, 559.2],
                    [556.0, 548.8, 0.0],
                ],
                1,
            ),
            // Short block.
            (
                [
                    [130.0, 165.0, 65.0],
                    [82.0, 165.0, 225.0],
                    [240.0, 165.0, 272.0],
                    [290.0, 165.0, 114.0],
                ],
                0,
            ),
            (
                [
                    [290.0, 0.0, 114.0],
                    [290.0, 165.0, 114.0],
                    [240.0, 165.0, 272.0],
                    [240.0, 0.0, 272.0],
                ],
                0,
            ),
            (
                [
                    [130.0, 0.0, 65.0],
                    [130.0, 165.0, 65.0],
                    [290.0, 165.0, 114.0],
                    [290.0, 0.0, 114.0],
                ],
                0,
            ),
            (
                [
                    [82.0, 0.0, 225.0],
                    [82.0, 165.0, 225.0],
                    [130.0, 165.0, 65.0],
                    [130.0, 0.0, 65.0],
                ],
                0,
            ),
            (
                [
                    [240.0, 0.0, 272.0],
                    [240.0, 165.0, 272.0],
                    [82.0, 165.0, 225.0],
                    [82.0, 0.0, 225.0],
                ],
                0,
            ),
            // Tall block.
            (
                [
                    [423.0, 330.0, 247.0],
                    [265.0, 330.0, 296.0],
                    [314.0, 330.0, 456.0],
                    [472.0, 330.0, 406.0],
                ],
                0,
            ),
            (
                [
                    [423.0, 0.0, 247.0],
                    [423.0, 330.0, 247.0],
                    [472.0, 330.0, 406.0],
                    [472.0, 0.0, 406.0],
                ],
                0,
            ),
            (
                [
                    [472.0, 0.0, 406.0],
                    [472.0, 330.0, 406.0],
                    [314.0, 330.0, 456.0],
                    [314.0, 0.0, 456.0],
                ],
                0,
            ),
            (
                [
                    [314.0, 0.0, 456.0],
                    [314.0, 330.0, 456.0],
                    [265.0, 330.0, 296.0],
                    [265.0, 0.0, 296.0],
                ],
                0,
            ),
            (
                [
                    [265.0, 0.0, 296.0],
                    [265.0, 330.0, 296.0],
                    [423.0, 330.0, 247.0],
                    [423.0, 0.0, 247.0],
                ],
                0,
            ),
            // Light, 0.1 mm below the ceiling, facing down.
            (
                [
                    [343.0, 548.7, 227.0],
                    [343.0, 548.7, 332.0],
                    [213.0, 548.7, 332.0],
                    [213.0, 548.7, 227.0],
                ],
                3,
            ),
        ];
        let mut triangles = Vec::new();
        let mut material_of = Vec::new();
        for (q, m) in &quads {
            let v = q.map(|p| mm(p[0], p[1], p[2]));
            triangles.push([v[0], v[1], v[2]]);
            triangles.push([v[0], v[2], v[3]]);
            material_of.extend([*m, *m]);
        }
        let light_area = 0.130 * 0.105;
        Scene {
            name: "cornell".into(),
            triangles,
            normals: Vec::new(),
            material_of,
            materials: vec![white, red, green, light],
            camera: Camera {
                position: mm(278.0, 273.0, -800.0),
                target: mm(278.0, 273.0, 0.0),
                up: Vec3::Y,
                // 35 mm focal length, 25 mm film: 2·atan(12.5/35).
                vfov_deg: 2.0 * (12.5f32 / 35.0).atan().to_degrees(),
            },
            primary: PrimaryLight::Spot {
                position: mm(278.0, 548.0, 279.5),
                direction: -Vec3::Y,
                intensity: Vec3::new(17.0, 12.0, 4.0) * light_area,
                inner: 0.0,
                outer: 80f32.to_radians() * 0.99,
            },
            unsupported: Vec::new(),
        }
    }

    /// The built-in Cornell box with glossy surfaces (glTF
    /// metallic-roughness): a varnished floor (a white dielectric, IOR 1.5,
    /// roughness 0.3), a polished metal tall block (roughness 0.15), a
    /// brushed gold short block (roughness 0.4) and a red plastic ball
    /// (roughness 0.2, radius 8 cm) on the short block; the walls stay
    /// Lambertian.
    pub fn cornell_box_glossy() -> Scene {
        let mut s = Scene::cornell_box();
        let floor = Material::gltf(Vec3::new(0.725, 0.71, 0.68), 0.0, 0.3);
        let silver = Material::gltf(Vec3::new(0.95, 0.93, 0.88), 1.0, 0.15);
        let gold = Material::gltf(Vec3::new(1.0, 0.78, 0.34), 1.0, 0.4);
        let plastic = Material::gltf(Vec3::new(0.7, 0.08, 0.06), 0.0, 0.2);
        let base = s.materials.len() as u32;
        s.materials.extend([floor, silver, gold, plastic]);
        // Triangles 0–1 are the floor, 10–19 the short block, 20–29 the tall one.
        for (range, m) in [(0..2, base), (10..20, base + 2), (20..30, base + 1)] {
            s.material_of[range].iter_mut().for_each(|k| *k = m);
        }
        let mut ball = crate::shapes::sphere(3);
        ball.materials = vec![plastic];
        s.append(ball, 0.08, Vec3::new(0.185, 0.165 + 0.08, 0.169));
        s.name = "cornell-glossy".into();
        s
    }

    /// The built-in Cornell box with its ceiling light split into `n × n`
    /// quads (`2n²` triangle lights, same total emission): a small many-light
    /// scene for tests of light selection.
    pub fn cornell_box_split_light(n: u32) -> Scene {
        Scene::cornell_box().split_light(n)
    }

    /// This scene with its first emissive quad (two triangles: the Cornell
    /// box's ceiling light) split into `n × n` quads of the same emission.
    pub fn split_light(mut self, n: u32) -> Scene {
        let s = &mut self;
        let light = s
            .material_of
            .iter()
            .position(|&m| s.materials[m as usize].emission.max_element() > 0.0)
            .expect("the box has a light");
        let [a, b, _] = s.triangles[light];
        let c = s.triangles[light + 1][2];
        // The light quad is a (corner), a→b (first edge), a→d (second edge).
        let m = s.material_of[light];
        s.triangles.drain(light..light + 2);
        s.material_of.drain(light..light + 2);
        let flat = !s.normals.is_empty();
        if flat {
            s.normals.drain(light..light + 2);
        }
        let (e1, e2) = (b - a, c - a);
        let n = n.max(1);
        for i in 0..n {
            for j in 0..n {
                let p =
                    |u: u32, v: u32| a + e1 * (u as f32 / n as f32) + e2 * (v as f32 / n as f32);
                let (p00, p10, p11, p01) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
                s.triangles.push([p00, p10, p11]);
                s.triangles.push([p00, p11, p01]);
                s.material_of.extend([m, m]);
                if flat {
                    let g = slc_core::ray::triangle_normal(p00, p10, p11);
                    s.normals.extend([[g; 3], [g; 3]]);
                }
            }
        }
        self
    }
}
