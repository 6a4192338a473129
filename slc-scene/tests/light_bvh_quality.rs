use glam::Vec3;
use slc_core::importance::Receiver;
use slc_scene::light_bvh::bvh_cone;
use slc_scene::pt::PtScene;
use slc_scene::scene_file::SceneFile;
use std::path::Path;

/// How much of its importance the light BVH keeps (issue 35, item 6): at
/// 128 points on the floor and the back wall of the many-lights scenes,
/// the relative variance `Σ cᵢ²/pᵢ / (Σ cᵢ)² − 1` of a one-light estimate
/// of the unshadowed direct light `Σ cᵢ` when light `i` is picked with
/// probability `pᵢ`: the tree's pmf, the leaves' importance without the
/// tree (`pᵢ ∝ importanceᵢ`), power, uniform and the ideal `cᵢ / Σ c`.
/// A diagnostic, not a check:
///   cargo test --release -p slc-scene --test light_bvh_quality -- --ignored --nocapture

#[test]
#[ignore]
fn light_bvh_quality() {
    for name in ["../scenes/many-small-lights.toml", "../scenes/far-bright-near-dim.toml"] {
        let f = SceneFile::load(Path::new(name)).unwrap();
        let pts = PtScene::new(&f.scene, &f.lights).unwrap();
        let ls = pts.lights();
        let set = pts.light_set();
        let bvh = pts.light_bvh();
        let n_l = ls.len();
        let mut acc = [0.0f64; 5];
        let mut npts = 0;
        let recv: Vec<(Vec3, Vec3)> = (0..64)
            .flat_map(|k| {
                let (a, b) = ((k % 8) as f32 / 8.0 + 0.06, (k / 8) as f32 / 8.0 + 0.06);
                [
                    (Vec3::new(a * 0.55, 0.0, b * 0.55), Vec3::Y),
                    (Vec3::new(a * 0.55, b * 0.54, 0.559), Vec3::NEG_Z),
                ]
            })
            .collect();
        for (p, n) in recv {
            let rc = Receiver::lambertian(p, n);
            let c: Vec<f64> = ls
                .iter()
                .map(|l| {
                    let (e, d2) = l.contribution_at(p);
                    let w = (p - l.bound().center) / d2.sqrt();
                    (e.max_element() * n.dot(-w).max(0.0)) as f64
                })
                .collect();
            let tot: f64 = c.iter().sum();
            if tot <= 0.0 {
                continue;
            }
            npts += 1;
            let imp: Vec<f64> = ls
                .iter()
                .zip(set.cones())
                .map(|(l, k)| rc.importance(&bvh_cone(l, k)) as f64)
                .collect();
            let isum: f64 = imp.iter().sum();
            let mut m = [0.0f64; 5];
            for i in 0..n_l {
                if c[i] <= 0.0 {
                    continue;
                }
                let ps = [
                    bvh.pmf(&rc, i) as f64,
                    imp[i] / isum,
                    set.alias().pdf(i),
                    1.0 / n_l as f64,
                    c[i] / tot,
                ];
                for j in 0..5 {
                    m[j] += if ps[j] > 0.0 { c[i] * c[i] / ps[j] } else { f64::INFINITY };
                }
            }
            for j in 0..5 {
                acc[j] += m[j] / (tot * tot) - 1.0;
            }
        }
        println!(
            "{name}: {npts} points; relative variance (Σc²/p)/(Σc)² − 1, mean: bvh {:.3} flat-importance {:.3} power {:.3} uniform {:.3} ideal {:.3}",
            acc[0] / npts as f64,
            acc[1] / npts as f64,
            acc[2] / npts as f64,
            acc[3] / npts as f64,
            acc[4] / npts as f64
        );
    }
}
