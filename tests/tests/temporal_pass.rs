//! The engine's temporal pass ([`TemporalPass`]) against the CPU's
//! [`Temporal`] over the same frames: the same G-buffers (the CPU's,
//! uploaded as an engine's textures), the same signals, the same cameras.
//! Both run slc-core's temporal functions, so they agree to float
//! rounding: accumulated values within 1e-4 relative, history lengths
//! equal, except where a pixel's change test sits on its threshold (a
//! rounding difference may flip it there: at most 0.5% of the pixels).
//! The sequence covers a static start, a camera move (disocclusion), a
//! jump of the signal (the change test) and a reported change.

use glam::Vec3;
use slc_core::xi::{pcg_hash, xi_from_bits};
use slc_cpu::temporal::Temporal;
use slc_cpu::vpl::VplContext;
use slc_scene::scene::{Camera, Scene};
use slc_scene::temporal::{TemporalSettings, TemporalView};
use slc_scene::vpl::GBuffer as CpuGBuffer;
use slc_tests::engine::{output, submit_and_read, upload};
use slc_tests::gpu;
use slc_wgpu::GpuError;
use slc_wgpu::passes::{
    GBuffer, Surface, SurfaceDesc, TemporalInputs, TemporalPass, TemporalPassDesc,
};

const W: u32 = 64;
const H: u32 = 48;

fn v4(v: Vec3, w: f32) -> [f32; 4] {
    [v.x, v.y, v.z, w]
}

/// Noise in `[0.5, 1.5)` per pixel and channel for frame `f`, times `scale`.
fn signal(f: u32, scale: f32) -> Vec<Vec3> {
    (0..W * H)
        .map(|i| {
            let h = pcg_hash(pcg_hash(i) ^ f.wrapping_mul(0x9e37_79b9));
            let c =
                [h, pcg_hash(h), pcg_hash(pcg_hash(h))].map(|b| (0.5 + xi_from_bits(b)) * scale);
            Vec3::from(c)
        })
        .collect()
}

fn desc() -> TemporalPassDesc {
    TemporalPassDesc {
        output_format: wgpu::TextureFormat::Rgba32Float,
        ..TemporalPassDesc::new(W, H)
    }
}

fn textures(gpu: &slc_wgpu::GpuContext, gb: &CpuGBuffer) -> (wgpu::TextureView, wgpu::TextureView) {
    let pos: Vec<[f32; 4]> = (0..gb.position.len())
        .map(|i| v4(gb.position[i], if gb.valid(i) { 1.0 } else { 0.0 }))
        .collect();
    let nrm: Vec<[f32; 4]> = gb.normal.iter().map(|&n| v4(n, 0.0)).collect();
    (upload(gpu, "position", (W, H), &pos), upload(gpu, "normal", (W, H), &nrm))
}

