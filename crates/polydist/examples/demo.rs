//! A tour of what polydist decides exactly today: predicates under the three kernels, polygon
//! validation with errors that say what and where, Melkman's hull and exact point location.
//!
//! Run it from the workspace root with `cargo run --release --example demo`.

use glam::DVec2;
use polydist::predicates::{Exact, Fast, Kernel, Robust};
use polydist::{ConvexPolygon, SimplePolygon};

fn main() {
    kernels();
    validation();
    hull_and_location();
}

/// Kettner et al.'s classroom example: how often does plain f64 misjudge a near-collinear turn?
fn kernels() {
    println!(
        "== Orientation of p = (0.5 + i·ulp, 0.5 + j·ulp), q = (12, 12), r = (24, 24), 0 ≤ i, j < 256 =="
    );
    let (q, r) = (DVec2::new(12.0, 12.0), DVec2::new(24.0, 24.0));
    let (mut fast_wrong, mut robust_wrong, mut total) = (0, 0, 0);
    let mut x = 0.5f64;
    for _ in 0..256 {
        let mut y = 0.5f64;
        for _ in 0..256 {
            let p = DVec2::new(x, y);
            let exact = Exact::orient(p, q, r);
            fast_wrong += usize::from(Fast::orient(p, q, r) != exact);
            robust_wrong += usize::from(Robust::orient(p, q, r) != exact);
            total += 1;
            y = y.next_up();
        }
        x = x.next_up();
    }
    println!("  Fast kernel (plain f64): {fast_wrong} of {total} orientations wrong");
    println!(
        "  Robust kernel:           {robust_wrong} of {total} wrong (exact by construction)\n"
    );
}

/// Invalid input gets a typed error that says what is wrong and where.
fn validation() {
    println!("== Validation ==");
    let pentagram: Vec<DVec2> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + f64::from(k) * 4.0 * std::f64::consts::PI / 5.0;
            DVec2::new(a.cos(), a.sin())
        })
        .collect();
    let bowtie = [
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 2.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(0.0, 2.0),
    ];
    let spike = [
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
    ];
    let cases: [(&str, Result<String, String>); 4] = [
        (
            "pentagram as convex",
            ConvexPolygon::try_new(&pentagram)
                .map(|p| format!("{} vertices", p.len()))
                .map_err(|e| e.to_string()),
        ),
        (
            "bow-tie as simple",
            SimplePolygon::try_new(&bowtie)
                .map(|p| format!("{} vertices", p.len()))
                .map_err(|e| e.to_string()),
        ),
        (
            "spike as simple",
            SimplePolygon::try_new(&spike)
                .map(|p| format!("{} vertices", p.len()))
                .map_err(|e| e.to_string()),
        ),
        (
            "NaN vertex",
            ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(f64::NAN, 1.0), DVec2::X])
                .map(|p| format!("{} vertices", p.len()))
                .map_err(|e| e.to_string()),
        ),
    ];
    for (name, result) in cases {
        match result {
            Ok(ok) => println!("  {name:<22} accepted: {ok}"),
            Err(e) => println!("  {name:<22} rejected: {e}"),
        }
    }
    println!();
}

/// A comb-shaped parcel: its Melkman hull, and exact location of points near its boundary.
fn hull_and_location() {
    println!("== Melkman hull and exact point location ==");
    let mut comb = vec![DVec2::new(0.0, 0.0), DVec2::new(9.0, 0.0)];
    for t in (0..5).rev() {
        let x = f64::from(t) * 2.0;
        comb.extend([DVec2::new(x + 1.0, 3.0), DVec2::new(x, 3.0)]);
        if t > 0 {
            comb.extend([DVec2::new(x, 1.0), DVec2::new(x - 1.0, 1.0)]);
        }
    }
    match SimplePolygon::try_new(&comb) {
        Ok(parcel) => {
            let hull = parcel.convex_hull();
            println!(
                "  comb with {} vertices; hull has {} vertices",
                parcel.len(),
                hull.len()
            );
            let between_teeth = DVec2::new(1.5, 2.0);
            let on_edge = DVec2::new(4.5, 0.0);
            let one_ulp_below = DVec2::new(4.5, -f64::from_bits(1));
            for (name, p) in [
                ("between two teeth", between_teeth),
                ("on the base edge", on_edge),
                ("one subnormal below it", one_ulp_below),
            ] {
                let (in_parcel, in_hull) = (format!("{:?}", parcel.locate(p)), hull.locate(p));
                println!("  {name:<24} parcel: {in_parcel:<8} hull: {in_hull:?}");
            }
        }
        Err(e) => println!("  the comb was rejected: {e}"),
    }
}
