//! Optimal line breaking with squared slack, in linear time, with the online column minima of
//! `monotone-minima` (a non-geometric use: concave one-dimensional dynamic programming).
//!
//! Run with `cargo run -p monotone-minima --example line_breaking`.

mod breaking;

const TEXT: &str = "The matrix is never materialised: entries are computed on demand, and the \
    search looks at a number of them proportional to the number of rows and columns. Optimal \
    line breaking is the classic dynamic program that fits this pattern, because the cost of a \
    line depends on the best way to break the text before it.";

fn main() {
    let words: Vec<&str> = TEXT.split_whitespace().collect();
    let widths: Vec<u64> = words.iter().map(|w| w.chars().count() as u64).collect();
    for width in [30, 45] {
        let Some((cost, starts)) = breaking::break_lines(&widths, width) else {
            println!("some word is wider than {width} columns");
            continue;
        };
        println!("width {width}, total squared slack {cost}:");
        for (k, &start) in starts.iter().enumerate() {
            let end = starts.get(k + 1).copied().unwrap_or(words.len());
            let line = words[start..end].join(" ");
            println!("|{line:<width$}|", width = width as usize);
        }
        println!();
    }
}
