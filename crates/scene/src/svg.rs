//! An SVG picture of a run (`polydist run --svg FILE`), written with our own code.
//!
//! The scene panel draws every body at one frame — the frame of the smallest distance any pair
//! reached (the first frame when no distance was asked) — with the closest-point segments, the
//! separation segments of simple bodies and the Hausdorff witnesses (each directed distance's
//! realizing vertex and its projection) of that frame.
//! Moving bodies also get their trajectory (the body frame's origin at every frame) and a dashed
//! outline at the last frame. A scene with more than one frame gets a second panel: each pair's
//! distance over time. Every element has a `class` (`body`, `ghost`, `trajectory`, `closest`,
//! `separation`, `hausdorff`, `distance-plot`, ...) so the picture can be styled or checked.

use core::fmt::Write as _;

use glam::DVec2;

use crate::load::Scene;
use crate::report::{FrameResult, PairReport, Report};

/// The scene panel's size in pixels.
const W: f64 = 800.0;
const H: f64 = 600.0;
/// The plot panel's height.
const PLOT_H: f64 = 260.0;
const MARGIN: f64 = 30.0;

/// Colours for bodies and plot lines, cycled.
const PALETTE: [&str; 8] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
];

/// XML-escapes text for element content and attribute values.
fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&apos;"),
            // Control characters are not allowed in XML 1.0 text.
            c if (c as u32) < 0x20 && c != '\t' && c != '\n' => o.push('?'),
            c => o.push(c),
        }
    }
    o
}

/// A number for SVG (finite; shortest form).
fn num(x: f64) -> String {
    if x.is_finite() {
        let s = format!("{x:.3}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" {
            "0".to_owned()
        } else {
            s.to_owned()
        }
    } else {
        "0".to_owned()
    }
}

/// The world-to-panel map: uniform scale, `y` up.
struct View {
    min: DVec2,
    scale: f64,
    off: DVec2,
}

impl View {
    fn fit(points: &[DVec2], w: f64, h: f64) -> View {
        let mut min = DVec2::splat(f64::INFINITY);
        let mut max = DVec2::splat(f64::NEG_INFINITY);
        for &p in points.iter().filter(|p| p.is_finite()) {
            min = min.min(p);
            max = max.max(p);
        }
        if !(min.x <= max.x && min.y <= max.y) {
            min = DVec2::ZERO;
            max = DVec2::ONE;
        }
        let size = (max - min).max(DVec2::splat(1e-9));
        let scale = ((w - 2.0 * MARGIN) / size.x).min((h - 2.0 * MARGIN) / size.y);
        let scale = if scale.is_finite() && scale > 0.0 {
            scale
        } else {
            1.0
        };
        let off = DVec2::new((w - size.x * scale) / 2.0, (h - size.y * scale) / 2.0);
        View { min, scale, off }
    }

    fn map(&self, p: DVec2) -> DVec2 {
        let q = (p - self.min) * self.scale;
        DVec2::new(self.off.x + q.x, H - (self.off.y + q.y))
    }

    fn points(&self, ps: &[DVec2]) -> String {
        ps.iter()
            .map(|&p| {
                let q = self.map(p);
                format!("{},{}", num(q.x), num(q.y))
            })
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// The frame index to draw: that of the smallest distance over all pairs (the first frame when no
/// distance was computed).
fn chosen_frame(scene: &Scene, report: &Report) -> usize {
    let mut best: Option<(f64, f64)> = None;
    for p in &report.pairs {
        for f in &p.frames {
            if let Some(d) = f.distance {
                if best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, f.t));
                }
            }
        }
    }
    let Some((_, t)) = best else { return 0 };
    (0..scene.time.frames)
        .find(|&k| scene.time.frame(k) == t)
        .unwrap_or(0)
}

/// The frame of a pair at time `t` (a static pair's only frame).
/// A segment between two realizing points of a pair (`class` and stroke colour), with a title.
fn segment(
    s: &mut String,
    (class, colour): (&str, &str),
    p: &PairReport,
    (a, b): ([f64; 2], [f64; 2]),
    what: &str,
    view: &View,
) {
    let (a, b) = (
        view.map(DVec2::from_array(a)),
        view.map(DVec2::from_array(b)),
    );
    let _ = writeln!(
        s,
        r#"<line class="{class}" data-pair="{} {}" x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="1.5"><title>{} – {}: {}</title></line>"#,
        esc(&p.a),
        esc(&p.b),
        num(a.x),
        num(a.y),
        num(b.x),
        num(b.y),
        esc(&p.a),
        esc(&p.b),
        esc(what)
    );
}