fn gpu_matches_cpu() {
    let Some(gpu) = gpu() else { return };
    let mut ctx = VplContext::new(&Scene::cornell_box(), W, H, 8, None).unwrap();
    let base = ctx.scene().camera;
    let step = Vec3::X * (0.1 * ctx.scene().diagonal());
    let moved = Camera { position: base.position + step, target: base.target + step, ..base };
    let mut pass = TemporalPass::new(gpu, &desc()).unwrap();
    let mut cpu = Temporal::new(W, H).unwrap();
    let out = output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let ts = TemporalSettings::default();
    // (camera, signal scale, reported change) per frame.
    let mut frames: Vec<(Camera, f32, bool)> = (0..10).map(|_| (base, 1.0, false)).collect();
    frames.extend((0..3).map(|_| (moved, 1.0, false)));
    frames.push((moved, 8.0, false));
    frames.extend((0..2).map(|_| (moved, 8.0, false)));
    frames.push((moved, 8.0, true));
    let (mut fresh_after_move, mut reset_by_jump) = (0, 0);
    for (f, &(camera, scale, changed)) in frames.iter().enumerate() {
        if ctx.scene().camera != camera {
            ctx.set_camera(camera).unwrap();
        }
        let gb = ctx.inputs().gbuffer.clone();
        let view = TemporalView::of_camera(&camera, W, H);
        let settings = if changed { ts.after_change() } else { ts };
        let s = signal(f as u32, scale);
        let want = cpu.accumulate(&s, &gb, &view, &settings).unwrap();
        let want_len = cpu.history_lengths();
        let (position, normal) = textures(gpu, &gb);
        let sig = upload(gpu, "signal", (W, H), &s.iter().map(|&c| v4(c, 0.0)).collect::<Vec<_>>());
        let gbuffer = GBuffer {
            surface: Surface::Position(&position),
            normal: &normal,
            eye: camera.position,
        };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(&mut enc, &TemporalInputs::new(gbuffer, &sig, &out_view), &view, &settings)
            .unwrap();
        let got = submit_and_read(gpu, enc, &out);
        let (mut off, mut lit) = (0, 0);
        for i in 0..got.len() {
            let g = got[i];
            let value_ok =
                (0..3).all(|c| (g[c] - want[i][c]).abs() <= 1e-4 * want[i][c].abs() + 1e-6);
            if gb.valid(i) {
                lit += 1;
                off += (!value_ok || (g[3] - want_len[i]).abs() > 1e-3) as usize;
            } else {
                assert_eq!(g, v4(s[i], 0.0), "frame {f}, pixel {i}: no surface, the signal itself");
            }
        }
        assert!(off * 200 <= lit, "frame {f}: {off} of {lit} pixels differ from the CPU's");
        if f == 10 {
            fresh_after_move =
                got.iter().enumerate().filter(|(i, g)| gb.valid(*i) && g[3] == 1.0).count();
        }
        // The jump's second frame (its first frame alone could be an
        // outlier: a change must persist): the history restarted there.
        if f == 14 {
            reset_by_jump =
                got.iter().enumerate().filter(|(i, g)| gb.valid(*i) && g[3] == 1.0).count() * 100
                    / lit;
        }
        if changed {
            assert!(got.iter().all(|g| g[3] <= 1.0), "a reported change drops the history");
        }
    }
    eprintln!(
        "camera move: {fresh_after_move} pixels start afresh; signal ×8: {reset_by_jump}% of the pixels reset"
    );
    assert!(fresh_after_move > 8, "the move uncovers surfaces");
    // Everywhere but where the move left fewer than TEMPORAL_MIN_MOMENTS
    // frames to judge by (observed: 98% reset).
    assert!(
        reset_by_jump >= 95,
        "an eightfold jump is a change wherever the history is long enough to judge"
    );
    gpu.take_errors().unwrap();
}

/// A pass built for motion vectors against the CPU's
/// `accumulate_with_motion` over a camera move, the motion vectors those
/// of the move (a static scene): the same numbers, as above.
fn motion_vectors_match_the_cpu() {
    let Some(gpu) = gpu() else { return };
    let mut ctx = VplContext::new(&Scene::cornell_box(), W, H, 8, None).unwrap();
    let base = ctx.scene().camera;
    let step = Vec3::X * (0.03 * ctx.scene().diagonal());
    let moved = Camera { position: base.position + step, target: base.target + step, ..base };
    let mut pass =
        TemporalPass::new(gpu, &TemporalPassDesc { motion_vectors: true, ..desc() }).unwrap();
    let mut cpu = Temporal::new(W, H).unwrap();
    let out = output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let ts = TemporalSettings::default();
    for f in 0..8u32 {
        let (camera, previous) =
            if f < 6 { (base, base) } else { (moved, if f == 6 { base } else { moved }) };
        if ctx.scene().camera != camera {
            ctx.set_camera(camera).unwrap();
        }
        let gb = ctx.inputs().gbuffer.clone();
        let m = TemporalView::of_camera(&previous, W, H).view_projection;
        let motion: Vec<glam::Vec2> = (0..(W * H) as usize)
            .map(|i| {
                let q = slc_core::temporal::reproject(
                    m.x_axis,
                    m.y_axis,
                    m.z_axis,
                    m.w_axis,
                    gb.position[i],
                    W as f32,
                    H as f32,
                );
                let here = glam::Vec2::new((i as u32 % W) as f32, (i as u32 / W) as f32);
                if gb.valid(i) {
                    (here - glam::Vec2::new(q.x, q.y)) / glam::Vec2::new(W as f32, H as f32)
                } else {
                    glam::Vec2::ZERO
                }
            })
            .collect();
        let view = TemporalView::of_camera(&camera, W, H);
        let s = signal(f, 1.0);
        let want = cpu.accumulate_with_motion(&s, &gb, &view, &motion, &ts).unwrap();
        let want_len = cpu.history_lengths();
        let (position, normal) = textures(gpu, &gb);
        let sig = upload(gpu, "signal", (W, H), &s.iter().map(|&c| v4(c, 0.0)).collect::<Vec<_>>());
        let mv = upload(
            gpu,
            "motion",
            (W, H),
            &motion.iter().map(|m| [m.x, m.y, 0.0, 0.0]).collect::<Vec<_>>(),
        );
        let gbuffer = GBuffer {
            surface: Surface::Position(&position),
            normal: &normal,
            eye: camera.position,
        };
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        pass.record(
            &mut enc,
            &TemporalInputs { motion: Some(&mv), ..TemporalInputs::new(gbuffer, &sig, &out_view) },
            &view,
            &ts,
        )
        .unwrap();
        let got = submit_and_read(gpu, enc, &out);
        let (mut off, mut lit, mut kept) = (0, 0, 0);
        for i in (0..got.len()).filter(|&i| gb.valid(i)) {
            lit += 1;
            kept += (got[i][3] > 1.0) as usize;
            let value_ok =
                (0..3).all(|c| (got[i][c] - want[i][c]).abs() <= 1e-4 * want[i][c].abs() + 1e-6);
            off += (!value_ok || (got[i][3] - want_len[i]).abs() > 1e-3) as usize;
        }
        assert!(off * 200 <= lit, "frame {f}: {off} of {lit} pixels differ from the CPU's");
        if f == 6 {
            assert!(
                kept * 10 > lit * 8,
                "the move keeps most history by the motion vectors ({kept} of {lit})"
            );
        }
    }
    gpu.take_errors().unwrap();
}

