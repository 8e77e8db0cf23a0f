//! The intention generator (Tu & Terzopoulos 1994 §6.2, Fig. 12) with its
//! predator (Fig. 13), prey (Fig. 15) and pacifist (§7.3) variants, the
//! single-item memory of §6.3 and the persistence threshold of the focusser.
//!
//! In order, each step:
//! 1. something inside the collision-sensitivity box → **avoid** (the current
//!    intention, if worth resuming, goes to memory);
//! 2. a remembered intention whose target is still in view is **resumed** once
//!    the danger of collision has passed (unless fear now demands action);
//! 3. fear F > f0 → **school** if the most dangerous predator's F_m < f1 and the
//!    fish schools, else **escape** (prey only: predators feel no fear and
//!    pacifists neither school nor escape);
//! 4. max(H, L) > r → **eat** or **mate**, whichever urge is larger (libido only
//!    for pacifists);
//! 5. prey that like to school **school** (an inceptive school forms by swimming
//!    to the others, §7.2); otherwise **wander** if the light and temperature
//!    suit the habits, else **leave** (predators never leave).
//!
//! The focusser passes on one target per intention: the most dangerous object
//! to avoid, the most threatening predator, the chosen food, prey or partner. A
//! new food, prey or partner replaces the current one only if it is nearer (or
//! cheaper, for prey) by more than the fish's persistence threshold ("fickle"
//! near 0, "devoted" large).

use serde::{Deserialize, Serialize};

use crate::sim::reef::mind::habits::{FishKind, Habits};
use crate::sim::reef::mind::mental_state::MentalState;

/// What a fish means to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Intention {
    Avoid,
    Escape,
    School,
    Eat,
    Mate,
    Leave,
    Wander,
}

impl Intention {
    pub const ALL: [Self; 7] = [
        Self::Avoid,
        Self::Escape,
        Self::School,
        Self::Eat,
        Self::Mate,
        Self::Leave,
        Self::Wander,
    ];

    pub fn label(self) -> &'static str {
        match self {
            Self::Avoid => "avoid",
            Self::Escape => "escape",
            Self::School => "school",
            Self::Eat => "eat",
            Self::Mate => "mate",
            Self::Leave => "leave",
            Self::Wander => "wander",
        }
    }

    /// Is this intention worth storing when an avoidance interrupts it?
    fn resumable(self) -> bool {
        matches!(self, Self::Eat | Self::Mate | Self::School | Self::Escape)
    }
}

/// What the focusser points the behaviour routine at.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind", content = "id")]
pub enum Target {
    /// Another animal, by index in the world.
    Animal(u32),
    /// A food particle, by its id.
    Food(u32),
    /// A static obstacle, by index.
    Obstacle(u32),
    /// The glass, the sand or the surface.
    Glass,
}

/// An intention with its focus.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Focus {
    pub intention: Intention,
    pub target: Option<Target>,
}

impl Focus {
    pub const WANDER: Self = Self {
        intention: Intention::Wander,
        target: None,
    };
}

/// What the perception system (after the focusser's filtering) tells the
/// intention generator this step. Lists hold only what the fish *sees*.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Percept {
    /// The most dangerous thing inside the collision-sensitivity box.
    pub collision: Option<Target>,
    /// Seen predators: index and F_i.
    pub predators: Vec<(u32, f32)>,
    /// Seen food: id and distance (metres), nearest first.
    pub food: Vec<(u32, f32)>,
    /// Seen prey (for predators): index and cost C_k, cheapest first.
    pub prey: Vec<(u32, f32)>,
    /// Seen potential partners: index and a rank (lower is better), best first.
    pub mates: Vec<(u32, f32)>,
    /// Other schooling fish of the same species in view.
    pub schoolmates_seen: usize,
    /// Do the ambient light and temperature suit the fish's habits?
    pub content: bool,
}

