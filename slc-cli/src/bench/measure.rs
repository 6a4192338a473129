//! Timing by the fastest of repeated runs, and one frame's error spread.

use anyhow::anyhow;

/// The run with the smallest `key` of `repeat` calls of `render`.
pub(super) fn fastest<T>(
    repeat: u32,
    mut render: impl FnMut() -> anyhow::Result<T>,
    key: impl Fn(&T) -> f64,
) -> anyhow::Result<T> {
    let mut best: Option<T> = None;
    for _ in 0..repeat {
        let f = render()?;
        if best.as_ref().is_none_or(|b| key(&f) < key(b)) {
            best = Some(f);
        }
    }
    best.ok_or_else(|| anyhow!("--repeat must be at least 1"))
}

/// Frames `0..repeat` of a configuration rendered by `render(frame)` (a
/// new ξ set each, as a user's frames have): the fastest by `key`, and the
/// mean and sample standard deviation of `rmse` over them all (one frame's
/// RMSE is one draw of a random error: ε decides its distribution).
pub(super) fn fastest_frames<T>(
    repeat: u32,
    mut render: impl FnMut(u32) -> anyhow::Result<T>,
    key: impl Fn(&T) -> f64,
    rmse: impl Fn(&T) -> f64,
) -> anyhow::Result<(T, Spread)> {
    let mut errors = Vec::new();
    let best = fastest(
        repeat,
        || {
            let f = render(errors.len() as u32)?;
            errors.push(rmse(&f));
            Ok(f)
        },
        key,
    )?;
    Ok((best, Spread::of(&errors)))
}

/// Mean and sample standard deviation (0 for one value).
#[derive(Clone, Copy, Debug)]
pub(super) struct Spread {
    /// The mean.
    pub(super) mean: f64,
    /// The sample standard deviation.
    pub(super) sd: f64,
}

impl Spread {
    pub(super) fn of(x: &[f64]) -> Spread {
        let n = x.len().max(1) as f64;
        let mean = x.iter().sum::<f64>() / n;
        let var = if x.len() > 1 {
            x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
        } else {
            0.0
        };
        Spread { mean, sd: var.sqrt() }
    }
}
