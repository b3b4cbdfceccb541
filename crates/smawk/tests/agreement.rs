//! The fast searches agree with the brute-force twins on random totally monotone matrices, and the
//! online variant agrees with a quadratic dynamic program.
//!
//! Every generated matrix is first checked with the exact checker, so a generator bug cannot make
//! the agreement vacuous. Families: Monge matrices (prefix sums of nonnegative weights, and convex
//! functions of sorted gaps), distances between points of two arcs of one circle with the second
//! arc reversed, staircases of +infinity, and tagged penalty entries. Shapes include 0, 1 and 2
//! rows and columns, skinny and square matrices.

use core::cmp::Ordering;
use core::f64::consts::PI;
use core::fmt::Debug;

use monotone_minima::{
    Matrix, Transpose, brute_force_row_minima, brute_force_row_minima_by,
    brute_force_row_minima_f64, check_totally_monotone, check_totally_monotone_by,
    check_totally_monotone_f64, column_minima, column_minima_by, column_minima_f64,
    online_column_minima, online_column_minima_by, online_column_minima_f64, row_minima,
    row_minima_by, row_minima_f64,
};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::subsequence;
use proptest::test_runner::FileFailurePersistence;

/// Failing cases are saved in `crates/smawk/proptest-regressions/agreement.txt` (cargo runs tests
/// from the package directory).
fn config() -> ProptestConfig {
    ProptestConfig {
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
            "proptest-regressions/agreement.txt",
        ))),
        ..ProptestConfig::default()
    }
}

/// A dense row-major matrix, so that failures print the whole matrix.
#[derive(Clone, Debug)]
struct Dense<T> {
    rows: usize,
    columns: usize,
    data: Vec<T>,
}

impl<T> Dense<T> {
    fn from_fn(rows: usize, columns: usize, mut f: impl FnMut(usize, usize) -> T) -> Self {
        let mut data = Vec::with_capacity(rows * columns);
        for i in 0..rows {
            for j in 0..columns {
                data.push(f(i, j));
            }
        }
        Self {
            rows,
            columns,
            data,
        }
    }

    fn get(&self, i: usize, j: usize) -> &T {
        &self.data[i * self.columns + j]
    }
}

impl<T: Clone> Matrix for Dense<T> {
    type Entry = T;

    fn rows(&self) -> usize {
        self.rows
    }

    fn columns(&self) -> usize {
        self.columns
    }

    fn entry(&self, row: usize, column: usize) -> T {
        self.get(row, column).clone()
    }
}

/// Shapes: tiny ones often, square ones up to 80, and skinny ones both ways.
fn shape() -> impl Strategy<Value = (usize, usize)> {
    prop_oneof![
        (0..=2_usize, 0..=2_usize),
        (0..=12_usize, 0..=12_usize),
        (0..=40_usize, 0..=40_usize),
        (40..=80_usize, 40..=80_usize),
        (0..=3_usize, 0..=300_usize),
        (0..=300_usize, 0..=3_usize),
    ]
}

/// Monge by construction: `u_i + v_j - S(i, j)` with `S` the 2-D prefix sums of nonnegative
/// weights (each adjacent 2×2 has `M[i][j] + M[i+1][j+1] - M[i][j+1] - M[i+1][j] = -w <= 0`).
fn prefix_sum_monge(rows: usize, columns: usize) -> impl Strategy<Value = Dense<i64>> {
    (
        vec(-30_i64..30, rows),
        vec(-300_i64..300, columns),
        vec(prop_oneof![8 => Just(0_i64), 1 => 1_i64..4], rows * columns),
    )
        .prop_map(move |(u, v, w)| {
            let mut s = vec![0_i64; rows * columns];
            for i in 0..rows {
                for j in 0..columns {
                    let up = if i > 0 { s[(i - 1) * columns + j] } else { 0 };
                    let left = if j > 0 { s[i * columns + j - 1] } else { 0 };
                    let diag = if i > 0 && j > 0 {
                        s[(i - 1) * columns + j - 1]
                    } else {
                        0
                    };
                    s[i * columns + j] = w[i * columns + j] + up + left - diag;
                }
            }
            Dense::from_fn(rows, columns, |i, j| u[i] + v[j] - s[i * columns + j])
        })
}