impl Percept {
    /// The rank (distance or cost) of `target` if the fish still sees it.
    pub fn rank_of(&self, target: Target) -> Option<f32> {
        let find = |list: &[(u32, f32)], id: u32| list.iter().find(|(i, _)| *i == id).map(|x| x.1);
        match target {
            Target::Food(id) => find(&self.food, id),
            Target::Animal(id) => find(&self.prey, id)
                .or_else(|| find(&self.mates, id))
                .or_else(|| find(&self.predators, id)),
            Target::Obstacle(_) | Target::Glass => None,
        }
    }

    /// Is `target` in view?
    pub fn sees(&self, target: Target) -> bool {
        self.rank_of(target).is_some()
    }
}

/// The intention generator of one fish: the current focus and the single-item
/// memory.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct IntentionGenerator {
    pub current: Focus,
    /// I_s: the intention interrupted by an avoidance, with its target.
    pub memory: Option<Focus>,
}

impl Default for IntentionGenerator {
    fn default() -> Self {
        Self {
            current: Focus::WANDER,
            memory: None,
        }
    }
}

impl IntentionGenerator {
    /// Chooses this step's intention and target. `state.fear` must already
    /// include the seen predators (see `MentalState::update`). `partner`: the
    /// fish is bonded in a courtship sequence (past looping, `reef/courtship.rs`) and
    /// keeps courting this partner whatever its urges and ranks say; only a
    /// danger of collision interrupts it.
    pub fn decide(
        &mut self,
        habits: &Habits,
        state: &MentalState,
        percept: &Percept,
        partner: Option<u32>,
    ) -> Focus {
        // 1. Immediate danger of collision.
        if let Some(obstacle) = percept.collision {
            if self.current.intention != Intention::Avoid && self.current.intention.resumable() {
                self.memory = Some(self.current);
            }
            self.current = Focus {
                intention: Intention::Avoid,
                target: Some(obstacle),
            };
            return self.current;
        }
        let feels_fear = habits.kind == FishKind::Prey;
        let afraid = feels_fear && state.fear > habits.fear_threshold;
        // 2. Resume the remembered intention.
        if let Some(remembered) = self.memory.take() {
            let target_in_view = remembered.target.is_none_or(|t| percept.sees(t));
            let still_wanted = match remembered.intention {
                Intention::Escape | Intention::School => afraid,
                _ => !afraid,
            };
            if target_in_view && still_wanted {
                self.current = remembered;
                return self.current;
            }
        }
        // 3. Fear.
        if afraid {
            let (worst, worst_fear) =
                percept
                    .predators
                    .iter()
                    .copied()
                    .fold(
                        (None, 0.0f32),
                        |(w, f), (i, fi)| if fi > f { (Some(i), fi) } else { (w, f) },
                    );
            let intention = if worst_fear < habits.panic_threshold && habits.schools {
                Intention::School
            } else {
                Intention::Escape
            };
            self.current = Focus {
                intention,
                target: worst.map(Target::Animal),
            };
            return self.current;
        }
        // 4. A bonded courtship goes on; otherwise hunger and libido.
        if let Some(p) = partner {
            self.current = Focus {
                intention: Intention::Mate,
                target: Some(Target::Animal(p)),
            };
            return self.current;
        }
        let libido = if habits.kind == FishKind::Pacifist {
            state.libido
        } else {
            0.0
        };
        let hunger = state.hunger;
        if hunger.max(libido) > habits.urge_threshold {
            let (intention, candidates): (Intention, &[(u32, f32)]) = if libido > hunger {
                (Intention::Mate, &percept.mates)
            } else if habits.kind == FishKind::Predator {
                (Intention::Eat, &percept.prey)
            } else {
                (Intention::Eat, &percept.food)
            };
            let wrap = |id: u32| match (intention, habits.kind) {
                (Intention::Eat, FishKind::Predator) | (Intention::Mate, _) => Target::Animal(id),
                _ => Target::Food(id),
            };
            let kept = (self.current.intention == intention)
                .then_some(self.current.target)
                .flatten()
                .and_then(|t| percept.rank_of(t).map(|rank| (t, rank)));
            let best = candidates.first().map(|&(id, rank)| (wrap(id), rank));
            let target = match (kept, best) {
                (Some((t, kept_rank)), Some((new, new_rank))) => {
                    let threshold = habits.persistence_body_lengths * body_length_unit(habits);
                    if kept_rank - new_rank > threshold {
                        Some(new)
                    } else {
                        Some(t)
                    }
                }
                (Some((t, _)), None) => Some(t),
                (None, best) => best.map(|b| b.0),
            };
            self.current = Focus { intention, target };
            return self.current;
        }
        // 5. School, wander or leave.
        let intention = if habits.kind == FishKind::Prey && habits.schools {
            Intention::School
        } else if percept.content || habits.kind == FishKind::Predator {
            Intention::Wander
        } else {
            Intention::Leave
        };
        self.current = Focus {
            intention,
            target: None,
        };
        self.current
    }
}

