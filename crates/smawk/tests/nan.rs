//! NaN in the `f64` functions: an error naming the entry, never a minimum.
//!
//! The fast searches look at O(rows + columns) entries, so they can only report NaNs they look
//! at; what they guarantee is that the first NaN they look at is reported, and that every minimum
//! they return was looked at (so it is not NaN).

use std::cell::RefCell;
use std::hint::black_box;

use monotone_minima::{
    NanError, brute_force_row_minima_f64, column_minima_f64, from_fn, online_column_minima_f64,
    row_minima_f64,
};
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;

fn config() -> ProptestConfig {
    ProptestConfig {
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
            "proptest-regressions/nan.txt",
        ))),
        ..ProptestConfig::default()
    }
}

fn position(e: NanError) -> (usize, usize) {
    (e.row(), e.column())
}

/// A NaN made at run time (on x86, `0.0 / 0.0` even has its sign bit set).
fn runtime_nan() -> f64 {
    black_box(0.0_f64) / black_box(0.0_f64)
}

#[test]
fn runtime_nan_is_an_error_not_a_minimum() {
    for nan in [runtime_nan(), -f64::NAN, f64::NAN] {
        assert!(nan.is_nan());
        let m = from_fn(1, 200, |_, j| {
            if j == 137 {
                nan
            } else {
                (j as f64 - 100.0).powi(2)
            }
        });
        assert_eq!(row_minima_f64(&m).map_err(position), Err((0, 137)));
        assert_eq!(
            brute_force_row_minima_f64(&m).map_err(position),
            Err((0, 137))
        );
    }
    // What the f64 functions exist to prevent: `total_cmp` orders a NaN with the sign bit set
    // below -infinity, so a search by `total_cmp` returns it as the minimum.
    let negative_nan = -f64::NAN;
    assert_eq!(
        negative_nan.total_cmp(&f64::NEG_INFINITY),
        core::cmp::Ordering::Less
    );
    let m = from_fn(1, 200, |_, j| {
        if j == 137 {
            negative_nan
        } else {
            (j as f64 - 100.0).powi(2)
        }
    });
    assert_eq!(monotone_minima::row_minima_by(&m, f64::total_cmp), [137]);
}

#[test]
fn nan_positions_are_in_the_callers_coordinates() {
    // A single column: every row's minimum is forced, but the f64 functions still look at it.
    let column = from_fn(100, 1, |i, _| if i == 42 { f64::NAN } else { i as f64 });
    assert_eq!(row_minima_f64(&column).map_err(position), Err((42, 0)));
    let row = from_fn(1, 100, |_, j| if j == 42 { f64::NAN } else { j as f64 });
    assert_eq!(column_minima_f64(&row).map_err(position), Err((0, 42)));
    assert_eq!(row_minima_f64(&from_fn(3, 0, |_, _| f64::NAN)), Ok(vec![]));
}

#[test]
fn an_all_nan_row_is_reported() {
    let m = from_fn(300, 300, |i, j| {
        if i == 123 {
            f64::NAN
        } else {
            (i as f64 - j as f64).powi(2)
        }
    });
    assert_eq!(row_minima_f64(&m).map_err(|e| e.row()), Err(123));
}

#[test]
fn online_nan_stops_the_computation() {
    let calls = RefCell::new(0);
    let result = online_column_minima_f64(1000, 0.0, |done, i, j| {
        *calls.borrow_mut() += 1;
        if j == 500 {
            f64::NAN
        } else {
            done[i] + (j - i) as f64
        }
    });
    assert_eq!(result.map_err(|e| e.column()), Err(500));
    assert!(*calls.borrow() < 5000, "it stopped at the NaN");
    // A NaN initial value is not an entry; the entries computed from it are.
    let result = online_column_minima_f64(10, f64::NAN, |done, i, j| done[i] + (j - i) as f64);
    assert_eq!(result.map_err(position), Err((0, 1)));
}

proptest! {
    #![proptest_config(config())]

    /// Random Monge matrices with NaNs sprinkled in: the result is an error for exactly the first
    /// NaN the search looked at, and otherwise no returned minimum is NaN (and each was looked at).
    #[test]
    fn looked_up_nans_are_reported(
        rows in 0..60_usize,
        columns in 1..60_usize,
        nans in vec((0..60_usize, 0..60_usize), 0..4),
        offsets in vec(-50.0_f64..50.0, 60),
    ) {
        let nan_at = |i: usize, j: usize| nans.iter().any(|&(a, b)| (a, b) == (i, j));
        let entry = |i: usize, j: usize| {
            if nan_at(i, j) { runtime_nan() } else { offsets[j] + (i as f64 - j as f64).powi(2) }
        };
        let seen = RefCell::new(Vec::new());
        let m = from_fn(rows, columns, |i, j| {
            seen.borrow_mut().push((i, j));
            entry(i, j)
        });
        let result = row_minima_f64(&m);
        let seen = seen.into_inner();
        let first_nan = seen.iter().copied().find(|&(i, j)| nan_at(i, j));
        match result {
            Err(e) => prop_assert_eq!(Some(position(e)), first_nan),
            Ok(minima) => {
                prop_assert_eq!(first_nan, None);
                for (i, &j) in minima.iter().enumerate() {
                    prop_assert!(!entry(i, j).is_nan());
                    prop_assert!(seen.contains(&(i, j)), "minimum ({}, {}) never looked at", i, j);
                }
            }
        }
    }
}
