//! The total-monotonicity checker is exact: it agrees with the definition (every 2×2
//! submatrix, not only adjacent ones) on random small matrices full of ties, its witnesses are
//! genuine, and it rejects the classic counterexamples.

use core::cmp::Ordering;

use monotone_minima::{
    CheckError, NotTotallyMonotone, Transpose, check_totally_monotone, check_totally_monotone_by,
    check_totally_monotone_f64, column_minima, from_fn, row_minima,
};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 2048,
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
            "proptest-regressions/checker.txt",
        ))),
        ..ProptestConfig::default()
    }
}

/// The definition, in O(m² n²): for all rows i < i2 and columns j < j2, row i strictly preferring
/// j2 implies row i2 strictly preferring j2.
fn is_totally_monotone_by_definition(m: &[Vec<u8>], columns: usize) -> bool {
    let rows = m.len();
    for i in 0..rows {
        for i2 in i + 1..rows {
            for j in 0..columns {
                for j2 in j + 1..columns {
                    if m[i][j2] < m[i][j] && m[i2][j2] >= m[i2][j] {
                        return false;
                    }
                }
            }
        }
    }
    true
}

/// Random small matrices over `0..values`: few values, so ties are everywhere.
fn small_matrix() -> impl Strategy<Value = (Vec<Vec<u8>>, usize)> {
    (0..=6_usize, 0..=7_usize, 2_u8..=4).prop_flat_map(|(rows, columns, values)| {
        (vec(vec(0..values, columns), rows), Just(columns))
    })
}

/// Row-sorted matrices are much more often totally monotone, so both verdicts get exercised.
fn nearly_monotone_matrix() -> impl Strategy<Value = (Vec<Vec<u8>>, usize)> {
    small_matrix().prop_map(|(mut m, columns)| {
        for row in &mut m {
            row.sort_unstable_by(|a, b| b.cmp(a));
        }
        (m, columns)
    })
}

fn check(m: &[Vec<u8>], columns: usize) -> Result<(), NotTotallyMonotone> {
    check_totally_monotone(&from_fn(m.len(), columns, |i, j| m[i][j]))
}

/// A witness must be a violating 2×2 submatrix on adjacent rows.
fn assert_genuine(m: &[Vec<u8>], witness: NotTotallyMonotone) -> Result<(), TestCaseError> {
    let ((i, i2), (j, j2)) = (witness.rows(), witness.columns());
    prop_assert_eq!(i2, i + 1);
    prop_assert!(j < j2);
    prop_assert!(
        m[i][j2] < m[i][j],
        "row {} does not prefer column {}",
        i,
        j2
    );
    prop_assert!(
        m[i2][j] <= m[i2][j2],
        "row {} prefers column {} too",
        i2,
        j2
    );
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn checker_matches_the_definition((m, columns) in prop_oneof![small_matrix(), nearly_monotone_matrix()]) {
        let verdict = check(&m, columns);
        prop_assert_eq!(verdict.is_ok(), is_totally_monotone_by_definition(&m, columns), "{:?}", m);
        if let Err(witness) = verdict {
            assert_genuine(&m, witness)?;
        }
    }

    /// A totally monotone matrix's searches agree with its row minima by definition.
    #[test]
    fn accepted_matrices_are_searched_correctly((m, columns) in nearly_monotone_matrix()) {
        let matrix = from_fn(m.len(), columns, |i, j| m[i][j]);
        if check_totally_monotone(&matrix).is_ok() {
            let expected: Vec<usize> = if columns == 0 {
                Vec::new()
            } else {
                // Leftmost minimum: min_by_key keeps the first of equal keys.
                m.iter().map(|row| (0..columns).min_by_key(|&j| row[j]).unwrap_or(0)).collect()
            };
            prop_assert_eq!(row_minima(&matrix), expected);
        }
    }
}

#[test]
fn only_a_non_adjacent_pair_of_columns_is_violated() {
    // Adjacent 2×2 submatrices are all fine; columns 0 and 2 are not: row 0 prefers column 2,
    // row 1 prefers column 0.
    let m = [[1, 2, 0], [0, 3, 1]];
    for j in 0..2 {
        let adjacent = from_fn(2, 2, |i, k| m[i][j + k]);
        assert_eq!(check_totally_monotone(&adjacent), Ok(()));
    }
    let witness = check_totally_monotone(&m).unwrap_err();
    assert_eq!((witness.rows(), witness.columns()), ((0, 1), (0, 2)));
    assert_eq!(
        witness.to_string(),
        "matrix is not totally monotone: row 0 prefers column 2 to column 0, but row 1 does not"
    );
}

