//! Unit tests of the VPL frame's internals (the near field's culling, the
//! glossy composition, the reused memory).

use super::fields::{PerReceiver, light_ranges};
use super::shade::{self, Cull, LightList};
use super::tiling::Tiling;
use super::*;
use slc_core::interleave::{interleave_flux_scale, vpl_near_range2};
use slc_core::light::INV_PI;
use slc_core::range::CullKind;

/// The near field at `tiling`'s receivers, as a frame shades it.
fn near_field(ctx: &VplContext, tiling: &Tiling, near_r2: f32, s: &VplSettings) -> PerReceiver {
    let cull = Cull::far(s.culling.kind());
    let mut r = PerReceiver::default();
    let mut all = LightList::default();
    ctx.near_lights_into(&mut all, &ctx.ranges(s), near_r2, cull);
    ctx.shade_near_in(&mut r, tiling, &all, near_r2, cull);
    r
}

/// The near field's tile culling drops nothing: for every method (SLC
/// with its own ranges, clamp, none) it equals every VPL evaluated at
/// every pixel by the same loop without culling, for any region and
/// tile size.
#[test]
fn near_field_culling_drops_nothing() {
    let ctx = VplContext::new(&Scene::cornell_box(), 16, 16, 512, None).unwrap();
    let near_r2 = 9.0 * ctx.min_d2();
    let v = ctx.vpls();
    let gb = ctx.gbuffer();
    for culling in
        [Culling::stochastic(0.002, 1.0).unwrap(), Culling::clamped(0.02).unwrap(), Culling::None]
    {
        let (cull, near_cull) = (Cull::far(culling.kind()), Cull::near(culling.kind()));
        let s = VplSettings { culling, ..VplSettings::default() };
        let mut all = LightList::default();
        for i in (0..v.len()).filter(|&i| v.flux[i] != Vec3::ZERO) {
            let (rt2, r2) = light_ranges(&s, i, v.flux[i] * interleave_flux_scale(PERIOD));
            let (rt2, r2) = if cull.kind == CullKind::Stochastic {
                (vpl_near_range2(rt2, PERIOD), vpl_near_range2(r2, PERIOD))
            } else {
                (rt2, r2)
            };
            all.push(v.position[i], v.normal[i], v.flux[i], rt2, r2);
        }
        let brute: Vec<(Vec3, u32)> = (0..gb.position.len())
            .map(|i| {
                if gb.valid(i) {
                    shade::shade(
                        &all,
                        gb.position[i],
                        gb.normal[i],
                        ctx.min_d2(),
                        near_r2,
                        near_cull,
                    )
                } else {
                    (Vec3::ZERO, 0)
                }
            })
            .collect();
        assert!(
            brute.iter().map(|b| b.1).sum::<u32>() > 1000,
            "{cull:?}: the near field holds lights"
        );
        for (region, tile) in [(64, 8), (32, 8), (32, 4), (16, 16), (7, 3)] {
            let (e, kept) = near_field(&ctx, &Tiling::regions(gb, region, tile), near_r2, &s)
                .per_pixel(&Tiling::regions(gb, region, tile));
            for i in 0..brute.len() {
                assert_eq!(
                    kept[i], brute[i].1,
                    "{cull:?}: pixel {i}, region {region}, tile {tile}"
                );
                assert!(
                    (e[i] - brute[i].0).abs().max_element()
                        <= 1e-5 * brute[i].0.max_element().max(1e-3),
                    "{cull:?}: pixel {i}: {} vs {}",
                    e[i],
                    brute[i].0
                );
            }
        }
    }
}

