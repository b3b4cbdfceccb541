//! Linear growth, by counting entry lookups (not by timing): the offline searches stay below
//! their documented bounds (`3 * columns + 12 * rows`; `+ rows` for the `f64` functions, which
//! check every returned minimum) and below `C_OFFLINE * (rows + columns)` on structured families
//! from 10 to 10^6 rows and columns, and the online search stays below `C_ONLINE * size` up to
//! 10^6 columns.
//!
//! Entries are cheap (a subtraction and a square) so that 10^6 runs in seconds in debug builds.
//! Run with `--nocapture` to see the measured constants.

use std::cell::Cell;
use std::f64::consts::PI;

use monotone_minima::{
    column_minima_f64, from_fn, online_column_minima, online_column_minima_f64, row_minima_by,
    row_minima_f64,
};

/// Offline searches: measured at most 3.23, and 3.68 for the `f64` functions, which look at every
/// minimum once more (see the table printed by `offline_lookups_are_linear`).
const C_OFFLINE: f64 = 4.0;

/// Online search: measured at most 11.6 per column (2.5 when every minimum is on the diagonal).
const C_ONLINE: f64 = 12.5;

/// splitmix64: deterministic uniform `f64` in `[0, 1)`.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1_u64 << 53) as f64
    }

    fn sorted(&mut self, n: usize) -> Vec<f64> {
        let mut v: Vec<f64> = (0..n).map(|_| self.next()).collect();
        v.sort_by(f64::total_cmp);
        v
    }
}

/// A totally monotone family: a name and `entries(m, n) -> entry function`.
type Family = (
    &'static str,
    fn(usize, usize) -> Box<dyn Fn(usize, usize) -> f64>,
);

fn families() -> Vec<Family> {
    vec![
        ("(x_i - y_j)^2, sorted random", |m, n| {
            let mut rng = SplitMix(1);
            let (x, y) = (rng.sorted(m), rng.sorted(n));
            Box::new(move |i, j| (x[i] - y[j]) * (x[i] - y[j]))
        }),
        ("|x_i - y_j|, evenly spread", |m, n| {
            let (m1, n1) = (m as f64, n as f64);
            Box::new(move |i, j| (i as f64 / m1 - j as f64 / n1).abs())
        }),
        ("distances between two arcs", |m, n| {
            let mut rng = SplitMix(2);
            let p: Vec<(f64, f64)> = rng
                .sorted(m)
                .iter()
                .map(|t| (0.9 * PI * t).sin_cos())
                .collect();
            let q: Vec<(f64, f64)> = rng
                .sorted(n)
                .iter()
                .rev()
                .map(|t| (PI + 0.9 * PI * t).sin_cos())
                .collect();
            Box::new(move |i, j| ((p[i].0 - q[j].0).powi(2) + (p[i].1 - q[j].1).powi(2)).sqrt())
        }),
        ("squares, +inf staircase", |m, n| {
            let mut rng = SplitMix(3);
            let (x, y) = (rng.sorted(m), rng.sorted(n));
            Box::new(move |i, j| {
                if j * m > (i + 1) * n {
                    f64::INFINITY
                } else {
                    (x[i] - y[j]).powi(2)
                }
            })
        }),
    ]
}

/// Lookups of `row_minima_by`, `row_minima_f64` and `column_minima_f64` (on the transpose) for
/// one family and shape.
fn count(family: &Family, m: usize, n: usize) -> [u64; 3] {
    let entry = (family.1)(m, n);
    let lookups = Cell::new(0_u64);
    let counted = from_fn(m, n, |i, j| {
        lookups.set(lookups.get() + 1);
        entry(i, j)
    });
    let rows = row_minima_by(&counted, f64::total_cmp);
    assert_eq!(rows.len(), m);
    let by = lookups.replace(0);
    assert_eq!(row_minima_f64(&counted).as_ref(), Ok(&rows));
    let f64_rows = lookups.replace(0);
    let transposed = from_fn(n, m, |j, i| {
        lookups.set(lookups.get() + 1);
        entry(i, j)
    });
    assert_eq!(column_minima_f64(&transposed), Ok(rows));
    [by, f64_rows, lookups.get()]
}