/// Ranks are in metres; the persistence threshold is in body lengths of a
/// standard reef fish (0.5 m) so that "devoted" means the same for every kind.
fn body_length_unit(_habits: &Habits) -> f32 {
    0.5
}

#[cfg(test)]
mod tests {
    use crate::sim::reef::mind::habits::Sex;
    use crate::sim::reef::mind::intention::*;
    use crate::sim::reef::mind::mental_state::MentalConstants;

    fn state(hunger: f32, libido: f32, fear: f32) -> MentalState {
        let mut s = MentalState::new(&MentalConstants::nominal(3.0), 0.0, 0.0);
        s.hunger = hunger;
        s.libido = libido;
        s.fear = fear;
        s
    }

    fn prey() -> Habits {
        Habits::new(FishKind::Prey, Sex::Female, 0)
    }

    #[test]
    fn collision_comes_first_and_interrupts_eating_which_resumes() {
        let mut g = IntentionGenerator::default();
        let hungry = state(0.9, 0.0, 0.0);
        let mut p = Percept {
            food: vec![(7, 2.0)],
            content: true,
            ..Default::default()
        };
        let f = g.decide(&prey(), &hungry, &p, None);
        assert_eq!(f.intention, Intention::Eat);
        assert_eq!(f.target, Some(Target::Food(7)));
        p.collision = Some(Target::Obstacle(0));
        let f = g.decide(&prey(), &hungry, &p, None);
        assert_eq!(f.intention, Intention::Avoid);
        assert_eq!(g.memory.map(|m| m.target), Some(Some(Target::Food(7))));
        // Still avoiding: memory kept.
        g.decide(&prey(), &hungry, &p, None);
        assert!(g.memory.is_some());
        p.collision = None;
        // A nearer particle is now in view, but the remembered one is resumed.
        p.food.insert(0, (9, 0.3));
        let f = g.decide(&prey(), &hungry, &p, None);
        assert_eq!(
            f,
            Focus {
                intention: Intention::Eat,
                target: Some(Target::Food(7))
            }
        );
        assert!(g.memory.is_none());
    }

    #[test]
    fn a_forgotten_target_out_of_view_is_not_resumed() {
        let mut g = IntentionGenerator::default();
        let hungry = state(0.9, 0.0, 0.0);
        let mut p = Percept {
            food: vec![(7, 2.0)],
            content: true,
            ..Default::default()
        };
        g.decide(&prey(), &hungry, &p, None);
        p.collision = Some(Target::Glass);
        g.decide(&prey(), &hungry, &p, None);
        p.collision = None;
        p.food = vec![(3, 4.0)];
        let f = g.decide(&prey(), &hungry, &p, None);
        assert_eq!(f.target, Some(Target::Food(3)));
    }

