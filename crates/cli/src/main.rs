//! `polydist`: runs scene files (an embedded default scene when given none) and checks them.
//!
//! ```text
//! polydist                      # runs the embedded default scene (same as `polydist run`)
//! polydist run [SCENE] [--json] [--kernel fast|robust|exact] [--no-coherence] [--no-count]
//!               [--no-broad-phase] [--threads N] [--svg FILE]
//! polydist check SCENE          # validates and explains every problem, without running
//! polydist batch [PAIRS.jsonl] [--effects distance,...] [--threads N]   # docs/batch.md
//! polydist batch --within R A.jsonl B.jsonl
//! ```
//!
//! Exit status: 0 when everything was computed, 1 when some pair failed (all pairs are still
//! reported) or a streamed query (all pairs within `r`) stopped at a run-time limit (the report's
//! `errors`, also printed on stderr), 2 when the scene is invalid or cannot be read.

use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, IsTerminal as _, Write as _};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand, ValueEnum};
use polydist_scene::{
    BatchOptions, Effect, EffectSet, KernelChoice, Origin, RunOptions, Scene, SceneErrors, Shape,
    batch_pairs, batch_within, load_file, load_str, plan, read_layer, render_svg, run,
    run_with_progress,
};

/// The default scene, shown by `polydist run` without a file.
const DEFAULT_SCENE: &str = include_str!("../../../fixtures/scenes/default.toml");
/// Its name in messages.
const DEFAULT_NAME: &str = "<embedded default scene: fixtures/scenes/default.toml>";

#[derive(Parser, Debug)]
#[command(
    name = "polydist",
    version,
    about = "Exact planar polygon distances: run a scene and compute exactly the effects it asks for",
    long_about = "Runs scene files (TOML or JSON, see docs/scene-format.md). Without a subcommand, runs \
                  the embedded default scene."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run a scene (the embedded default scene when no file is given).
    Run {
        /// The scene file (TOML, or JSON by extension or content).
        scene: Option<PathBuf>,
        /// Print the report as JSON (schema in docs/scene-format.md) instead of a table.
        #[arg(long)]
        json: bool,
        /// Override the scene's precision kernel.
        #[arg(long, value_enum)]
        kernel: Option<KernelArg>,
        /// Turn temporal coherence off (the results are identical; only the cost changes).
        #[arg(long)]
        no_coherence: bool,
        /// Do not count predicates (the `predicates` costs become null).
        #[arg(long)]
        no_count: bool,
        /// Turn the broad phase off for queries with `within` (the results are identical; only the
        /// cost changes).
        #[arg(long)]
        no_broad_phase: bool,
        /// The number of threads (default: all cores, or RAYON_NUM_THREADS).
        #[arg(long)]
        threads: Option<usize>,
        /// Also draw the scene as SVG into FILE: bodies at the frame of the smallest distance,
        /// closest-point segments, Hausdorff witnesses; trajectories and distance over time for
        /// moving scenes.
        #[arg(long, value_name = "FILE")]
        svg: Option<PathBuf>,
    },
    /// Answer pairs of polygons given as JSON lines, streaming, in parallel (docs/batch.md); with
    /// `--within R A B`, every pair of layers A and B at distance at most R.
    Batch {
        /// The JSON-lines file of pairs (default or `-`: stdin); with `--within`, the two layer
        /// files.
        files: Vec<PathBuf>,
        /// Effects of lines that give none, comma-separated (default: distance).
        #[arg(long, value_delimiter = ',')]
        effects: Vec<String>,
        /// All pairs of two layers within this distance.
        #[arg(long)]
        within: Option<f64>,
        /// The precision kernel (default robust).
        #[arg(long, value_enum)]
        kernel: Option<KernelArg>,
        /// The number of threads (default: all cores, or RAYON_NUM_THREADS).
        #[arg(long)]
        threads: Option<usize>,
        /// Lines answered per parallel chunk (default 1024).
        #[arg(long)]
        chunk: Option<usize>,
    },
    /// Validate a scene and explain every problem, without running it.
    Check {
        /// The scene file.
        scene: PathBuf,
    },
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum KernelArg {
    Fast,
    Robust,
    Exact,
}

impl From<KernelArg> for KernelChoice {
    fn from(k: KernelArg) -> Self {
        match k {
            KernelArg::Fast => KernelChoice::Fast,
            KernelArg::Robust => KernelChoice::Robust,
            KernelArg::Exact => KernelChoice::Exact,
        }
    }
}

