//! Turns the lab's state into what the GPU draws this frame in one 3D view: camera
//! uniforms, one instance per animal, and the static meshes (rebuilt only when the
//! world is).
//!
//! Level of detail: fish drawn shorter than [`FISH_LOD_BELOW_PX`] pixels, and all
//! but the [`MAX_DETAILED_FISH`] nearest, go after the others in the instance list
//! and are drawn with the low-poly `mesh::fish_lod` (92 triangles instead of 536).
//! Up to a thousand fish, only the size rule applies: fish the camera comes close to
//! keep every fin. A tank of 20,000 fish then costs 2.3 million triangles instead of
//! 10.7 million.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use bytemuck::Zeroable;
use glam::Vec3;

use super::body_skin::{BodyLook, BodyShape, BodySkin};
use super::fish_palette::{livery, ray_livery, shark_livery};
use super::mesh::{self, Mesh};
use super::orbit_camera::OrbitCamera;
use super::scene_renderer::{FishInstance, SceneCallback, SceneUniforms, StaticScene, ViewCache};
use crate::lab::Run;
use crate::sim::BodySpecies;
use crate::sim::common::spare::release_spare;
use crate::sim::scene::{BodyToDraw, PointShape, Scenery};

/// Fish drawn shorter than this (physical pixels, snout to tail root) use the
/// low-poly mesh. Chosen by eye: below about 30 pixels the two meshes are hard to
/// tell apart with MSAA, and the eye (a flat triangle in the LOD) is still a dot.
pub const FISH_LOD_BELOW_PX: f32 = 28.0;

/// At most this many fish, the nearest, are drawn with the full mesh (536 triangles
/// each, so about half a million triangles); chosen so that a budget laptop GPU
/// still draws 20,000 fish at interactive rates.
pub const MAX_DETAILED_FISH: usize = 1_000;

/// Static scene generations come from one counter for the whole program, so that no
/// two worlds (in two views, or one view after a reset) share one.
static NEXT_STATIC_GENERATION: AtomicU64 = AtomicU64::new(1);

/// What the builder keeps for one view between frames.
#[derive(Default)]
struct BuiltView {
    /// The lab's world generation the static scene was built for.
    world_generation: Option<u64>,
    statics: Option<StaticScene>,
    fish: Arc<Vec<FishInstance>>,
    sharks: Arc<Vec<FishInstance>>,
    rays: Arc<Vec<FishInstance>>,
    /// Deformed bodies of the physical fish (physics scene), rebuilt every frame.
    bodies: Arc<Mesh>,
}

/// The two skinned shapes, built once.
struct Skins {
    fish: BodySkin,
    shark: BodySkin,
}

/// How much the selected physical fish is tinted (the skin's highlight, 0–1).
const SELECTED_HIGHLIGHT: f32 = 0.8;

/// Builds a [`SceneCallback`] each frame for each view, reusing allocations.
#[derive(Default)]
pub struct FrameBuilder {
    views: ViewCache<BuiltView>,
    skins: Option<Skins>,
    /// The physical animal drawn highlighted.
    selected: Option<usize>,
}

/// Skins every physical animal of `run` into `out`, interpolated by `alpha`,
/// highlighting animal `selected`.
fn build_bodies(
    skins: &mut Option<Skins>,
    selected: Option<usize>,
    run: &Run,
    alpha: f32,
    out: &mut Mesh,
) {
    out.vertices.clear();
    out.indices.clear();
    let scene = run.scene();
    append_scenery(&scene.scenery(), out);
    let animals = scene.bodies_to_draw();
    if animals.is_empty() {
        return;
    }
    let skins = skins.get_or_insert_with(|| Skins {
        fish: BodySkin::new(BodyShape::Fish),
        shark: BodySkin::new(BodyShape::Shark),
    });
    let nodes = run.drawn_nodes_all_m(alpha);
    for BodyToDraw {
        index,
        species,
        hue,
    } in animals
    {
        let (skin, look) = match species {
            BodySpecies::Fish => (&skins.fish, BodyLook::fish(livery(hue))),
            BodySpecies::Shark => (&skins.shark, BodyLook::shark(shark_livery(hue))),
        };
        let look = if selected == Some(index) {
            look.highlighted(SELECTED_HIGHLIGHT)
        } else {
            look
        };
        skin.append_deformed(&nodes[index], &look, out);
    }
}

