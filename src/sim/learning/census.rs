//! This folder's measurement scripts (see [`crate::census`]).

use std::time::Instant;

use crate::census::Census;
use crate::sim::body::BodyParams;
use crate::sim::body::physical_fish::BodySpecies;
use crate::sim::learning::learned_motor::{
    MEASURE_SECS, measure_hand_tuned_swim, measure_motion_with,
};
use crate::sim::learning::race::PAPER_RACE_STEPS;
use crate::sim::learning::*;

/// The scripts, in the order `shoal-census` lists them.
pub const CENSUSES: &[Census] = &[Census {
    name: "learning-figures",
    about: "the shipped set, the learned motor, the buoy run and a shark's training and race (docs/learning.md; about a minute)",
    run: learning_figures,
}];

/// The figures of `docs/learning.md`, printed (not asserted; the behaviours are
/// asserted by the tests of each module): the shipped set's drills, the
/// hand-tuned swim-MC against the learned motor at several speeds and turns, the
/// buoys reached, and a shark trained for 6840 evaluations racing its
/// checkpoints.
fn learning_figures() {
    let set = LearnedControllerSet::pretrained().expect("shipped set");
    println!("Shipped set (fish, default setup, 6840 steps per drill):");
    for d in &set.drills {
        let c = &d.controller;
        let freqs: Vec<String> = c
            .controller
            .modes
            .iter()
            .map(|m| format!("{:.2}", m.frequency_hz))
            .collect();
        println!(
            "{:?}: E {:.3}, modes {} Hz, energy {:.3} (ac {:.3}), speed {:.3} BL/s, turn {:.1} °/s",
            c.task,
            d.objective,
            freqs.join("/"),
            c.controller.energy_fraction,
            c.controller.ac_energy_fraction,
            c.motion.speed_body_lengths_per_sec,
            c.motion.turn_rate_deg_per_sec
        );
    }
    let params = BodyParams::default();
    let map = set.motor_map().expect("map");
    let hand = measure_hand_tuned_swim(1.0, BodySpecies::Fish, params, MEASURE_SECS);
    println!("hand-tuned swim-MC at full speed: {hand:?}");
    for (speed, turn) in [
        (1.0, 0.0),
        (0.5, 0.0),
        (0.25, 0.0),
        (1.0, 0.5),
        (1.0, 1.0),
        (1.0, -0.5),
        (1.0, -1.0),
    ] {
        let motor = LearnedMotor::new(map.clone());
        let m = measure_motion_with(BodySpecies::Fish, params, MEASURE_SECS, |t| {
            motor.muscles_at(speed, turn, t)
        });
        println!("learned motor speed {speed}, turn {turn}: {m:?}");
    }
    let l = BodySpecies::Fish.body_length_m();
    let buoys = [
        glam::Vec3::new(8.0 * l, 2.0 * l, 0.0),
        glam::Vec3::new(l, 4.0 * l, 0.0),
    ];
    let mut tracker = BuoyTracker::new(map, BodySpecies::Fish, params, buoys);
    tracker.run_until_both_reached(300.0);
    println!("buoys reached at {:?} s", tracker.reached_secs());

    let setup = TrainingSetup {
        species: BodySpecies::Shark,
        ..TrainingSetup::default()
    };
    let mut trainer = Trainer::new(setup, AnnealingSchedule::default(), 1);
    trainer.set_checkpoints(&PAPER_RACE_STEPS);
    let start = trainer.best_evaluation().objective;
    let t0 = Instant::now();
    trainer.run_evaluations(6840);
    let secs = t0.elapsed().as_secs_f64();
    println!(
        "shark SWIM_FAR: E {start:.3} -> {:.3}, {:.0} evaluations/s",
        trainer.best_evaluation().objective,
        6840.0 / secs
    );
    for c in trainer.checkpoints() {
        println!("  checkpoint {}: E {:.3}", c.evaluations, c.objective);
    }
    for laps in [1.0, 3.0] {
        let mut race = Race::new(
            RaceEntrant::from_checkpoints(trainer.checkpoints()),
            BodySpecies::Shark,
            setup.body,
        );
        race.run(laps * setup.simulated_secs());
        let d: Vec<String> = race
            .distances_m()
            .iter()
            .map(|d| format!("{d:.3}"))
            .collect();
        println!("race over {:.2} s: {} m", race.time_secs(), d.join(", "));
    }
}
