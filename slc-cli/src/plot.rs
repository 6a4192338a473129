//! Plots with plotters: speed against error for `slc bench`, the polar
//! candela curve for `slc ies`. `.svg` or `.png` by the file's extension;
//! PNG text uses the Ubuntu font bundled by `epaint_default_fonts`, so no
//! system font is needed.

use crate::report::{PtReport, Report};
use anyhow::{Context, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // Registration fails only for unparsable font data, which a bundled
        // font is not; the SVG backend never needs it.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        );
    });
}

/// Draws with `draw` onto an SVG or PNG of `size` chosen by `path`'s extension.
fn with_backend(
    path: &Path,
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<SVGBackend<'_>, Shift>) -> anyhow::Result<()>,
    draw_png: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    // Both backends measure text with the registered font.
    register_font();
    check_path("plot file", path)?;
    match extension(path).as_deref() {
        Some("svg") => {
            let root = SVGBackend::new(path, size).into_drawing_area();
            draw(&root)?;
            root.present().with_context(|| format!("cannot write {}", path.display()))
        }
        Some("png") => {
            let root = BitMapBackend::new(path, size).into_drawing_area();
            draw_png(&root)?;
            root.present().with_context(|| format!("cannot write {}", path.display()))
        }
        _ => unreachable!("check_path"),
    }
}

fn extension(path: &Path) -> Option<String> {
    path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase)
}

/// Checks, before any work, that `flag`'s plot path ends in `.svg` or
/// `.png` and that its folder exists.
pub fn check_path(flag: &str, path: &Path) -> anyhow::Result<()> {
    crate::output_folder(flag, path)?;
    match extension(path).as_deref() {
        Some("svg" | "png") => Ok(()),
        _ => Err(anyhow!("{flag} {}: a plot must end in .svg or .png", path.display())),
    }
}

/// Every plot's legend: the series' labels in the upper right on a
/// translucent white box, `size`-point text.
fn legend<'a, DB: DrawingBackend + 'a, X: Ranged<ValueType = f64>, Y: Ranged<ValueType = f64>>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    size: u32,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", size))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
}

/// Colour of each method in every plot.
pub fn method_color(method: &str) -> RGBColor {
    match method {
        "slc" => RGBColor(31, 119, 180),
        "clamp" => RGBColor(214, 39, 40),
        "none" => RGBColor(40, 40, 40),
        "reference" => RGBColor(120, 120, 120),
        "slc-reservoir" => RGBColor(148, 103, 189),
        "slc-weighted" => RGBColor(23, 190, 207),
        "uniform" => RGBColor(255, 127, 14),
        "power" => RGBColor(140, 86, 75),
        "lightbvh" => RGBColor(227, 119, 194),
        _ => RGBColor(44, 160, 44),
    }
}

/// Points of `pts` (time, error) not beaten by a faster-and-better point,
/// sorted by time.
pub fn pareto_front(pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = pts.to_vec();
    v.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in v {
        if front.last().is_none_or(|l| p.1 < l.1) {
            front.push(p);
        }
    }
    front
}

/// RMSE (log) against shading time (log), one point per run, each method's
/// Pareto front joined by a line.
pub fn speed_vs_error(report: &Report, path: &Path) -> anyhow::Result<()> {
    with_backend(
        path,
        (960, 640),
        |a| speed_vs_error_on(report, a),
        |a| speed_vs_error_on(report, a),
    )
}

