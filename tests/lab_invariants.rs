//! Integration tests through the public API, as the app and `window.shoal` drive it:
//! whatever a teacher or a script does, the run is reproducible, no fish leaves the
//! tank or enters a rock, and nothing becomes NaN.

use serde_json::json;
use shoal::automation::{Command, StateReport};
use shoal::lab::Lab;
use shoal::settings::Settings;

fn assert_sound(lab: &Lab) {
    let world = lab.world();
    for (i, fish) in world.fish().iter().enumerate() {
        assert!(
            fish.position_m.is_finite() && fish.velocity_m_per_s.is_finite(),
            "fish {i} is not finite"
        );
        assert!(
            world.tank().contains(fish.position_m, 0.0),
            "fish {i} left the tank"
        );
        for obstacle in world.obstacles() {
            assert!(
                obstacle.signed_distance_m(fish.position_m) >= 0.0,
                "fish {i} is inside a rock"
            );
        }
    }
}

#[test]
fn a_scripted_lesson_is_reproducible_to_the_bit() {
    let lesson = |lab: &mut Lab| {
        for command in [
            Command::Set(json!({"fish_count": 300, "speed": 4})),
            Command::Step(600),
            Command::Set(json!({"fish_count": 50})),
            Command::Step(300),
            Command::Reset(Some(9)),
            Command::Step(450),
        ] {
            command.execute(lab).unwrap();
        }
        lab.world()
            .fish()
            .iter()
            .map(|f| (f.position_m, f.velocity_m_per_s))
            .collect::<Vec<_>>()
    };
    let a = lesson(&mut Lab::new(Settings::default()));
    let b = lesson(&mut Lab::new(Settings::default()));
    assert_eq!(a, b);
}

#[test]
fn fish_stay_in_the_tank_and_out_of_rocks_at_every_setting() {
    for (fish_count, speed, seed) in [(1, 0.25, 0), (200, 1.0, 1), (2_000, 8.0, 4_294_967_295)] {
        let mut lab = Lab::new(Settings {
            fish_count,
            speed,
            seed,
            ..Settings::default()
        });
        // Frames of very different lengths, as a struggling machine delivers them.
        for frame in 0..300 {
            let frame_secs = [0.001, 0.016, 0.05, 0.3, 2.0][frame % 5];
            lab.advance_frame(frame_secs, frame as f64 * 0.05);
            if frame % 10 == 0 {
                assert_sound(&lab);
            }
        }
        assert_sound(&lab);
        let state = StateReport::new(&lab, "native", 0.0);
        assert!(state.time_secs > 0.0);
        assert!(state.time_secs.is_finite());
    }
}

#[test]
fn twenty_thousand_fish_step_without_nan() {
    let mut lab = Lab::new(Settings {
        fish_count: 20_000,
        ..Settings::default()
    });
    lab.step(30);
    assert_sound(&lab);
}
