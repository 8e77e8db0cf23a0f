//! The neighbour forces of the SIMBA boid layer (Lim & Tan; Reynolds 1987):
//! separation, alignment and cohesion among the neighbours a fish can see.
//!
//! A neighbour is seen when it is within the vision distance and inside the vision
//! angle: the field of view is a cone of half-angle `vision_angle_rad / 2` around
//! the heading, leaving a blind cone behind (a vision angle of 300° leaves a 60°
//! blind cone, as in Tu & Terzopoulos §5). Each force is a steering force in the
//! papers' form: desired velocity − current velocity, limited to the maximum force
//! (NOTES.md, "SIMBA steering").

use glam::Vec3;

use super::fish::Fish;
use super::spatial_grid::SpatialGrid;
use super::steering::limit;

/// What a fish perceives of its neighbours and how hard it may steer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Perception {
    /// How far a fish sees its neighbours, metres.
    pub vision_distance_m: f32,
    /// Full width of the field of view, radians (2π: no blind spot).
    pub vision_angle_rad: f32,
    /// Speed a fish steers towards, m/s.
    pub max_speed_m_per_s: f32,
    /// Largest steering acceleration, m/s².
    pub max_force_m_per_s2: f32,
}

/// Separation, alignment and cohesion for one fish.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NeighbourForces {
    pub separation_m_per_s2: Vec3,
    pub alignment_m_per_s2: Vec3,
    pub cohesion_m_per_s2: Vec3,
    /// How many neighbours the fish saw.
    pub neighbours: u32,
}

/// Is `other` inside the field of view of a fish at `position` heading `heading`?
pub fn sees(position_m: Vec3, heading: Vec3, other_m: Vec3, perception: &Perception) -> bool {
    let offset = other_m - position_m;
    let distance = offset.length();
    if !(distance > 0.0 && distance <= perception.vision_distance_m) {
        return false;
    }
    let half_angle = (perception.vision_angle_rad * 0.5).clamp(0.0, std::f32::consts::PI);
    heading.dot(offset / distance) >= half_angle.cos() - 1e-6
}

/// The three neighbour forces on `fish[i]`, looking up neighbours in `grid`
/// (built over the same positions with a cell of at least the vision distance).
///
/// - separation: away from each seen neighbour, weighted by 1/distance
///   (closer neighbours push harder), desired speed the maximum;
/// - alignment: towards the seen neighbours' mean heading, at the maximum speed;
/// - cohesion: seek the seen neighbours' centre.
pub fn neighbour_forces(
    fish: &[Fish],
    i: usize,
    grid: &SpatialGrid,
    perception: &Perception,
) -> NeighbourForces {
    let me = &fish[i];
    let heading = me.heading();
    let mut away = Vec3::ZERO;
    let mut velocity_sum = Vec3::ZERO;
    let mut position_sum = Vec3::ZERO;
    let mut neighbours = 0u32;
    grid.for_each_candidate(me.position_m, perception.vision_distance_m, |j| {
        if j == i || !sees(me.position_m, heading, fish[j].position_m, perception) {
            return;
        }
        let offset = me.position_m - fish[j].position_m;
        away += offset.normalize_or_zero() / offset.length().max(1e-3);
        velocity_sum += fish[j].velocity_m_per_s;
        position_sum += fish[j].position_m;
        neighbours += 1;
    });
    if neighbours == 0 {
        return NeighbourForces::default();
    }
    let n = neighbours as f32;
    let steer = |desired: Vec3| limit(desired - me.velocity_m_per_s, perception.max_force_m_per_s2);
    NeighbourForces {
        separation_m_per_s2: steer(away.normalize_or_zero() * perception.max_speed_m_per_s),
        alignment_m_per_s2: steer(velocity_sum.normalize_or_zero() * perception.max_speed_m_per_s),
        cohesion_m_per_s2: steer(
            (position_sum / n - me.position_m).normalize_or_zero() * perception.max_speed_m_per_s,
        ),
        neighbours,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PERCEPTION: Perception = Perception {
        vision_distance_m: 2.0,
        vision_angle_rad: 300f32.to_radians(),
        max_speed_m_per_s: 0.8,
        max_force_m_per_s2: 1.5,
    };

    fn grid_for(fish: &[Fish]) -> SpatialGrid {
        let mut grid = SpatialGrid::default();
        let positions: Vec<Vec3> = fish.iter().map(|f| f.position_m).collect();
        grid.rebuild(
            Vec3::new(-6.0, 0.0, -4.0),
            Vec3::new(6.0, 4.5, 4.0),
            2.0,
            &positions,
        );
        grid
    }

    #[test]
    fn a_neighbour_in_the_blind_cone_or_too_far_is_not_seen() {
        let p = Vec3::new(0.0, 2.0, 0.0);
        assert!(sees(p, Vec3::X, p + Vec3::X, &PERCEPTION), "ahead");
        assert!(sees(p, Vec3::X, p + Vec3::Z, &PERCEPTION), "beside");
        assert!(
            !sees(p, Vec3::X, p - Vec3::X, &PERCEPTION),
            "straight behind"
        );
        let behind_25_deg =
            p + Vec3::new(-(25f32.to_radians().cos()), 0.0, 25f32.to_radians().sin());
        assert!(
            !sees(p, Vec3::X, behind_25_deg, &PERCEPTION),
            "inside the 60° blind cone"
        );
        assert!(
            !sees(p, Vec3::X, p + Vec3::X * 2.5, &PERCEPTION),
            "beyond vision distance"
        );
    }

    #[test]
    fn separation_pushes_away_alignment_matches_and_cohesion_pulls_in() {
        let me = Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X * 0.5, 0.4, 0.0);
        let close = Fish::new(Vec3::new(0.5, 2.0, 0.3), Vec3::Z * 0.5, 0.4, 0.0);
        let far = Fish::new(Vec3::new(1.5, 2.0, 0.9), Vec3::Z * 0.5, 0.4, 0.0);
        let fish = [me, close, far];
        let f = neighbour_forces(&fish, 0, &grid_for(&fish), &PERCEPTION);
        assert_eq!(f.neighbours, 2);
        assert!(f.separation_m_per_s2.z < 0.0, "away from neighbours at +z");
        assert!(
            f.alignment_m_per_s2.z > 0.0,
            "turn towards the neighbours' +z heading"
        );
        assert!(
            f.cohesion_m_per_s2.z > 0.0,
            "towards the neighbours' centre"
        );
        for v in [
            f.separation_m_per_s2,
            f.alignment_m_per_s2,
            f.cohesion_m_per_s2,
        ] {
            assert!(v.length() <= PERCEPTION.max_force_m_per_s2 + 1e-5);
        }
    }

    #[test]
    fn a_lone_or_coincident_fish_feels_nothing_and_never_nan() {
        let lone = [Fish::new(Vec3::new(0.0, 2.0, 0.0), Vec3::X, 0.4, 0.0)];
        assert_eq!(
            neighbour_forces(&lone, 0, &grid_for(&lone), &PERCEPTION),
            NeighbourForces::default()
        );
        let twins = [lone[0], lone[0]];
        let f = neighbour_forces(&twins, 0, &grid_for(&twins), &PERCEPTION);
        assert!(f.separation_m_per_s2.is_finite() && f.cohesion_m_per_s2.is_finite());
    }
}
