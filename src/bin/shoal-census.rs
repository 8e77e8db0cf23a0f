//! `shoal-census`: the measurement scripts whose figures the docs quote
//! (`shoal::census`). Run them in release: several take minutes.
//!
//! ```text
//! shoal-census            # lists every script with what it measures
//! shoal-census NAME …     # runs those scripts, in order
//! ```
//!
//! An unknown name is one line on stderr and exit code 2.

#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    use std::process::ExitCode;

    let names: Vec<String> = std::env::args().skip(1).collect();
    if names.is_empty() || names.iter().any(|n| n == "--help" || n == "-h") {
        println!("usage: shoal-census NAME ...\n\nscripts:");
        for c in shoal::census::all() {
            println!("  {:<34} {}", c.name, c.about);
        }
        return ExitCode::SUCCESS;
    }
    let mut scripts = Vec::new();
    for name in &names {
        match shoal::census::find(name) {
            Some(c) => scripts.push(c),
            None => {
                eprintln!(
                    "shoal-census: no script called {name:?} (run without arguments to list them)"
                );
                return ExitCode::from(2);
            }
        }
    }
    for c in scripts {
        println!("== {}: {}", c.name, c.about);
        (c.run)();
    }
    ExitCode::SUCCESS
}
