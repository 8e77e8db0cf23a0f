//! One interface over the four simulated scenes: the boid tank (the aquarium and
//! the schooling lab), the physics fish tank, the reef and the learning lab.
//!
//! Everything outside `sim/` that needs "the world of this tank" (the lab's runs,
//! the renderer, the automation API, the benchmarks) holds one [`SceneWorld`] and
//! asks it; the dispatch over the scenes lives here, one `match` per method, and
//! nowhere else. A scene that wants to be drawn, stepped, measured and picked
//! implements the methods below; `ARCHITECTURE.md` ("Add a scene") lists the rest
//! of a new scene's files.
//!
//! Animals are numbered per scene (the index every method and the UI use):
//! - boids: the fish, then the sharks, then the stingrays;
//! - physics: the fish, then the sharks;
//! - reef: every animal, eaten ones included (they are not drawn or picked);
//! - learning: the demo fish, then the race's sharks.

use glam::Vec3;
use serde::Serialize;

use crate::sim::body::NODE_COUNT;
use crate::sim::boids::attention::Attention;
pub use crate::sim::common::moment::{FoundMoment, Moment};
use crate::sim::learning::learning_lab::LearningLab;
use crate::sim::reef::mind::FishKind;
use crate::sim::reef::world::{ReefBody, ReefWorld};
use crate::sim::{
    BodySpecies, Fish, Obstacle, PhysicalFish, PhysicsWorld, SchoolMetrics, Tank, World,
};

/// Metrics samples of the boid scenes are taken every this many steps
/// (15 × 1/60 s = 0.25 s; the scenes' `sample_every_steps`, `src/scenes/`).
pub const BOID_SAMPLE_EVERY_STEPS: u64 = 15;
/// Metrics samples of the fish-world scenes are taken every this many steps
/// (5 × 0.055 s = 0.275 s, about the boid scenes' quarter second).
pub const FISH_WORLD_SAMPLE_EVERY_STEPS: u64 = 5;

/// What a scene reports to the metrics history at a sample.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SceneMetrics {
    pub time_secs: f64,
    /// Order parameters of the school (the boid fish; the physics fish; the
    /// reef's living prey; nothing in the learning lab).
    pub school: SchoolMetrics,
    /// Share of fish-steps on which each boid force acted over the last second
    /// (boid scenes with the boid layer on; zeros elsewhere).
    pub force_frequencies: [f64; 5],
    /// Animals eaten by predators since the start.
    pub catches: u64,
}

/// A muscle-driven animal to draw with the skinned body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyToDraw {
    /// The animal's index in its scene.
    pub index: usize,
    pub species: BodySpecies,
    /// Livery hue, 0–1.
    pub hue: f32,
}

/// How a point-mass animal is drawn: which rigid mesh and livery.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointShape {
    Fish,
    Shark,
    Stingray,
}

/// A point-mass animal to draw with a rigid mesh.
#[derive(Clone, Copy, Debug)]
pub struct PointToDraw<'a> {
    /// The animal's index in its scene (where the lab's interpolated
    /// positions keep it).
    pub index: usize,
    pub shape: PointShape,
    /// Its body: length, heading and tail phase.
    pub body: &'a Fish,
    /// Livery hue, 0–1.
    pub hue: f32,
}

/// Things in the water that are drawn but are not animals.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scenery {
    /// The reef's plankton particles.
    pub plankton_m: Vec<Vec3>,
    /// The learning lab's buoys, which its swimmer tracks.
    pub buoys_m: Vec<Vec3>,
    /// The reef's seaweed blades, each a chain of nodes from the sand up.
    pub seaweed_m: Vec<Vec<Vec3>>,
}

/// A scene's own part of `shoal.state()`: at most one of these is present,
/// under its scene's key. The boid scenes report through the metrics.
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct SceneReport {
    /// The physics scene: the selected fish, in detail.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub physics: Option<crate::sim::physics::report::PhysicsReport>,
    /// The reef scene: counts, the selected fish's mind, the latest events.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reef: Option<crate::sim::reef::report::ReefReport>,
    /// The learning lab: training progress, the controllers in use, race, buoys.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub learning: Option<crate::sim::learning::report::LearningReport>,
}

