//! The lab's measurement script (see [`crate::census`]): when each reef demo's
//! moment comes, for the skip's lead and limit (`lab/skip.rs`).

use super::Lab;
use crate::settings::{Scene, Settings};
use crate::sim::reef::demos::ReefScene;
use crate::sim::reef::events::ReefEventKind;

/// Prints when each demo's moment comes on the default (muscle) bodies, seeds
/// 1–4: the skip's outcome, then the events of the minute after it (escapes,
/// meals and intentions left out).
pub(crate) fn skip_moments() {
    for d in ReefScene::ALL {
        for seed in 1..=4 {
            let mut lab = reef_demo_lab(d, seed);
            lab.skip_to_moment().expect("every reef demo has a moment");
            let outcome = lab.finish_skip_now();
            println!("{d:?} seed {seed}: {outcome:?}");
            lab.step((60.0 / lab.step_secs()) as u32);
            for e in lab.runs()[0].scene().reef().expect("a reef demo").events() {
                if !matches!(
                    e.kind,
                    ReefEventKind::BeganEscape { .. }
                        | ReefEventKind::AteFood { .. }
                        | ReefEventKind::Intention { .. }
                ) {
                    println!("    {:6.1} s  {}", e.time_secs, e.text);
                }
            }
        }
    }
}

/// A lab on the reef's `demo` with `seed`, the rest default: the runs the
/// skip's tests and its census script (`skip-moments`, below) skip
/// through.
pub(crate) fn reef_demo_lab(demo: ReefScene, seed: u64) -> Lab {
    let mut settings = Settings {
        scene: Scene::Reef,
        seed,
        ..Settings::default()
    };
    settings.reef.demo = demo;
    Lab::new(settings)
}
