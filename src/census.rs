//! Measurement scripts: the runs whose figures the docs quote (feeding rates on
//! muscles, the strike census, the body's convergence table, the cost of a
//! banded solve…). They are not tests: they assert nothing and take minutes, so
//! they live here, each registered by name, and `shoal-census` runs them:
//!
//! ```text
//! cargo run --release --bin shoal-census              # lists them
//! cargo run --release --bin shoal-census -- NAME …    # runs those, in order
//! ```
//!
//! Each model folder keeps its own scripts beside the code they measure (in a
//! `census.rs` of its own, which may reach its folder's internals) and lists them
//! in a `CENSUSES` table; [`all`] gathers the tables. Native only.

/// One measurement script.
#[derive(Clone, Copy, Debug)]
pub struct Census {
    /// The name `shoal-census` runs it by (kebab-case, unique).
    pub name: &'static str,
    /// What it measures and which document quotes it, in one line.
    pub about: &'static str,
    /// Runs it, printing its figures to standard output.
    pub run: fn(),
}

/// Every registered script, in the order `shoal-census` lists them.
pub fn all() -> Vec<&'static Census> {
    [
        crate::sim::body::census::CENSUSES,
        crate::sim::reef::census::CENSUSES,
        crate::sim::learning::census::CENSUSES,
        APP_CENSUSES,
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The scripts that measure the app around the simulation (the lab's skips,
/// the investigations, the frame builder); each lives in a `census.rs` beside
/// the code it measures.
const APP_CENSUSES: &[Census] = &[
    Census {
        name: "skip-moments",
        about: "when each reef demo's moment comes, seeds 1-4, and the minute after (lab/skip.rs)",
        run: crate::lab::census::skip_moments,
    },
    Census {
        name: "tail-beat-speeds",
        about: "the speeds 'How does a fish swim?' measures (docs/investigations.md)",
        run: crate::investigation::census::tail_beat_speeds,
    },
    Census {
        name: "frame-cost",
        about: "CPU time to build and copy a frame's fish instances, 5 000 and 20 000 fish (frame_builder.rs)",
        run: crate::render::census::frame_cost,
    },
];

/// The script called `name`.
pub fn find(name: &str) -> Option<&'static Census> {
    all().into_iter().find(|c| c.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn census_names_are_unique_and_kebab_case() {
        let names: Vec<&str> = all().iter().map(|c| c.name).collect();
        for (i, name) in names.iter().enumerate() {
            assert!(
                name.chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'),
                "{name} is not kebab-case"
            );
            assert!(!names[..i].contains(name), "{name} is registered twice");
        }
        assert!(find("no-such-census").is_none());
    }

    #[test]
    fn every_script_the_docs_quote_is_registered() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut pages = vec![root.join("README.md"), root.join("ARCHITECTURE.md")];
        let docs = std::fs::read_dir(root.join("docs")).expect("the docs folder");
        pages.extend(
            docs.flatten()
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|e| e == "md")),
        );
        let mut quoted = 0;
        for page in pages {
            let text = std::fs::read_to_string(&page).expect("a readable page");
            // `shoal-census -- NAME` and `shoal-census NAME`.
            for (at, _) in text.match_indices("shoal-census ") {
                let rest = text[at + "shoal-census ".len()..].trim_start_matches("-- ");
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '-')
                    .collect();
                if name.len() > 2 && !name.starts_with('-') {
                    quoted += 1;
                    assert!(
                        find(&name).is_some(),
                        "{} quotes shoal-census {name}, which is not registered",
                        page.display()
                    );
                }
            }
        }
        assert!(quoted > 10, "only {quoted} quoted scripts found");
    }
}