#[test]
fn offline_lookups_are_linear() {
    let mut shapes: Vec<(usize, usize)> = Vec::new();
    for n in [10, 100, 1_000, 10_000, 100_000, 1_000_000] {
        shapes.push((n, n));
    }
    for n in [100, 10_000, 1 << 18] {
        shapes.extend([
            (n / 64, n),
            (n, n / 64),
            (1, n),
            (n, 1),
            (n / 2, n),
            (n, n / 2),
        ]);
    }
    for m in 2..8 {
        shapes.extend([(m, 1000), (1000, m)]);
    }
    println!(
        "{:<32} {:>9} {:>9} {:>12} {:>8}",
        "family", "rows", "columns", "lookups", "/(m+n)"
    );
    for family in families() {
        let mut worst_large: f64 = 0.0;
        for &(m, n) in &shapes {
            let [by, f64_rows, f64_columns] = count(&family, m, n);
            // The f64 functions also look at every returned minimum once more.
            let (generic, checked) = (3 * n + 12 * m, 3 * n + 13 * m);
            for (lookups, bound) in [(by, generic), (f64_rows, checked), (f64_columns, checked)] {
                let ratio = lookups as f64 / (m + n) as f64;
                println!("{:<32} {m:>9} {n:>9} {lookups:>12} {ratio:>8.3}", family.0);
                assert!(
                    lookups <= bound as u64,
                    "{}: {m} x {n}: {lookups} lookups exceed the documented bound {bound}",
                    family.0
                );
                assert!(
                    ratio <= C_OFFLINE,
                    "{}: {m} x {n}: {ratio:.3} lookups per row and column",
                    family.0
                );
                if m + n >= 100_000 {
                    worst_large = worst_large.max(ratio);
                }
            }
        }
        println!(
            "{}: worst ratio at m + n >= 1e5: {worst_large:.3}",
            family.0
        );
    }
}

/// Online dynamic programs with weights satisfying the quadrangle inequality, chosen to exercise
/// every case of the algorithm: minima on the diagonal (resets), far from it (large blocks), and
/// line breaking with tagged overflow.
#[test]
fn online_lookups_are_linear() {
    println!(
        "{:<28} {:>9} {:>12} {:>8}",
        "program", "size", "lookups", "/size"
    );
    for size in [10, 100, 1_000, 10_000, 100_000, 1_000_000] {
        for (name, target) in [
            ("(j - i - 1)^2: diagonal", 1.0),
            ("(j - i - 40)^2: blocks", 40.0),
            ("(j - i - 10^4)^2", 1e4),
        ] {
            let lookups = Cell::new(0_u64);
            let result = online_column_minima_f64(size, 0.0, |done, i, j| {
                lookups.set(lookups.get() + 1);
                done[i] + ((j - i) as f64 - target).powi(2)
            })
            .expect("no NaN");
            assert_eq!(result.values.len(), size);
            let ratio = lookups.get() as f64 / size as f64;
            println!("{name:<28} {size:>9} {:>12} {ratio:>8.3}", lookups.get());
            assert!(
                ratio <= C_ONLINE,
                "{name}: {size}: {ratio:.3} lookups per column"
            );
        }
        // Line breaking: random word widths 1..=10, lines of 60.
        let mut rng = SplitMix(4);
        let prefix: Vec<u64> = std::iter::once(0)
            .chain((0..size).scan(0, |sum, _| {
                *sum += 1 + (rng.next() * 10.0) as u64;
                Some(*sum)
            }))
            .collect();
        let lookups = Cell::new(0_u64);
        let result = online_column_minima(size, (0_u8, 0_u64), |done: &[(u8, u64)], i, j| {
            lookups.set(lookups.get() + 1);
            let length = prefix[j] - prefix[i] + (j - i - 1) as u64;
            // (0, cost) fits, (1, overflow) does not: tagged, compared exactly.
            if length <= 60 && done[i].0 == 0 {
                (0, done[i].1 + (60 - length).pow(2))
            } else {
                (1, length.saturating_sub(60))
            }
        });
        assert_eq!(result.values.len(), size);
        let ratio = lookups.get() as f64 / size as f64;
        println!(
            "{:<28} {size:>9} {:>12} {ratio:>8.3}",
            "line breaking, width 60",
            lookups.get()
        );
        assert!(
            ratio <= C_ONLINE,
            "line breaking: {size}: {ratio:.3} lookups per column"
        );
    }
}
