//! The server process killed (SIGKILL) mid-lesson while its clients are sending,
//! and restarted on the same database: every acknowledged prediction and result
//! is still there, every client reconnects by itself and resends what was not
//! acknowledged, and nothing is counted twice (the CSVs are checked row by row).
//! Runs the built `shoal-class` binary against SQLite, and against PostgreSQL
//! when `SHOAL_CLASS_TEST_POSTGRES` is set.

// The harness reports more figures than this test checks.
#[allow(dead_code)]
mod loadkit;

use std::time::Duration;

async fn database_urls() -> Vec<String> {
    let dir = std::env::temp_dir().join(format!("shoal-class-kill-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("class.sqlite");
    let mut urls = vec![format!("sqlite://{}", file.display())];
    if let Ok(url) = std::env::var("SHOAL_CLASS_TEST_POSTGRES") {
        urls.push(url);
    }
    urls
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn killing_the_server_mid_lesson_loses_nothing_and_counts_nothing_twice() {
    let dist = std::env::temp_dir().join(format!("shoal-class-kill-dist-{}", std::process::id()));
    std::fs::create_dir_all(&dist).unwrap();
    std::fs::write(dist.join("index.html"), "<!doctype html>").unwrap();
    for database in database_urls().await {
        let spec = loadkit::ServerSpec {
            binary: env!("CARGO_BIN_EXE_shoal-class").into(),
            database: database.clone(),
            port: loadkit::free_port(),
            dist: dist.clone(),
        };
        let plan = loadkit::Plan {
            classes: 3,
            students: 8,
            results: 4,
            think_ms: 150,
            ramp_ms: 300,
            kill_at: Some(0.4),
            down_ms: 300,
            deadline: Duration::from_secs(60),
        };
        let r = loadkit::run(&plan, &spec).await.expect("the lesson runs");
        let k = r.kill.as_ref().expect("the server was killed");
        eprintln!("{database}: {r:?}");
        assert!(r.failures.is_empty(), "{:?}", r.failures);
        assert_eq!(r.lost, 0);
        assert_eq!(r.csv_rows, r.csv_rows_expected);
        assert_eq!(r.csv_rows_expected, 3 * 8 * 4 * 2);
        // Every client (24 students and 3 teachers) came back by itself.
        assert_eq!(k.reconnects, 27);
        // The kill came while results were still being sent.
        assert!(k.results_acked_before < 3 * 8 * 4, "{k:?}");
    }
}