/// One living animal's state ([`SceneWorld::living_states`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnimalState {
    /// Its index in the scene (see the module doc).
    pub index: usize,
    /// Its centre, metres.
    pub position_m: Vec3,
    /// Its velocity, m/s, where the body keeps one.
    pub velocity_m_per_s: Option<Vec3>,
    /// A muscle body's nodes, metres.
    pub nodes_m: Option<[Vec3; NODE_COUNT]>,
}

/// The simulated world of one tank.
#[derive(Clone)]
pub enum SceneWorld {
    /// Point-mass fish, sharks and stingrays: the aquarium (wandering) and the
    /// schooling lab (the SIMBA boid layer on).
    Boids(Box<World>),
    /// Muscle-driven fish steered by the boid layer (Tu & Terzopoulos §3).
    Physics(Box<PhysicsWorld>),
    /// Fish with minds, on muscle or point-mass bodies (Tu & Terzopoulos §5–7).
    Reef(Box<ReefWorld>),
    /// The learning centre (Tu & Terzopoulos §4): training, the demo fish and the
    /// race, in open water.
    Learning(Box<LearningLab>),
}

impl SceneWorld {
    /// The moment this scene is about, if it has one (the reef's demos).
    pub fn moment(&self) -> Option<Moment> {
        match self {
            Self::Reef(w) => Some(w.config().scene.moment()),
            Self::Boids(_) | Self::Physics(_) | Self::Learning(_) => None,
        }
    }

    /// Events logged since the start (0 in scenes without a log).
    pub fn events_logged(&self) -> u64 {
        match self {
            Self::Reef(w) => w.events_logged(),
            Self::Boids(_) | Self::Physics(_) | Self::Learning(_) => 0,
        }
    }

    /// The scene's moment, if it happened after the first `logged_before`
    /// events.
    pub fn moment_since(&self, logged_before: u64) -> Option<FoundMoment> {
        match self {
            Self::Reef(w) => w.moment_since(logged_before).map(|e| FoundMoment {
                time_secs: e.time_secs,
                subject: e.kind.subject(),
                follow: w.config().scene.moment().follow,
                text: e.text.clone(),
                words: e.words(),
            }),
            Self::Boids(_) | Self::Physics(_) | Self::Learning(_) => None,
        }
    }

    /// Advances the world by one step of [`Self::dt_secs`].
    pub fn step(&mut self) {
        match self {
            Self::Boids(w) => w.step(),
            Self::Physics(w) => w.step(),
            Self::Reef(w) => w.step(),
            Self::Learning(w) => w.step(),
        }
    }

    /// The scene's part of `shoal.state()`, with the animal `selected` (by
    /// index) in detail.
    pub fn report(&self, selected: Option<u32>) -> SceneReport {
        match self {
            Self::Boids(_) => SceneReport::default(),
            Self::Physics(w) => SceneReport {
                physics: Some(w.report(selected)),
                ..SceneReport::default()
            },
            Self::Reef(w) => SceneReport {
                reef: Some(w.report(selected)),
                ..SceneReport::default()
            },
            Self::Learning(w) => SceneReport {
                learning: Some(w.report()),
                ..SceneReport::default()
            },
        }
    }

    /// Length of one step, seconds: 1/60 s for boids, the fish world's
    /// 0.055 s for the others (`paper_time::FISH_STEP_SECS`).
    pub fn dt_secs(&self) -> f64 {
        match self {
            Self::Boids(_) => f64::from(World::DT_SECS),
            Self::Physics(w) => f64::from(w.dt_secs()),
            Self::Reef(w) => f64::from(w.dt_secs()),
            Self::Learning(w) => f64::from(w.dt_secs()),
        }
    }

    /// Simulated seconds since the world began.
    pub fn time_secs(&self) -> f64 {
        match self {
            Self::Boids(w) => w.time_secs(),
            Self::Physics(w) => w.time_secs(),
            Self::Reef(w) => w.time_secs(),
            Self::Learning(w) => w.demo_steps() as f64 * f64::from(w.dt_secs()),
        }
    }