/// Plankton, buoys and seaweed, lit with their vertex colours.
fn append_scenery(scenery: &Scenery, out: &mut Mesh) {
    mesh::append_particles(
        out,
        &scenery.plankton_m,
        PLANKTON_DRAWN_RADIUS_M,
        mesh::FOOD_RGB,
    );
    mesh::append_particles(out, &scenery.buoys_m, BUOY_DRAWN_RADIUS_M, mesh::BUOY_RGB);
    for (k, weed) in scenery.seaweed_m.iter().enumerate() {
        let angle = k as f32 * 2.4;
        let across = Vec3::new(angle.cos(), 0.0, angle.sin());
        mesh::append_ribbon(out, weed, SEAWEED_WIDTH_M, across, mesh::SEAWEED_RGB);
    }
}

/// Drawn radius of a plankton particle, metres (larger than life, 4 cm, so a
/// class sees it from across the tank).
const PLANKTON_DRAWN_RADIUS_M: f32 = 0.04;
/// Drawn radius of a buoy of the learning lab, metres.
const BUOY_DRAWN_RADIUS_M: f32 = 0.15;
/// Width of a seaweed blade, metres.
const SEAWEED_WIDTH_M: f32 = 0.12;

impl FrameBuilder {
    /// Highlights physical animal `index` (the selected fish) from the next frame on.
    pub fn set_selected(&mut self, index: Option<u32>) {
        self.selected = index.map(|i| i as usize);
    }

    /// The frame for 3D view `view_id` (see [`SceneCallback::view_id`]) of
    /// `size_px` physical pixels at animation time `time_secs`.
    ///
    /// Animals are drawn `alpha` of the way between their last two simulated
    /// positions.
    pub fn build(
        &mut self,
        run: &Run,
        alpha: f32,
        camera: &OrbitCamera,
        size_px: [u32; 2],
        time_secs: f32,
        view_id: u32,
    ) -> SceneCallback {
        let scene = run.scene();
        let tank = scene.tank();
        let view = self.views.draw(view_id, BuiltView::default);
        let world_generation = run.generation();
        let statics = match &view.statics {
            Some(statics) if view.world_generation == Some(world_generation) => statics.clone(),
            _ => {
                let mut mesh_of_statics = Mesh::default();
                mesh_of_statics.append(&mesh::sand_floor(tank));
                mesh_of_statics.append(&mesh::tank_frame(tank));
                mesh_of_statics.append(&mesh::obstacles(scene.obstacles(), scene.seed()));
                let statics = StaticScene {
                    generation: NEXT_STATIC_GENERATION.fetch_add(1, Ordering::Relaxed),
                    mesh: Arc::new(mesh_of_statics),
                };
                view.world_generation = Some(world_generation);
                view.statics = Some(statics.clone());
                statics
            }
        };

        let eye = camera.eye_m();
        let drawn = run.drawn_positions_m(alpha);
        // Near fish from the front of the list, far ones from the back; sharks
        // and stingrays each in their own list.
        let focal_px = size_px[1] as f32 / (2.0 * (camera.fov_y_rad * 0.5).tan());
        let lod_below = FISH_LOD_BELOW_PX / focal_px.max(1e-3);
        let points = scene.points_to_draw();
        let count = points
            .iter()
            .filter(|p| p.shape == PointShape::Fish)
            .count();
        let fish = Arc::make_mut(&mut view.fish);
        fish.clear();
        fish.resize(count, FishInstance::zeroed());
        let sharks = Arc::make_mut(&mut view.sharks);
        sharks.clear();
        let rays = Arc::make_mut(&mut view.rays);
        rays.clear();
        release_spare(fish, 1024);
        let (mut near, mut far) = (0, count);
        for point in &points {
            let position = drawn[point.index];
            match point.shape {
                PointShape::Fish => {
                    let instance = instance(point.body, position, livery(point.hue).rgba());
                    // Drawn length ≈ focal × length / distance, compared without a root.
                    let length = point.body.body_length_m;
                    if length * length >= lod_below * lod_below * position.distance_squared(eye) {
                        fish[near] = instance;
                        near += 1;
                    } else {
                        far -= 1;
                        fish[far] = instance;
                    }
                }
                PointShape::Shark => sharks.push(instance(
                    point.body,
                    position,
                    shark_livery(point.hue).rgba(),
                )),
                PointShape::Stingray => {
                    rays.push(instance(point.body, position, ray_livery(point.hue).rgba()));
                }
            }
        }
        release_spare(sharks, 64);
        release_spare(rays, 64);
        // Beyond the budget, only the nearest keep the full mesh.
        let mut detailed = near;
        if detailed > MAX_DETAILED_FISH {
            let distance = |f: &FishInstance| Vec3::from(f.position_m).distance_squared(eye);
            fish[..near].select_nth_unstable_by(MAX_DETAILED_FISH, |a, b| {
                distance(a).total_cmp(&distance(b))
            });
            detailed = MAX_DETAILED_FISH;
        }

        build_bodies(
            &mut self.skins,
            self.selected,
            run,
            alpha,
            Arc::make_mut(&mut view.bodies),
        );
        Arc::make_mut(&mut view.bodies).release_spare();

        let aspect = size_px[0] as f32 / size_px[1].max(1) as f32;
        SceneCallback {
            view_id,
            uniforms: SceneUniforms::new(
                camera.world_to_clip(aspect),
                eye,
                tank.min_m,
                tank.max_m,
                time_secs,
            ),
            fish: Arc::clone(&view.fish),
            fish_detailed: detailed,
            sharks: Arc::clone(&view.sharks),
            rays: Arc::clone(&view.rays),
            statics,
            bodies: Arc::clone(&view.bodies),
            size_px,
        }
    }
}