/// Monge by construction: `u_i + v_j + g(x_i - y_j)` with `x`, `y` sorted and `g` convex
/// (`t²` or `|t|`), small integers so that ties are frequent.
fn convex_gap_monge(rows: usize, columns: usize) -> impl Strategy<Value = Dense<i64>> {
    (
        vec(-10_i64..10, rows),
        vec(-10_i64..10, columns),
        vec(-20_i64..20, rows),
        vec(-20_i64..20, columns),
        any::<bool>(),
    )
        .prop_map(move |(mut x, mut y, u, v, square)| {
            x.sort_unstable();
            y.sort_unstable();
            Dense::from_fn(rows, columns, |i, j| {
                let gap = x[i] - y[j];
                u[i] + v[j] + if square { gap * gap } else { 3 * gap.abs() }
            })
        })
}

fn monge(rows: usize, columns: usize) -> impl Strategy<Value = Dense<i64>> {
    prop_oneof![
        prefix_sum_monge(rows, columns),
        convex_gap_monge(rows, columns)
    ]
}

/// Euclidean distances from points on one arc of a circle (in increasing angle) to points on a
/// disjoint later arc of the same circle taken in decreasing angle: a Monge matrix (the diagonals
/// of a convex quadrilateral are longer than two opposite sides). Angles are on a grid, so the
/// Monge inequalities hold with a margin far above rounding.
fn arc_distances(rows: usize, columns: usize) -> impl Strategy<Value = Dense<f64>> {
    let grid: Vec<u32> = (0..1000).collect();
    (
        subsequence(grid.clone(), rows),
        subsequence(grid, columns),
        0.5_f64..20.0,
        -5.0_f64..5.0,
        -5.0_f64..5.0,
        0.0_f64..(2.0 * PI),
    )
        .prop_map(move |(a, b, radius, cx, cy, phase)| {
            let step = 0.9 * PI / 1000.0;
            let point = |angle: f64| (cx + radius * angle.cos(), cy + radius * angle.sin());
            let p: Vec<_> = a
                .iter()
                .map(|&k| point(phase + f64::from(k) * step))
                .collect();
            let q: Vec<_> = b
                .iter()
                .rev()
                .map(|&k| point(phase + PI + f64::from(k) * step))
                .collect();
            Dense::from_fn(rows, columns, |i, j| {
                f64::hypot(p[i].0 - q[j].0, p[i].1 - q[j].1)
            })
        })
}

/// A nondecreasing sequence of `len` values in `0..=max`.
fn staircase(len: usize, max: usize) -> impl Strategy<Value = Vec<usize>> {
    vec(0..=max, len).prop_map(|mut v| {
        v.sort_unstable();
        v
    })
}

/// +infinity from column `hi_i` on, `hi` nondecreasing (all-infinite rows only at the top): the
/// premise of total monotonicity then only involves finite entries, so it stays monotone.
fn with_infinities<T: Clone + Debug>(
    base: impl Strategy<Value = Dense<T>>,
    infinity: T,
) -> impl Strategy<Value = Dense<T>> {
    base.prop_flat_map(move |m| {
        let infinity = infinity.clone();
        staircase(m.rows, m.columns).prop_map(move |hi| {
            Dense::from_fn(m.rows, m.columns, |i, j| {
                if j >= hi[i] {
                    infinity.clone()
                } else {
                    m.get(i, j).clone()
                }
            })
        })
    })
}

/// Amato-style entries: `Dist < Penalty < Infinity`, penalties `n - j` shrinking to the right,
/// compared exactly (derived `Ord`: variant order, then payload).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Tagged<D> {
    Dist(D),
    Penalty(usize),
    Infinity,
}

