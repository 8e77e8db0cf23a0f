//! Integration tests through the public API, as the app and `window.shoal` drive it:
//! whatever a teacher or a script does, the run is reproducible, no fish leaves the
//! tank or enters a rock, and nothing becomes NaN.

use serde_json::json;
use shoal::automation::{Command, StateReport};
use shoal::lab::Lab;
use shoal::settings::Settings;

fn assert_sound(lab: &Lab) {
    for run in lab.runs() {
        if let Some(world) = run.scene().boids() {
            assert_world_sound(world);
        }
        let metrics = run.metrics();
        assert!(
            metrics.polarization.is_finite()
                && metrics.milling.is_finite()
                && metrics.nnd_body_lengths.is_finite()
                && metrics.mean_speed.is_finite(),
            "{metrics:?}"
        );
    }
}

fn assert_world_sound(world: &shoal::sim::World) {
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
            Command::Set(json!({"left": {"fish_count": 300}, "speed": 4})),
            Command::Step(600),
            Command::Set(json!({"scene": "boids", "compare": true, "right": {"fish_count": 50}})),
            Command::Step(300),
            Command::Set(json!({"left": {"mode": "monte_carlo", "cohesion": 70}})),
            Command::Step(300),
            Command::Reset(Some(9)),
            Command::Step(450),
        ] {
            command.execute(lab).unwrap();
        }
        lab.runs()
            .iter()
            .flat_map(|run| run.scene().boids().unwrap().fish().iter())
            .map(|f| (f.position_m, f.velocity_m_per_s))
            .collect::<Vec<_>>()
    };
    let a = lesson(&mut Lab::new(Settings::default()));
    let b = lesson(&mut Lab::new(Settings::default()));
    assert_eq!(a, b);
}

#[test]
fn fish_stay_in_the_tank_and_out_of_rocks_at_every_setting() {
    for (fish_count, speed, seed, scene) in [
        (1, 0.25, 0u64, "aquarium"),
        (200, 1.0, 1, "aquarium"),
        (2_000, 8.0, 4_294_967_295, "aquarium"),
        (1, 0.25, 0, "boids"),
        (300, 2.0, 3, "boids"),
        (2_000, 8.0, 4_294_967_295, "boids"),
    ] {
        let mut lab = Lab::new(Settings::default());
        Command::Set(json!({
            "speed": speed, "seed": seed, "scene": scene, "compare": scene == "boids",
            "left": {"fish_count": fish_count}, "right": {"fish_count": fish_count},
        }))
        .execute(&mut lab)
        .unwrap();
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
    for scene in ["aquarium", "boids"] {
        let mut lab = Lab::new(Settings::default());
        Command::Set(json!({"scene": scene, "left": {"fish_count": 20_000}}))
            .execute(&mut lab)
            .unwrap();
        lab.step(30);
        assert_sound(&lab);
    }
}

#[test]
fn compare_mode_starts_both_tanks_from_the_same_fish_and_they_part_ways() {
    let mut lab = Lab::new(Settings::default());
    Command::Set(json!({"scene": "boids", "compare": true}))
        .execute(&mut lab)
        .unwrap();
    let [left, right] = lab.runs() else {
        panic!("compare mode shows two tanks");
    };
    assert_eq!(
        left.scene().boids().unwrap().fish(),
        right.scene().boids().unwrap().fish(),
        "same seed, same starting positions"
    );
    // A minute: the group school forms within it (docs/boids.md).
    Command::Step(3600).execute(&mut lab).unwrap();
    let left = lab.runs()[0].metrics();
    let right = lab.runs()[1].metrics();
    assert_eq!(left.time_secs, right.time_secs, "one clock for both tanks");
    assert!(
        right.polarization > left.polarization + 0.2,
        "the group tank (right) lines up more than the solitary one: {} vs {}",
        right.polarization,
        left.polarization
    );
    let state = serde_json::to_value(StateReport::new(&lab, "native", 0.0)).unwrap();
    assert!(state["metrics_right"]["polarization"].is_number());
    assert_eq!(state["compare"], true);
    // Switching compare off keeps one tank.
    Command::Set(json!({"compare": false}))
        .execute(&mut lab)
        .unwrap();
    assert_eq!(lab.runs().len(), 1);
    let csv = lab.metrics_csv();
    assert!(csv.starts_with("tank,time_s,polarization"));
}

/// Every node of every physical animal is finite, in the tank and out of the rocks.
fn assert_physics_sound(lab: &Lab) {
    let run = &lab.runs()[0];
    let Some(physics) = run.scene().physics() else {
        panic!("not the physics scene");
    };
    for (i, animal) in physics.animals().iter().enumerate() {
        for p in animal.nodes_m() {
            assert!(p.is_finite(), "animal {i} is not finite");
            assert!(physics.tank().contains(p, 0.0), "animal {i} left the tank");
            for obstacle in physics.obstacles() {
                assert!(
                    obstacle.signed_distance_m(p) > -0.02,
                    "animal {i} is inside a rock"
                );
            }
        }
    }
}

#[test]
fn physical_fish_are_reproducible_finite_and_stay_in_the_tank_whatever_the_teacher_does() {
    let lesson = |lab: &mut Lab| {
        let mut checks = 0;
        for command in [
            Command::Set(json!({"scene": "physics", "seed": 5, "speed": 8,
                "physics": {"fish_count": 12, "sharks": 2, "current_m_per_s": 0.3}})),
            Command::Step(400),
            Command::Set(json!({"physics": {"behaviour": "wander", "selected": 3,
                "hand_control": true, "hand_speed": 1.0, "hand_pitch_deg": 28}})),
            Command::Step(300),
            Command::Turn(-180.0),
            Command::Step(300),
            Command::Set(json!({"physics": {"behaviour": "drift", "fish_count": 5,
                "hand_pitch_deg": -28}})),
            Command::Step(300),
        ] {
            command.execute(lab).unwrap();
            assert_physics_sound(lab);
            checks += 1;
        }
        assert_eq!(checks, 8);
        // Frames of very different lengths, as a struggling machine delivers them.
        for frame in 0..100 {
            let frame_secs = [0.001, 0.016, 0.05, 0.3, 2.0][frame % 5];
            lab.advance_frame(frame_secs, frame as f64 * 0.05);
        }
        assert_physics_sound(lab);
        lab.runs()[0]
            .scene()
            .physics()
            .unwrap()
            .animals()
            .iter()
            .flat_map(|a| a.nodes_m())
            .map(|p| p.to_array().map(f32::to_bits))
            .collect::<Vec<_>>()
    };
    let a = lesson(&mut Lab::new(Settings::default()));
    let b = lesson(&mut Lab::new(Settings::default()));
    assert_eq!(a, b);
}