fn speed_vs_error_on<DB: DrawingBackend>(
    report: &Report,
    root: &DrawingArea<DB, Shift>,
) -> anyhow::Result<()> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(err)?;
    let runs: Vec<_> = report.runs.iter().filter(|r| r.rmse > 0.0 && r.shading_ms > 0.0).collect();
    if runs.is_empty() {
        return Err(anyhow!("no run with positive RMSE and time to plot"));
    }
    let (tmin, tmax) = runs
        .iter()
        .fold((f64::MAX, 0.0f64), |(a, b), r| (a.min(r.shading_ms), b.max(r.shading_ms)));
    // One frame's spread about the mean RMSE (`rmse_sd`, where the run
    // rendered several frames) as an error bar, cut where it would reach 0.
    let spread = |r: &crate::report::Run| {
        let sd = r.rmse_sd.unwrap_or(0.0);
        ((r.rmse - sd).max(r.rmse * 0.1), r.rmse + sd)
    };
    let (emin, emax) =
        runs.iter().fold((f64::MAX, 0.0f64), |(a, b), r| (a.min(spread(r).0), b.max(spread(r).1)));
    let title = format!(
        "Speed vs error: {} {}x{}, {} lights, {} backend",
        report.scene, report.width, report.height, report.lights, report.backend
    );
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        // log10 of both on linear axes: evenly spaced, always-labelled ticks.
        .build_cartesian_2d(
            (tmin / 1.4).log10()..(tmax * 1.4).log10(),
            (emin / 1.4).log10()..(emax * 1.4).log10(),
        )
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("shading time (ms, log scale)")
        .y_desc("RMSE vs reference (log scale)")
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .x_labels(12)
        .y_labels(12)
        .x_label_formatter(&|v| {
            let t = 10f64.powf(*v);
            if t < 10.0 { format!("{t:.2}") } else { format!("{t:.0}") }
        })
        .y_label_formatter(&|v| format!("{:.1e}", 10f64.powf(*v)))
        .draw()
        .map_err(err)?;
    let mut methods: Vec<&str> = runs.iter().map(|r| r.method.as_str()).collect();
    methods.dedup();
    methods.sort();
    methods.dedup();
    for m in methods {
        let color = method_color(m);
        let pts: Vec<(f64, f64)> = runs
            .iter()
            .filter(|r| r.method == m)
            .map(|r| (r.shading_ms.log10(), r.rmse.log10()))
            .collect();
        let front = pareto_front(&pts);
        chart
            .draw_series(LineSeries::new(front, color.stroke_width(2)))
            .map_err(err)?
            .label(m.to_string())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
            });
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 5, color.filled()))).map_err(err)?;
        chart
            .draw_series(
                runs.iter().filter(|r| r.method == m && r.rmse_sd.is_some_and(|sd| sd > 0.0)).map(
                    |r| {
                        let (lo, hi) = spread(r);
                        ErrorBar::new_vertical(
                            r.shading_ms.log10(),
                            lo.log10(),
                            r.rmse.log10(),
                            hi.log10(),
                            color.stroke_width(1),
                            8,
                        )
                    },
                ),
            )
            .map_err(err)?;
        chart
            .draw_series(runs.iter().filter(|r| r.method == m && r.param.is_some()).map(|r| {
                Text::new(
                    format!("{}", r.param.unwrap_or_default()),
                    ((r.shading_ms * 1.02).log10(), (r.rmse * 1.06).log10()),
                    ("sans-serif", 13).into_font().color(&color),
                )
            }))
            .map_err(err)?;
    }
    legend(&mut chart, 18).map_err(err)?;
    Ok(())
}

/// Path tracing: RMSE (log) against time (log) per method.
pub fn rmse_over_time(report: &PtReport, path: &Path) -> anyhow::Result<()> {
    with_backend(
        path,
        (960, 640),
        |a| rmse_over_time_on(report, a),
        |a| rmse_over_time_on(report, a),
    )
}

fn rmse_over_time_on<DB: DrawingBackend>(
    report: &PtReport,
    root: &DrawingArea<DB, Shift>,
) -> anyhow::Result<()> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(err)?;
    let pts: Vec<(f64, f64)> = report
        .runs
        .iter()
        .flat_map(|r| r.series.iter().map(|s| (s.0, s.2)))
        .filter(|p| p.0 > 0.0 && p.1 > 0.0)
        .collect();
    if pts.is_empty() {
        return Err(anyhow!("no samples to plot"));
    }
    let (tmin, tmax) = pts.iter().fold((f64::MAX, 0.0f64), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (emin, emax) = pts.iter().fold((f64::MAX, 0.0f64), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let title = format!(
        "RMSE vs time: {} {}x{}, {} lights, {} backend",
        report.scene, report.width, report.height, report.lights, report.backend
    );
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d(
            (tmin / 1.2).log10()..(tmax * 1.2).log10(),
            (emin / 1.2).log10()..(emax * 1.2).log10(),
        )
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("render time (ms, log scale)")
        .y_desc("RMSE vs reference (log scale)")
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .x_labels(10)
        .y_labels(10)
        .x_label_formatter(&|v| format!("{:.0}", 10f64.powf(*v)))
        .y_label_formatter(&|v| format!("{:.1e}", 10f64.powf(*v)))
        .draw()
        .map_err(err)?;
    for r in &report.runs {
        let color = method_color(&r.method);
        let line: Vec<(f64, f64)> = r
            .series
            .iter()
            .filter(|s| s.0 > 0.0 && s.2 > 0.0)
            .map(|s| (s.0.log10(), s.2.log10()))
            .collect();
        chart
            .draw_series(LineSeries::new(line, color.stroke_width(2)))
            .map_err(err)?
            .label(r.method.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
            });
    }
    legend(&mut chart, 18).map_err(err)?;
    Ok(())
}

/// A suite's net RMSE per method over uniform sampling's, one column per
/// scene (log scale; below 1 beats uniform sampling at equal time).
pub fn suite_vs_uniform(rows: &[crate::report::SuiteRow], path: &Path) -> anyhow::Result<()> {
    with_backend(
        path,
        (1280, 720),
        |a| suite_vs_uniform_on(rows, a),
        |a| suite_vs_uniform_on(rows, a),
    )
}

