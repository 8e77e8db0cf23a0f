//! `shoal-class --port 8080 --database sqlite://shoal-class.sqlite --dist dist`

use axum::serve::ListenerExt;
use std::net::SocketAddr;
use std::path::PathBuf;

use clap::Parser;

/// The Shoal class server: serves the web app and relays a class's lesson.
/// Class data is deleted --keep-days days after the class started.
#[derive(Parser, Debug)]
#[command(version)]
struct Args {
    /// Address to listen on (put HTTPS in front with a reverse proxy).
    #[arg(long, default_value = "127.0.0.1")]
    address: std::net::IpAddr,
    #[arg(long, default_value_t = 8080)]
    port: u16,
    /// sqlite://FILE (created if missing) or postgres://USER:PASSWORD@HOST/DB.
    #[arg(long, default_value = "sqlite://shoal-class.sqlite")]
    database: String,
    /// The web app's files (the output of `trunk build --release`).
    #[arg(long, default_value = "dist")]
    dist: PathBuf,
    /// Days a class and all its data are kept after it started.
    #[arg(long, default_value_t = 14)]
    keep_days: u32,
}

#[tokio::main]
async fn main() {
    let args = Args::parse();
    let pool = match shoal_class::db::open(&args.database).await {
        Ok(p) => p,
        Err(e) => {
            eprintln!("shoal-class: cannot open {}: {e}", args.database);
            std::process::exit(1);
        }
    };
    tokio::spawn(shoal_class::retention_task(pool.clone(), args.keep_days));
    let app = shoal_class::app(
        pool,
        shoal_class::Config {
            dist: args.dist,
            ..Default::default()
        },
    );
    let addr = SocketAddr::new(args.address, args.port);
    let listener = match tokio::net::TcpListener::bind(addr).await {
        Ok(l) => l,
        Err(e) => {
            eprintln!("shoal-class: cannot listen on {addr}: {e}");
            std::process::exit(1);
        }
    };
    eprintln!(
        "shoal-class: serving on http://{addr} (classes kept {} days)",
        args.keep_days
    );
    // Small messages go out at once: a reply and the view after it are two
    // writes, and with Nagle's algorithm the second waits for the first's ACK.
    let listener = listener.tap_io(|tcp| {
        let _ = tcp.set_nodelay(true);
    });
    if let Err(e) = axum::serve(listener, app).await {
        eprintln!("shoal-class: {e}");
        std::process::exit(1);
    }
}
