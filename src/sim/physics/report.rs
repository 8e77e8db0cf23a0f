//! The physics tank's part of `shoal.state()`: counts and the selected fish in
//! detail.

use serde::Serialize;

use super::world::PhysicsWorld;

/// The physics scene as `shoal.state().physics` reports it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PhysicsReport {
    /// Muscle-driven fish and sharks.
    pub fish: usize,
    pub sharks: usize,
    /// Node moves made by the hard rule (glass and rocks) since the start.
    pub constraint_moves: u64,
    /// The selected animal, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub selected: Option<SelectedFishReport>,
}

/// One physical fish, in the tank frame (y up), SI units.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SelectedFishReport {
    pub index: usize,
    pub species: &'static str,
    pub body_length_m: f32,
    /// Length along the spine over the rest length (1 when relaxed).
    pub length_ratio: f32,
    pub position_m: [f32; 3],
    pub velocity_m_per_s: [f32; 3],
    pub speed_m_per_s: f32,
    /// Where the fore body points, averaged over a tail beat (unit).
    pub heading: [f32; 3],
    /// The velocity the steering layer (or the hand command) asked for.
    pub desired_velocity_m_per_s: [f32; 3],
    /// swim-MC speed, fraction of the top speed.
    pub swim_speed_fraction: f32,
    pub turning: bool,
    /// Pectoral fin angles θ, radians (π/2 flat, π brake).
    pub fin_left_rad: f32,
    pub fin_right_rad: f32,
    /// The 12 muscle contractions in [0, 1]: anterior, middle, posterior
    /// segment; each left dorsal, left ventral, right dorsal, right ventral.
    pub muscles: [f32; crate::sim::body::MUSCLE_COUNT],
    /// The water current at the fish.
    pub water_m_per_s: [f32; 3],
    /// Is the teacher driving it?
    pub hand_control: bool,
}

impl PhysicsWorld {
    /// What `shoal.state().physics` reports, with `selected` in detail.
    pub fn report(&self, selected: Option<u32>) -> PhysicsReport {
        let physics = self;
        let selected = selected.and_then(|i| {
            let index = i as usize;
            let a = physics.animals().get(index)?;
            Some(SelectedFishReport {
                index,
                species: a.species.name(),
                body_length_m: a.body_length_m(),
                length_ratio: a.body().spine_length_m() / a.body_length_m(),
                position_m: a.point.position_m.to_array(),
                velocity_m_per_s: a.point.velocity_m_per_s.to_array(),
                speed_m_per_s: a.point.velocity_m_per_s.length(),
                heading: a.heading().to_array(),
                desired_velocity_m_per_s: physics.desired_m_per_s(index).to_array(),
                swim_speed_fraction: a.motor().speed_fraction,
                turning: a.is_turning(),
                fin_left_rad: a.motor().fins.left_angle_rad,
                fin_right_rad: a.motor().fins.right_angle_rad,
                muscles: a.motor().muscles,
                water_m_per_s: physics.water_at(a.point.position_m).to_array(),
                hand_control: physics.hand_controlled() == Some(index),
            })
        });
        PhysicsReport {
            fish: physics.fish_count(),
            sharks: physics.shark_count(),
            constraint_moves: physics.constraint_moves(),
            selected,
        }
    }
}
