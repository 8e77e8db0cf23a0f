//! Light and temperature of the reef's water, the ambient conditions a fish
//! senses (Tu & Terzopoulos 1994 §5: a temperature sensor at the body's centre,
//! and brightness from the retinal image) and judges against its habits (§6.2:
//! content → wander, otherwise leave).
//!
//! - **Light** falls off with depth (Beer–Lambert, attenuation length
//!   [`EnvironmentParams::light_attenuation_m`]) and is dimmer towards the shaded −x end of the
//!   tank, under an overhang: bright water is near the surface at +x, dark water
//!   deep at −x.
//! - **Temperature** is warmest near a warm vent on the floor at +x, +z and
//!   coldest deep at the far end: normalised to [0, 1] and shown in °C
//!   ([`EnvironmentParams::cold_c`] … [`EnvironmentParams::warm_c`]).
//!
//! Both fields are static, smooth and cheap; fish read them every step.

use crate::sim::common::fmath;
use glam::Vec3;

use crate::sim::common::tank::Tank;

/// The tuning of the reef's light and temperature fields ([`Environment`]),
/// held by each `Environment` (the `Default`) and read through
/// [`Environment::params`]. The shapes' own coefficients (the vent's place, the
/// thermocline's 0.15 … 0.55, the plume's 0.6) stay in the formulas they shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnvironmentParams {
    /// Depth over which light falls to 1/e, metres (3, chosen: the floor of the
    /// 4.5 m tank gets a fifth of the surface light, like clear coastal water a few
    /// metres down).
    pub light_attenuation_m: f32,
    /// Share of the light that reaches the shaded end of the tank (0.35, chosen).
    pub shade_fraction: f32,
    /// Temperature at normalised 0, °C (16).
    pub cold_c: f32,
    /// Temperature at normalised 1, °C (28).
    pub warm_c: f32,
    /// Radius of the warm vent's plume, metres (3, chosen: a third of the tank).
    pub vent_radius_m: f32,
}

impl Default for EnvironmentParams {
    fn default() -> Self {
        Self {
            light_attenuation_m: 3.0,
            shade_fraction: 0.35,
            cold_c: 16.0,
            warm_c: 28.0,
            vent_radius_m: 3.0,
        }
    }
}

/// The light and temperature fields of one tank.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Environment {
    pub tank: Tank,
    /// Where the warm water rises, metres (on the floor).
    pub warm_vent_m: Vec3,
    params: EnvironmentParams,
}

impl Environment {
    /// The fields of `tank` with the default tuning.
    pub fn new(tank: Tank) -> Self {
        Self::with_params(tank, EnvironmentParams::default())
    }

    /// The fields of `tank` with the tuning `params`.
    pub fn with_params(tank: Tank, params: EnvironmentParams) -> Self {
        let size = tank.size_m();
        Self {
            tank,
            params,
            warm_vent_m: Vec3::new(
                tank.min_m.x + 0.8 * size.x,
                tank.min_m.y,
                tank.min_m.z + 0.75 * size.z,
            ),
        }
    }

    /// The fields' tuning.
    pub fn params(&self) -> &EnvironmentParams {
        &self.params
    }

    /// Brightness of the water at `p_m`, 0 (dark) … 1 (just under the sunlit
    /// surface).
    pub fn brightness_at(&self, p_m: Vec3) -> f32 {
        let depth = (self.tank.max_m.y - p_m.y).max(0.0);
        let size = self.tank.size_m();
        let across = ((p_m.x - self.tank.min_m.x) / size.x.max(1e-3)).clamp(0.0, 1.0);
        let shade_fraction = self.params.shade_fraction;
        let shade = shade_fraction + (1.0 - shade_fraction) * smoothstep(across);
        let b = fmath::exp(-depth / self.params.light_attenuation_m) * shade;
        if b.is_finite() {
            b.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// Temperature at `p_m`, 0 (cold) … 1 (warm).
    pub fn temperature_01_at(&self, p_m: Vec3) -> f32 {
        let size = self.tank.size_m();
        let height = ((p_m.y - self.tank.min_m.y) / size.y.max(1e-3)).clamp(0.0, 1.0);
        // Background: warmer near the surface (a thermocline), 0.15 … 0.55.
        let background = 0.15 + 0.4 * height;
        let d2 = (p_m - self.warm_vent_m).length_squared();
        let vent_radius_m = self.params.vent_radius_m;
        let plume = fmath::exp(-d2 / (2.0 * vent_radius_m * vent_radius_m));
        let t = background + 0.6 * plume;
        if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.5
        }
    }

    /// Temperature at `p_m`, °C.
    pub fn temperature_c_at(&self, p_m: Vec3) -> f32 {
        let (cold_c, warm_c) = (self.params.cold_c, self.params.warm_c);
        cold_c + (warm_c - cold_c) * self.temperature_01_at(p_m)
    }

    /// Unit direction in which `field` grows fastest at `p_m` (central
    /// differences over 0.25 m), or zero where it is flat.
    pub fn gradient_direction(&self, p_m: Vec3, field: impl Fn(&Self, Vec3) -> f32) -> Vec3 {
        let h = 0.25;
        let g = Vec3::new(
            field(self, p_m + Vec3::X * h) - field(self, p_m - Vec3::X * h),
            field(self, p_m + Vec3::Y * h) - field(self, p_m - Vec3::Y * h),
            field(self, p_m + Vec3::Z * h) - field(self, p_m - Vec3::Z * h),
        );
        if g.length_squared() < 1e-12 {
            Vec3::ZERO
        } else {
            g.normalize_or_zero()
        }
    }
}

fn smoothstep(x: f32) -> f32 {
    x * x * (3.0 - 2.0 * x)
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::environment::*;

    #[test]
    fn light_is_brighter_near_the_surface_and_at_the_sunny_end() {
        let env = Environment::new(Tank::default());
        let shallow = env.brightness_at(Vec3::new(0.0, 4.2, 0.0));
        let deep = env.brightness_at(Vec3::new(0.0, 0.3, 0.0));
        assert!(shallow > 2.0 * deep, "{shallow} {deep}");
        let sunny = env.brightness_at(Vec3::new(5.5, 2.0, 0.0));
        let shaded = env.brightness_at(Vec3::new(-5.5, 2.0, 0.0));
        assert!(sunny > 2.0 * shaded, "{sunny} {shaded}");
        assert!((0.0..=1.0).contains(&env.brightness_at(Vec3::splat(f32::NAN))));
    }

    #[test]
    fn the_vent_is_warm_and_the_far_deep_corner_cold() {
        let env = Environment::new(Tank::default());
        let vent = env.temperature_c_at(env.warm_vent_m + Vec3::Y * 0.5);
        let cold = env.temperature_c_at(Vec3::new(-5.5, 0.3, -3.5));
        assert!(vent > 24.0 && cold < 19.0, "{vent} {cold}");
        let up = env.gradient_direction(Vec3::new(-5.0, 1.0, -3.0), Environment::temperature_01_at);
        assert!(up.y > 0.0, "{up}");
    }
}
