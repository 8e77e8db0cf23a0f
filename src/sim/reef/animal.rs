//! The reef's animals, the data every stage of the step reads or writes: a
//! body with its [`Drive`] and a mind (habits, mental state, intention
//! generator, focus). The minds stage lives here too ([`ReefAnimal::think`]):
//! from what the animal perceived, its mental state is updated and the
//! intention generator chooses an intention and a focus (Tu & Terzopoulos
//! §5–6, `reef/mind/`).

use std::collections::VecDeque;

use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::sim::reef::bodies::{Drive, ReefBody};
use crate::sim::reef::courtship::Partner;
use crate::sim::reef::environment::Environment;
use crate::sim::reef::mind::{
    FishKind, Focus, Habits, Intention, IntentionGenerator, MentalState, Percept, Sex,
};

/// Most animals in a reef.
pub const MAX_REEF_ANIMALS: usize = 200;
/// Seconds between mind-history samples.
pub const HISTORY_EVERY_SECS: f64 = 0.5;
/// Mind-history samples kept per animal (2 minutes).
pub const HISTORY_LEN: usize = 240;

/// One sample of an animal's mind, for the inspector's history plot and the
/// reef's CSV export.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MindSample {
    pub time_secs: f32,
    pub hunger: f32,
    pub libido: f32,
    pub fear: f32,
    /// What it meant to do at that moment.
    pub intention: Intention,
}

/// An animal of the reef: body and mind.
#[derive(Clone, Debug)]
pub struct ReefAnimal {
    /// The habits in use: the demo's own with the teacher's traits put in.
    pub habits: Habits,
    /// The habits the demo gave this animal.
    pub demo_habits: Habits,
    pub mental: MentalState,
    pub generator: IntentionGenerator,
    /// This step's intention and target.
    pub focus: Focus,
    pub body: ReefBody,
    /// Colour around the colour wheel, 0..1.
    pub hue: f32,
    /// Eaten animals stay in the list (indices are names) but no longer live.
    pub alive: bool,
    /// Is the mouth open (sucking in)?
    pub mouth_open: bool,
    /// The velocity the behaviour asked for last step, m/s.
    pub desired_m_per_s: Vec3,
    /// Mean brightness of the retinal image (refreshed about every 4 s, one
    /// fish in four each second).
    pub brightness: f32,
    /// Water temperature at the centre, °C.
    pub temperature_c: f32,
    /// Recent hunger, libido and fear.
    pub history: VecDeque<MindSample>,
    /// The predator last seen, where, and for how many more seconds it is
    /// remembered (see [`crate::sim::reef::params::ReefParams::threat_memory_secs`]):
    /// the fish flees from where it last saw a predator it has lost from view.
    pub last_threat: Option<(u32, Vec3, f32)>,
    /// The courting partner last seen, how it looked, and for how many more
    /// seconds it is remembered (the same
    /// [`crate::sim::reef::params::ReefParams::threat_memory_secs`] as a
    /// predator): a courting fish follows its partner where it sees it, or
    /// where it last saw it, never where it went unseen.
    pub last_mate: Option<(u32, Partner, f32)>,
    /// What the body keeps between steps for moving (the bodies stage's).
    drive: Drive,
}

/// One animal's memory of another (a predator, a courting partner): what it
/// sees now, kept for `memory_secs`; out of view, what it last saw, for
/// `dt_secs` less each step, then forgotten.
fn remember<T>(
    kept: Option<(u32, T, f32)>,
    sighted: Option<(u32, T)>,
    memory_secs: f32,
    dt_secs: f32,
) -> Option<(u32, T, f32)> {
    match sighted {
        Some((j, looks)) => Some((j, looks, memory_secs)),
        None => kept
            .map(|(j, looks, left)| (j, looks, left - dt_secs))
            .filter(|k| k.2 > 0.0),
    }
}

/// An animal of `kind` numbered `index`: "shark 3", "fish 7", "pacifist 2",
/// in the language in force.
pub fn animal_name(kind: FishKind, index: usize) -> String {
    let kind = match kind {
        FishKind::Predator => "shark",
        FishKind::Prey => "fish",
        FishKind::Pacifist => "pacifist",
    };
    crate::tr!("reef-animal", kind = kind, index = index)
}

/// What the others see of one animal this step, read before anyone moves:
/// the input of every animal's perception and behaviour.
#[derive(Clone, Copy, Debug)]
pub(super) struct Seen {
    pub position_m: Vec3,
    pub head_m: Vec3,
    pub heading: Vec3,
    pub velocity_m_per_s: Vec3,
    pub length_m: f32,
    pub alive: bool,
    pub kind: FishKind,
    pub sex: Sex,
    pub species: u8,
    /// Swims in a school now, whatever its intention (see
    /// [`crate::sim::reef::perception::in_a_school`]).
    pub schooling: bool,
}

