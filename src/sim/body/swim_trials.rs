//! Measured swims of a bare body ([`FishBody`] driven by the swim-MC, no bridge):
//! the runs the body's tests assert on and its census scripts print
//! (`sim/body/census.rs`), kept in one place so both measure the same way.
//! Native only.

use glam::Vec3;

use crate::sim::body::{
    BodyCommand, BodyParams, ControlSampling, FishBody, PectoralFins, SwimMc, SwimParams,
};

/// Length of the measured fish in metres: the paper's 26 units, so numbers read
/// as paper units.
pub const LENGTH_M: f32 = 26.0;

/// Swims `fish` for `secs` with fixed swim-MC parameters and fins, the controller
/// sampled as `sampling` says; returns the fish and its centre of mass at the
/// half-way time.
pub fn swim_sampled(
    mut fish: FishBody,
    params: SwimParams,
    fins: PectoralFins,
    secs: f32,
    sampling: ControlSampling,
) -> (FishBody, Vec3) {
    let mut mc = SwimMc::default();
    let dt = fish.dt_secs();
    let steps = (secs / dt) as usize;
    let mut half = Vec3::ZERO;
    for k in 0..steps {
        match sampling {
            ControlSampling::PerStep => fish.step(
                &BodyCommand {
                    muscle_contractions: mc.muscles_at(&params, dt),
                    fins,
                },
                Vec3::ZERO,
            ),
            ControlSampling::PerSubstep => {
                fish.step_with(&fins, Vec3::ZERO, |t| mc.muscles_at(&params, t));
            }
        }
        mc.advance(&params, dt);
        if k + 1 == steps / 2 {
            half = fish.centre_of_mass_m();
        }
    }
    (fish, half)
}

/// Mean forward speed of the default body over the second half of a 60 s run,
/// body lengths per second.
pub fn speed_bl_per_s(params: SwimParams) -> f32 {
    speed_with(params, BodyParams::default(), ControlSampling::default())
}

/// [`speed_bl_per_s`] on a body with `body` parameters, the controller sampled as
/// `sampling` says.
pub fn speed_with(params: SwimParams, body: BodyParams, sampling: ControlSampling) -> f32 {
    let fish = FishBody::with_params(LENGTH_M, Vec3::ZERO, Vec3::X, body);
    let (fish, half) = swim_sampled(fish, params, PectoralFins::NEUTRAL, 60.0, sampling);
    (fish.centre_of_mass_m() - half).x / 30.0 / LENGTH_M
}

/// Swim-MC parameters with the same `amplitude` and `frequency_hz` for both
/// segments.
pub fn with(amplitude: f32, frequency_hz: f32) -> SwimParams {
    SwimParams {
        anterior_amplitude: amplitude,
        anterior_frequency_hz: frequency_hz,
        posterior_amplitude: amplitude,
        posterior_frequency_hz: frequency_hz,
    }
}

/// Top speed (the swim-MC's maximal parameters, body lengths/s) and the heading
/// change of the four key turns of `SteeringMap::DEFAULT` (30/45/60/90°, left,
/// degrees) on a body with `body` parameters, the controllers sampled as
/// `sampling` says.
pub fn resolution_row(body: BodyParams, sampling: ControlSampling) -> (f32, [f32; 4]) {
    use crate::sim::body::turn_mc::{SteeringMap, TurnDirection, measure_turn_deg_with};
    let top = speed_with(SwimParams::MAX, body, sampling);
    let turns = SteeringMap::DEFAULT
        .keys
        .map(|(_, p)| measure_turn_deg_with(p, TurnDirection::Left, body, sampling));
    (top, turns)
}