fn load(scene: Option<&PathBuf>) -> Result<Scene, SceneErrors> {
    match scene {
        Some(path) => load_file(path),
        None => load_str(
            DEFAULT_SCENE,
            &Origin {
                name: DEFAULT_NAME.to_owned(),
                dir: None,
                json: Some(false),
            },
        ),
    }
}

fn print(text: &str) -> ExitCode {
    let mut out = std::io::stdout().lock();
    // A closed pipe (`polydist run | head`) is not a failure of the run: the write error is ignored.
    let _closed = out.write_all(text.as_bytes()).and_then(|()| out.flush());
    ExitCode::SUCCESS
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        None => run_command(None, false, None, RunOptions::default()),
        Some(Command::Run {
            scene,
            json,
            kernel,
            no_coherence,
            no_count,
            no_broad_phase,
            threads,
            svg,
        }) => run_command(
            scene.as_ref(),
            json,
            svg.as_ref(),
            RunOptions {
                kernel: kernel.map(KernelChoice::from),
                coherence: no_coherence.then_some(false),
                count_predicates: !no_count,
                broad_phase: !no_broad_phase,
                threads,
                ..RunOptions::default()
            },
        ),
        Some(Command::Check { scene }) => check_command(&scene),
        Some(Command::Batch {
            files,
            effects,
            within,
            kernel,
            threads,
            chunk,
        }) => {
            let mut options = BatchOptions {
                kernel: kernel.map_or(KernelChoice::Robust, KernelChoice::from),
                ..BatchOptions::default()
            };
            if let Some(c) = chunk {
                options.chunk = c;
            }
            if !effects.is_empty() {
                let mut set = EffectSet::EMPTY;
                for e in &effects {
                    match serde_json::from_value::<Effect>(serde_json::Value::String(e.clone())) {
                        Ok(e) => set.insert(e),
                        Err(_) => {
                            eprintln!(
                                "polydist batch: unknown effect '{e}' (expected distance, closest_points, vertex_distance, hausdorff or cmmr)"
                            );
                            return ExitCode::from(2);
                        }
                    }
                }
                options.effects = set;
            }
            let go = || batch_command(&files, within, &options);
            match threads.map(|t| {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(t.max(1))
                    .build()
            }) {
                Some(Ok(pool)) => pool.install(go),
                Some(Err(e)) => {
                    eprintln!("polydist batch: cannot start {threads:?} threads: {e}");
                    ExitCode::from(2)
                }
                None => go(),
            }
        }
    }
}

/// Opens a file, or stdin for `-`.
fn open_input(path: Option<&PathBuf>) -> std::io::Result<Box<dyn BufRead>> {
    match path {
        None => Ok(Box::new(std::io::stdin().lock())),
        Some(p) if p.as_os_str() == "-" => Ok(Box::new(std::io::stdin().lock())),
        Some(p) => Ok(Box::new(BufReader::new(File::open(p)?))),
    }
}

fn batch_command(files: &[PathBuf], within: Option<f64>, options: &BatchOptions) -> ExitCode {
    let stdout = std::io::stdout();
    let out = BufWriter::new(stdout.lock());
    let result = match within {
        None => {
            if files.len() > 1 {
                eprintln!(
                    "polydist batch: one file of pairs (or stdin); two layer files need --within R"
                );
                return ExitCode::from(2);
            }
            let input = match open_input(files.first()) {
                Ok(i) => i,
                Err(e) => {
                    eprintln!("polydist batch: {}: {e}", files[0].display());
                    return ExitCode::from(2);
                }
            };
            batch_pairs(input, out, options)
        }
        Some(r) => {
            if files.len() != 2 || r.is_nan() || r < 0.0 {
                eprintln!("polydist batch --within R A B: two layer files and R >= 0");
                return ExitCode::from(2);
            }
            let mut layers = Vec::new();
            let mut errors = Vec::new();
            for (name, path) in ["a", "b"].into_iter().zip(files) {
                let read = open_input(Some(path)).and_then(|i| read_layer(i, name));
                match read {
                    Ok((polys, errs)) => {
                        layers.push(polys);
                        errors.extend(errs);
                    }
                    Err(e) => {
                        eprintln!("polydist batch: {}: {e}", path.display());
                        return ExitCode::from(2);
                    }
                }
            }
            let mut out = out;
            let wrote = errors
                .iter()
                .try_for_each(|e| writeln!(out, "{e}"))
                .and_then(|()| batch_within(&layers[0], &layers[1], r, options, out));
            wrote.map(|mut s| {
                s.errors += errors.len() as u64;
                s
            })
        }
    };
    match result {
        Ok(s) if s.errors == 0 => ExitCode::SUCCESS,
        Ok(s) => {
            eprintln!(
                "polydist batch: {} of {} lines had errors (see the error lines)",
                s.errors,
                s.lines + if within.is_some() { s.errors } else { 0 }
            );
            ExitCode::from(1)
        }
        // A closed pipe (`polydist batch | head`) ends the batch quietly.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polydist batch: {e}");
            ExitCode::from(2)
        }
    }
}

