//! Emissive textures on triangle lights: each triangle of an emissive mesh
//! is one slc triangle light of constant radiance, so a textured emitter
//! gives each triangle its texture's mean over the triangle's UVs
//! (`emissive × mean`): every triangle emits the power the texture gives
//! it; a pattern finer than the triangles is averaged over each one.
//!
//! The mean is taken at the centroids of the `k × k` congruent triangles
//! the UV triangle divides into (exact for a colour linear in UV), `k`
//! from the triangle's footprint in texels (4 to 32), with nearest-texel
//! lookups, the material's `uv_transform` and UV channel, and the image
//! sampler's address modes (Bevy's default sampler, `ClampToEdge`, where
//! the image has none of its own). Colours are read as Bevy reads them
//! (`Image::get_color_at`, sRGB decoded to linear).

use bevy::image::{ImageAddressMode, ImageSampler};
use bevy::math::Affine2;
use bevy::mesh::{Mesh, UvChannel, VertexAttributeValues};
use bevy::prelude::{Image, LinearRgba};

/// Per triangle of `mesh` (in the order of `Mesh::triangles`, which
/// [`crate::extract::mesh_triangles`] reads), the mean linear RGB of `image` over
/// the triangle's UVs in `channel`, mapped by `uv_transform`; or why it
/// cannot be read (no such UVs, a compressed or unreadable format).
pub(crate) fn triangle_means(
    mesh: &Mesh,
    image: &Image,
    channel: UvChannel,
    uv_transform: Affine2,
) -> Result<Vec<glam::Vec3>, String> {
    let attribute = match channel {
        UvChannel::Uv0 => Mesh::ATTRIBUTE_UV_0,
        UvChannel::Uv1 => Mesh::ATTRIBUTE_UV_1,
    };
    let Some(VertexAttributeValues::Float32x2(uvs)) = mesh.attribute(attribute) else {
        return Err(format!("the emissive texture needs the mesh's {channel:?} UVs (Float32x2)"));
    };
    // The UVs as positions of a copy: Mesh::triangles then yields them in
    // the order, with the same topology and omissions, as the triangles.
    let mut flat = mesh.clone();
    let lifted: Vec<[f32; 3]> = uvs
        .iter()
        .map(|&uv| {
            let t = uv_transform.transform_point2(uv.into());
            [t.x, t.y, 0.0]
        })
        .collect();
    flat.insert_attribute(Mesh::ATTRIBUTE_POSITION, lifted);
    let texels = Texels::new(image)?;
    let means = flat.triangles().map_err(|e| e.to_string())?;
    means
        .map(|t| {
            let [a, b, c] = t.vertices.map(|v| glam::Vec2::new(v.x, v.y));
            texels.mean(a, b, c)
        })
        .collect()
}

/// An image read by nearest texel with its sampler's address modes.
struct Texels<'a> {
    image: &'a Image,
    size: glam::UVec2,
    modes: [ImageAddressMode; 2],
}

impl<'a> Texels<'a> {
    fn new(image: &'a Image) -> Result<Self, String> {
        let size = image.size();
        if size.x == 0 || size.y == 0 {
            return Err("the emissive texture is empty".into());
        }
        let modes = match &image.sampler {
            ImageSampler::Descriptor(d) => [d.address_mode_u, d.address_mode_v],
            ImageSampler::Default => [ImageAddressMode::ClampToEdge; 2],
        };
        let texels = Texels { image, size: glam::UVec2::new(size.x, size.y), modes };
        texels.at(glam::Vec2::ZERO)?;
        Ok(texels)
    }

    /// The texel holding `uv`, as Bevy decodes it (linear RGB).
    fn at(&self, uv: glam::Vec2) -> Result<glam::Vec3, String> {
        let x = texel(uv.x, self.size.x, self.modes[0]);
        let y = texel(uv.y, self.size.y, self.modes[1]);
        let c = self
            .image
            .get_color_at(x, y)
            .map_err(|e| format!("the emissive texture cannot be read: {e:?}"))?;
        let c = LinearRgba::from(c);
        Ok(glam::Vec3::new(c.red, c.green, c.blue))
    }

    /// The mean over the UV triangle `(a, b, c)`: the centroids of its
    /// `k²` congruent sub-triangles (`k` rows; the "up" triangles at
    /// barycentric `(i + 1/3, j + 1/3)/k`, the "down" ones at
    /// `(i + 2/3, j + 2/3)/k`).
    fn mean(&self, a: glam::Vec2, b: glam::Vec2, c: glam::Vec2) -> Result<glam::Vec3, String> {
        let texel_area =
            ((b - a).perp_dot(c - a) * 0.5).abs() * self.size.x as f32 * self.size.y as f32;
        let k = ((2.0 * texel_area).sqrt().ceil() as u32).clamp(4, 32);
        let kf = k as f32;
        let at = |s: f32, t: f32| self.at(a + (b - a) * (s / kf) + (c - a) * (t / kf));
        let mut sum = glam::Vec3::ZERO;
        for i in 0..k {
            for j in 0..k - i {
                sum += at(i as f32 + 1.0 / 3.0, j as f32 + 1.0 / 3.0)?;
                if i + j + 1 < k {
                    sum += at(i as f32 + 2.0 / 3.0, j as f32 + 2.0 / 3.0)?;
                }
            }
        }
        Ok(sum / (kf * kf))
    }
}