/// Row `i`: penalties before column `lo_i`, distances up to `hi_i`, then infinity; `lo` and `hi`
/// nondecreasing.
fn tagged<D: Clone + Debug>(
    base: impl Strategy<Value = Dense<D>>,
) -> impl Strategy<Value = Dense<Tagged<D>>> {
    base.prop_flat_map(|m| {
        (staircase(m.rows, m.columns), staircase(m.rows, m.columns)).prop_map(move |(a, b)| {
            let n = m.columns;
            Dense::from_fn(m.rows, n, |i, j| {
                let (lo, hi) = (a[i].min(b[i]), a[i].max(b[i]));
                if j < lo {
                    Tagged::Penalty(n - j)
                } else if j < hi {
                    Tagged::Dist(m.get(i, j).clone())
                } else {
                    Tagged::Infinity
                }
            })
        })
    })
}

fn cmp_tagged_f64(a: &Tagged<f64>, b: &Tagged<f64>) -> Ordering {
    match (a, b) {
        // Distances here are finite and never -0.0, where total_cmp and IEEE differ.
        (Tagged::Dist(x), Tagged::Dist(y)) => x.total_cmp(y),
        (Tagged::Penalty(x), Tagged::Penalty(y)) => x.cmp(y),
        (Tagged::Infinity, Tagged::Infinity) => Ordering::Equal,
        (Tagged::Dist(_), _) | (Tagged::Penalty(_), Tagged::Infinity) => Ordering::Less,
        _ => Ordering::Greater,
    }
}

/// The expected result length: one per row, or none without columns.
fn expected_len<M: Matrix>(m: &M) -> usize {
    if m.columns() == 0 { 0 } else { m.rows() }
}

/// All the searches on an `Ord` matrix against the brute force, rows and (via the transpose)
/// columns.
fn agree_ord<T: Ord + Clone + Debug>(m: &Dense<T>) -> Result<(), TestCaseError> {
    prop_assert_eq!(check_totally_monotone(m), Ok(()), "generator bug: {:?}", m);
    let expected = brute_force_row_minima(m);
    prop_assert_eq!(expected.len(), expected_len(m));
    prop_assert_eq!(&row_minima(m), &expected);
    prop_assert_eq!(&row_minima_by(m, Ord::cmp), &expected);
    prop_assert_eq!(&column_minima(&Transpose(m)), &expected);
    prop_assert_eq!(&column_minima_by(&Transpose(m), Ord::cmp), &expected);
    Ok(())
}

/// All the searches on an `f64` matrix without NaN or -0.0 against the brute force.
fn agree_f64(m: &Dense<f64>) -> Result<(), TestCaseError> {
    prop_assert_eq!(
        check_totally_monotone_f64(m),
        Ok(()),
        "generator bug: {:?}",
        m
    );
    let expected = brute_force_row_minima_f64(m);
    prop_assert_eq!(expected.as_ref().map(Vec::len), Ok(expected_len(m)));
    prop_assert_eq!(&row_minima_f64(m), &expected);
    prop_assert_eq!(&column_minima_f64(&Transpose(m)), &expected);
    let expected = expected.unwrap_or_default();
    prop_assert_eq!(&brute_force_row_minima_by(m, f64::total_cmp), &expected);
    prop_assert_eq!(&row_minima_by(m, f64::total_cmp), &expected);
    prop_assert_eq!(&column_minima_by(&Transpose(m), f64::total_cmp), &expected);
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn monge_matrices(m in shape().prop_flat_map(|(r, c)| monge(r, c))) {
        agree_ord(&m)?;
    }

    #[test]
    fn arc_distance_matrices(m in shape().prop_flat_map(|(r, c)| arc_distances(r, c))) {
        agree_f64(&m)?;
    }

    #[test]
    fn monge_with_infinities(m in with_infinities(shape().prop_flat_map(|(r, c)| monge(r, c)), i64::MAX)) {
        agree_ord(&m)?;
    }

    #[test]
    fn arcs_with_infinities(
        m in with_infinities(shape().prop_flat_map(|(r, c)| arc_distances(r, c)), f64::INFINITY),
    ) {
        agree_f64(&m)?;
    }

    #[test]
    fn tagged_penalties(m in tagged(shape().prop_flat_map(|(r, c)| monge(r, c)))) {
        agree_ord(&m)?;
    }

    #[test]
    fn tagged_penalties_on_arcs(m in tagged(shape().prop_flat_map(|(r, c)| arc_distances(r, c)))) {
        prop_assert_eq!(check_totally_monotone_by(&m, cmp_tagged_f64), Ok(()), "generator bug: {:?}", m);
        let expected = brute_force_row_minima_by(&m, cmp_tagged_f64);
        prop_assert_eq!(expected.len(), expected_len(&m));
        prop_assert_eq!(&row_minima_by(&m, cmp_tagged_f64), &expected);
        prop_assert_eq!(&column_minima_by(&Transpose(&m), cmp_tagged_f64), &expected);
    }

    /// Not totally monotone: any answer is allowed, but one valid column per row and no panic.
    #[test]
    fn arbitrary_matrices_do_not_panic(
        m in shape().prop_flat_map(|(r, c)| vec(0_u8..4, r * c).prop_map(move |data| Dense { rows: r, columns: c, data })),
    ) {
        let minima = row_minima(&m);
        prop_assert_eq!(minima.len(), expected_len(&m));
        prop_assert!(minima.iter().all(|&j| j < m.columns));
        let minima = column_minima(&m);
        prop_assert_eq!(minima.len(), if m.rows == 0 { 0 } else { m.columns });
        prop_assert!(minima.iter().all(|&i| i < m.rows));
    }
}

