//! Fish without the boid layer: they wander, swim several body lengths and
//! spread through the tank.

use glam::Vec3;

use super::world;

#[test]
fn fish_swim_several_body_lengths_in_ten_seconds() {
    let mut w = world(3, 200);
    let start: Vec<Vec3> = w.fish().iter().map(|f| f.position_m).collect();
    for _ in 0..600 {
        w.step();
    }
    let n = w.fish().len() as f32;
    let mean_displacement_m: f32 = w
        .fish()
        .iter()
        .zip(&start)
        .map(|(f, p)| f.position_m.distance(*p))
        .sum::<f32>()
        / n;
    let mean_body_length_m: f32 = w.fish().iter().map(|f| f.body_length_m).sum::<f32>() / n;
    assert!(
        mean_displacement_m > 5.0 * mean_body_length_m,
        "mean displacement {mean_displacement_m} m"
    );
}

#[test]
fn fish_released_at_one_end_spread_through_the_tank_within_a_minute() {
    // Twenty fish let go together near the left glass, low in the water.
    let mut w = world(5, 20);
    let release_m = Vec3::new(w.tank().min_m.x + 0.6, 1.5, w.tank().center_m().z);
    for fish in w.fish_mut() {
        fish.position_m = release_m;
    }
    // Coarse grid: 4 cells along x, 2 in height, 3 along z.
    let cells = [4usize, 2, 3];
    let mut visited = [[[false; 3]; 2]; 4];
    for _ in 0..3_600 {
        w.step();
        for fish in w.fish() {
            let u = (fish.position_m - w.tank().min_m) / w.tank().size_m();
            let cell = |axis: usize| ((u[axis] * cells[axis] as f32) as usize).min(cells[axis] - 1);
            visited[cell(0)][cell(1)][cell(2)] = true;
        }
    }
    let count = visited.iter().flatten().flatten().filter(|v| **v).count();
    assert!(count >= 18, "visited only {count} of 24 cells");
}