#[test]
fn a_violation_between_distant_rows_is_found_on_adjacent_ones() {
    // Rows 0 and 2 violate; row 1 sits between them, so some adjacent pair violates too.
    let m = [[5, 1], [3, 3], [1, 4]];
    let witness = check_totally_monotone(&m).unwrap_err();
    assert_eq!(witness.rows().1, witness.rows().0 + 1);
    assert_eq!(witness.columns(), (0, 1));
}

#[test]
fn row_monotone_is_not_column_monotone() {
    // The column_minima documentation example.
    let m = [[2, 3], [1, 5]];
    assert_eq!(check_totally_monotone(&m), Ok(()));
    assert_eq!(row_minima(&m), [0, 0]);
    let witness = check_totally_monotone(&Transpose(&m)).unwrap_err();
    assert_eq!((witness.rows(), witness.columns()), ((0, 1), (0, 1)));
    // The column minima move up: column 0 at row 1, column 1 at row 0.
    assert_eq!(column_minima(&m), [1, 0]);
}

#[test]
fn ties_are_handled_exactly() {
    // Row 0 ties, so it prefers nothing: no constraint on row 1.
    assert_eq!(check_totally_monotone(&[[1, 1], [0, 9]]), Ok(()));
    // Row 0 strictly prefers column 1; row 1 ties, which is not a strict preference.
    assert!(check_totally_monotone(&[[2, 1], [4, 4]]).is_err());
    // All equal: totally monotone.
    assert_eq!(check_totally_monotone(&[[7; 5]; 4]), Ok(()));
}

#[test]
fn small_shapes_are_always_monotone() {
    assert_eq!(check_totally_monotone(&[[3, 1, 2]]), Ok(()));
    assert_eq!(check_totally_monotone(&[[3], [1], [2]]), Ok(()));
    let empty: [[u8; 0]; 2] = [[], []];
    assert_eq!(check_totally_monotone(&empty), Ok(()));
    assert_eq!(check_totally_monotone(&from_fn(0, 0, |_, _| 0)), Ok(()));
}

#[test]
fn f64_checker_reports_nan_first_and_violations() {
    let nan_late = from_fn(3, 3, |i, j| {
        if (i, j) == (2, 1) {
            f64::NAN
        } else {
            (i as f64 - j as f64).abs()
        }
    });
    assert_eq!(
        check_totally_monotone_f64(&nan_late).map_err(nan_position),
        Err(Some((2, 1)))
    );
    // A violation in rows 0 and 1 does not hide a NaN in row 2.
    let both = from_fn(3, 2, |i, j| [[2.0, 1.0], [1.0, 2.0], [0.0, f64::NAN]][i][j]);
    assert_eq!(
        check_totally_monotone_f64(&both).map_err(nan_position),
        Err(Some((2, 1)))
    );
    let violation = from_fn(2, 2, |i, j| [[2.0, 1.0], [1.0, 2.0]][i][j]);
    assert!(matches!(
        check_totally_monotone_f64(&violation),
        Err(CheckError::NotTotallyMonotone(_))
    ));
    // IEEE order: -0.0 == 0.0, so this is a tie, not a preference.
    let zeros = from_fn(2, 2, |i, j| [[0.0, -0.0], [0.0, 1.0]][i][j]);
    assert_eq!(check_totally_monotone_f64(&zeros), Ok(()));
    let nan = monotone_minima::brute_force_row_minima_f64(&nan_late).unwrap_err();
    assert_eq!(
        CheckError::from(nan).to_string(),
        "NaN matrix entry at row 2, column 1"
    );
}

fn nan_position(e: CheckError) -> Option<(usize, usize)> {
    match e {
        CheckError::Nan(nan) => Some((nan.row(), nan.column())),
        CheckError::NotTotallyMonotone(_) => None,
    }
}

#[test]
fn an_inconsistent_order_does_not_panic() {
    // Not a total order: the verdict is meaningless, but there must be no panic (the checker
    // does not use the standard sorts, which may panic on such orders).
    let m = from_fn(40, 40, |i, j| (i * 7 + j * 13) % 11);
    let mut flip = false;
    let _meaningless = check_totally_monotone_by(&m, |_, _| {
        flip = !flip;
        if flip {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    });
}