/// The explicit small shapes, with and without columns, and a 1 × 1.
#[test]
fn empty_and_tiny_shapes() {
    let empty: [[i32; 0]; 3] = [[], [], []];
    assert_eq!(row_minima(&empty), Vec::<usize>::new());
    assert_eq!(column_minima(&empty), Vec::<usize>::new());
    let none: [[i32; 4]; 0] = [];
    assert_eq!(row_minima(&none), Vec::<usize>::new());
    assert_eq!(column_minima(&none), Vec::<usize>::new());
    assert_eq!(row_minima(&[[7]]), [0]);
    assert_eq!(column_minima(&[[7]]), [0]);
    assert_eq!(row_minima_f64(&[[f64::INFINITY]]), Ok(vec![0]));
    let huge = monotone_minima::from_fn(usize::MAX, 0, |_, _| 0_u8);
    assert_eq!(row_minima(&huge), Vec::<usize>::new());
}

// ---------------------------------------------------------------------------------------------
// Online column minima against a quadratic dynamic program.

/// `f(0) = initial`, `f(j) = min_{i<j} entry(f, i, j)`, topmost `i` on ties.
fn quadratic_dp<T: Clone>(
    size: usize,
    initial: T,
    entry: impl Fn(&[T], usize, usize) -> T,
    less: impl Fn(&T, &T) -> bool,
) -> (Vec<T>, Vec<usize>) {
    let mut values = Vec::new();
    let mut rows = Vec::new();
    if size == 0 {
        return (values, rows);
    }
    values.push(initial);
    rows.push(0);
    for j in 1..size {
        let mut best = entry(&values, 0, j);
        let mut best_row = 0;
        for i in 1..j {
            let value = entry(&values, i, j);
            if less(&value, &best) {
                best = value;
                best_row = i;
            }
        }
        values.push(best);
        rows.push(best_row);
    }
    (values, rows)
}

/// A dynamic program `f(j) = min_{i<j} f(i) + a_i + b_j + g(P_j - P_i)` with `P` increasing and
/// `g` convex: the weights satisfy the quadrangle inequality.
#[derive(Clone, Debug)]
struct ConvexDp {
    positions: Vec<i64>,
    a: Vec<i64>,
    b: Vec<i64>,
    target: i64,
}

impl ConvexDp {
    fn weight(&self, i: usize, j: usize) -> i64 {
        let gap = self.positions[j] - self.positions[i] - self.target;
        self.a[i] + self.b[j] + gap * gap
    }
}

