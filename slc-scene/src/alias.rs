//! Walker's alias table (Vose's construction): the `power` baseline's light
//! selection, read by both backends (the GPU gets [`crate::lights::LightSet::power_table`]).

/// Samples index `i` with probability `wᵢ/Σw` in O(1).
#[derive(Clone, Debug)]
pub struct AliasTable {
    prob: Vec<f64>,
    alias: Vec<usize>,
    pdf: Vec<f64>,
}

impl AliasTable {
    /// Builds the table; non-finite or negative weights count as 0, and an
    /// all-zero set is sampled uniformly.
    pub fn new(weights: &[f64]) -> AliasTable {
        let n = weights.len();
        let w: Vec<f64> =
            weights.iter().map(|&x| if x.is_finite() && x > 0.0 { x } else { 0.0 }).collect();
        let total: f64 = w.iter().sum();
        let pdf: Vec<f64> = if total > 0.0 {
            w.iter().map(|x| x / total).collect()
        } else {
            vec![1.0 / n.max(1) as f64; n]
        };
        let mut prob = vec![0.0; n];
        let mut alias = vec![0; n];
        let mut scaled: Vec<f64> = pdf.iter().map(|p| p * n as f64).collect();
        let (mut small, mut large): (Vec<usize>, Vec<usize>) =
            (0..n).partition(|&i| scaled[i] < 1.0);
        while !small.is_empty() && !large.is_empty() {
            let (s, l) = (small.pop().expect("non-empty"), *large.last().expect("non-empty"));
            prob[s] = scaled[s];
            alias[s] = l;
            scaled[l] -= 1.0 - scaled[s];
            if scaled[l] < 1.0 {
                large.pop();
                small.push(l);
            }
        }
        for i in small.into_iter().chain(large) {
            prob[i] = 1.0;
        }
        AliasTable { prob, alias, pdf }
    }

    /// Index for uniforms `u1, u2 ∈ [0, 1)`, as the GPU draws it from
    /// [`AliasTable::entries`] in f32: the column by slc-core's
    /// `uniform_light`, then `alias_choice` against the column's keep
    /// probability.
    pub fn sample(&self, u1: f32, u2: f32) -> usize {
        let i = slc_core::reservoir::uniform_light(u1, self.prob.len() as u32);
        slc_core::reservoir::alias_choice(
            i,
            self.alias[i as usize] as u32,
            self.prob[i as usize] as f32,
            u2,
        ) as usize
    }

    /// Probability of index `i`.
    pub fn pdf(&self, i: usize) -> f64 {
        self.pdf[i]
    }

    /// Per index: the probability of keeping it in its column, its alias,
    /// and its pmf (e.g. for upload to the GPU).
    pub fn entries(&self) -> impl Iterator<Item = (f64, usize, f64)> + '_ {
        (0..self.prob.len()).map(|i| (self.prob[i], self.alias[i], self.pdf[i]))
    }
}

#[cfg(test)]
mod tests {
    use super::AliasTable;

    #[test]
    fn alias_table_reproduces_the_distribution_exactly() {
        // With a fine grid over (u1, u2) the sampled frequencies equal the
        // weights up to the grid resolution.
        let w = [1.0, 3.0, 0.0, 6.0, 2.5];
        let t = AliasTable::new(&w);
        let total: f64 = w.iter().sum();
        let m = 2000;
        let mut count = [0usize; 5];
        for a in 0..m {
            for b in 0..m {
                count[t.sample((a as f32 + 0.5) / m as f32, (b as f32 + 0.5) / m as f32)] += 1;
            }
        }
        for i in 0..5 {
            let f = count[i] as f64 / (m * m) as f64;
            assert!((f - w[i] / total).abs() < 2.0 / m as f64, "{i}: {f} vs {}", w[i] / total);
            assert!((t.pdf(i) - w[i] / total).abs() < 1e-12);
        }
    }
}
