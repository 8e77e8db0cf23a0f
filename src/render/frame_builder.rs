//! Turns the lab's state into what the GPU draws this frame: camera uniforms, one
//! instance per fish, and the static meshes (rebuilt only when the world is).

use std::sync::Arc;

use super::fish_palette::livery;
use super::mesh::{self, Mesh};
use super::orbit_camera::OrbitCamera;
use super::scene_renderer::{FishInstance, SceneCallback, SceneUniforms, StaticScene};
use crate::lab::Run;

/// Builds a [`SceneCallback`] each frame, reusing allocations.
#[derive(Default)]
pub struct FrameBuilder {
    statics: Option<StaticScene>,
    instances: Arc<Vec<FishInstance>>,
}

impl FrameBuilder {
    /// The frame for a 3D view of `run` of `size_px` physical pixels at animation
    /// time `time_secs`; fish are drawn `alpha` of the way between their last two
    /// simulated positions.
    pub fn build(
        &mut self,
        run: &Run,
        alpha: f32,
        camera: &OrbitCamera,
        size_px: [u32; 2],
        time_secs: f32,
        _view_id: u32,
    ) -> SceneCallback {
        let world = run.world();
        let tank = world.tank();
        let generation = run.generation();
        if self.statics.as_ref().map(|s| s.generation) != Some(generation) {
            let mut scene = Mesh::default();
            scene.append(&mesh::sand_floor(tank));
            scene.append(&mesh::tank_frame(tank));
            scene.append(&mesh::obstacles(world.obstacles(), world.seed()));
            self.statics = Some(StaticScene {
                generation,
                mesh: Arc::new(scene),
            });
        }

        let instances = Arc::make_mut(&mut self.instances);
        instances.clear();
        instances.extend(world.fish().iter().enumerate().map(|(i, fish)| {
            let look = livery(fish.hue);
            FishInstance {
                position_m: run.drawn_position_m(i, alpha).to_array(),
                body_length_m: fish.body_length_m,
                forward: fish.heading().to_array(),
                tail_phase_rad: fish.tail_phase_rad,
                color: [look.rgb[0], look.rgb[1], look.rgb[2], look.bars],
            }
        }));

        let aspect = size_px[0] as f32 / size_px[1].max(1) as f32;
        SceneCallback {
            uniforms: SceneUniforms::new(
                camera.world_to_clip(aspect),
                camera.eye_m(),
                tank.min_m,
                tank.max_m,
                time_secs,
            ),
            fish: Arc::clone(&self.instances),
            statics: self.statics.clone().unwrap_or(StaticScene {
                generation,
                mesh: Arc::new(Mesh::default()),
            }),
            size_px,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lab::Lab;
    use crate::settings::Settings;

    #[test]
    fn one_instance_per_fish_and_statics_rebuilt_only_on_reset() {
        let mut lab = Lab::new(Settings::default());
        let camera = OrbitCamera::framing(
            lab.world().tank().min_m,
            lab.world().tank().max_m,
            16.0 / 9.0,
        );
        let mut builder = FrameBuilder::default();
        let first = builder.build(&lab.runs()[0], 1.0, &camera, [800, 450], 0.0, 0);
        assert_eq!(first.fish.len(), lab.world().fish().len());
        assert!(
            first
                .fish
                .iter()
                .all(|f| f.position_m.iter().all(|c| c.is_finite()))
        );
        assert!(!first.statics.mesh.indices.is_empty());
        lab.step(10);
        let second = builder.build(&lab.runs()[0], 1.0, &camera, [800, 450], 0.1, 0);
        assert!(Arc::ptr_eq(&first.statics.mesh, &second.statics.mesh));
        lab.reset(Some(5));
        let third = builder.build(&lab.runs()[0], 1.0, &camera, [800, 450], 0.2, 0);
        assert_ne!(third.statics.generation, second.statics.generation);
    }
}
