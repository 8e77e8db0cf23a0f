//! `shoal-lab`: Shoal's experiments headless, on every core (issue 16).
//!
//! ```text
//! shoal-lab experiment.json [--shard I/N] [--out file.csv] [--threads N]
//! shoal-lab merge a.csv b.csv … [--out all.csv]
//! shoal-lab bench experiment.json [--runs K]
//! shoal-lab soak [--scene NAME] [--minutes M] [--seed N] [--verbose]
//! ```
//!
//! `soak` runs every scene (or one) for `M` simulated minutes (default 60)
//! under a random change every simulated 10 s and the extremes (`shoal::soak`),
//! one scene after the other, and prints one line of figures per scene: steps,
//! changes applied and refused, rule violations, the wall time and the heap in
//! use (counted by this binary's global allocator) at the start, after the
//! warm-up and at the end, and its peak. Exit code 1 if any scene broke a
//! rule.
//!
//! The runs are the library's (`shoal::experiment`), the same the browser runs
//! one slice per frame; here rayon spreads them over the cores and indicatif
//! shows the progress. The CSV is the library's too, in run order, so its bytes
//! do not depend on the thread count or the sharding. Bad input (a design the
//! library refuses, an unreadable file, shards that do not fit together) is one
//! line on stderr naming the field, and exit code 2. See `docs/experiments.md`.

#[cfg(target_arch = "wasm32")]
fn main() {}

