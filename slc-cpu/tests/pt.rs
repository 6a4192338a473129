//! Path tracer: unbiasedness against uniform light sampling, the reservoir
//! against full candidates, MIS consistency, and bad emitters.

use glam::Vec3;
use slc_cpu::pt::{PtMethod, PtRender, PtScene, PtSettings};
use slc_cpu::scene::Scene;

/// The Cornell box with its ceiling light split into 8×8 quads (128
/// triangle lights), so SLC has many lights to cull.
fn many_light_box() -> Scene {
    Scene::cornell_box_split_light(8)
}

fn mean_and_sigma(samples: &[f64]) -> (f64, f64) {
    let n = samples.len() as f64;
    let m = samples.iter().sum::<f64>() / n;
    let var = samples.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0);
    (m, (var / n).sqrt())
}

/// Image means per pass of a method (each pass independent: new ξ, new samples).
fn pass_means(method: PtMethod, passes: u32) -> Vec<f64> {
    let mut pts = PtScene::new(&many_light_box(), &[]).unwrap();
    assert_eq!(pts.light_count(), 128);
    let s = PtSettings { method, error_bound: 0.05, ..PtSettings::default() };
    let mut acc = PtRender::new(32, 32);
    let mut prev = 0.0;
    (0..passes)
        .map(|_| {
            pts.render(&mut acc, &s, 1).unwrap();
            let total = acc.image().mean() * acc.passes as f64;
            let m = total - prev;
            prev = total;
            m
        })
        .collect()
}

/// SLC (and its reservoir) against uniform light sampling: both estimate the
/// same image, so their pass means agree within 5σ of the difference
/// (σ² = σ²_a/n + σ²_b/n, from the per-pass sample variances; fixed seeds).
#[test]
fn slc_and_reservoir_match_uniform_in_expectation() {
    let uniform = pass_means(PtMethod::Uniform, 400);
    let (mu, su) = mean_and_sigma(&uniform);
    assert!(mu > 0.0);
    for method in [PtMethod::Slc, PtMethod::SlcReservoir, PtMethod::Power, PtMethod::LightBvh] {
        let (m, sm) = mean_and_sigma(&pass_means(method, 400));
        eprintln!("{}: {m:.5} vs uniform {mu:.5}, 5σ = {:.5}", method.name(), 5.0 * (su * su + sm * sm).sqrt());
        let bound = 5.0 * (su * su + sm * sm).sqrt();
        assert!((m - mu).abs() <= bound, "{}: mean {m} vs uniform {mu} (5σ = {bound})", method.name());
    }
}

#[test]
fn zero_area_or_bad_emitters_are_errors() {
    let mut s = Scene::cornell_box();
    // A degenerate emissive triangle.
    s.triangles.push([Vec3::ZERO, Vec3::X, Vec3::X * 2.0]);
    s.material_of.push(3);
    assert!(PtScene::new(&s, &[]).err().unwrap().to_string().contains("zero area"));
    let mut s = Scene::cornell_box();
    s.materials[3].emission = Vec3::new(-1.0, 0.0, 0.0);
    assert!(PtScene::new(&s, &[]).is_err());
    let mut s = Scene::cornell_box();
    s.triangles[0][0] = Vec3::NAN;
    assert!(PtScene::new(&s, &[]).is_err());
    let mut s = Scene::cornell_box();
    s.materials[3].emission = Vec3::ZERO;
    assert!(PtScene::new(&s, &[]).err().unwrap().to_string().contains("no light"));
}

#[test]
fn renders_are_finite_and_deterministic() {
    let mut a = PtScene::new(&Scene::cornell_box(), &[]).unwrap();
    let mut b = PtScene::new(&Scene::cornell_box(), &[]).unwrap();
    for method in PtMethod::ALL {
        let s = PtSettings { method, ..PtSettings::default() };
        let (mut ra, mut rb) = (PtRender::new(16, 16), PtRender::new(16, 16));
        a.render(&mut ra, &s, 2).unwrap();
        b.render(&mut rb, &s, 2).unwrap();
        assert_eq!(ra.image(), rb.image(), "{}", method.name());
        assert!(ra.image().is_finite() && ra.image().mean() > 0.0);
    }
    let bad = PtSettings { error_bound: f32::NAN, ..PtSettings::default() };
    assert!(a.render(&mut PtRender::new(4, 4), &bad, 1).is_err());
}