fn frame_at(frames: &[FrameResult], t: f64, moving: bool) -> Option<&FrameResult> {
    if moving {
        frames.iter().find(|f| f.t == t)
    } else {
        frames.first()
    }
}

/// Renders a run as an SVG document (see the module docs).
///
/// # Complexity
/// `O(total vertices + frames · (bodies + pairs))`.
#[must_use]
pub fn render_svg(scene: &Scene, report: &Report) -> String {
    let k = chosen_frame(scene, report);
    let t = scene.time.frame(k);
    let last = scene.time.frame(scene.time.frames.saturating_sub(1));
    let moving_scene = scene.time.frames > 1;
    let posed = |b: &crate::load::Body, t: f64| -> Vec<DVec2> {
        let pose = b.motion.pose_at(t);
        b.shape.vertices().iter().map(|&v| pose.apply(v)).collect()
    };
    let bodies_now: Vec<Vec<DVec2>> = scene.bodies.iter().map(|b| posed(b, t)).collect();
    let trajectories: Vec<Option<Vec<DVec2>>> = scene
        .bodies
        .iter()
        .map(|b| {
            (!b.motion.is_static() && moving_scene).then(|| {
                (0..scene.time.frames)
                    .map(|j| b.motion.pose_at(scene.time.frame(j)).translation)
                    .collect()
            })
        })
        .collect();
    let ghosts: Vec<Option<Vec<DVec2>>> = scene
        .bodies
        .iter()
        .map(|b| (!b.motion.is_static() && moving_scene).then(|| posed(b, last)))
        .collect();

    let mut all: Vec<DVec2> = bodies_now.iter().flatten().copied().collect();
    all.extend(trajectories.iter().flatten().flatten());
    all.extend(ghosts.iter().flatten().flatten());
    let view = View::fit(&all, W, H);

    let plot = moving_scene
        && report
            .pairs
            .iter()
            .any(|p| p.moving && p.frames.iter().any(|f| f.distance.is_some()));
    let total_h = if plot { H + PLOT_H } else { H };
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{}" viewBox="0 0 {W} {}" font-family="sans-serif" font-size="12">"#,
        num(total_h),
        num(total_h)
    );
    let _ = writeln!(
        s,
        r#"<title>{} at t = {}</title>
<rect class="background" x="0" y="0" width="{W}" height="{}" fill="white"/>"#,
        esc(&scene.name),
        num(t),
        num(total_h)
    );
    let _ = writeln!(s, r#"<g class="scene">"#);
    for (i, b) in scene.bodies.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        if let Some(tr) = &trajectories[i] {
            let _ = writeln!(
                s,
                r#"<polyline class="trajectory" data-body="{}" points="{}" fill="none" stroke="{colour}" stroke-opacity="0.6" stroke-dasharray="2,3"/>"#,
                esc(&b.id),
                view.points(tr)
            );
        }
        if let Some(g) = &ghosts[i] {
            let _ = writeln!(
                s,
                r#"<polygon class="ghost" data-body="{}" data-t="{}" points="{}" fill="none" stroke="{colour}" stroke-dasharray="5,4"/>"#,
                esc(&b.id),
                num(last),
                view.points(g)
            );
        }
        let _ = writeln!(
            s,
            r#"<polygon class="body" data-body="{}" data-t="{}" points="{}" fill="{colour}" fill-opacity="0.35" stroke="{colour}"/>"#,
            esc(&b.id),
            num(t),
            view.points(&bodies_now[i])
        );
        if let Some(first) = bodies_now[i].first() {
            let c =
                bodies_now[i].iter().fold(DVec2::ZERO, |a, &p| a + p) / bodies_now[i].len() as f64;
            let c = if c.is_finite() { c } else { *first };
            let q = view.map(c);
            let _ = writeln!(
                s,
                r#"<text class="label" x="{}" y="{}" text-anchor="middle">{}</text>"#,
                num(q.x),
                num(q.y),
                esc(&b.id)
            );
        }
    }
    for p in &report.pairs {
        let Some(f) = frame_at(&p.frames, t, p.moving) else {
            continue;
        };
        if let Some(c) = f.closest_points {
            let d = f
                .distance
                .map_or_else(|| "-".to_owned(), |d| format!("{d}"));
            let what = format!("distance {d}");
            segment(
                &mut s,
                ("closest", "black"),
                p,
                (c.point_a, c.point_b),
                &what,
                &view,
            );
        }
        if let Some(r) = f.separation {
            let what = format!("separation {}", r.distance);
            segment(
                &mut s,
                ("separation", "darkgreen"),
                p,
                (r.point_a, r.point_b),
                &what,
                &view,
            );
        }
        if let Some(h) = f.hausdorff.as_deref() {
            for (dir, d) in [("a_to_b", h.a_to_b), ("b_to_a", h.b_to_a)] {
                let (a, b) = (
                    view.map(DVec2::from_array(d.point)),
                    view.map(DVec2::from_array(d.projection)),
                );
                let _ = writeln!(
                    s,
                    r#"<line class="hausdorff" data-pair="{} {}" data-direction="{dir}" x1="{}" y1="{}" x2="{}" y2="{}" stroke="crimson" stroke-dasharray="4,2"><title>h({dir}) = {}</title></line>"#,
                    esc(&p.a),
                    esc(&p.b),
                    num(a.x),
                    num(a.y),
                    num(b.x),
                    num(b.y),
                    d.distance
                );
                let _ = writeln!(
                    s,
                    r#"<circle class="hausdorff-vertex" cx="{}" cy="{}" r="3" fill="crimson"/>"#,
                    num(a.x),
                    num(a.y)
                );
            }
        }
    }
    let _ = writeln!(s, "</g>");
    if plot {
        plot_panel(&mut s, scene, report, t);
    }
    let _ = writeln!(s, "</svg>");
    s
}

