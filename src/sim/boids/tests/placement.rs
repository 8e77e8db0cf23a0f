//! Placement: the seed's rocks, pillars and ledges, a teacher's layout and
//! edits (checked, and every animal pushed out at once), the obstacles' JSON,
//! and spawning sharks and stingrays.

use glam::{Vec2, Vec3};

use super::{assert_all_fish_legal, seed_with_a_ledge, world};
use crate::sim::boids::placement::{OBSTACLE_GAP_M, footprint};
use crate::sim::boids::world::{World, WorldConfig};
use crate::sim::common::obstacle::{Obstacle, WALL_CLEARANCE_M};

#[test]
fn default_scene_has_4_to_6_rocks_2_to_3_pillars_and_0_to_1_ledge_that_do_not_overlap() {
    let mut ledges_seen = 0;
    for seed in 0..20 {
        let w = world(seed, 0);
        let count = |f: fn(&Obstacle) -> bool| w.obstacles().iter().filter(|o| f(o)).count();
        let rocks = count(|o| matches!(o, Obstacle::Rock { .. }));
        let pillars = count(|o| matches!(o, Obstacle::Cylinder { .. }));
        let ledges = count(|o| matches!(o, Obstacle::Polygon { .. }));
        assert!((4..=6).contains(&rocks), "seed {seed}");
        assert!((2..=3).contains(&pillars), "seed {seed}");
        assert!(ledges <= 1, "seed {seed}");
        ledges_seen += ledges;
        for o in w.obstacles() {
            assert_eq!(o.validate(w.tank()), Ok(()), "seed {seed}");
        }
        for (i, a) in w.obstacles().iter().enumerate() {
            let (ca, ra) = footprint(a);
            // Far enough from the glass (checked at mid-height).
            let middle_m = Vec3::new(ca.x, w.tank().center_m().y, ca.y);
            assert!(w.tank().contains(middle_m, ra + WALL_CLEARANCE_M - 1e-4));
            for b in &w.obstacles()[i + 1..] {
                let (cb, rb) = footprint(b);
                assert!(ca.distance(cb) >= ra + rb + OBSTACLE_GAP_M);
            }
        }
    }
    assert!(ledges_seen > 0, "no seed placed a reef ledge");
}

#[test]
fn obstacles_round_trip_through_json_with_a_kind_tag() {
    let w = world(seed_with_a_ledge(), 0);
    let json = serde_json::to_string(w.obstacles()).unwrap();
    assert!(json.contains(r#""kind":"rock""#), "{json}");
    assert!(json.contains(r#""kind":"polygon""#), "{json}");
    assert!(json.contains("footprint_m") && json.contains("radius_m"));
    let back: Vec<Obstacle> = serde_json::from_str(&json).unwrap();
    assert_eq!(back, w.obstacles());
    let config: WorldConfig = serde_json::from_str(r#"{"seed": 5}"#).unwrap();
    assert_eq!(
        config,
        WorldConfig {
            seed: 5,
            ..WorldConfig::default()
        }
    );
    let default = WorldConfig::default();
    assert_eq!(
        (default.fish_count, default.sharks, default.stingrays),
        (200, 0, 0)
    );
    assert!(default.obstacles.is_none());
}

#[test]
fn a_teachers_layout_is_used_exactly_and_survives_a_reset() {
    let layout = vec![
        Obstacle::Rock {
            center_m: Vec3::new(0.0, -0.2, 0.0),
            radius_m: 0.8,
        },
        Obstacle::Polygon {
            footprint_m: vec![
                Vec2::new(2.0, 1.0),
                Vec2::new(4.0, 1.0),
                Vec2::new(3.0, 2.5),
            ],
            base_y_m: 0.0,
            height_m: 1.0,
        },
    ];
    let mut w = World::new(WorldConfig {
        obstacles: Some(layout.clone()),
        ..WorldConfig::default()
    });
    assert_eq!(w.obstacles(), &layout[..]);
    assert_all_fish_legal(&w);
    w.reset(9);
    assert_eq!(w.obstacles(), &layout[..]);
}

#[test]
fn adding_moving_and_removing_obstacles_keeps_every_fish_outside() {
    let mut w = world(4, 1_000);
    w.set_species_counts(0, 3);
    for _ in 0..30 {
        w.step();
    }
    // A big rock dropped into the middle of the school.
    let rock = Obstacle::Rock {
        center_m: w.tank().center_m() * Vec3::new(1.0, 0.0, 1.0),
        radius_m: 1.4,
    };
    let before = w.obstacles().len();
    match w.add_obstacle(rock) {
        Ok(index) => {
            assert_eq!(index, before);
            assert_all_fish_legal(&w);
            // Moving it sweeps through more fish; they are pushed out at once.
            if w.move_obstacle(index, Vec2::new(-3.5, 1.5)).is_ok() {
                assert_all_fish_legal(&w);
            }
            assert!(w.remove_obstacle(index));
        }
        Err(reason) => assert!(reason.to_string().contains("too close"), "{reason}"),
    }
    assert!(!w.remove_obstacle(99));
    assert!(w.move_obstacle(99, Vec2::ZERO).is_err());
    // Invalid obstacles are refused with a reason and change nothing.
    let count = w.obstacles().len();
    let outside = Obstacle::Cylinder {
        base_center_m: Vec3::new(5.8, 0.0, 0.0),
        radius_m: 0.3,
        height_m: 2.0,
    };
    assert!(
        w.add_obstacle(outside)
            .unwrap_err()
            .to_string()
            .contains("glass")
    );
    assert_eq!(w.obstacles().len(), count);
    // A whole new layout: a ledge across the middle.
    w.set_obstacles(vec![Obstacle::Polygon {
        footprint_m: vec![
            Vec2::new(-3.0, -1.0),
            Vec2::new(3.0, -1.0),
            Vec2::new(3.0, 1.0),
            Vec2::new(-3.0, 1.0),
        ],
        base_y_m: 0.0,
        height_m: 2.0,
    }]);
    assert_eq!(w.obstacles().len(), 1);
    assert_all_fish_legal(&w);
    for _ in 0..120 {
        w.step();
        assert_all_fish_legal(&w);
    }
}

#[test]
fn species_counts_are_capped_and_spawned_legally() {
    let mut w = world(6, 100);
    w.set_species_counts(50, 50);
    assert_eq!((w.sharks().len(), w.stingrays().len()), (10, 20));
    assert_all_fish_legal(&w);
    w.set_species_counts(1, 2);
    assert_eq!((w.sharks().len(), w.stingrays().len()), (1, 2));
    for s in w.sharks() {
        let length_m = s.body.body_length_m;
        assert!((1.5..=2.0).contains(&length_m));
    }
}
