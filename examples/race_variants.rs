//! Why the race's last two sharks finish close, and what widens the gap: the
//! figures of `docs/learning.md`, "The race: why the last sharks are close".
//!
//! ```sh
//! cargo run --release --example race_variants
//! ```
//!
//! For the default learning setup and three variants (twice the control samples,
//! a three times slower cooling schedule, one sample per annealing move), seeds 1
//! and 2: the best E at the paper's race checkpoints (90 … 6840 annealing steps),
//! the race over one training interval, and how much farther the 6840-step shark
//! swims than the 5490-step one.
use shoal::sim::BodySpecies;
use shoal::sim::learning::{
    AnnealingSchedule, PAPER_RACE_STEPS, Race, RaceEntrant, Trainer, TrainingSetup,
};
fn main() {
    let base = TrainingSetup {
        species: BodySpecies::Shark,
        ..TrainingSetup::default()
    };
    let variants: Vec<(&str, TrainingSetup, AnnealingSchedule)> = vec![
        ("default", base, AnnealingSchedule::default()),
        (
            "N=30 samples",
            TrainingSetup {
                sample_count: 30,
                ..base
            },
            AnnealingSchedule::default(),
        ),
        (
            "schedule K=20000",
            base,
            AnnealingSchedule {
                planned_evaluations: 20000,
                ..AnnealingSchedule::default()
            },
        ),
        (
            "1 sample per move",
            base,
            AnnealingSchedule {
                entries_per_move: 1,
                ..AnnealingSchedule::default()
            },
        ),
    ];
    for (name, setup, schedule) in variants {
        for seed in [1u64, 2] {
            let mut t = Trainer::new(setup, schedule, seed);
            t.set_checkpoints(&PAPER_RACE_STEPS);
            t.run_evaluations(6840);
            let es: Vec<String> = t
                .checkpoints()
                .iter()
                .map(|c| format!("{:.3}", c.objective))
                .collect();
            let mut race = Race::new(
                RaceEntrant::from_checkpoints(t.checkpoints()),
                BodySpecies::Shark,
                setup.body,
            );
            race.run(setup.simulated_secs());
            let d = race.distances_m();
            let ds: Vec<String> = d.iter().map(|x| format!("{x:.3}")).collect();
            println!(
                "{name} seed {seed}: E [{}] race m [{}] 6840 vs 5490: {:+.1} %",
                es.join(", "),
                ds.join(", "),
                100.0 * (d[5] / d[4] - 1.0)
            );
        }
    }
}