/// Counts the heap in use, for `shoal-lab soak`'s memory figures.
#[cfg(not(target_arch = "wasm32"))]
#[global_allocator]
static ALLOCATOR: cap::Cap<std::alloc::System> = cap::Cap::new(std::alloc::System, usize::MAX);

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    native::main()
}

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::process::ExitCode;
    use std::time::Instant;

    use indicatif::{ProgressBar, ProgressStyle};
    use rayon::prelude::*;

    use shoal::experiment::{
        Design, Plan, RunResult, RunSpec, experiment_csv, merge_csv, summarise, summary_table,
    };

    const USAGE: &str =
        "usage: shoal-lab experiment.json [--shard I/N] [--out file.csv] [--threads N]
       shoal-lab merge a.csv b.csv ... [--out all.csv]
       shoal-lab bench experiment.json [--runs K] [--threads N]
       shoal-lab soak [--scene NAME] [--minutes M] [--seed N] [--verbose]";

    /// Steps a worker runs between two updates of the progress bar. Default
    /// 600 (10 simulated seconds of the schooling lab): a few updates a second.
    const STEPS_PER_SLICE: u64 = 600;

    /// A failure: the message, and whether it is the input's fault (exit 2) or
    /// the machine's (exit 1: a file that cannot be written).
    struct Failure {
        message: String,
        bad_input: bool,
    }

    fn bad(message: impl Into<String>) -> Failure {
        Failure {
            message: message.into(),
            bad_input: true,
        }
    }

    pub fn main() -> ExitCode {
        let args: Vec<String> = std::env::args().skip(1).collect();
        match run(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(f) => {
                eprintln!("shoal-lab: {}", f.message.replace('\n', " "));
                ExitCode::from(if f.bad_input { 2 } else { 1 })
            }
        }
    }

    /// The command line, parsed: positional arguments and the options.
    #[derive(Default)]
    struct Args {
        files: Vec<String>,
        out: Option<String>,
        shard: Option<(usize, usize)>,
        threads: Option<usize>,
        runs: Option<usize>,
        bench: bool,
    }

    fn parse(args: &[String]) -> Result<Args, Failure> {
        let mut parsed = Args::default();
        let mut it = args.iter();
        while let Some(arg) = it.next() {
            let mut value = |name: &str| {
                it.next()
                    .cloned()
                    .ok_or_else(|| bad(format!("{name} needs a value\n{USAGE}")))
            };
            match arg.as_str() {
                "--out" | "-o" => parsed.out = Some(value("--out")?),
                "--shard" => {
                    let text = value("--shard")?;
                    let shard = text
                        .split_once('/')
                        .and_then(|(i, n)| Some((i.parse().ok()?, n.parse().ok()?)))
                        .filter(|&(i, n): &(usize, usize)| n > 0 && i < n)
                        .ok_or_else(|| {
                            bad(format!(
                                "--shard: '{text}' is not I/N with 0 <= I < N (shards count from 0)"
                            ))
                        })?;
                    parsed.shard = Some(shard);
                }
                "--threads" | "-j" => {
                    let text = value("--threads")?;
                    let n = text
                        .parse()
                        .ok()
                        .filter(|&n: &usize| n > 0)
                        .ok_or_else(|| {
                            bad(format!("--threads: '{text}' is not a whole number above 0"))
                        })?;
                    parsed.threads = Some(n);
                }
                "--runs" => {
                    let text = value("--runs")?;
                    let n = text
                        .parse()
                        .ok()
                        .filter(|&n: &usize| n > 0)
                        .ok_or_else(|| {
                            bad(format!("--runs: '{text}' is not a whole number above 0"))
                        })?;
                    parsed.runs = Some(n);
                }
                "--bench" => parsed.bench = true,
                other if other.starts_with('-') => {
                    return Err(bad(format!("unknown option '{other}'\n{USAGE}")));
                }
                file => parsed.files.push(file.to_owned()),
            }
        }
        Ok(parsed)
    }

    fn run(args: &[String]) -> Result<(), Failure> {
        if args.iter().any(|a| a == "--help" || a == "-h") {
            println!("{USAGE}\n\nThe experiment file and the CSV: docs/experiments.md");
            return Ok(());
        }
        match args.first().map(String::as_str) {
            None => Err(bad(USAGE)),
            Some("merge") => merge(&parse(&args[1..])?),
            Some("soak") => soak(&args[1..]),
            Some("bench") => {
                let mut parsed = parse(&args[1..])?;
                parsed.bench = true;
                experiment(&parsed)
            }
            Some(_) => experiment(&parse(args)?),
        }
    }

    fn read(path: &str) -> Result<String, Failure> {
        std::fs::read_to_string(path).map_err(|err| bad(format!("{path}: {err}")))
    }

    fn write(path: Option<&str>, text: &str) -> Result<(), Failure> {
        match path {
            Some(path) => std::fs::write(path, text).map_err(|err| Failure {
                message: format!("{path}: {err}"),
                bad_input: false,
            }),
            None => {
                use std::io::Write as _;
                std::io::stdout()
                    .write_all(text.as_bytes())
                    .map_err(|err| Failure {
                        message: format!("stdout: {err}"),
                        bad_input: false,
                    })
            }
        }
    }

    fn load_plan(path: &str) -> Result<Plan, Failure> {
        let text = read(path)?;
        Design::from_json(&text)
            .and_then(|design| design.validate())
            .map_err(|err| bad(format!("{path}: {err}")))
    }

    fn pool(threads: usize) -> Result<rayon::ThreadPool, Failure> {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|err| Failure {
                message: format!("cannot start {threads} threads: {err}"),
                bad_input: false,
            })
    }

    /// Every run of `specs` on `threads` threads, in run order.
    fn run_all(
        plan: &Plan,
        specs: &[RunSpec],
        threads: usize,
        bar: &ProgressBar,
    ) -> Result<Vec<RunResult>, Failure> {
        Ok(pool(threads)?.install(|| {
            specs
                .par_iter()
                .map(|spec| {
                    let mut run = shoal::experiment::ExperimentRun::new(plan, spec);
                    let mut before = 0;
                    loop {
                        let progress = run.advance(STEPS_PER_SLICE);
                        bar.inc(progress.steps_done - before);
                        before = progress.steps_done;
                        if progress.done {
                            break;
                        }
                    }
                    run.finish()
                })
                .collect()
        }))
    }

    fn progress_bar(plan: &Plan, runs: usize, label: &str) -> ProgressBar {
        let bar = ProgressBar::new(plan.steps_per_run() * runs as u64);
        bar.set_style(
            ProgressStyle::with_template(
                "{prefix} [{bar:32}] {percent:>3}% {elapsed_precise} (about {eta} left)",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        bar.set_prefix(label.to_owned());
        bar
    }

    fn cores() -> usize {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    }

    fn experiment(args: &Args) -> Result<(), Failure> {
        let [path] = args.files.as_slice() else {
            return Err(bad(format!("give one experiment file\n{USAGE}")));
        };
        let plan = load_plan(path)?;
        if args.bench {
            return bench(&plan, args);
        }
        let specs = match args.shard {
            Some((i, n)) => plan.runs_for_shard(i, n),
            None => plan.runs(),
        };
        let threads = args.threads.unwrap_or_else(cores);
        let estimate = plan.estimate();
        eprintln!(
            "{}: {} of {} runs, {} steps each, on {threads} thread(s); about {:.1} s on one core",
            plan.design.name,
            specs.len(),
            plan.run_count(),
            plan.steps_per_run(),
            estimate.secs_one_core * specs.len() as f64 / plan.run_count().max(1) as f64,
        );
        let bar = progress_bar(&plan, specs.len(), "runs");
        let started = Instant::now();
        let results = run_all(&plan, &specs, threads, &bar)?;
        bar.finish_and_clear();
        let secs = started.elapsed().as_secs_f64();
        write(
            args.out.as_deref(),
            &experiment_csv(&plan, &results, args.shard),
        )?;
        eprintln!(
            "{} runs in {secs:.1} s ({:.2} runs/s){}",
            results.len(),
            results.len() as f64 / secs.max(1e-9),
            args.out
                .as_deref()
                .map_or(String::new(), |o| format!(", written to {o}"))
        );
        if args.shard.is_none() {
            eprint!("{}", summary_table(&plan, &summarise(&plan, &results)));
        }
        Ok(())
    }

    /// Runs per second on one core and on every core, and the speed-up.
    fn bench(plan: &Plan, args: &Args) -> Result<(), Failure> {
        let mut specs = plan.runs();
        specs.truncate(args.runs.unwrap_or(specs.len()));
        let all = args.threads.unwrap_or_else(cores);
        let mut rates = Vec::new();
        let mut csvs = Vec::new();
        for threads in [1, all] {
            let bar = progress_bar(plan, specs.len(), &format!("{threads} thread(s)"));
            let started = Instant::now();
            let results = run_all(plan, &specs, threads, &bar)?;
            bar.finish_and_clear();
            let secs = started.elapsed().as_secs_f64().max(1e-9);
            let rate = specs.len() as f64 / secs;
            println!(
                "{threads:>3} thread(s): {} runs in {secs:.2} s: {rate:.3} runs/s, {:.0} steps/s",
                specs.len(),
                (plan.steps_per_run() * specs.len() as u64) as f64 / secs
            );
            rates.push(rate);
            csvs.push(experiment_csv(plan, &results, None));
        }
        println!(
            "speed-up on {all} threads: {:.2}× (the same CSV: {})",
            rates[1] / rates[0],
            if csvs[0] == csvs[1] { "yes" } else { "NO" }
        );
        Ok(())
    }

    fn merge(args: &Args) -> Result<(), Failure> {
        if args.files.is_empty() {
            return Err(bad(format!("merge: give the shard files\n{USAGE}")));
        }
        let files = args
            .files
            .iter()
            .map(|path| Ok((path.clone(), read(path)?)))
            .collect::<Result<Vec<_>, Failure>>()?;
        let merged = merge_csv(&files).map_err(|err| bad(format!("merge: {err}")))?;
        write(args.out.as_deref(), &merged)?;
        if let Some(out) = &args.out {
            eprintln!("merged {} files into {out}", files.len());
        }
        Ok(())
    }

    /// `shoal-lab soak`: see the module doc.
    fn soak(args: &[String]) -> Result<(), Failure> {
        use shoal::settings::Scene;
        use shoal::soak::{SoakConfig, soak};
        let mut scenes: Vec<Scene> = Scene::ALL.to_vec();
        let (mut minutes, mut seed, mut verbose) = (60.0, 1u64, false);
        let mut it = args.iter();
        while let Some(arg) = it.next() {
            let mut value = |name: &str| {
                it.next()
                    .cloned()
                    .ok_or_else(|| bad(format!("{name} needs a value\n{USAGE}")))
            };
            match arg.as_str() {
                "--scene" => {
                    let name = value("--scene")?;
                    let scene = Scene::ALL
                        .into_iter()
                        .find(|s| s.name() == name)
                        .ok_or_else(|| {
                            let names: Vec<&str> = Scene::ALL.iter().map(|s| s.name()).collect();
                            bad(format!(
                                "--scene: '{name}' is not a scene: {}",
                                names.join(", ")
                            ))
                        })?;
                    scenes = vec![scene];
                }
                "--minutes" => {
                    let text = value("--minutes")?;
                    minutes = text
                        .parse()
                        .ok()
                        .filter(|m: &f64| m.is_finite() && *m > 0.0)
                        .ok_or_else(|| bad(format!("--minutes: '{text}' is not above 0")))?;
                }
                "--seed" => {
                    let text = value("--seed")?;
                    seed = text
                        .parse()
                        .map_err(|_| bad(format!("--seed: '{text}' is not a whole number")))?;
                }
                "--verbose" | "-v" => verbose = true,
                other => return Err(bad(format!("unknown option '{other}'\n{USAGE}"))),
            }
        }
        let heap = || Some(crate::ALLOCATOR.allocated() as u64);
        // One scene after the other, so each one's heap figures are its own
        // (run one process per scene, `--scene`, to use more cores).
        let reports: Vec<shoal::soak::SoakReport> = scenes
            .iter()
            .map(|&scene| {
                let config = SoakConfig::new(scene, minutes, seed);
                let name = scene.name();
                soak(&config, &heap, &mut |t, what, outcome| {
                    if verbose {
                        match outcome {
                            Ok(()) => eprintln!("{name} {t:.0} s {what}"),
                            Err(e) => eprintln!("{name} {t:.0} s {what}: refused: {e}"),
                        }
                    }
                })
            })
            .collect();
        let mut sound = true;
        for report in &reports {
            println!("{}", report.line());
            sound &= report.is_sound();
            if verbose {
                for (kind, n) in &report.refusals {
                    println!("  refused {n} x {kind}");
                }
            }
        }
        println!(
            "heap peak {:.2} MiB, in use now {:.2} MiB",
            crate::ALLOCATOR.max_allocated() as f64 / 1048576.0,
            crate::ALLOCATOR.allocated() as f64 / 1048576.0
        );
        if sound {
            Ok(())
        } else {
            Err(Failure {
                message: "the soak broke a rule (see above)".to_owned(),
                bad_input: false,
            })
        }
    }
}
