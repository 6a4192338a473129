//! Linear RGB images: EXR and PNG output, RMSE.

#[cfg(feature = "io")]
use crate::OutputError;
use glam::Vec3;
#[cfg(feature = "io")]
use std::path::Path;

/// A linear HDR RGB image, row-major, y down.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` pixels.
    pub data: Vec<Vec3>,
}

impl Image {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        Image { width, height, data: vec![Vec3::ZERO; width as usize * height as usize] }
    }

    /// Root-mean-square error over all pixels and channels.
    pub fn rmse(&self, reference: &Image) -> f64 {
        assert_eq!(
            (self.width, self.height),
            (reference.width, reference.height),
            "image sizes differ"
        );
        let n = self.data.len() as f64 * 3.0;
        let sum: f64 = self
            .data
            .iter()
            .zip(&reference.data)
            .map(|(a, b)| (*a - *b).as_dvec3().length_squared())
            .sum();
        (sum / n).sqrt()
    }

    /// Mean over pixels and channels.
    pub fn mean(&self) -> f64 {
        self.data.iter().map(|p| (p.x + p.y + p.z) as f64).sum::<f64>()
            / (3.0 * self.data.len() as f64)
    }

    /// Mean of each channel (`[r, g, b]`) over all pixels: what a test
    /// compares, so an error in one channel is not diluted by the others.
    pub fn channel_means(&self) -> [f64; 3] {
        let n = self.data.len().max(1) as f64;
        let s = self
            .data
            .iter()
            .fold([0.0f64; 3], |a, p| [a[0] + p.x as f64, a[1] + p.y as f64, a[2] + p.z as f64]);
        s.map(|c| c / n)
    }

    /// `true` when every channel of every pixel is finite.
    pub fn is_finite(&self) -> bool {
        self.data.iter().all(|p| p.is_finite())
    }

    #[cfg(feature = "io")]
    /// Writes a linear half-float RGB OpenEXR file.
    pub fn write_exr(&self, path: &Path) -> Result<(), OutputError> {
        let w = self.width as usize;
        exr::prelude::write_rgb_file(path, w, self.height as usize, |x, y| {
            let p = self.data[y * w + x];
            (p.x, p.y, p.z)
        })
        .map_err(|e| OutputError(path.display().to_string(), e.to_string()))
    }

    #[cfg(feature = "io")]
    /// Reads the first RGB(A) layer of an OpenEXR file.
    pub fn read_exr(path: &Path) -> Result<Image, OutputError> {
        let img = exr::prelude::read_first_rgba_layer_from_file(
            path,
            |res, _| Image::new(res.width() as u32, res.height() as u32),
            |img: &mut Image,
             pos: exr::prelude::Vec2<usize>,
             (r, g, b, _a): (f32, f32, f32, f32)| {
                let w = img.width as usize;
                img.data[pos.y() * w + pos.x()] = Vec3::new(r, g, b);
            },
        )
        .map_err(|e| OutputError(path.display().to_string(), e.to_string()))?;
        Ok(img.layer_data.channel_data.pixels)
    }

    #[cfg(feature = "io")]
    /// Writes an 8-bit sRGB PNG preview: `exposure · L`, then Reinhard-style
    /// `x/(1+x)` per channel scaled so that 1.0 maps near white, then sRGB.
    pub fn write_png(&self, path: &Path, exposure: f32) -> Result<(), OutputError> {
        crate::check_exposure(exposure)
            .map_err(|e| OutputError(path.display().to_string(), e.to_string()))?;
        let bytes: Vec<u8> = self.data.iter().flat_map(|p| tonemap(*p * exposure)).collect();
        write_rgb8_png(path, self.width, self.height, &bytes)
    }
}

#[cfg(feature = "io")]
/// Writes 8-bit RGB bytes (`width × height × 3`, row-major) as a PNG.
pub fn write_rgb8_png(
    path: &Path,
    width: u32,
    height: u32,
    bytes: &[u8],
) -> Result<(), OutputError> {
    let err = |e: String| OutputError(path.display().to_string(), e);
    let file = std::fs::File::create(path).map_err(|e| err(e.to_string()))?;
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(|e| err(e.to_string()))?;
    writer.write_image_data(bytes).map_err(|e| err(e.to_string()))?;
    writer.finish().map_err(|e| err(e.to_string()))
}

/// Display mapping used by the PNG previews.
pub fn tonemap(c: Vec3) -> [u8; 3] {
    let map = |x: f32| {
        let x = if x.is_finite() { x.max(0.0) } else { 0.0 };
        (slc_core::frame::display_encode(x) * 255.0 + 0.5).clamp(0.0, 255.0) as u8
    };
    [map(c.x), map(c.y), map(c.z)]
}