fn convex_dp() -> impl Strategy<Value = ConvexDp> {
    prop_oneof![0..=3_usize, 0..=60_usize, 100..=400_usize].prop_flat_map(|size| {
        (
            vec(1_i64..6, size),
            vec(-15_i64..15, size),
            vec(-15_i64..15, size),
            0_i64..40,
        )
            .prop_map(|(steps, a, b, target)| {
                let positions = steps
                    .iter()
                    .scan(0, |p, s| {
                        *p += s;
                        Some(*p)
                    })
                    .collect();
                ConvexDp {
                    positions,
                    a,
                    b,
                    target,
                }
            })
    })
}

/// Lines of words `i..j` either fit (cost: the best cost up to `i` plus the squared slack) or
/// overflow (ordered by the overflow alone, above every line that fits).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum LineCost {
    Fits(u64),
    Overflows(u64),
}

fn line_cost(widths_prefix: &[u64], width: u64, done: &[LineCost], i: usize, j: usize) -> LineCost {
    // Words i..j with single spaces between them.
    let length = widths_prefix[j] - widths_prefix[i] + (j - i - 1) as u64;
    match done[i] {
        LineCost::Fits(cost) if length <= width => LineCost::Fits(cost + (width - length).pow(2)),
        _ => LineCost::Overflows(length.saturating_sub(width)),
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn online_convex_dp_matches_quadratic(dp in convex_dp()) {
        let size = dp.positions.len();
        let entry = |done: &[i64], i: usize, j: usize| done[i] + dp.weight(i, j);
        let (values, rows) = quadratic_dp(size, 0, entry, |a, b| a < b);
        let online = online_column_minima(size, 0, entry);
        prop_assert_eq!(&online.values, &values);
        prop_assert_eq!(&online.rows, &rows);
        let online = online_column_minima_by(size, 0, entry, Ord::cmp);
        prop_assert_eq!(&online.values, &values);
        prop_assert_eq!(&online.rows, &rows);
    }

    #[test]
    fn online_f64_dp_matches_quadratic(dp in convex_dp()) {
        // Small integers: every f64 operation is exact, so the comparison can be exact too.
        let size = dp.positions.len();
        let entry = |done: &[f64], i: usize, j: usize| done[i] + dp.weight(i, j) as f64;
        let (values, rows) = quadratic_dp(size, 0.0, entry, |a, b| a < b);
        let online = online_column_minima_f64(size, 0.0, entry);
        prop_assert_eq!(online.as_ref().map(|o| &o.values), Ok(&values));
        prop_assert_eq!(online.as_ref().map(|o| &o.rows), Ok(&rows));
    }

    #[test]
    fn online_line_breaking_matches_quadratic(
        widths in prop_oneof![vec(1_u64..8, 0..4), vec(1_u64..8, 0..80), vec(1_u64..8, 200..400)],
        width in 8_u64..40,
    ) {
        let prefix: Vec<u64> = core::iter::once(0)
            .chain(widths.iter().scan(0, |p, w| {
                *p += w;
                Some(*p)
            }))
            .collect();
        let size = prefix.len();
        let entry = |done: &[LineCost], i: usize, j: usize| line_cost(&prefix, width, done, i, j);
        let initial = LineCost::Fits(0);
        let (values, rows) = quadratic_dp(size, initial, entry, |a, b| a < b);
        let online = online_column_minima(size, initial, entry);
        prop_assert_eq!(&online.values, &values);
        prop_assert_eq!(&online.rows, &rows);
    }
}

/// The online functions on 0, 1 and 2 columns.
#[test]
fn online_tiny_sizes() {
    let entry = |done: &[i32], i: usize, j: usize| done[i] + (j - i) as i32;
    let none = online_column_minima(0, 5, entry);
    assert!(none.values.is_empty() && none.rows.is_empty());
    let one = online_column_minima(1, 5, entry);
    assert_eq!((one.values, one.rows), (vec![5], vec![0]));
    let two = online_column_minima(2, 5, entry);
    assert_eq!((two.values, two.rows), (vec![5, 6], vec![0, 0]));
}