    /// Steps since the world began.
    pub fn steps(&self) -> u64 {
        match self {
            Self::Boids(w) => w.steps(),
            Self::Physics(w) => w.steps(),
            Self::Reef(w) => w.steps(),
            Self::Learning(w) => w.demo_steps(),
        }
    }

    /// The seed the world was built from (it also shapes the rocks' look).
    pub fn seed(&self) -> u64 {
        match self {
            Self::Boids(w) => w.seed(),
            Self::Physics(w) => w.seed(),
            Self::Reef(w) => w.config().seed,
            Self::Learning(w) => w.seed(),
        }
    }

    pub fn tank(&self) -> &Tank {
        match self {
            Self::Boids(w) => w.tank(),
            Self::Physics(w) => w.tank(),
            Self::Reef(w) => w.tank(),
            Self::Learning(w) => w.tank(),
        }
    }

    /// Rocks, pillars and ledges (none in the learning lab's open water).
    pub fn obstacles(&self) -> &[Obstacle] {
        match self {
            Self::Boids(w) => w.obstacles(),
            Self::Physics(w) => w.obstacles(),
            Self::Reef(w) => w.obstacles(),
            Self::Learning(_) => &[],
        }
    }

    /// Animals in the tank now (eaten ones not counted).
    pub fn animal_count(&self) -> usize {
        match self {
            Self::Boids(w) => w.fish().len() + w.sharks().len() + w.stingrays().len(),
            Self::Physics(w) => w.animals().len(),
            Self::Reef(w) => w.alive_count(),
            Self::Learning(w) => 1 + w.race_nodes_m().len(),
        }
    }

    /// Fish in the tank now: the boid or physics fish without sharks and
    /// stingrays; the reef's living animals; the learning lab's demo fish and
    /// racers.
    pub fn fish_count(&self) -> usize {
        match self {
            Self::Boids(w) => w.fish().len(),
            Self::Physics(w) => w.fish_count(),
            Self::Reef(_) | Self::Learning(_) => self.animal_count(),
        }
    }

    /// The metrics now (`None`: the scene has no school to measure).
    pub fn metrics(&self) -> Option<SceneMetrics> {
        Some(match self {
            Self::Boids(w) => {
                let m = w.metrics();
                SceneMetrics {
                    time_secs: w.time_secs(),
                    school: m.school,
                    force_frequencies: if w.boids().is_some() {
                        m.force_frequencies_recent
                    } else {
                        [0.0; 5]
                    },
                    catches: m.catches,
                }
            }
            Self::Physics(w) => SceneMetrics {
                time_secs: w.time_secs(),
                school: w.school_metrics(),
                ..SceneMetrics::default()
            },
            Self::Reef(w) => SceneMetrics {
                time_secs: w.time_secs(),
                school: w.school_metrics(),
                catches: u64::from(w.counts().prey_eaten),
                ..SceneMetrics::default()
            },
            Self::Learning(_) => return None,
        })
    }

    /// The mean speed now (m/s) of the fish the school's metrics measure
    /// ([`Self::metrics`]): the boid tanks' fish (not sharks or stingrays), the
    /// physics tank's fish (not sharks), the reef's living prey. `None` in the
    /// learning lab, which has no school. Speeds are over the ground, as the
    /// metrics' mean speed (a fish drifting with the current travels too).
    pub fn school_mean_speed_m_per_s(&self) -> Option<f64> {
        let (sum, n) = match self {
            Self::Boids(w) => w.fish().iter().fold((0.0, 0usize), |(s, n), f| {
                (s + f64::from(f.velocity_m_per_s.length()), n + 1)
            }),
            Self::Physics(w) => w.animals()[..w.fish_count()]
                .iter()
                .fold((0.0, 0usize), |(s, n), a| {
                    (s + f64::from(a.point.velocity_m_per_s.length()), n + 1)
                }),
            Self::Reef(w) => w
                .living()
                .filter(|(_, a)| a.habits.kind == FishKind::Prey)
                .fold((0.0, 0usize), |(s, n), (_, a)| {
                    (s + f64::from(a.body.velocity_m_per_s().length()), n + 1)
                }),
            Self::Learning(_) => return None,
        };
        Some(if n == 0 { 0.0 } else { sum / n as f64 })
    }

