//! The bounding-sphere hierarchy on arbitrary light sets, NaN and ∞
//! included: bad input is rejected before it reaches the tree; accepted
//! input answers every query exactly as a brute-force scan, with a range
//! tail of 0 to 4 lights (`Bsh::with_tail`) as without, split at the
//! median or by the sphere-area heuristic, 2 to 8 wide; and the grid over
//! its leaves (`BshGrid`, over a box the input draws) finds what the walk
//! finds, in its order, wherever it answers.
#![no_main]

use arbitrary::Arbitrary;
use glam::Vec3;
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
