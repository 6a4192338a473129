//! A generated kernel in naga's other back ends (SPIR-V, GLSL, HLSL, MSL)
//! for engines that are not on wgpu (`slc shaders --out DIR`).

use crate::{Generated, ShaderError};

/// A kernel in every naga back end.
#[derive(Debug)]
pub struct Translations {
    /// SPIR-V words.
    pub spv: Vec<u32>,
    /// GLSL 4.30 shader of the first entry point (compute kernels: `main`).
    pub glsl: String,
    /// GLSL 4.30 of every entry point (GLSL holds one per shader): `(entry
    /// point, source)`, in [`Kernel::entry_points`](crate::Kernel::entry_points) order.
    pub glsl_entries: Vec<(String, String)>,
    /// HLSL (shader model 5.1).
    pub hlsl: String,
    /// Metal Shading Language.
    pub msl: String,
}

/// Translates a generated kernel to SPIR-V, GLSL, HLSL and MSL.
pub fn translate(g: &Generated) -> Result<Translations, ShaderError> {
    let kernel = g.kernel.name();
    let err = |backend: &'static str| {
        move |e: &dyn std::fmt::Display| ShaderError::Translate {
            kernel,
            backend,
            message: e.to_string(),
        }
    };
    // naga's default adds debug names only in debug builds: fix the flags
    // (names included) so the SPIR-V does not depend on the build profile.
    let spv_flags = naga::back::spv::WriterFlags::ADJUST_COORDINATE_SPACE
        | naga::back::spv::WriterFlags::LABEL_VARYINGS
        | naga::back::spv::WriterFlags::CLAMP_FRAG_DEPTH
        | naga::back::spv::WriterFlags::DEBUG;
    let spv_opts = naga::back::spv::Options { flags: spv_flags, ..Default::default() };
    let spv = naga::back::spv::write_vec(&g.module, &g.info, &spv_opts, None)
        .map_err(|e| err("spv")(&e))?;
    let mut glsl_entries = Vec::new();
    for &(entry, stage) in g.kernel.entry_points() {
        let mut out = String::new();
        let glsl_opts = naga::back::glsl::Options {
            version: naga::back::glsl::Version::Desktop(430),
            ..Default::default()
        };
        let glsl_pipe = naga::back::glsl::PipelineOptions {
            shader_stage: stage,
            entry_point: entry.into(),
            multiview: None,
        };
        naga::back::glsl::Writer::new(
            &mut out,
            &g.module,
            &g.info,
            &glsl_opts,
            &glsl_pipe,
            naga::proc::BoundsCheckPolicies::default(),
        )
        .and_then(|mut w| w.write())
        .map_err(|e| err("glsl")(&e))?;
        glsl_entries.push((entry.to_string(), out));
    }
    let glsl = glsl_entries[0].1.clone();
    let mut hlsl = String::new();
    let hlsl_opts = naga::back::hlsl::Options::default();
    let hlsl_pipe = naga::back::hlsl::PipelineOptions::default();
    naga::back::hlsl::Writer::new(&mut hlsl, &hlsl_opts, &hlsl_pipe)
        .write(&g.module, &g.info, None)
        .map_err(|e| err("hlsl")(&e))?;
    let (msl, _) = naga::back::msl::write_string(
        &g.module,
        &g.info,
        &naga::back::msl::Options::default(),
        &naga::back::msl::PipelineOptions::default(),
    )
    .map_err(|e| err("msl")(&e))?;
    Ok(Translations { spv, glsl, glsl_entries, hlsl, msl })
}