    #[test]
    fn fear_makes_prey_school_or_escape() {
        let mut g = IntentionGenerator::default();
        let h = prey();
        let p = Percept {
            predators: vec![(4, 0.5)],
            ..Default::default()
        };
        // F above f0 = 0.3, F_m = 0.5 < f1 = 0.8: school.
        let f = g.decide(&h, &state(1.0, 0.0, 0.5), &p, None);
        assert_eq!(f.intention, Intention::School);
        let p = Percept {
            predators: vec![(4, 0.9), (5, 0.2)],
            ..Default::default()
        };
        let f = g.decide(&h, &state(1.0, 0.0, 1.0), &p, None);
        assert_eq!(
            f,
            Focus {
                intention: Intention::Escape,
                target: Some(Target::Animal(4))
            }
        );
        // A non-schooling prey escapes even a distant predator.
        let loner = Habits {
            schools: false,
            ..h
        };
        let p = Percept {
            predators: vec![(4, 0.4)],
            ..Default::default()
        };
        assert_eq!(
            g.decide(&loner, &state(0.0, 0.0, 0.4), &p, None).intention,
            Intention::Escape
        );
        // Below f0: no evasive action.
        assert_eq!(
            g.decide(&h, &state(0.0, 0.0, 0.2), &p, None).intention,
            Intention::School
        );
    }

    #[test]
    fn predators_feel_no_fear_and_never_leave() {
        let mut g = IntentionGenerator::default();
        let shark = Habits::new(FishKind::Predator, Sex::Male, 9);
        let p = Percept {
            predators: vec![(1, 1.0)],
            prey: vec![(3, 5.0), (8, 6.0)],
            content: false,
            ..Default::default()
        };
        let f = g.decide(&shark, &state(0.2, 0.9, 1.0), &p, None);
        assert_eq!(f.intention, Intention::Wander);
        let f = g.decide(&shark, &state(0.6, 0.9, 1.0), &p, None);
        assert_eq!(
            f,
            Focus {
                intention: Intention::Eat,
                target: Some(Target::Animal(3))
            }
        );
    }

    #[test]
    fn pacifists_mate_when_libido_beats_hunger_and_leave_bad_water() {
        let mut g = IntentionGenerator::default();
        let h = Habits::new(FishKind::Pacifist, Sex::Male, 2);
        let p = Percept {
            mates: vec![(5, 1.0)],
            food: vec![(1, 1.0)],
            predators: vec![(9, 1.0)],
            content: false,
            ..Default::default()
        };
        let f = g.decide(&h, &state(0.3, 0.6, 1.0), &p, None);
        assert_eq!(
            f,
            Focus {
                intention: Intention::Mate,
                target: Some(Target::Animal(5))
            }
        );
        let f = g.decide(&h, &state(0.6, 0.3, 1.0), &p, None);
        assert_eq!(
            f,
            Focus {
                intention: Intention::Eat,
                target: Some(Target::Food(1))
            }
        );
        let f = g.decide(&h, &state(0.1, 0.1, 0.0), &p, None);
        assert_eq!(f.intention, Intention::Leave);
        let content = Percept { content: true, ..p };
        assert_eq!(
            g.decide(&h, &state(0.1, 0.1, 0.0), &content, None)
                .intention,
            Intention::Wander
        );
    }

    #[test]
    fn persistence_decides_whether_a_nearer_target_wins() {
        let hungry = state(0.9, 0.0, 0.0);
        for (persistence, switches) in [(0.0, true), (20.0, false)] {
            let h = Habits {
                persistence_body_lengths: persistence,
                ..prey()
            };
            let mut g = IntentionGenerator::default();
            let mut p = Percept {
                food: vec![(1, 3.0)],
                ..Default::default()
            };
            g.decide(&h, &hungry, &p, None);
            p.food = vec![(2, 1.0), (1, 3.0)];
            let f = g.decide(&h, &hungry, &p, None);
            let expected = if switches {
                Target::Food(2)
            } else {
                Target::Food(1)
            };
            assert_eq!(f.target, Some(expected), "persistence {persistence}");
        }
    }
}