/// On the glossy box, the VPL frame shades VPL light with the whole
/// glTF BRDF: without culling and without denoise its image equals, at
/// every pixel, `L_e + f(l, v)·direct + Σ_v Φ_v ⊙ f(l_v, v) · T_v`
/// (`l` toward the primary light; `f = albedo/π` on Lambertian pixels)
/// summed here in f64 over the VPLs each method gives the pixel
/// (Reference: all of them; None: its interleaved subset at `P²`× the
/// flux, with and without the near-field split's share at the VPL's
/// own flux), each pixel's material found by casting its camera ray,
/// `f` from `Material::eval` (slc-core's BRDF). Tolerance: f32 sums of
/// 4,096 terms. The glossy pixels' VPL light must differ from the
/// Lambertian `albedo/π · E` (else the test would prove nothing).
#[test]
fn glossy_vpl_light_is_the_brdf_sum_over_vpls() {
    use slc_core::interleave::{interleave_subset, shifted_subset, vpl_near_weight};
    use slc_core::light::vpl_transfer;
    let scene = Scene::cornell_box_glossy();
    let (w, h) = (24u32, 24u32);
    let ctx = VplContext::new(&scene, w, h, 64, None).unwrap();
    let (gb, v, min_d2) = (ctx.gbuffer(), ctx.vpls(), ctx.min_d2());
    assert!(gb.has_specular());
    let size = v.size as usize;
    let scale = interleave_flux_scale(PERIOD) as f64;
    let default_near = VplSettings::default().near_r2(min_d2);
    for (culling, near_radius, near_r2) in [
        (Culling::Reference, None, 0.0),
        (Culling::None, Some(0.0), 0.0),
        (Culling::None, None, default_near),
    ] {
        let settings =
            VplSettings { culling, denoise: false, near_radius, ..VplSettings::default() };
        let shift = slc_core::interleave::interleave_shift(settings.seed, settings.frame, PERIOD);
        let image = ctx.render(&settings).unwrap().image;
        let (mut glossy, mut differs, mut direct_differs) = (0, 0, 0);
        for i in 0..(w * h) as usize {
            let (px, py) = (i % w as usize, i / w as usize);
            let dir = scene.camera.ray_dir(px as f32, py as f32, w, h);
            let Some(hit) = ctx.geo.intersect(scene.camera.position, dir, 0.0, f32::INFINITY)
            else {
                assert_eq!(image.data[i], Vec3::ZERO, "pixel {i}: background");
                continue;
            };
            let m = scene.materials[scene.material_of[hit.triangle as usize] as usize];
            let (x, n) = (gb.position[i], gb.normal[i]);
            let view = (scene.camera.position - x).normalize();
            let (mut sum, mut lambert) = (glam::DVec3::ZERO, glam::DVec3::ZERO);
            for k in 0..v.len() {
                let class = interleave_subset(px as u32, py as u32, PERIOD);
                let in_subset = interleave_subset((k % size) as u32, (k / size) as u32, PERIOD)
                    == shifted_subset(class, shift, PERIOD);
                let d = x - v.position[k];
                let near = vpl_near_weight(d.length_squared(), near_r2) as f64;
                let share = match culling {
                    Culling::Reference => 1.0,
                    _ => near + (1.0 - near) * if in_subset { scale } else { 0.0 },
                };
                if share == 0.0 {
                    continue;
                }
                let t = vpl_transfer(v.normal[k], n, d, min_d2) as f64 * share;
                let f = m.eval(n, view, -d.normalize()).as_dvec3();
                sum += v.flux[k].as_dvec3() * f * t;
                lambert += v.flux[k].as_dvec3() * (m.albedo * INV_PI).as_dvec3() * t;
            }
            // The primary light's direct term: the whole BRDF toward it.
            let f_direct = if m.has_specular() {
                m.eval(n, view, scene.primary.direction_from(x))
            } else {
                m.albedo * INV_PI
            };
            let base = (gb.emission[i] + f_direct * ctx.direct[i]).as_dvec3();
            let lambert_direct = (m.albedo * INV_PI * ctx.direct[i]).as_dvec3();
            let expect = base + sum;
            let got = image.data[i].as_dvec3();
            assert!(
                (got - expect).abs().max_element() <= 2e-5 * expect.max_element() + 1e-7,
                "{culling:?}, R_n² {near_r2}: pixel {i} ({:?}): {got} vs {expect}",
                m
            );
            if m.has_specular() {
                glossy += 1;
                differs += ((sum - lambert).abs().max_element() > 0.1 * sum.max_element()) as u32;
                let direct = base - gb.emission[i].as_dvec3();
                direct_differs += ((direct - lambert_direct).abs().max_element()
                    > 0.1 * direct.max_element()) as u32;
            }
        }
        assert!(
            glossy > 100 && differs > glossy / 4,
            "{culling:?}: {glossy} glossy pixels, {differs} unlike Lambertian"
        );
        // The metal sphere has no diffuse lobe: its direct light is not `albedo/π · E`.
        assert!(
            direct_differs > glossy / 4,
            "{culling:?}: {glossy} glossy pixels, {direct_differs} with a direct term unlike Lambertian"
        );
    }
}

/// The specular correction leaves the Lambertian part alone: on the
/// glossy box, with every method and the denoise, the irradiance, near
/// field and kept counts are bit for bit those of the same G-buffer
/// without its lobes (the path a Lambertian scene takes, which gives
/// main's images byte for byte), and so is every Lambertian pixel of
/// the image; the glossy pixels change.
#[test]
fn specular_correction_leaves_lambertian_pixels_bit_identical() {
    let scene = Scene::cornell_box_glossy();
    let ctx = VplContext::new(&scene, 40, 32, 64, None).unwrap();
    let mut lambert = VplContext::new(&scene, 40, 32, 64, None).unwrap();
    lambert.inputs.gbuffer.specular.clear();
    lambert.from_gbuffer.build(&lambert.inputs.gbuffer);
    let gb = ctx.gbuffer();
    for culling in
        [Culling::default(), Culling::clamped(0.1).unwrap(), Culling::None, Culling::Reference]
    {
        let s = VplSettings { culling, ..VplSettings::default() };
        let (a, b) = (ctx.shade(&s).unwrap(), lambert.shade(&s).unwrap());
        assert!(b.specular.is_empty() && !a.specular.is_empty());
        assert!(
            a.irradiance == b.irradiance && a.near == b.near && a.kept == b.kept,
            "{culling:?}"
        );
        let (ia, ib) = (ctx.finish(a, &s).image, lambert.finish(b, &s).image);
        let mut changed = 0;
        for i in 0..ia.data.len() {
            if gb.specular_at(i).is_none() {
                assert_eq!(ia.data[i], ib.data[i], "{culling:?}: Lambertian pixel {i}");
            } else {
                changed += (ia.data[i] != ib.data[i]) as usize;
            }
        }
        assert!(changed > 20, "{culling:?}: {changed} glossy pixels changed");
    }
}