/// The instance of an animal drawn at `position_m` with colour `rgba`.
fn instance(animal: &crate::sim::Fish, position_m: Vec3, rgba: [f32; 4]) -> FishInstance {
    FishInstance {
        position_m: position_m.to_array(),
        body_length_m: animal.body_length_m,
        forward: animal.heading().to_array(),
        tail_phase_rad: animal.tail_phase_rad,
        color: rgba,
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
            lab.scene().tank().min_m,
            lab.scene().tank().max_m,
            16.0 / 9.0,
        );
        let mut builder = FrameBuilder::default();
        let first = builder.build(&lab.runs()[0], 1.0, &camera, [800, 450], 0.0, 0);
        assert_eq!(first.fish.len(), lab.scene().boids().unwrap().fish().len());
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

    #[test]
    fn two_views_of_two_labs_keep_their_own_static_scenes() {
        let lab_a = Lab::new(Settings::default());
        let lab_b = Lab::new(Settings {
            seed: 99,
            ..Settings::default()
        });
        let tank = lab_a.scene().tank();
        let camera = OrbitCamera::framing(tank.min_m, tank.max_m, 1.0);
        let mut builder = FrameBuilder::default();
        let a1 = builder.build(&lab_a.runs()[0], 1.0, &camera, [400, 400], 0.0, 0);
        let b1 = builder.build(&lab_b.runs()[0], 1.0, &camera, [400, 400], 0.0, 1);
        assert_ne!(a1.statics.generation, b1.statics.generation);
        assert_eq!((a1.view_id, b1.view_id), (0, 1));
        let a2 = builder.build(&lab_a.runs()[0], 1.0, &camera, [400, 400], 0.1, 0);
        let b2 = builder.build(&lab_b.runs()[0], 1.0, &camera, [400, 400], 0.1, 1);
        assert!(Arc::ptr_eq(&a1.statics.mesh, &a2.statics.mesh));
        assert!(Arc::ptr_eq(&b1.statics.mesh, &b2.statics.mesh));
    }

    /// Drawn length in pixels of instance `f` for `camera` in a view `height_px` high.
    fn drawn_length_px(f: &FishInstance, camera: &OrbitCamera, height_px: u32) -> f32 {
        let focal_px = height_px as f32 / (2.0 * (camera.fov_y_rad * 0.5).tan());
        let distance = Vec3::from(f.position_m).distance(camera.eye_m());
        f.body_length_m * focal_px / distance
    }

    #[test]
    fn every_scene_draws_each_animal_once_as_its_world_says() {
        use crate::settings::Scene;
        use crate::sim::reef::world::ReefBodyKind;
        for scene in Scene::ALL {
            let mut settings = Settings {
                scene,
                ..Settings::default()
            };
            settings.left.sharks = 1;
            settings.left.stingrays = 2;
            settings.physics.sharks = 1;
            settings.reef.body = ReefBodyKind::PointMass;
            let lab = Lab::new(settings);
            let tank = lab.scene().tank();
            let camera = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
            let frame =
                FrameBuilder::default().build(&lab.runs()[0], 1.0, &camera, [800, 450], 0.0, 0);
            let world = lab.scene();
            let drawn = frame.fish.len() + frame.sharks.len() + frame.rays.len();
            let skinned = world.bodies_to_draw().len();
            // Every animal in the tank is drawn once: as an instance or a skin.
            assert_eq!(drawn + skinned, world.animal_count(), "{scene:?}");
            assert!(frame.fish.len() + skinned > 0, "{scene:?} draws no fish");
            let scenery = world.scenery();
            let particles = scenery.plankton_m.len() + scenery.buoys_m.len();
            assert_eq!(
                !frame.bodies.indices.is_empty(),
                skinned > 0 || particles > 0 || !scenery.seaweed_m.is_empty(),
                "{scene:?}"
            );
        }
    }

    #[test]
    fn fish_small_on_screen_come_last_for_the_low_poly_mesh() {
        let mut settings = Settings::default();
        settings.left.fish_count = 2_000;
        let lab = Lab::new(settings);
        let tank = lab.scene().tank();
        let mut camera = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
        let mut builder = FrameBuilder::default();
        let mut budget_used = false;
        for (distance_m, height_px) in [(camera.distance_m, 1080), (2.0, 1080), (2.0, 200)] {
            camera.distance_m = distance_m;
            let frame = builder.build(&lab.runs()[0], 1.0, &camera, [1920, height_px], 0.0, 0);
            assert_eq!(frame.fish.len(), 2_000);
            assert!(frame.fish_detailed <= MAX_DETAILED_FISH);
            budget_used |= frame.fish_detailed == MAX_DETAILED_FISH;
            let (near, far) = frame.fish.split_at(frame.fish_detailed);
            let distance = |f: &FishInstance| Vec3::from(f.position_m).distance(camera.eye_m());
            let farthest_near = near.iter().map(distance).fold(0.0, f32::max);
            assert!(
                near.iter()
                    .all(|f| drawn_length_px(f, &camera, height_px) >= FISH_LOD_BELOW_PX * 0.999)
            );
            assert!(far.iter().all(|f| {
                drawn_length_px(f, &camera, height_px) <= FISH_LOD_BELOW_PX * 1.001
                    || distance(f) >= farthest_near
            }));
            println!(
                "camera {distance_m:.1} m away, {height_px} px high: {} of 2000 fish detailed",
                near.len()
            );
        }
        assert!(
            budget_used,
            "the default view at 1080p draws over 1,000 fish in full"
        );
        // Every fish is there once: the partition only reorders.
        let mut indices: Vec<u32> = builder
            .build(&lab.runs()[0], 1.0, &camera, [1920, 1080], 0.0, 0)
            .fish
            .iter()
            .map(|f| f.position_m[0].to_bits() ^ f.position_m[2].to_bits().rotate_left(7))
            .collect();
        indices.sort_unstable();
        indices.dedup();
        assert_eq!(indices.len(), 2_000);
    }
}
