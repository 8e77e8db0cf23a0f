//! Behavioural specifications of the fish body (Tu & Terzopoulos 1994 §3) and of
//! the physical fish that drives it through the bridge, by topic: it swims under
//! the swim-MC and speed follows amplitude and frequency (`swimming`); it rests
//! without input and survives long random use (`integrity`); its results do not
//! hang on the time step (`convergence`); its pectoral fins pitch, brake, yaw and
//! roll it (`fins`) and trim it (`trim`); the turn-MC turns it by the angle asked
//! for, to either side (`turning`); the bridge steers it to a target (`steering`).
//! All runs are deterministic (fixed seeds, fixed step). The runs the census
//! scripts share live in `body::swim_trials` and `physical_fish::trials`.

mod convergence;
mod fins;
mod integrity;
mod steering;
mod swimming;
mod trim;
mod turning;

use glam::Vec3;

use crate::sim::body::swim_trials::{LENGTH_M, swim_sampled};
use crate::sim::body::{ControlSampling, FishBody, PectoralFins, SwimParams};

/// Swims for `secs` with fixed parameters and fins; returns the fish and its centre
/// of mass at the half-way time.
fn swim(params: SwimParams, fins: PectoralFins, secs: f32) -> (FishBody, Vec3) {
    swim_from(
        FishBody::new(LENGTH_M, Vec3::ZERO, Vec3::X),
        params,
        fins,
        secs,
    )
}

/// As [`swim`] from a given fish, the controller sampled at every substep.
fn swim_from(
    fish: FishBody,
    params: SwimParams,
    fins: PectoralFins,
    secs: f32,
) -> (FishBody, Vec3) {
    swim_sampled(fish, params, fins, secs, ControlSampling::default())
}
