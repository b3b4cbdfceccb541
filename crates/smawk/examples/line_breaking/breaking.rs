//! Optimal line breaking with squared slack, by online column minima (shared by the
//! `line_breaking` example and `tests/examples.rs`).

use monotone_minima::online_column_minima;

/// The cost of the best layout of the first `j` words whose last line is words `i..j`.
///
/// Lines that fit cost the best layout up to `i` plus the squared slack. Lines that overflow
/// are ordered by their overflow alone, above every line that fits: with an `f64` cost such as
/// `1e30 + overflow`, the overflows would round to equal values, the ties would break total
/// monotonicity, and the search could pick a wrong line. The derived order compares exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Cost {
    /// The line fits: total cost of the layout.
    Fits(u64),
    /// The line is this much too long.
    Overflows(u64),
}

/// The layout of `widths` (word widths, one space between words) into lines of at most `width`
/// that minimises the sum over all lines, the last one included, of `(width - length)²`.
///
/// Returns the total cost and the index of the first word of each line, or `None` if a word is
/// wider than a line. Time `O(n)`: the cost of a line is a convex function of its length, so the
/// dynamic program's matrix has column minima moving down, and the online search applies.
pub(crate) fn break_lines(widths: &[u64], width: u64) -> Option<(u64, Vec<usize>)> {
    if widths.iter().any(|&w| w > width) {
        return None;
    }
    // prefix[j] = widths[0] + ... + widths[j - 1].
    let prefix: Vec<u64> = core::iter::once(0)
        .chain(widths.iter().scan(0_u64, |sum, &w| {
            *sum = sum.saturating_add(w);
            Some(*sum)
        }))
        .collect();
    let n = widths.len();
    let result = online_column_minima(n + 1, Cost::Fits(0), |done: &[Cost], i, j| {
        // Words i..j (i < j), with j - i - 1 spaces.
        let length = (prefix[j] - prefix[i]).saturating_add((j - i - 1) as u64);
        match done[i] {
            Cost::Fits(cost) if length <= width => {
                Cost::Fits(cost.saturating_add((width - length).pow(2)))
            }
            _ => Cost::Overflows(length.saturating_sub(width)),
        }
    });
    // Every word fits on a line of its own, so the optimum fits.
    let Cost::Fits(total) = result.values[n] else {
        return None;
    };
    let mut starts = Vec::new();
    let mut j = n;
    while j > 0 {
        j = result.rows[j];
        starts.push(j);
    }
    starts.reverse();
    Some((total, starts))
}
