//! The boid tank both the aquarium and the schooling lab are: what each asks of
//! it (its [`crate::scenes::SceneClass::boid_tank`]) is the one place the two
//! scenes differ. The aquarium's fish wander with the seed's rocks; the
//! schooling lab turns the boid layer on and adds sharks, stingrays and a
//! teacher's rocks.

use crate::settings::PredationSettings;
use crate::sim::{BoidParams, Obstacle, SceneWorld, World, WorldConfig};

/// What one boid tank should be.
#[derive(Clone, Debug, PartialEq)]
pub struct BoidTank {
    /// The seed, the animals and the rocks.
    pub config: WorldConfig,
    /// The SIMBA boid layer's weights and mode, or `None` for fish that
    /// wander.
    pub boids: Option<BoidParams>,
    /// The confusion effect and joint flight.
    pub predation: PredationSettings,
}

/// What following new settings changed in a world
/// ([`crate::scenes::SceneClass::follow`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Followed {
    /// Animals came or went (the lab's drawing snapshot must be retaken).
    pub recount: bool,
    /// The rocks were replaced (the renderer's static meshes are stale).
    pub obstacles: bool,
}

impl BoidTank {
    /// A new world of this tank.
    pub fn build(&self) -> SceneWorld {
        let mut world = World::new(self.config.clone());
        world.set_boids(self.boids);
        self.predation.apply_to_boids(world.world_params_mut());
        SceneWorld::Boids(Box::new(world))
    }

    /// Brings `world` to this tank without restarting it: counts, the boid
    /// layer, species and rocks. `obstacles_applied` is the rocks the settings
    /// asked for when last applied (`None`: the seed's), updated here.
    pub fn follow(
        &self,
        world: &mut World,
        obstacles_applied: &mut Option<Vec<Obstacle>>,
    ) -> Followed {
        let mut change = Followed::default();
        let config = &self.config;
        if config.fish_count != world.fish().len() {
            world.set_fish_count(config.fish_count);
            change.recount = true;
        }
        if world.boids() != self.boids.as_ref() {
            world.set_boids(self.boids);
        }
        self.predation.apply_to_boids(world.world_params_mut());
        if (config.sharks, config.stingrays) != (world.sharks().len(), world.stingrays().len()) {
            world.set_species_counts(config.sharks, config.stingrays);
            change.recount = true;
        }
        if config.obstacles != *obstacles_applied {
            world.set_obstacles(match &config.obstacles {
                Some(obstacles) => obstacles.clone(),
                // Back to the seed's layout.
                None => World::seeded_obstacles(config.seed),
            });
            obstacles_applied.clone_from(&config.obstacles);
            change.obstacles = true;
        }
        change
    }
}