/// The texel index along an axis of `n` texels for coordinate `u` under
/// `mode` (a border reads as the edge: slc has no border colour).
fn texel(u: f32, n: u32, mode: ImageAddressMode) -> u32 {
    let u = if u.is_finite() { u } else { 0.0 };
    let wrapped = match mode {
        ImageAddressMode::Repeat => u - u.floor(),
        ImageAddressMode::MirrorRepeat => {
            let m = u.rem_euclid(2.0);
            if m > 1.0 { 2.0 - m } else { m }
        }
        ImageAddressMode::ClampToEdge | ImageAddressMode::ClampToBorder => u.clamp(0.0, 1.0),
    };
    ((wrapped * n as f32) as u32).min(n - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use bevy::asset::RenderAssetUsages;
    use bevy::image::ImageSamplerDescriptor;
    use bevy::prelude::{Mesh as BevyMesh, Plane3d, Triangle2d, Vec2, Vec3};
    use bevy::render::render_resource::{Extent3d, TextureDimension, TextureFormat};

    /// A `w × h` linear RGBA32F image from `f(x, y)`.
    fn image(w: u32, h: u32, f: impl Fn(u32, u32) -> [f32; 3]) -> Image {
        let data: Vec<u8> = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .flat_map(|(x, y)| {
                let [r, g, b] = f(x, y);
                [r, g, b, 1.0].into_iter().flat_map(f32::to_le_bytes).collect::<Vec<_>>()
            })
            .collect();
        Image::new(
            Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            TextureDimension::D2,
            data,
            TextureFormat::Rgba32Float,
            RenderAssetUsages::default(),
        )
    }

    fn close(a: glam::Vec3, b: glam::Vec3) -> bool {
        (a - b).abs().max_element() < 1e-5
    }

    /// A constant texture gives its colour; a texture linear in u gives
    /// its value at each triangle's UV centroid (the sub-triangle rule is
    /// exact for linear colours up to the texels' quantisation).
    #[test]
    fn means_of_constant_and_linear_textures() {
        let plane: BevyMesh = Plane3d::new(Vec3::Y, Vec2::splat(1.0)).into();
        let red = image(4, 4, |_, _| [0.8, 0.4, 0.2]);
        let m = triangle_means(&plane, &red, UvChannel::Uv0, Affine2::IDENTITY).unwrap();
        assert_eq!(m.len(), plane.triangles().unwrap().count());
        assert!(m.iter().all(|&c| close(c, glam::Vec3::new(0.8, 0.4, 0.2))), "{m:?}");

        // 1024 texels along u, value (x + 0.5)/1024: the mean over a
        // triangle is its UV centroid's u within a texel.
        let ramp = image(1024, 1, |x, _| [(x as f32 + 0.5) / 1024.0; 3]);
        let tri: BevyMesh = Triangle2d::new(Vec2::ZERO, Vec2::X, Vec2::Y).into();
        let m = triangle_means(&tri, &ramp, UvChannel::Uv0, Affine2::IDENTITY).unwrap();
        let uvs = match tri.attribute(BevyMesh::ATTRIBUTE_UV_0) {
            Some(VertexAttributeValues::Float32x2(v)) => v.clone(),
            _ => unreachable!(),
        };
        let centroid = (uvs[0][0] + uvs[1][0] + uvs[2][0]) / 3.0;
        assert!((m[0].x - centroid).abs() < 2.0 / 1024.0, "{} vs {centroid}", m[0].x);
    }

    /// Address modes: u = 1.25 reads texel 1 of 4 repeated (0.25), texel 3
    /// mirrored (0.75) and clamped; the default sampler clamps.
    #[test]
    fn address_modes() {
        assert_eq!(texel(1.25, 4, ImageAddressMode::Repeat), 1);
        assert_eq!(texel(1.25, 4, ImageAddressMode::MirrorRepeat), 3);
        assert_eq!(texel(-0.25, 4, ImageAddressMode::MirrorRepeat), 1);
        assert_eq!(texel(1.25, 4, ImageAddressMode::ClampToEdge), 3);
        assert_eq!(texel(-3.0, 4, ImageAddressMode::ClampToEdge), 0);
        assert_eq!(texel(f32::NAN, 4, ImageAddressMode::Repeat), 0);
        let mut img = image(2, 1, |x, _| [x as f32; 3]);
        let tri: BevyMesh = Triangle2d::new(Vec2::ZERO, Vec2::X, Vec2::Y).into();
        // The whole triangle shifted to u in [2, 2.5]: clamped, texel 1.
        let shift =
            Affine2::from_scale_angle_translation(Vec2::splat(0.5), 0.0, Vec2::new(2.0, 0.0));
        let m = triangle_means(&tri, &img, UvChannel::Uv0, shift).unwrap();
        assert!(close(m[0], glam::Vec3::ONE), "{m:?}");
        // Repeated, u in [0, 0.5] mod 1: texel 0 only.
        img.sampler = ImageSampler::Descriptor(ImageSamplerDescriptor {
            address_mode_u: ImageAddressMode::Repeat,
            ..Default::default()
        });
        let m = triangle_means(&tri, &img, UvChannel::Uv0, shift).unwrap();
        assert!(m[0].max_element() < 0.5, "{m:?}");
    }

    /// No UVs in the asked channel: a reason, not a panic.
    #[test]
    fn missing_uvs_are_an_error() {
        let plane: BevyMesh = Plane3d::new(Vec3::Y, Vec2::splat(1.0)).into();
        let img = image(2, 2, |_, _| [1.0; 3]);
        assert!(triangle_means(&plane, &img, UvChannel::Uv1, Affine2::IDENTITY).is_err());
    }
}