fn suite_vs_uniform_on<DB: DrawingBackend>(
    rows: &[crate::report::SuiteRow],
    root: &DrawingArea<DB, Shift>,
) -> anyhow::Result<()> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(err)?;
    let mut scenes: Vec<&str> = Vec::new();
    let mut methods: Vec<&str> = Vec::new();
    for r in rows {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
        if !methods.contains(&r.method.as_str()) {
            methods.push(&r.method);
        }
    }
    // Ratios the reference's noise left unmeasurable (NaN) are not drawn;
    // the axis spans 0.9–1.1 at least.
    let ys = rows.iter().map(|r| r.rmse_vs_uniform).filter(|v| v.is_finite() && *v > 0.0);
    let (lo, hi) = ys.fold((1.0f64, 1.0f64), |(a, b), v| (a.min(v), b.max(v)));
    let (lo, hi) = ((lo.min(0.9) / 1.2).log10(), (hi.max(1.1) * 1.2).log10());
    let n = scenes.len();
    // Scenes as rows (their names read across), the ratio along x.
    let mut chart = ChartBuilder::on(root)
        .caption(
            "Net RMSE over uniform sampling's at equal time, per suite scene",
            ("sans-serif", 24),
        )
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(220)
        .build_cartesian_2d(lo..hi, -0.5f64..n as f64 - 0.5)
        .map_err(err)?;
    let names: Vec<String> = scenes.iter().map(|s| s.to_string()).collect();
    chart
        .configure_mesh()
        .x_desc("net RMSE / uniform's (log scale; < 1 beats uniform sampling)")
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 18))
        .y_labels(n.max(1))
        .y_label_formatter(&|v| {
            let i = v.round();
            if (v - i).abs() < 1e-6 && i >= 0.0 {
                names.get(i as usize).cloned().unwrap_or_default()
            } else {
                String::new()
            }
        })
        .x_labels(10)
        .x_label_formatter(&|v| format!("{:.2}", 10f64.powf(*v)))
        .draw()
        .map_err(err)?;
    chart
        .draw_series(LineSeries::new(
            vec![(0.0, -0.5), (0.0, n as f64 - 0.5)],
            BLACK.stroke_width(1),
        ))
        .map_err(err)?;
    for (k, m) in methods.iter().enumerate() {
        let color = method_color(m);
        // Each method a little off the row, so equal values stay visible.
        let dy = (k as f64 - (methods.len() as f64 - 1.0) / 2.0) * 0.08;
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.method == *m && r.rmse_vs_uniform.is_finite() && r.rmse_vs_uniform > 0.0)
            .filter_map(|r| {
                scenes
                    .iter()
                    .position(|s| *s == r.scene)
                    .map(|i| (r.rmse_vs_uniform.log10(), i as f64 + dy))
            })
            .collect();
        chart
            .draw_series(pts.into_iter().map(|p| Circle::new(p, 5, color.filled())))
            .map_err(err)?
            .label(m.to_string())
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, color.filled()));
    }
    legend(&mut chart, 16).map_err(err)?;
    Ok(())
}

/// Polar candela plot of an IES profile: the C = 0°/180° and C = 90°/270°
/// planes, γ = 0° (nadir) pointing down, rings of equal candela.
pub fn ies_polar(p: &slc_core::ies::IesProfile, title: &str, path: &Path) -> anyhow::Result<()> {
    with_backend(path, (720, 760), |a| ies_polar_on(p, title, a), |a| ies_polar_on(p, title, a))
}