/// A progress bar on stderr (drawn only when stderr is a terminal, and only once a run has taken
/// half a second: short runs stay silent).
struct ProgressBar {
    start: Instant,
    /// The last drawn permille plus one (0: nothing drawn yet).
    drawn: AtomicU64,
}

impl ProgressBar {
    const WIDTH: u64 = 40;

    fn new() -> ProgressBar {
        ProgressBar {
            start: Instant::now(),
            drawn: AtomicU64::new(0),
        }
    }

    fn update(&self, done: u64, total: u64) {
        if total == 0 || self.start.elapsed() < Duration::from_millis(500) {
            return;
        }
        let permille = done.min(total) * 1000 / total;
        let previous = self.drawn.swap(permille + 1, Ordering::Relaxed);
        if previous == permille + 1 {
            return;
        }
        let filled = permille * Self::WIDTH / 1000;
        let bar: String = (0..Self::WIDTH)
            .map(|i| if i < filled { '#' } else { '-' })
            .collect();
        let mut err = std::io::stderr().lock();
        let _ = write!(
            err,
            "\r[{bar}] {:>5.1}% ({done}/{total}) {:.1}s",
            permille as f64 / 10.0,
            self.start.elapsed().as_secs_f64()
        );
        let _ = err.flush();
    }

    fn finish(&self) {
        if self.drawn.load(Ordering::Relaxed) != 0 {
            let mut err = std::io::stderr().lock();
            let _ = write!(err, "\r{:width$}\r", "", width = Self::WIDTH as usize + 40);
            let _ = err.flush();
        }
    }
}

fn run_command(
    path: Option<&PathBuf>,
    json: bool,
    svg: Option<&PathBuf>,
    options: RunOptions,
) -> ExitCode {
    let scene = match load(path) {
        Ok(s) => s,
        Err(e) => {
            eprint!("{e}");
            return ExitCode::from(2);
        }
    };
    let report = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new();
        let report = run_with_progress(&scene, &options, &|done, total| bar.update(done, total));
        bar.finish();
        report
    } else {
        run(&scene, &options)
    };
    if let Some(file) = svg {
        if let Err(e) = std::fs::write(file, render_svg(&scene, &report)) {
            eprintln!("polydist: cannot write {}: {e}", file.display());
            return ExitCode::from(2);
        }
    }
    let text = if json {
        match serde_json::to_string_pretty(&report) {
            Ok(mut s) => {
                s.push('\n');
                s
            }
            Err(e) => {
                eprintln!("cannot write the report as JSON: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        report.to_table()
    };
    let printed = print(&text);
    if report.failed {
        for e in &report.errors {
            eprintln!("polydist: {e}");
        }
        if report.pairs.iter().any(|p| p.failed) || report.errors.is_empty() {
            eprintln!("polydist: some pairs failed (see the report)");
        }
        return ExitCode::from(1);
    }
    printed
}

fn check_command(path: &PathBuf) -> ExitCode {
    match load(Some(path)) {
        Ok(scene) => {
            let convex = scene
                .bodies
                .iter()
                .filter(|b| matches!(b.shape, Shape::Convex(_)))
                .count();
            let moving = scene
                .bodies
                .iter()
                .filter(|b| !b.motion.is_static())
                .count();
            let plan = plan(&scene);
            let n = scene.bodies.len() as u64;
            // A streamed query (all pairs within r) names every pair without a job.
            let pairs = if plan.streamed.is_some() {
                format!(
                    "{} pairs ({} planned as jobs, the others streamed from the broad phase frame by frame)",
                    n * n.saturating_sub(1) / 2,
                    plan.jobs.len()
                )
            } else {
                format!("{} pairs", plan.jobs.len())
            };
            print(&format!(
                "{}: ok: scene '{}', {} bodies ({convex} convex, {} simple, {moving} moving), {} queries, {pairs}, {} frames, kernel {}\n",
                path.display(),
                scene.name,
                scene.bodies.len(),
                scene.bodies.len() - convex,
                scene.queries.len(),
                scene.time.frames,
                scene.kernel.name()
            ))
        }
        Err(e) => {
            eprint!("{}: {e}", path.display());
            ExitCode::from(2)
        }
    }
}
