//! IES LM-63 photometric files: parser and candela lookup.
//!
//! Formats: LM-63-1986 (no header line), LM-63-1991 (`IESNA91`),
//! LM-63-1995 and LM-63-2002 (`IESNA:LM-63-…`); `TILT=NONE`,
//! `TILT=INCLUDE` (data parsed and kept) and `TILT=<file>` (name kept). Like
//! most renderers we do not apply tilt factors: they describe a lamp tilted
//! away from its test position, which a renderer's fixed orientation does not
//! model. Absolute photometry (lumens = −1) needs no special case: candela
//! values are used as written, times the candela multiplier and the ballast
//! factor (and, before 2002, the ballast-lamp photometric factor).
//!
//! No maintained, permissively licensed `no_std` Rust crate parses LM-63 with
//! all symmetries and typed, line-numbered errors, so this one is written
//! here. The parser never panics and allocates at most in proportion to its
//! input (counts are checked against the tokens actually present).
//!
//! Lookup (type C): vertical angle γ (0° = nadir), horizontal angle C, with
//! the LM-63 horizontal symmetries decided by the first/last horizontal
//! angle: last 0° (rotationally symmetric), 0–90° (quadrant symmetric),
//! 0–180° (bilateral about the 0–180° plane), 90–270° (bilateral about the
//! 90–270° plane), 0–360° (none). Bilinear interpolation in (γ, C); zero
//! outside the vertical range. The lookup is shared code: the GPU runs the
//! same function over the same flattened table ([`IesProfile::table`]).
//!
//! Files: [`lookup`] (the shared candela lookup and the portable arctangent
//! it uses) and `parse.rs` (the LM-63 parser).

pub mod lookup;
mod parse;

pub use lookup::{
    atan_portable, atan2_portable, ies_candela, ies_candela_dir, ies_fold_c, ies_lerp_t,
    ies_light_candela, ies_segment,
};

use alloc::string::String;
use alloc::vec::Vec;

/// LM-63 edition, from the file's first line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IesFormat {
    /// LM-63-1986: no identifying first line.
    Lm63_1986,
    /// LM-63-1991: `IESNA91`.
    Lm63_1991,
    /// LM-63-1995: `IESNA:LM-63-1995`.
    Lm63_1995,
    /// LM-63-2002: `IESNA:LM-63-2002`.
    Lm63_2002,
}

/// Photometric coordinate system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PhotometricType {
    /// Type C (vertical axis; the usual one for building and road lighting).
    C,
    /// Type B (horizontal axis; floodlights).
    B,
    /// Type A (automotive).
    A,
}

/// The file's tilt section.
#[derive(Clone, Debug, PartialEq)]
pub enum Tilt {
    /// `TILT=NONE`.
    None,
    /// `TILT=INCLUDE` with its lamp-to-luminaire geometry, angles and factors.
    Include {
        /// Lamp-to-luminaire geometry code (1–3).
        geometry: u32,
        /// Tilt angles in degrees.
        angles: Vec<f32>,
        /// Multiplying factors per angle.
        factors: Vec<f32>,
    },
    /// `TILT=<file name>`: an external tilt file (not read).
    File(String),
}

/// A parsed LM-63 profile.
#[derive(Clone, Debug, PartialEq)]
pub struct IesProfile {
    /// Edition.
    pub format: IesFormat,
    /// `[KEYWORD] value` lines (1991 and later), in file order.
    pub keywords: Vec<(String, String)>,
    /// Tilt section.
    pub tilt: Tilt,
    /// Number of lamps.
    pub lamps: u32,
    /// Lumens per lamp; −1 marks absolute photometry.
    pub lumens_per_lamp: f32,
    /// Candela multiplier.
    pub multiplier: f32,
    /// Photometric type.
    pub photometric_type: PhotometricType,
    /// Units of the luminous opening: 1 feet, 2 metres.
    pub units: u32,
    /// Luminous opening width, length, height.
    pub opening: [f32; 3],
    /// Ballast factor.
    pub ballast_factor: f32,
    /// Ballast-lamp photometric factor (1991/1995) or "future use" (2002).
    pub ballast_lamp_factor: f32,
    /// Input watts.
    pub input_watts: f32,
    /// Vertical angles (degrees), strictly increasing.
    pub vertical: Vec<f32>,
    /// Horizontal angles (degrees), strictly increasing.
    pub horizontal: Vec<f32>,
    /// Candela values as written, `horizontal.len() × vertical.len()`,
    /// horizontal-major.
    pub candela: Vec<f32>,
    table: Vec<f32>,
    max_candela: f32,
}

/// Largest accepted angle count in one direction.
pub const MAX_ANGLES: usize = 100_000;
/// Largest accepted candela table.
pub const MAX_VALUES: usize = 4_000_000;

impl IesProfile {
    /// `true` for type C photometry (the type [`crate::light::IesLight`] uses).
    pub fn is_type_c(&self) -> bool {
        self.photometric_type == PhotometricType::C
    }

    /// Photometric type.
    pub fn photometric_type(&self) -> PhotometricType {
        self.photometric_type
    }

    /// The flattened lookup table (see [`ies_candela`]); candela values
    /// already multiplied by the file's multipliers.
    pub fn table(&self) -> &[f32] {
        &self.table
    }

    /// Peak candela × multipliers: the light's `I_max`.
    pub fn max_candela(&self) -> f32 {
        self.max_candela
    }

    /// Candela at vertical angle γ and horizontal angle C (degrees), with
    /// multipliers applied.
    pub fn candela_at(&self, gamma: f32, c: f32) -> f32 {
        ies_candela(&self.table, 0, gamma, c)
    }

    /// Total luminous flux (lumens, with multipliers) integrated from the
    /// table over the sphere: `∫∫ I(γ, C) sin γ dγ dC`, midpoint rule on a
    /// 0.5° grid.
    pub fn total_flux(&self) -> f64 {
        const N_G: usize = 360;
        const N_C: usize = 720;
        let (dg, dc) =
            (core::f64::consts::PI / N_G as f64, 2.0 * core::f64::consts::PI / N_C as f64);
        let mut sum = 0.0f64;
        for i in 0..N_G {
            let g = (i as f64 + 0.5) * dg;
            let mut ring = 0.0f64;
            for j in 0..N_C {
                let c = (j as f64 + 0.5) * dc;
                ring += self.candela_at(g.to_degrees() as f32, c.to_degrees() as f32) as f64;
            }
            sum += ring * libm::sin(g);
        }
        sum * dg * dc
    }
}