fn wrong_inputs_are_typed_errors() {
    let Some(gpu) = gpu() else { return };
    let ctx = VplContext::new(&Scene::cornell_box(), W, H, 8, None).unwrap();
    let gb = &ctx.inputs().gbuffer;
    let (position, normal) = textures(gpu, gb);
    let out = output(gpu, (W, H));
    let out_view = out.create_view(&Default::default());
    let sig = upload(gpu, "signal", (W, H), &vec![[0.0; 4]; (W * H) as usize]);
    let small = upload(gpu, "small", (W / 2, H), &vec![[0.0; 4]; (W * H / 2) as usize]);
    let gbuffer = GBuffer { surface: Surface::Position(&position), normal: &normal, eye: gb.eye };
    let view = TemporalView::of_camera(&ctx.scene().camera, W, H);
    let mut pass = TemporalPass::new(gpu, &desc()).unwrap();
    let mut enc = gpu.device.create_command_encoder(&Default::default());
    let ok = TemporalInputs::new(gbuffer, &sig, &out_view);
    let ts = TemporalSettings::default();
    assert!(matches!(
        pass.record(&mut enc, &TemporalInputs { signal: &small, ..ok }, &view, &ts),
        Err(GpuError::Binding { .. })
    ));
    assert!(matches!(
        pass.record(&mut enc, &TemporalInputs { output: &sig, ..ok }, &view, &ts),
        Err(GpuError::Binding { .. })
    ));
    let nan = TemporalView { eye: Vec3::NAN, ..view };
    assert!(matches!(pass.record(&mut enc, &ok, &nan, &ts), Err(GpuError::Setting(_))));
    assert!(matches!(
        pass.record(&mut enc, &ok, &view, &TemporalSettings { max_history: 0.0 }),
        Err(GpuError::Setting(_))
    ));
    let depth = TemporalPassDesc {
        surface: SurfaceDesc::Depth { format: wgpu::TextureFormat::Depth32Float },
        ..desc()
    };
    let mut depth_pass = TemporalPass::new(gpu, &depth).unwrap();
    assert!(
        matches!(depth_pass.record(&mut enc, &ok, &view, &ts), Err(GpuError::Binding { .. })),
        "positions for a depth pass"
    );
    assert!(matches!(
        TemporalPass::new(gpu, &TemporalPassDesc::new(0, 4)),
        Err(GpuError::Setting(_))
    ));
    // Motion vectors given to a pass built without them, and missing for one built with them.
    assert!(matches!(
        pass.record(&mut enc, &TemporalInputs { motion: Some(&sig), ..ok }, &view, &ts),
        Err(GpuError::Binding { .. })
    ));
    let mut moving =
        TemporalPass::new(gpu, &TemporalPassDesc { motion_vectors: true, ..desc() }).unwrap();
    assert!(matches!(moving.record(&mut enc, &ok, &view, &ts), Err(GpuError::Binding { .. })));
    pass.record(&mut enc, &ok, &view, &ts).unwrap();
    gpu.queue.submit([enc.finish()]);
    gpu.take_errors().unwrap();
}

slc_tests::harness!(Gpu: gpu_matches_cpu, Gpu: motion_vectors_match_the_cpu, Gpu: wrong_inputs_are_typed_errors,);
