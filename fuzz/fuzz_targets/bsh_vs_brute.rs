//! The bounding-sphere hierarchy on arbitrary light sets, NaN and ∞
//! included: bad input is rejected before it reaches the tree; accepted
//! input answers every query exactly as a brute-force scan, with a range
//! tail of 0 to 4 lights (`Bsh::with_tail`) as without, split at the
//! median or by the sphere-area heuristic, 2 to 8 wide; and the grid over
//! its leaves (`BshGrid`, over a box the input draws) finds what the walk
//! finds, in its order, wherever it answers: for points, and in a grid
//! built for a glossy reach the input draws, for glossy receivers whose
//! lobe (GGX α, metal or not, view, mirror direction) it draws too.
#![no_main]

use arbitrary::Arbitrary;
use glam::{Vec3, Vec4};
use libfuzzer_sys::fuzz_target;
use slc_core::bsh::{Bsh, BshGrid, BshShape, BshSplit};
use slc_core::light::LightBound;
use slc_core::sphere::{Aabb, Sphere};

#[derive(Arbitrary, Debug)]
struct Input {
    lights: Vec<([f32; 3], f32, f32)>,
    queries: Vec<([f32; 3], f32, [f32; 3])>,
    tail: u8,
}

fuzz_target!(|input: Input| {
    let lights = &input.lights[..input.lights.len().min(512)];
    let bounds: Vec<LightBound> =
        lights.iter().map(|&(c, e, _)| LightBound { center: Vec3::from(c), extent: e }).collect();
    let valid =
        bounds.iter().all(|b| b.center.is_finite() && b.extent.is_finite() && b.extent >= 0.0);
    let split = if input.tail & 0x80 == 0 { BshSplit::Median } else { BshSplit::SphereArea };
    let shape = BshShape { split, width: 2 + (input.tail as u32 >> 4 & 7) % 7 };
    let mut bsh = match Bsh::build_with(&bounds, shape) {
        Ok(t) => {
            assert!(valid, "accepted invalid bounds");
            t.with_tail((input.tail & 0xf) as usize % 5).expect("a tail of at most 4")
        }
        Err(_) => {
            assert!(!valid, "rejected valid bounds");
            return;
        }
    };
    let r2: Vec<f32> = lights.iter().map(|l| l.2).collect();
    if bsh.refit(&r2).is_err() {
        assert!(r2.iter().any(|r| !(*r >= 0.0)), "rejected valid ranges");
        return;
    }
    let spheres: Vec<Sphere> = bounds.iter().zip(&r2).map(|(b, &r)| b.range_sphere(r)).collect();
    let grid = input.queries.first().and_then(|&(q, _, e)| {
        BshGrid::build_at(&bsh, Vec3::from(q), Vec3::from(q) + Vec3::from(e), input.tail as u32)
    });
    // A grid for glossy receivers reaching up to w ∈ [1, 9), and each
    // query's receiver lobe: a valid one, as a material gives (the walk's
    // inner bounds hold for those), drawn from the query's numbers.
    let unit = |v: f32| if v.is_finite() { v.abs().fract() } else { 0.5 };
    let glossy = input.queries.first().and_then(|&(q, r, e)| {
        let w = 1.0 + 8.0 * unit(r);
        BshGrid::build_reaching_at(
            &bsh,
            Vec3::from(q),
            Vec3::from(q) + Vec3::from(e),
            input.tail as u32,
            w,
        )
    });
    let lobe = |r: f32, e: [f32; 3]| -> (Vec3, Vec4) {
        let alpha = (0.02 + unit(e[0])).min(1.0).powi(2);
        let metal = if unit(r) < 0.5 { 1.0 } else { 0.0 };
        let l = slc_core::brdf::receiver_lobe(
            Vec3::splat(0.8),
            metal,
            Vec3::splat(0.04),
            1.0,
            alpha,
            unit(e[1]),
        );
        let dir = Vec3::from(e).try_normalize().unwrap_or(Vec3::Z);
        (dir, slc_core::brdf::range_lobe(l))
    };
    for &(q, r, e) in input.queries.iter().take(16) {
        let x = Vec3::from(q);
        let brute = |t: &dyn Fn(&Sphere) -> bool| -> Vec<u32> {
            (0..spheres.len() as u32).filter(|&i| t(&spheres[i as usize])).collect()
        };
        let mut got = Vec::new();
        bsh.for_each_containing(x, |i| got.push(i));
        got.sort_unstable();
        assert_eq!(got, brute(&|s| s.contains(x)), "containing {x:?}");
        if let Some(g) = &grid {
            let (mut walk, mut cells) = (Vec::new(), Vec::new());
            bsh.for_each_containing(x, |i| walk.push(i));
            if g.for_each_containing(x, |i| cells.push(i)) {
                assert_eq!(cells, walk, "the grid at {x:?}");
            }
        }
        if let Some(g) = &glossy {
            let (dir, rl) = lobe(r, e);
            let (mut walk, mut cells) = (Vec::new(), Vec::new());
            bsh.for_each_reaching(x, dir, rl, |i| walk.push(i));
            if g.for_each_reaching(x, dir, rl, |i| cells.push(i)) {
                assert_eq!(cells, walk, "the glossy grid at {x:?}, lobe {rl:?}");
            }
        }
        let s = Sphere::new(x, r);
        got.clear();
        bsh.for_each_overlapping_sphere(s, |i| got.push(i));
        got.sort_unstable();
        assert_eq!(got, brute(&|t| t.overlaps_sphere(&s)), "overlapping {s:?}");
        let b = Aabb { min: x, max: x + Vec3::from(e) };
        got.clear();
        bsh.for_each_overlapping_aabb(b, |i| got.push(i));
        got.sort_unstable();
        assert_eq!(got, brute(&|t| t.overlaps_aabb(&b)), "overlapping {b:?}");
    }
});