    /// The counts the lab keeps over time for the CSV export, at a metrics
    /// sample (the reef's living animals by kind, food and counters; `None`
    /// elsewhere: the other scenes' numbers over time are their metrics).
    pub fn census(&self) -> Option<crate::sim::reef::report::ReefCensus> {
        match self {
            Self::Reef(w) => Some(w.census()),
            Self::Boids(_) | Self::Physics(_) | Self::Learning(_) => None,
        }
    }

    /// Where every animal is now, by index (see the module doc): its centre for a
    /// point mass, its position for a muscle body. The lab keeps the previous
    /// step's copy so that drawing interpolates the same way in every scene.
    pub fn positions_m(&self, out: &mut Vec<Vec3>) {
        out.clear();
        match self {
            Self::Boids(w) => out.extend(
                w.fish()
                    .iter()
                    .chain(w.sharks().iter().map(|s| &s.body))
                    .chain(w.stingrays().iter().map(|r| &r.body))
                    .map(|f| f.position_m),
            ),
            Self::Physics(w) => out.extend(w.animals().iter().map(|a| a.point.position_m)),
            Self::Reef(w) => out.extend(w.animals().iter().map(|a| a.body.position_m())),
            Self::Learning(_) => {
                let mut nodes = Vec::new();
                self.nodes_m(&mut nodes);
                out.extend(nodes.iter().map(centre));
            }
        }
    }

    /// The state of every living animal, for checks that a run stays sound
    /// (the soak, `crate::soak`): its index, its centre, its velocity where
    /// the body has one (the learning lab's swimmers report none) and its
    /// nodes for a muscle body. Eaten reef animals are left out: they are
    /// neither drawn nor stepped.
    pub fn living_states(&self, out: &mut Vec<AnimalState>) {
        out.clear();
        let point = |index: usize, f: &Fish| AnimalState {
            index,
            position_m: f.position_m,
            velocity_m_per_s: Some(f.velocity_m_per_s),
            nodes_m: None,
        };
        match self {
            Self::Boids(w) => out.extend(
                w.fish()
                    .iter()
                    .chain(w.sharks().iter().map(|s| &s.body))
                    .chain(w.stingrays().iter().map(|r| &r.body))
                    .enumerate()
                    .map(|(i, f)| point(i, f)),
            ),
            Self::Physics(w) => {
                out.extend(
                    w.animals()
                        .iter()
                        .enumerate()
                        .map(|(index, a)| AnimalState {
                            index,
                            position_m: a.point.position_m,
                            velocity_m_per_s: Some(a.point.velocity_m_per_s),
                            nodes_m: Some(a.nodes_m()),
                        }),
                )
            }
            Self::Reef(w) => out.extend(w.living().map(|(index, a)| match &a.body {
                ReefBody::Physical(p) => AnimalState {
                    index,
                    position_m: a.body.position_m(),
                    velocity_m_per_s: Some(a.body.velocity_m_per_s()),
                    nodes_m: Some(p.nodes_m()),
                },
                ReefBody::Point(f) => point(index, f),
            })),
            Self::Learning(_) => {
                let mut nodes = Vec::new();
                self.nodes_m(&mut nodes);
                out.extend(nodes.into_iter().enumerate().map(|(index, n)| AnimalState {
                    index,
                    position_m: centre(&n),
                    velocity_m_per_s: None,
                    nodes_m: Some(n),
                }));
            }
        }
    }