/// The distance-over-time panel below the scene panel.
fn plot_panel(s: &mut String, scene: &Scene, report: &Report, t_mark: f64) {
    let (t0, t1) = (
        scene.time.start,
        scene.time.end.max(scene.time.start + 1e-12),
    );
    let dmax = report
        .pairs
        .iter()
        .flat_map(|p| &p.frames)
        .filter_map(|f| f.distance)
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max)
        .max(1e-12);
    let (x0, x1) = (MARGIN + 40.0, W - MARGIN);
    let (y0, y1) = (H + PLOT_H - MARGIN, H + MARGIN);
    let px = |t: f64| x0 + (t - t0) / (t1 - t0) * (x1 - x0);
    let py = |d: f64| y0 - d / dmax * (y0 - y1);
    let _ = writeln!(s, r#"<g class="distance-plot">"#);
    let _ = writeln!(
        s,
        r#"<line class="axis" x1="{}" y1="{}" x2="{}" y2="{}" stroke="black"/>
<line class="axis" x1="{}" y1="{}" x2="{}" y2="{}" stroke="black"/>
<text class="axis-label" x="{}" y="{}">distance over time (max {})</text>
<text class="axis-label" x="{}" y="{}" text-anchor="end">t = {}</text>
<text class="axis-label" x="{}" y="{}">t = {}</text>
<line class="marker" x1="{}" y1="{}" x2="{}" y2="{}" stroke="gray" stroke-dasharray="3,3"/>"#,
        num(x0),
        num(y0),
        num(x1),
        num(y0),
        num(x0),
        num(y0),
        num(x0),
        num(y1),
        num(x0 + 5.0),
        num(y1 - 8.0),
        esc(&format!("{dmax}")),
        num(x1),
        num(y0 + 16.0),
        num(t1),
        num(x0),
        num(y0 + 16.0),
        num(t0),
        num(px(t_mark)),
        num(y0),
        num(px(t_mark)),
        num(y1)
    );
    for (i, p) in report.pairs.iter().enumerate() {
        if !p.moving {
            continue;
        }
        let pts: Vec<String> = p
            .frames
            .iter()
            .filter_map(|f| f.distance.map(|d| (f.t, d)))
            .map(|(t, d)| format!("{},{}", num(px(t)), num(py(d))))
            .collect();
        if pts.is_empty() {
            continue;
        }
        let _ = writeln!(
            s,
            r#"<polyline class="distance" data-pair="{} {}" points="{}" fill="none" stroke="{}"><title>{} – {}</title></polyline>"#,
            esc(&p.a),
            esc(&p.b),
            pts.join(" "),
            PALETTE[i % PALETTE.len()],
            esc(&p.a),
            esc(&p.b)
        );
    }
    let _ = writeln!(s, "</g>");
}
