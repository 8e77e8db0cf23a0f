//! The investigations' measurement script (see [`crate::census`]): the speeds
//! *How does a fish swim?* measures, quoted by `docs/investigations.md`.

use super::catalogue::{MeasurementKind, find};
use super::measure::TailBeatRun;

/// The speeds *How does a fish swim?* measures (the figures of
/// `docs/investigations.md`): its tail-beat run played to the end, body lengths
/// per second at each frequency.
pub(crate) fn tail_beat_speeds() {
    let MeasurementKind::TailBeat {
        frequencies_hz,
        secs,
    } = find("how-swim")
        .expect("a catalogued investigation")
        .measurement
    else {
        panic!("how-swim measures tail beats");
    };
    let mut run = TailBeatRun::new(frequencies_hz, secs);
    run.run_to_end();
    for (f, v) in frequencies_hz.iter().zip(run.speeds()) {
        println!("{f} Hz: {v:.3} body lengths/s");
    }
}
