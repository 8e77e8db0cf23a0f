//! The class server's load harness (issue 37): plays many classes' lessons at
//! once against a real `shoal-class` process and reports message latency (send
//! to ack), messages lost, every class's CSV checked row by row, and the
//! server's memory (RSS from /proc). With `--kill-at` it also kills the server
//! (SIGKILL) mid-lesson and restarts it on the same database.
//!
//! ```sh
//! cargo build --release --manifest-path class/Cargo.toml --bin shoal-class
//! cargo run --release --manifest-path class/Cargo.toml --example load -- \
//!     --classes 40 --students 35 --database sqlite:///tmp/load.sqlite
//! ```
//!
//! The clients open one connection each (1,400 + 40 teachers by default), so
//! the open-file limit (`ulimit -n`) must be above that for both processes.

#[path = "../tests/loadkit/mod.rs"]
mod loadkit;

use std::path::PathBuf;
use std::time::Duration;

use clap::Parser;

#[derive(Parser, Debug)]
struct Args {
    #[arg(long, default_value_t = 40)]
    classes: usize,
    #[arg(long, default_value_t = 35)]
    students: usize,
    /// Results each student posts (two CSV rows each).
    #[arg(long, default_value_t = 2)]
    results: usize,
    /// A student waits up to this long (uniformly random) before each message.
    #[arg(long, default_value_t = 2000)]
    think_ms: u64,
    /// Classes start and students join spread over this long.
    #[arg(long, default_value_t = 10000)]
    ramp_ms: u64,
    /// The server's --database (a SQLite file is removed first for a fresh run).
    #[arg(long, default_value = "sqlite:///tmp/shoal-class-load.sqlite")]
    database: String,
    /// The server binary.
    #[arg(long, default_value = "class/target/release/shoal-class")]
    server: PathBuf,
    /// Kill the server (SIGKILL) once this fraction of the results is
    /// acknowledged, then restart it on the same database.
    #[arg(long)]
    kill_at: Option<f64>,
    /// How long the server stays down when killed.
    #[arg(long, default_value_t = 500)]
    down_ms: u64,
    /// Seconds after which unacknowledged messages count as lost.
    #[arg(long, default_value_t = 300)]
    deadline_s: u64,
}

fn ms(d: Duration) -> String {
    format!("{:.1}", d.as_secs_f64() * 1000.0)
}

#[tokio::main]
async fn main() {
    let args = Args::parse();
    if let Some(file) = args.database.strip_prefix("sqlite://") {
        for suffix in ["", "-wal", "-shm"] {
            let _ = std::fs::remove_file(format!("{file}{suffix}"));
        }
    }
    let dist = std::env::temp_dir().join(format!("shoal-class-load-dist-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dist);
    let _ = std::fs::write(
        dist.join("index.html"),
        "<!doctype html><title>load</title>",
    );
    let spec = loadkit::ServerSpec {
        binary: args.server.clone(),
        database: args.database.clone(),
        port: loadkit::free_port(),
        dist,
    };
    let plan = loadkit::Plan {
        classes: args.classes,
        students: args.students,
        results: args.results,
        think_ms: args.think_ms,
        ramp_ms: args.ramp_ms,
        kill_at: args.kill_at,
        down_ms: args.down_ms,
        deadline: Duration::from_secs(args.deadline_s),
    };
    eprintln!("load: {plan:?}, database {}", args.database);
    let r = match loadkit::run(&plan, &spec).await {
        Ok(r) => r,
        Err(e) => {
            eprintln!("load: {e}");
            std::process::exit(1);
        }
    };
    println!(
        "connections {} (students {}), messages acknowledged {}, lesson took {:.1} s ({:.0} messages/s)",
        r.connections,
        plan.classes * plan.students,
        r.messages,
        r.wall.as_secs_f64(),
        r.messages as f64 / r.wall.as_secs_f64()
    );
    println!(
        "latency send→ack (ms): p50 {} p99 {} max {}",
        ms(r.latency.0),
        ms(r.latency.1),
        ms(r.latency.2)
    );
    println!("| message | count | p50 ms | p99 ms | max ms |");
    println!("| --- | --- | --- | --- | --- |");
    for (kind, (n, p50, p99, max)) in &r.by_kind {
        println!(
            "| {kind} | {n} | {} | {} | {} |",
            ms(*p50),
            ms(*p99),
            ms(*max)
        );
    }
    println!("errors received: {:?}", r.errors);
    println!(
        "lost (never acknowledged): {}; CSV rows {} of {} expected",
        r.lost, r.csv_rows, r.csv_rows_expected
    );
    println!(
        "server RSS: idle {:.1} MiB, peak {:.1} MiB",
        r.rss_idle_kib as f64 / 1024.0,
        r.rss_peak_kib as f64 / 1024.0
    );
    if let Some(k) = &r.kill {
        println!(
            "kill: {} messages in flight at SIGKILL ({} results acknowledged before); {} clients reconnected; all back {} ms after the kill, {} ms after the restart; {} messages acknowledged after a resend (longest {} ms from first send)",
            k.in_flight,
            k.results_acked_before,
            k.reconnects,
            ms(k.all_back),
            ms(k.back_after_restart),
            k.resent_acked,
            ms(k.resent_max)
        );
    }
    for f in r.failures.iter().take(20) {
        println!("FAILURE: {f}");
    }
    if !r.failures.is_empty() || r.lost > 0 || r.csv_rows != r.csv_rows_expected {
        println!("RESULT: FAILED ({} failures)", r.failures.len());
        std::process::exit(1);
    }
    println!("RESULT: ok");
}