/// A frame's memory kept for the next one changes no frame: a frame
/// rendered after frames of other methods, settings and sizes of its
/// buffers (near field off, no denoise, a frame whose `Shaded` was
/// never finished) is bit for bit a frame of a fresh context, on the
/// glossy box (so the specular buffers are reused too).
#[test]
fn reused_frame_memory_changes_no_frame() {
    let scene = Scene::cornell_box_glossy();
    let ctx = VplContext::new(&scene, 40, 32, 64, None).unwrap();
    let settings = [
        VplSettings::default(),
        VplSettings { culling: Culling::None, ..VplSettings::default() },
        VplSettings { near_radius: Some(0.0), frame: 3, ..VplSettings::default() },
        VplSettings {
            culling: Culling::clamped(0.1).unwrap(),
            denoise: false,
            ..VplSettings::default()
        },
        VplSettings { frame: 5, ..VplSettings::default() },
    ];
    let fresh: Vec<Vec<Vec3>> = settings
        .iter()
        .map(|s| VplContext::new(&scene, 40, 32, 64, None).unwrap().render(s).unwrap().image.data)
        .collect();
    for round in 0..2 {
        let _unfinished = ctx.shade(&settings[1]).unwrap();
        for (s, expected) in settings.iter().zip(&fresh) {
            assert!(ctx.render(s).unwrap().image.data == *expected, "round {round}: {s:?}");
        }
    }
}

/// The culled near field is unbiased: its expectation over ξ equals the
/// unculled near field at every pixel, by stratified quadrature through
/// the real code (`shade_near_in` with `fixed_xi` at the midpoints of M
/// strata). Each light's term is `w·T/p` on the ξ interval where it is
/// kept (which ends at ξ = 1) and 0 elsewhere, so the midpoint rule
/// misses each light by at most 2 strata of `w·T/p`: the bound is `2/M`
/// of the near field with every light kept (ξ → 1), plus f32 summation.
/// The error bound is chosen so that culling drops most near lights.
#[test]
fn culled_near_field_expectation_equals_unculled() {
    let ctx = VplContext::new(&Scene::cornell_box(), 24, 24, 256, None).unwrap();
    let near_r2 = 16.0 * ctx.min_d2();
    let s =
        VplSettings { culling: Culling::stochastic(0.02, 1.0).unwrap(), ..VplSettings::default() };
    let near = |s: &VplSettings| {
        let f = near_field(&ctx, &ctx.from_gbuffer.near, near_r2, s);
        let (e, kept) = f.per_pixel(&ctx.from_gbuffer.near);
        (e, kept, f.work.tested)
    };
    let (truth, truth_kept, truth_evals) = near(&VplSettings { culling: Culling::None, ..s });
    let fixed = |x: f32| near(&VplSettings { fixed_xi: Some(x), ..s });
    let all_kept = fixed(slc_core::range::Xi::MAX.get()).0;
    const M: usize = 256;
    let mut mean = vec![glam::DVec3::ZERO; truth.len()];
    let (mut kept, mut listed) = (0u64, 0u64);
    for j in 0..M {
        let (e, k, evals) = fixed((j as f32 + 0.5) / M as f32);
        for (m, v) in mean.iter_mut().zip(&e) {
            *m += v.as_dvec3() / M as f64;
        }
        kept += k.iter().map(|&k| k as u64).sum::<u64>();
        listed += evals;
    }
    let unculled = truth_kept.iter().map(|&k| k as u64).sum::<u64>() * M as u64;
    assert!(
        kept * 4 < unculled && listed < truth_evals * M as u64,
        "culling must bite: kept {kept} of {unculled}, tested {listed} of {}",
        truth_evals * M as u64
    );
    for i in 0..truth.len() {
        let t = truth[i].as_dvec3();
        let bound = all_kept[i].as_dvec3() * (2.0 / M as f64) + t.abs() * 1e-5 + 1e-12;
        for c in 0..3 {
            assert!(
                (mean[i][c] - t[c]).abs() <= bound[c],
                "pixel {i} channel {c}: E[culled] {} vs unculled {} (bound {})",
                mean[i][c],
                t[c],
                bound[c]
            );
        }
    }
}
