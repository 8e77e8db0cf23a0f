//! The reef's part of `shoal.state()`: who is alive, counts, courting pairs,
//! the latest events and the selected fish's mind.

use serde::Serialize;

use super::mind::FishKind;
use super::world::{ReefBody, ReefWorld};

/// The reef scene as `shoal.state().reef` reports it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ReefReport {
    pub demo: crate::sim::reef::demos::ReefScene,
    pub body: crate::sim::reef::world::ReefBodyKind,
    /// Living animals by kind.
    pub predators: usize,
    pub prey: usize,
    pub pacifists: usize,
    pub food: usize,
    pub counts: crate::sim::reef::world::ReefCounts,
    /// Courting pairs: male, female, phase.
    pub pairs: Vec<(u32, u32, crate::sim::reef::courtship::Phase)>,
    /// The last 20 events, oldest first.
    pub events: Vec<crate::sim::reef::events::ReefEvent>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub selected: Option<SelectedMindReport>,
}

/// The selected reef fish: body, habits and mind.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SelectedMindReport {
    pub index: usize,
    pub name: String,
    pub alive: bool,
    pub habits: crate::sim::reef::mind::Habits,
    pub hunger: f32,
    pub libido: f32,
    pub fear: f32,
    pub intention: crate::sim::reef::mind::Intention,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target: Option<crate::sim::reef::mind::Target>,
    /// The single-item memory: an intention interrupted by an avoidance.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub remembered: Option<crate::sim::reef::mind::Focus>,
    pub mouth_open: bool,
    /// Mean brightness of its retinal image, [0, 1].
    pub brightness: f32,
    pub temperature_c: f32,
    pub position_m: [f32; 3],
    pub heading: [f32; 3],
    pub speed_m_per_s: f32,
    /// The velocity its behaviour routine asked for.
    pub desired_velocity_m_per_s: [f32; 3],
    /// Muscle body only: swim-MC speed fraction and the 12 muscles.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub swim_speed_fraction: Option<f32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub muscles: Option<[f32; crate::sim::body::MUSCLE_COUNT]>,
}

/// The reef's numbers at one instant: living animals by kind, plankton in the
/// water and the counters since the start. The lab keeps one every metrics
/// sample for the CSV export's counts table.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ReefCensus {
    pub time_secs: f64,
    pub predators: usize,
    pub prey: usize,
    pub pacifists: usize,
    /// Plankton particles drifting now.
    pub food: usize,
    pub counts: crate::sim::reef::world::ReefCounts,
}

impl ReefWorld {
    /// Living animals by kind, food and the counters now.
    pub fn census(&self) -> ReefCensus {
        let alive = |kind: FishKind| self.living().filter(|(_, a)| a.habits.kind == kind).count();
        ReefCensus {
            time_secs: self.time_secs(),
            predators: alive(FishKind::Predator),
            prey: alive(FishKind::Prey),
            pacifists: alive(FishKind::Pacifist),
            food: self.food().len(),
            counts: self.counts(),
        }
    }

    /// What `shoal.state().reef` reports, with `selected`'s mind in detail.
    pub fn report(&self, selected: Option<u32>) -> ReefReport {
        let reef = self;
        let alive = |kind: FishKind| {
            reef.animals()
                .iter()
                .filter(|a| a.alive && a.habits.kind == kind)
                .count()
        };
        let selected = selected.and_then(|i| {
            let index = i as usize;
            let a = reef.animals().get(index)?;
            let (swim_speed_fraction, muscles) = match &a.body {
                ReefBody::Physical(p) => (Some(p.motor().speed_fraction), Some(p.motor().muscles)),
                ReefBody::Point(_) => (None, None),
            };
            Some(SelectedMindReport {
                index,
                name: a.name(index),
                alive: a.alive,
                habits: a.habits,
                hunger: a.mental.hunger,
                libido: a.mental.libido,
                fear: a.mental.fear,
                intention: a.focus.intention,
                target: a.focus.target,
                remembered: a.generator.memory,
                mouth_open: a.mouth_open,
                brightness: a.brightness,
                temperature_c: a.temperature_c,
                position_m: a.body.position_m().to_array(),
                heading: a.body.heading().to_array(),
                speed_m_per_s: a.body.velocity_m_per_s().length(),
                desired_velocity_m_per_s: a.desired_m_per_s.to_array(),
                swim_speed_fraction,
                muscles,
            })
        });
        let events = reef.events();
        ReefReport {
            demo: reef.config().scene,
            body: reef.config().body,
            predators: alive(FishKind::Predator),
            prey: alive(FishKind::Prey),
            pacifists: alive(FishKind::Pacifist),
            food: reef.food().len(),
            counts: reef.counts(),
            pairs: reef
                .pairs()
                .iter()
                .map(|p| (p.male, p.female, p.phase))
                .collect(),
            events: events
                .iter()
                .skip(events.len().saturating_sub(20))
                .cloned()
                .collect(),
            selected,
        }
    }
}
