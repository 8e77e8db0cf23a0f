//! What the confusion effect and joint flight do for a school: the figures of
//! `docs/departures.md` and the *Why do fish school?* prompt after the reveal.
//!
//! ```sh
//! cargo run --release --example confusion_switch            # seeds 41–50
//! cargo run --release --example confusion_switch -- 11 20   # other seeds
//! ```
//!
//! Each run is the investigation's own setup (40 fish and one shark in each
//! tank, *Individual* on the left, *Group* on the right, 180 simulated
//! seconds) on a seed the investigation does not use, with the switches as
//! named; it prints the sharks' catches in each tank.

use shoal::investigation::catalogue::INVESTIGATIONS;
use shoal::investigation::setup_settings;
use shoal::lab::Lab;

fn catches(seed: u64, confusion: bool, joint_flight: bool) -> (u64, u64) {
    let inv = INVESTIGATIONS
        .iter()
        .find(|i| i.id == "why-school")
        .expect("the why-school investigation");
    let mut settings = setup_settings(inv).expect("its setup applies");
    settings.seed = seed;
    settings.predation.confusion = confusion;
    settings.predation.joint_flight = joint_flight;
    let mut lab = Lab::new(settings);
    let steps = (180.0 / lab.step_secs()).round() as u32;
    lab.step(steps);
    let c = |i: usize| {
        lab.runs()[i]
            .scene()
            .boids()
            .expect("a boid tank")
            .catches()
    };
    (c(0), c(1))
}

fn main() {
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let (first, last) = match args.as_slice() {
        [a, b] => (*a, *b),
        _ => (41, 50),
    };
    println!("| seed | switches | loners caught | school caught |");
    println!("| --- | --- | --- | --- |");
    let cases = [
        ("both on", true, true),
        ("confusion off", false, true),
        ("joint flight off", true, false),
        ("paper only", false, false),
    ];
    let mut totals = [(0, 0, 0); 4];
    for seed in first..=last {
        for (k, (name, confusion, joint)) in cases.iter().enumerate() {
            let (loners, school) = catches(seed, *confusion, *joint);
            totals[k].0 += loners;
            totals[k].1 += school;
            if school < loners {
                totals[k].2 += 1;
            }
            println!("| {seed} | {name} | {loners} | {school} |");
        }
    }
    let n = last - first + 1;
    println!();
    println!("| switches | loners caught | school caught | tanks where the school lost fewer |");
    println!("| --- | --- | --- | --- |");
    for (k, (name, _, _)) in cases.iter().enumerate() {
        let (l, s, fewer) = totals[k];
        println!("| {name} | {l} | {s} | {fewer} of {n} |");
    }
}