fn ies_polar_on<DB: DrawingBackend>(
    p: &slc_core::ies::IesProfile,
    title: &str,
    root: &DrawingArea<DB, Shift>,
) -> anyhow::Result<()> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(err)?;
    let peak = (p.max_candela() as f64).max(1e-9);
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 22))
        .margin(20)
        .build_cartesian_2d(-1.15..1.15, -1.15..1.15)
        .map_err(err)?;
    // Rings at 25%, 50%, 75%, 100% of the peak, and 30° spokes.
    for k in 1..=4 {
        let r = k as f64 / 4.0;
        let ring: Vec<(f64, f64)> = (0..=120)
            .map(|i| {
                let a = i as f64 / 120.0 * std::f64::consts::TAU;
                (r * a.cos(), r * a.sin())
            })
            .collect();
        chart.draw_series(LineSeries::new(ring, RGBColor(200, 200, 200))).map_err(err)?;
        chart
            .draw_series(std::iter::once(Text::new(
                format!("{:.0} cd", peak * r),
                (0.02, -r + 0.02),
                ("sans-serif", 14),
            )))
            .map_err(err)?;
    }
    for k in 0..12 {
        let a = k as f64 * std::f64::consts::PI / 6.0;
        chart
            .draw_series(LineSeries::new(
                [(0.0, 0.0), (a.sin(), -a.cos())],
                RGBColor(225, 225, 225),
            ))
            .map_err(err)?;
    }
    let curve = |c_right: f32, c_left: f32| -> Vec<(f64, f64)> {
        // Right half: plane c_right, γ from 0 (down) to 180 (up); left half: c_left back down.
        let mut v: Vec<(f64, f64)> = (0..=360)
            .map(|i| {
                let g = i as f64 * 0.5;
                let r = p.candela_at(g as f32, c_right) as f64 / peak;
                (r * g.to_radians().sin(), -r * g.to_radians().cos())
            })
            .collect();
        v.extend((0..=360).rev().map(|i| {
            let g = i as f64 * 0.5;
            let r = p.candela_at(g as f32, c_left) as f64 / peak;
            (-r * g.to_radians().sin(), -r * g.to_radians().cos())
        }));
        v
    };
    let c0 = RGBColor(31, 119, 180);
    let c90 = RGBColor(214, 39, 40);
    chart
        .draw_series(LineSeries::new(curve(0.0, 180.0), c0.stroke_width(2)))
        .map_err(err)?
        .label("C = 0° / 180°")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c0.stroke_width(3)));
    chart
        .draw_series(LineSeries::new(curve(90.0, 270.0), c90.stroke_width(2)))
        .map_err(err)?
        .label("C = 90° / 270°")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c90.stroke_width(3)));
    legend(&mut chart, 16).map_err(err)?;
    Ok(())
}

/// `slc bench --flicker`: per sequence (columns), each method's RMSE
/// against the frame's reference (top) and against its previous frame
/// (bottom) over the frames, log scale.
pub fn flicker(report: &crate::report::FlickerReport, path: &Path) -> anyhow::Result<()> {
    with_backend(path, (1440, 800), |a| flicker_on(report, a), |a| flicker_on(report, a))
}

fn flicker_on<DB: DrawingBackend>(
    report: &crate::report::FlickerReport,
    root: &DrawingArea<DB, Shift>,
) -> anyhow::Result<()> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(err)?;
    let title = format!(
        "Flicker: {} {}x{}, {} VPLs, eps {}",
        report.scene, report.width, report.height, report.vpls, report.error_bound
    );
    let root = root.titled(&title, ("sans-serif", 24)).map_err(err)?;
    let panels = root.split_evenly((2, report.sequences.len().max(1)));
    let colors = [
        RGBColor(31, 119, 180),
        RGBColor(44, 160, 44),
        RGBColor(255, 127, 14),
        RGBColor(40, 40, 40),
    ];
    for (row, what) in ["RMSE vs frame's reference", "RMSE vs previous frame"].iter().enumerate() {
        for (col, s) in report.sequences.iter().enumerate() {
            let series: Vec<Vec<(f64, f64)>> = s
                .curves
                .iter()
                .map(|c| {
                    let (v, first) = if row == 0 { (&c.rmse, 0) } else { (&c.temporal_rmse, 1) };
                    v.iter()
                        .enumerate()
                        .filter(|(_, e)| **e > 0.0)
                        .map(|(f, &e)| ((f + first) as f64, e.log10()))
                        .collect()
                })
                .collect();
            let all: Vec<f64> = series.iter().flatten().map(|p| p.1).collect();
            if all.is_empty() {
                continue;
            }
            let (lo, hi) = all.iter().fold((f64::MAX, f64::MIN), |(a, b), &y| (a.min(y), b.max(y)));
            let mut chart = ChartBuilder::on(&panels[row * report.sequences.len() + col])
                .caption(format!("{}: {what}", s.sequence), ("sans-serif", 17))
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(64)
                .build_cartesian_2d(0.0..report.frames as f64, (lo - 0.1)..(hi + 0.1))
                .map_err(err)?;
            chart
                .configure_mesh()
                .x_desc("frame")
                .label_style(("sans-serif", 13))
                .y_label_formatter(&|v| format!("{:.1e}", 10f64.powf(*v)))
                .draw()
                .map_err(err)?;
            for (k, (c, pts)) in s.curves.iter().zip(series).enumerate() {
                let color = colors[k % colors.len()];
                chart
                    .draw_series(LineSeries::new(pts, color.stroke_width(2)))
                    .map_err(err)?
                    .label(c.method.clone())
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
                    });
            }
            if row == 0 && col == 0 {
                legend(&mut chart, 13).map_err(err)?;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::pareto_front;

    #[test]
    fn pareto_front_keeps_only_undominated_points() {
        let pts = [(3.0, 0.1), (1.0, 0.5), (2.0, 0.6), (4.0, 0.05), (5.0, 0.07)];
        assert_eq!(pareto_front(&pts), vec![(1.0, 0.5), (3.0, 0.1), (4.0, 0.05)]);
    }
}