impl Seen {
    /// How `a` looks now (`schooling` is filled in by the perception stage).
    pub(super) fn of(a: &ReefAnimal) -> Self {
        Self {
            position_m: a.body.position_m(),
            head_m: a.body.head_m(),
            heading: a.body.heading(),
            velocity_m_per_s: a.body.velocity_m_per_s(),
            length_m: a.body.body_length_m(),
            alive: a.alive,
            kind: a.habits.kind,
            sex: a.habits.sex,
            species: a.habits.species,
            schooling: false,
        }
    }
}

/// What the minds stage reads besides the animal: what it perceived and the
/// world around it.
pub(super) struct MindInputs<'a> {
    pub percept: &'a Percept,
    /// Its distances (in its body lengths) to the predators it fears.
    pub predator_distances: Vec<f32>,
    /// The most frightening predator actually in view, and where it is.
    pub sighted: Option<(u32, Vec3)>,
    /// The courting partner it follows, if in view, and how it looks.
    pub mate_sighted: Option<(u32, Partner)>,
    /// Its bonded courtship partner, if it has one.
    pub partner: Option<u32>,
    pub env: &'a Environment,
    pub threat_memory_secs: f32,
    pub dt_secs: f32,
}

impl ReefAnimal {
    /// A newborn animal of `habits` with `body` (born at `position_m`,
    /// `length_m` long), swimming at `velocity_m_per_s`, in water of
    /// `brightness` and `temperature_c`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn new(
        habits: Habits,
        body: ReefBody,
        hue: f32,
        position_m: Vec3,
        length_m: f32,
        velocity_m_per_s: Vec3,
        brightness: f32,
        temperature_c: f32,
    ) -> Self {
        let habits = habits.sanitized();
        let drive = Drive::new(position_m, velocity_m_per_s, length_m, hue);
        Self {
            mental: MentalState::new(&habits.mental, 0.0, 0.0),
            habits,
            demo_habits: habits,
            generator: IntentionGenerator::default(),
            focus: Focus::WANDER,
            body,
            hue,
            alive: true,
            mouth_open: false,
            desired_m_per_s: velocity_m_per_s,
            brightness,
            temperature_c,
            history: VecDeque::new(),
            last_threat: None,
            last_mate: None,
            drive,
        }
    }

    /// "shark 3", "fish 7", "pacifist 2", in the language in force.
    pub fn name(&self, index: usize) -> String {
        animal_name(self.habits.kind, index)
    }

    /// What the body keeps between steps for moving.
    pub(super) fn drive_mut(&mut self) -> &mut Drive {
        &mut self.drive
    }

    /// The body and its drive, both to be moved by the bodies stage.
    pub(super) fn body_and_drive_mut(&mut self) -> (&mut ReefBody, &mut Drive) {
        (&mut self.body, &mut self.drive)
    }

    /// Puts the body down at `position_m` heading along `heading`, at rest
    /// (a test or a teacher's drag).
    pub(super) fn place(&mut self, position_m: Vec3, heading: Vec3) {
        let length = self.body.body_length_m();
        self.body = self.body.placed(position_m, heading, length);
        let intended_m_per_s = self.body.heading() * 0.5 * self.body.top_speed_m_per_s();
        self.drive.placed(position_m, intended_m_per_s);
    }

    /// The minds stage for this animal: remembers the predator in view (or
    /// forgets one lost from view a little more), feels the water's
    /// temperature, updates hunger, libido and fear, and lets the intention
    /// generator choose this step's focus. Returns the focus before.
    pub(super) fn think(&mut self, inputs: MindInputs) -> Focus {
        let dt = inputs.dt_secs;
        let memory = inputs.threat_memory_secs;
        self.last_threat = remember(self.last_threat, inputs.sighted, memory, dt);
        self.last_mate = remember(self.last_mate, inputs.mate_sighted, memory, dt);
        self.temperature_c = inputs.env.temperature_c_at(self.body.position_m());
        self.mental
            .update(&self.habits.mental, dt, inputs.predator_distances);
        // Predators feel no fear and no libido; prey do not mate (§7.1–7.2).
        match self.habits.kind {
            FishKind::Predator => (self.mental.fear, self.mental.libido) = (0.0, 0.0),
            FishKind::Prey => self.mental.libido = 0.0,
            FishKind::Pacifist => {}
        }
        let before = self.focus;
        self.focus =
            self.generator
                .decide(&self.habits, &self.mental, inputs.percept, inputs.partner);
        before
    }

    /// Keeps a sample of the mind at `time_secs` (the last
    /// [`HISTORY_LEN`]).
    pub(super) fn record_history(&mut self, time_secs: f32) {
        if self.history.len() == HISTORY_LEN {
            self.history.pop_front();
        }
        self.history.push_back(MindSample {
            time_secs,
            hunger: self.mental.hunger,
            libido: self.mental.libido,
            fear: self.mental.fear,
            intention: self.focus.intention,
        });
    }
}
