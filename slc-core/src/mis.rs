//! Multiple importance sampling weights (Veach & Guibas 1995). With SLC the
//! light strategy's pdf includes the Russian-roulette probability (talk:
//! "Multiple importance sampling"): `pdf_light = pdf(select) · p_rr(d) ·
//! pdf_area(y)`, converted to solid angle
//! ([`crate::light::area_to_solid_angle_pdf`]).

use crate::light::INV_PI;
use crate::wgsl::*;

crate::shared! {
    /// Balance heuristic weight of strategy `a` against `b`: `a / (a + b)`
    /// (0 when both pdfs are 0).
    pub fn mis_balance(pdf_a: f32, pdf_b: f32) -> f32 {
        let s: f32 = pdf_a + pdf_b;
        if s <= 0.0 {
            return 0.0;
        }
        return pdf_a / s;
    }

    /// Power heuristic (β = 2) weight of strategy `a` against `b`:
    /// `a² / (a² + b²)` (0 when both pdfs are 0).
    pub fn mis_power(pdf_a: f32, pdf_b: f32) -> f32 {
        let a2: f32 = pdf_a * pdf_a;
        let s: f32 = a2 + pdf_b * pdf_b;
        if s <= 0.0 {
            return 0.0;
        }
        return a2 / s;
    }

    /// Cosine-weighted hemisphere pdf of a diffuse BSDF sample: `max(cos θ, 0)/π`.
    pub fn cosine_pdf(cos_theta: f32) -> f32 {
        return max(cos_theta, 0.0) * INV_PI;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one() {
        for (a, b) in [(1.0f32, 3.0f32), (0.5, 0.5), (1e-20, 1.0), (7.0, 0.0)] {
            assert!((mis_balance(a, b) + mis_balance(b, a) - 1.0).abs() < 1e-6);
            assert!((mis_power(a, b) + mis_power(b, a) - 1.0).abs() < 1e-6);
        }
        assert_eq!(mis_balance(0.0, 0.0), 0.0);
        assert_eq!(mis_power(0.0, 0.0), 0.0);
    }
}