    /// The nodes of every animal now, by index: a muscle body's 23 nodes, a
    /// point mass's centre 23 times (boid scenes: none).
    pub fn nodes_m(&self, out: &mut Vec<[Vec3; NODE_COUNT]>) {
        out.clear();
        match self {
            Self::Boids(_) => {}
            Self::Physics(w) => out.extend(w.animals().iter().map(|a| a.nodes_m())),
            Self::Reef(w) => out.extend(w.animals().iter().map(|a| match &a.body {
                ReefBody::Physical(p) => p.nodes_m(),
                ReefBody::Point(_) => [a.body.position_m(); NODE_COUNT],
            })),
            Self::Learning(w) => out.extend(
                std::iter::once(w.demo_nodes_m())
                    .chain(w.race_nodes_m().into_iter().map(|(_, n)| n)),
            ),
        }
    }

    /// The muscle-driven animals to draw with the skinned body (living ones).
    pub fn bodies_to_draw(&self) -> Vec<BodyToDraw> {
        match self {
            Self::Boids(_) => Vec::new(),
            Self::Physics(w) => w
                .animals()
                .iter()
                .enumerate()
                .map(|(index, a)| BodyToDraw {
                    index,
                    species: a.species,
                    hue: a.hue,
                })
                .collect(),
            Self::Reef(w) => w
                .living()
                .filter_map(|(index, a)| match &a.body {
                    ReefBody::Physical(p) => Some(BodyToDraw {
                        index,
                        species: p.species,
                        hue: a.hue,
                    }),
                    ReefBody::Point(_) => None,
                })
                .collect(),
            Self::Learning(w) => {
                let species = w.species();
                let racers = w.race_nodes_m().len();
                std::iter::once(BodyToDraw {
                    index: 0,
                    species,
                    hue: 0.1,
                })
                .chain((1..=racers).map(|index| BodyToDraw {
                    index,
                    species,
                    hue: 0.55 + 0.05 * index as f32,
                }))
                .collect()
            }
        }
    }

    /// The point-mass animals to draw with rigid meshes (living ones), in index
    /// order: the boid tanks' fish, sharks and stingrays; the reef's animals on
    /// point-mass bodies. The muscle bodies are [`Self::bodies_to_draw`].
    pub fn points_to_draw(&self) -> Vec<PointToDraw<'_>> {
        match self {
            Self::Boids(w) => {
                let fish = w.fish().iter().map(|f| (PointShape::Fish, f));
                let sharks = w.sharks().iter().map(|s| (PointShape::Shark, &s.body));
                let rays = w
                    .stingrays()
                    .iter()
                    .map(|r| (PointShape::Stingray, &r.body));
                fish.chain(sharks)
                    .chain(rays)
                    .enumerate()
                    .map(|(index, (shape, body))| PointToDraw {
                        index,
                        shape,
                        body,
                        hue: body.hue,
                    })
                    .collect()
            }
            Self::Reef(w) => w
                .living()
                .filter_map(|(index, a)| match &a.body {
                    ReefBody::Point(body) => Some(PointToDraw {
                        index,
                        shape: if a.habits.kind == FishKind::Predator {
                            PointShape::Shark
                        } else {
                            PointShape::Fish
                        },
                        body,
                        hue: a.hue,
                    }),
                    ReefBody::Physical(_) => None,
                })
                .collect(),
            Self::Physics(_) | Self::Learning(_) => Vec::new(),
        }
    }

    /// What else is in the water: the reef's plankton and seaweed, the
    /// learning lab's buoys.
    pub fn scenery(&self) -> Scenery {
        match self {
            Self::Reef(w) => Scenery {
                plankton_m: w.food().iter().map(|f| f.position_m).collect(),
                seaweed_m: w.seaweed().iter().map(|s| s.nodes_m.clone()).collect(),
                ..Scenery::default()
            },
            Self::Learning(w) => Scenery {
                buoys_m: w.buoys_m().to_vec(),
                ..Scenery::default()
            },
            Self::Boids(_) | Self::Physics(_) => Scenery::default(),
        }
    }

    /// The animals a click can select, by index, with their body lengths
    /// (the physics fish; the reef's living animals; none elsewhere).
    pub fn pickable(&self) -> Vec<(usize, f32)> {
        match self {
            Self::Physics(w) => w
                .animals()
                .iter()
                .enumerate()
                .map(|(i, a)| (i, a.body_length_m()))
                .collect(),
            Self::Reef(w) => w
                .living()
                .map(|(i, a)| (i, a.body.body_length_m()))
                .collect(),
            // The schooling lab's fish (clicked to see what they pay attention to).
            Self::Boids(w) => w
                .fish()
                .iter()
                .enumerate()
                .map(|(i, f)| (i, f.body_length_m))
                .collect(),
            Self::Learning(_) => Vec::new(),
        }
    }

    /// What fish `index` pays attention to, as of the last step: the boid
    /// tanks' fish with the boid layer on (`None` elsewhere; see
    /// [`World::attention`]).
    pub fn attention(&self, index: usize) -> Option<Attention> {
        match self {
            Self::Boids(w) => w.attention(index),
            Self::Physics(_) | Self::Reef(_) | Self::Learning(_) => None,
        }
    }

    /// Is animal `index` drawn from its nodes (a muscle body)?
    pub fn has_body(&self, index: usize) -> bool {
        match self {
            Self::Boids(_) => false,
            Self::Physics(_) | Self::Learning(_) => true,
            Self::Reef(w) => w
                .animals()
                .get(index)
                .is_some_and(|a| matches!(a.body, ReefBody::Physical(_))),
        }
    }

    /// Muscle-driven animal `index`, whose muscles the plots can trace.
    pub fn physical_fish(&self, index: usize) -> Option<&PhysicalFish> {
        match self {
            Self::Physics(w) => w.animals().get(index),
            Self::Reef(w) => match &w.animals().get(index)?.body {
                ReefBody::Physical(p) => Some(p),
                ReefBody::Point(_) => None,
            },
            Self::Boids(_) | Self::Learning(_) => None,
        }
    }

    /// Does the world turn its selected animal on the teacher's command
    /// (`shoal.turn`, the *Turn* button)? The physics tank's muscle fish do.
    pub fn turns_on_command(&self) -> bool {
        match self {
            Self::Physics(_) => true,
            Self::Boids(_) | Self::Reef(_) | Self::Learning(_) => false,
        }
    }

    /// Starts a turn of `angle_deg` (+ left) on animal `index`, in a world
    /// that [turns on command](Self::turns_on_command); elsewhere nothing
    /// happens.
    pub fn turn(&mut self, index: usize, angle_deg: f32) {
        match self {
            Self::Physics(w) => w.turn(index, angle_deg),
            Self::Boids(_) | Self::Reef(_) | Self::Learning(_) => {}
        }
    }

    /// The boid world, in the aquarium and the schooling lab.
    pub fn boids(&self) -> Option<&World> {
        match self {
            Self::Boids(w) => Some(w.as_ref()),
            _ => None,
        }
    }

    /// The physics fish tank, in its scene.
    pub fn physics(&self) -> Option<&PhysicsWorld> {
        match self {
            Self::Physics(w) => Some(w.as_ref()),
            _ => None,
        }
    }

    /// The reef, in its scene.
    pub fn reef(&self) -> Option<&ReefWorld> {
        match self {
            Self::Reef(w) => Some(w.as_ref()),
            _ => None,
        }
    }

    /// The learning lab, in its scene.
    pub fn learning(&self) -> Option<&LearningLab> {
        match self {
            Self::Learning(w) => Some(w),
            _ => None,
        }
    }

    /// The learning lab, to train, race, save or load it.
    pub fn learning_mut(&mut self) -> Option<&mut LearningLab> {
        match self {
            Self::Learning(w) => Some(w),
            _ => None,
        }
    }

    /// The learning lab this world is, to keep while another scene shows
    /// (its training is minutes of work); `None` for every other world.
    pub fn into_learning(self) -> Option<LearningLab> {
        match self {
            Self::Learning(w) => Some(*w),
            _ => None,
        }
    }
}

/// The centre of a body's nodes.
pub fn centre(nodes: &[Vec3; NODE_COUNT]) -> Vec3 {
    nodes.iter().sum::<Vec3>() / NODE_COUNT as f32
}
