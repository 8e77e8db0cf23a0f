//! The reef's tuning (issue 17: one tuning struct per model, as rapier's
//! `IntegrationParameters`): every chosen or tuned number that shapes how the
//! reef's fish behave, with its value, unit and source. The world holds one
//! ([`ReefParams::default`]) and reads it; `ReefWorld::params` shows it.
//!
//! Paper data stays where it is: the body (node masses, spring stiffnesses)
//! in `body/body_layout.rs`, the mind's rates in `mind/mental_state.rs` and
//! `mind/habits.rs`, the paper's field of view and prey-cost weights β1, β2
//! in `reef/perception.rs`. Array sizes, counts and logging intervals stay consts
//! (`MAX_REEF_ANIMALS`, `MAX_FOOD`, `HISTORY_LEN`, `EVENT_LOG_LEN`, …), as does
//! the point body's time step (`POINT_BODY_DT_SECS`, the world clock).

use crate::sim::body::drive::DriveParams;
use crate::sim::common::steering_tuning::SteeringTuning;

/// The reef's tuning.
#[derive(Clone, Debug, PartialEq)]
pub struct ReefParams {
    /// The shared "steer a muscle fish within its body's reach" recipe, with the
    /// reef's containment ([`DriveParams::reef`]: 8 s ahead, 1.5 body lengths;
    /// the response time of 0.25 s, as the physics tank's).
    pub drive: DriveParams,
    /// The shared steering layer's recipe ([`SteeringTuning::default`]): the
    /// wander pitch's fade and the rock algorithm's clearance (to which the reef's
    /// fish add half their body length).
    pub steering: SteeringTuning,
    /// The courtship routine's numbers (`reef/courtship.rs`).
    pub courtship: CourtshipParams,
    /// The behaviour routines' numbers (`reef/behaviour.rs`).
    pub behaviour: BehaviourParams,
    /// The motor choice's numbers (`reef/motor_choice.rs`).
    pub motor_choice: MotorChoiceParams,
    /// The vision sensor's and the school test's numbers (`reef/perception.rs`).
    pub perception: PerceptionParams,
    /// Longest time since the last meal (and mating) a reef fish starts with,
    /// seconds. 30, chosen: the clocks differ from fish to fish, and a fish with
    /// Shoal's calm p0 that ate 0.7 of its appetite 30 s ago has hunger 0.55.
    pub start_fed_for_max_secs: f32,
    /// The *Courtship* demo's digestion rate as a fraction of the nominal p0. 0.1,
    /// chosen: see the demo's setup in `populate`.
    pub courtship_digestion_fraction: f32,
    /// Food within this distance of the mouth, and in front of it
    /// ([`ReefParams::suck_cone_cos`]), is sucked in, body lengths (1.0, chosen: the muscle
    /// body turns in circles of about two body lengths, so it passes food at
    /// about a body length more often than it meets it head on; with 0.4 and
    /// 0.8 six hungry fish ate 0 and 1 particles in a minute, measured).
    pub suck_range_body_lengths: f32,
    /// How many metres of level swimming a metre of climbing or diving costs a
    /// muscle fish choosing its food (its perceptual focusser weighs the food's
    /// distance so, §6.3). 1.5, chosen: chasing food, the fins trim the muscle
    /// body to climb at up to 44° (`MotorChoiceParams::forage_max_fin_pitch_rad`,
    /// `BodyParams::fin_trim_gain`) and it turns in a circle of 1.2 body
    /// lengths, so food overhead is reached by a spiral. *Feeding*, seeds 1–8,
    /// 60 / 132 s (`shoal-census feeding-agility`): 202 / 469 plankton with 1.5, 170 /
    /// 407 with 4 (point masses 342 / 723). With the old 29° climbs 4 was best
    /// (seeds 1–8, 60 s, before the libm change: 45 with 1, 116 with 2, 149
    /// with 4, 134 with 10; `docs/departures.md`, climb effort). The
    /// point-mass body climbs as fast as it swims (1).
    pub climb_effort_muscle_body: f32,
    /// How much of the detour round its turning circle a muscle fish counts
    /// when it ranks the food it sees: the level distance it ranks by is the
    /// straight distance plus this share of the difference between the path it
    /// must swim (an arc of its turning circle,
    /// [`ReefParams::body_turn_radius_body_lengths`], then straight on;
    /// `behaviour::level_reach_m`) and the straight distance. 0 ranks by distance.
    /// Default 0.5 (chosen, issue 13): the muscle body turns at about 24°/s at
    /// most whatever its speed (its circle does not shrink when it slows down,
    /// `shoal-census held-bend-radius`), so food a metre
    /// behind it is further in time than food two metres ahead. *Feeding*, six
    /// ravenous fish, seeds 1–8, 60 s: 142 plankton with 0, 145 with 0.3, 165
    /// with 0.5, 174 with 1 (point masses 342); ranking by distance, the fish
    /// spent a third of their chases with the food 90° or more off their heading,
    /// with 0.5 a fifth, with 1 a twentieth (`shoal-census feeding-time-budget`). With 1, a school of muscle prey in the default
    /// reef lined up on the one particle ahead of them all and jammed there
    /// (seeds 1–8, 1 minute: 136 collision starts, 107 with 0, 118 with 0.5).
    /// The point-mass body turns on the spot and ranks by distance.
    pub turning_path_weight: f32,
    /// The vacuum acts in the half-space ahead of the mouth (cos 90° = 0).
    pub suck_cone_cos: f32,
    /// A predator opens its mouth on prey within this distance, body lengths (0.6).
    pub predator_suck_range_body_lengths: f32,
    /// Prey whose centre comes this close to the predator's mouth is swallowed,
    /// body lengths of the predator (0.3, chosen).
    pub swallow_body_lengths: f32,
    /// Pull of the vacuum on food, m/s at the mouth (0.6).
    pub vacuum_speed_m_per_s: f32,
    /// Pull of the vacuum on prey, m/s² (2, chosen: a fleeing fish at top speed
    /// still slips away from a mouth it is not already in).
    pub vacuum_accel_m_per_s2: f32,
    /// A food particle this close to the mouth is eaten, metres (0.06).
    pub eat_distance_m: f32,
    /// Sinking speed of plankton, m/s (0.01).
    pub plankton_sink_m_per_s: f32,
    /// One new particle is released every this many seconds while fewer than the
    /// target count drift in the water (1.5).
    pub food_release_secs: f32,
    /// Radius of the muscle body's turning circle, body lengths (1.2: measured
    /// 1.03–1.14 for 90° turns from 0.4–1.0 of the top speed on the converged body,
    /// `body/physical_fish.rs` agility tests, docs/fish-body.md; a little more for margin.
    /// It was 0.75 on the earlier body, which turned in 0.6–0.7. In the *Feeding*
    /// demo, seeds 3 and 4, 60 s, muscle fish ate 32 plankton with 0.75, 34 with 1.2
    /// and 35 with 0: within the seed noise.)
    pub body_turn_radius_body_lengths: f32,
    /// A predator that leaves the field of view still frightens for this long,
    /// seconds, at the place it was last seen (3, chosen: the paper's fear counts
    /// sighted predators only, and a fleeing fish that turned its blind cone to the
    /// shark stopped, turned back to look, and fled again, measured).
    pub threat_memory_secs: f32,
    /// How far from the glass a fish keeps while it closes in on its food, prey
    /// or partner, body lengths; it then also heeds only the glass it would reach
    /// before the target. Default 0.3 (chosen). With the cruising margin of 1.5
    /// body lengths a one-metre shark turned away a metre and a half from the
    /// glass, so prey that fled to the glass could never be reached: loners
    /// escaped a hungry shark by hiding in corners (measured: one prey in 40
    /// minutes, against nine from schools).
    pub chase_glass_margin_body_lengths: f32,
    /// How close other prey must be to a predator's target to confuse its
    /// strike, in the target's body lengths. Default 2 (chosen: the spacing of a
    /// loose school, Pitcher & Partridge 1979 give about one body length between
    /// neighbours).
    pub confusion_radius_body_lengths: f32,
    /// The confusion effect (Neill & Cullen 1974; Landeau & Terborgh 1986: a
    /// predator's success per attack falls as the prey group grows, because many
    /// similar targets moving together make it hard to fix on one): a strike on
    /// prey with `n` other prey near it succeeds with probability
    /// 1 / (1 + c n), c this constant. Default 1 (chosen): one neighbour halves
    /// the success, six leave one strike in seven; with 0.5 (tried first) the
    /// schools were hardly safer than loners (105 against 130 prey eaten in
    /// 12 × 2 minutes, with 1: 88 against 129; `docs/fish-mind.md`). Not in
    /// Tu & Terzopoulos, whose schooling prey are protected only by the
    /// predator's choice (β1); without it a shark faster than its prey catches
    /// schooling and lone prey at the same rate once it has chosen.
    pub confusion_per_neighbour: f32,
    /// The confusion effect on or off (the settings' `predation.confusion`).
    /// Default on. Off, every strike that reaches its prey succeeds, as in
    /// Tu & Terzopoulos, whatever the crowd around the prey.
    pub confusion: bool,
    /// Joint flight on or off (the settings' `predation.joint_flight`). Default
    /// on: a schooling fish that flees keeps with the schoolmates it sees
    /// ([`crate::sim::reef::behaviour::escape_with_school`], our addition). Off,
    /// every fish flees straight away from the predator alone, the paper's
    /// escape routine (§7.2).
    pub joint_flight: bool,
    /// Seconds a predator needs after a missed strike before it can strike again
    /// (mouth closed, still chasing). Default 1.5 (chosen: long enough for the
    /// prey's dart to take it out of the mouth's reach).
    pub missed_strike_recovery_secs: f32,
}

impl Default for ReefParams {
    fn default() -> Self {
        Self {
            drive: DriveParams::reef(),
            steering: SteeringTuning::default(),
            courtship: CourtshipParams::default(),
            behaviour: BehaviourParams::default(),
            motor_choice: MotorChoiceParams::default(),
            perception: PerceptionParams::default(),
            start_fed_for_max_secs: 30.0,
            courtship_digestion_fraction: 0.1,
            suck_range_body_lengths: 1.0,
            climb_effort_muscle_body: 1.5,
            turning_path_weight: 0.5,
            suck_cone_cos: 0.0,
            predator_suck_range_body_lengths: 0.6,
            swallow_body_lengths: 0.3,
            vacuum_speed_m_per_s: 0.6,
            vacuum_accel_m_per_s2: 2.0,
            eat_distance_m: 0.06,
            plankton_sink_m_per_s: 0.01,
            food_release_secs: 1.5,
            body_turn_radius_body_lengths: 1.2,
            threat_memory_secs: 3.0,
            chase_glass_margin_body_lengths: 0.3,
            confusion_radius_body_lengths: 2.0,
            confusion_per_neighbour: 1.0,
            confusion: true,
            joint_flight: true,
            missed_strike_recovery_secs: 1.5,
        }
    }
}

/// The courtship routine's tuning (Tu & Terzopoulos §7.3, `reef/courtship.rs`).
#[derive(Clone, Debug, PartialEq)]
pub struct CourtshipParams {
    /// Passes of the male's mouth through the looping point before circling (the
    /// paper: "currently 6").
    pub loops_to_circle: u32,
    /// Full turns the female makes while circling before the ascent (the paper: "a
    /// fixed number"; 1.5, chosen: long enough to see, short for a slow body).
    pub circling_turns: f32,
    /// Touches of the male's mouth on the female's abdomen (the paper: "e.g., 3").
    pub nuzzles: u32,
    /// Seconds the male backs off after a touch (2, chosen).
    pub back_off_secs: f32,
    /// Seconds of ascent before the female hovers (6, chosen), or until she is a
    /// body length under the surface.
    pub ascent_secs: f32,
    /// A phase that lasts longer than this breaks the pair up, seconds (150).
    pub phase_timeout_secs: f32,
    /// A partner out of sight this long breaks the pair up, seconds (10).
    pub lost_secs: f32,
    /// Frequency of the looping point's up-and-down motion, Hz (0.2, chosen).
    pub loop_hz: f32,
    /// The male's speed while looping, fraction of his top speed (0.5, chosen). The
    /// paper's male loops "vigorously"; at 0.9 the muscle male overshot the point
    /// and swam wide circles back to it, passing it once in 15–40 s: with the fin
    /// brace of `body::body_layout`, 6 of 8 seeds spawned within 5 minutes at 0.9,
    /// 8 of 8 at 0.7 and at 0.5, at 0.5 sooner (104–167 s; 15 of seeds 1–16;
    /// point-mass pairs 16 of 16 at 43–61 s). `shoal-census courtship-seeds`.
    pub loop_speed_fraction: f32,
    /// The male's mouth within this many body lengths of the looping point counts
    /// one pass (the paper: "reaches the vicinity"; 1.0, chosen: the muscle body
    /// loops in circles about two body lengths wide and passed within half a
    /// length too rarely to finish in minutes, measured).
    pub pass_body_lengths: f32,
    /// Seconds between two counted passes (3, chosen: one pass per swing).
    pub pass_interval_secs: f32,
    /// The male's look-ahead along her axis while he swims in for a touch, and how
    /// far behind her abdomen he goes first when he is beside or ahead of her, his
    /// body lengths (3, chosen: more than twice the muscle body's turning radius,
    /// `ReefParams::body_turn_radius_body_lengths`, so the look-ahead point is never
    /// inside his turning circle, where the chase swims straight on. Seeds 1–8 /
    /// 1–16 spawning within 5 minutes on muscle bodies, `shoal-census
    /// courtship-seeds`: look-ahead 1.5: 5 / 10; 2.5: 6 / 14; 3: 7 / 14; the earlier
    /// fixed line-up point 1.5 behind her: 1 / 4.)
    pub staging_body_lengths: f32,
    /// The male's mouth within this many body lengths of her abdomen is a touch (0.35).
    pub touch_body_lengths: f32,
}

impl Default for CourtshipParams {
    fn default() -> Self {
        Self {
            loops_to_circle: 6,
            circling_turns: 1.5,
            nuzzles: 3,
            back_off_secs: 2.0,
            ascent_secs: 6.0,
            phase_timeout_secs: 150.0,
            lost_secs: 10.0,
            loop_hz: 0.2,
            loop_speed_fraction: 0.5,
            pass_body_lengths: 1.0,
            pass_interval_secs: 3.0,
            staging_body_lengths: 3.0,
            touch_body_lengths: 0.35,
        }
    }
}

/// The behaviour routines' tuning (Tu & Terzopoulos §6.4 and §7.2,
/// `reef/behaviour.rs`).
#[derive(Clone, Debug, PartialEq)]
pub struct BehaviourParams {
    /// Cruising speed, fraction of the top speed (0.7, the physics scene's value).
    pub cruise_fraction: f32,
    /// Speed while avoiding, fraction of the top speed: slow enough to turn
    /// tightly, fast enough for the turn-MC's thrust (0.5).
    pub avoid_fraction: f32,
    /// Distance kept between schooling neighbours, body lengths ("roughly one body
    /// length", §7.2; 1).
    pub school_spacing_body_lengths: f32,
    /// Slowest a schooling fish swims to match slow neighbours, fraction of its top
    /// speed (0.2: the point-mass body's minimum speed in the reef; a muscle body
    /// slower than that barely turns).
    pub school_min_speed_fraction: f32,
    /// Steepest climb or dive of a chase by a body that turns in circles, radians
    /// (0.44, 25°, the physics tank's limit on intended pitch).
    pub max_chase_pitch_rad: f32,
    /// How much a fleeing schooling fish follows its own flight rather than its
    /// school (0–1). Default 0.6 (chosen: the school stays together but every
    /// fish still turns away from the predator).
    pub escape_share_in_school: f32,
    /// Does a fleeing schooling fish that sees schoolmates swim in the school's
    /// gait ([`crate::sim::reef::motor_choice::Gait::School`]: on the muscle
    /// body, the boid layer's intended velocity through the desired-velocity
    /// bridge, as when schooling) rather than the swim gait, whose turns of
    /// [`MotorChoiceParams::turn_mc_min_deg`] or more are ballistic turn-MC
    /// turns? Default true (chosen, measured: with
    /// the swim gait each fish of a fleeing muscle school turned alone, for 4–7
    /// s, and the school scattered where the predator struck; see
    /// `docs/fish-mind.md`, "Lone against schooling prey"). The point-mass body
    /// has no gaits.
    pub escape_in_school_gait: bool,
    /// The school routine's urgency in the flight of a muscle fish fleeing in
    /// the school's gait (0–1; the swim gait and the point-mass body use 1, full
    /// fright, whose spacing is 0.7 of [`Self::school_spacing_body_lengths`]).
    /// Default 0.5 (chosen, measured: spacing 0.85; with 1 the bridge held the
    /// fleeing school so tight that fish collisions in the default reef on
    /// muscles rose by a quarter, seeds 1–8 × 1 min: 147 against 118 in the
    /// swim gait; with 0.5, 124).
    pub escape_fright_in_school_gait: f32,
    /// Steepest climb or dive of a chase for food by a body that turns in
    /// circles, radians (0.7, chosen with
    /// [`MotorChoiceParams::forage_max_fin_pitch_rad`], see there; at 0.44, as
    /// the other chases, *Feeding* seeds 1–8 gave 186 / 436 plankton in 60 /
    /// 132 s against 190 / 450, with the fins at 0.5 both).
    /// Other chases keep [`BehaviourParams::max_chase_pitch_rad`].
    pub max_food_chase_pitch_rad: f32,
}

impl Default for BehaviourParams {
    fn default() -> Self {
        Self {
            cruise_fraction: 0.7,
            avoid_fraction: 0.5,
            school_spacing_body_lengths: 1.0,
            school_min_speed_fraction: 0.2,
            max_chase_pitch_rad: 0.44,
            escape_share_in_school: 0.6,
            escape_in_school_gait: true,
            escape_fright_in_school_gait: 0.5,
            max_food_chase_pitch_rad: 0.7,
        }
    }
}

/// The motor choice's tuning (the muscle body's motor controllers for a
/// routine's wish, `reef/motor_choice.rs`).
#[derive(Clone, Debug, PartialEq)]
pub struct MotorChoiceParams {
    /// Smallest heading error the routine turns with a turn-MC turn, degrees: 90,
    /// chosen, a goal at the fish's side or behind it (`docs/fish-mind.md`: the six
    /// hungry fish of the *Feeding* demo ate 99, 145 and 160 plankton in 4 × 132 s
    /// with 45°, 90° and 120°, 173 with the held bend alone: a turn-MC turn swims a
    /// wide arc at full beat and overshoots near food). Below it the held bend
    /// keeps the course (see `reef/motor_choice.rs`'s module doc).
    pub turn_mc_min_deg: f32,
    /// Bend per radian of heading error while keeping the course, 1/rad (3: full bend
    /// from 19° of error). The physics scene's bridge, which turns whole corners with
    /// the held bend, uses 4 (`MotorParams::steer_gain_per_rad`); here, where turns
    /// of 90° and more go to the turn-MC, 4 measured worse on the reef demos (feeding
    /// seeds 3–4: 27 plankton against 32 at 3; courtship seed 2 reached only nuzzling;
    /// 25 collision starts in the muscle reef's minute on seed 2).
    pub course_gain_per_rad: f32,
    /// Fin pitch per radian of elevation error (2, chosen: a 15° climb request tilts
    /// the fins by the full 0.5 rad).
    pub pitch_gain: f32,
    /// Largest fin pitch while swimming, radians (0.5, as in the fin tests of
    /// `body/tests.rs`).
    pub max_fin_pitch_rad: f32,
    /// A fish swimming faster than this share of its top speed brakes with its fins
    /// when the routine wants less than half its speed (0.3, the bridge's rule).
    pub brake_above_fraction: f32,
    /// swim-MC speed of a bobbing fish, fraction of the top speed (0.15, chosen:
    /// enough water over the fins to lift and sink the fish, slow enough for the
    /// braking fins to hold it almost in place; measured in `body/physical_fish.rs`).
    pub bob_swim_fraction: f32,
    /// Bobbing frequency, Hz (0.5, chosen: one rise and fall every 2 s).
    pub bob_hz: f32,
    /// Fin angle of a bobbing fish while it rises, radians from flat (1.1, chosen:
    /// leading edge well up, the fin brakes and lifts). While it sinks the fins are
    /// tilted the other way as far as they go (θ = π/4).
    pub bob_lift_pitch_rad: f32,
    /// Largest fin pitch while chasing food
    /// ([`crate::sim::reef::motor_choice::Gait::Forage`]), radians. 0.7,
    /// chosen. A food chase sets its fins to the wished climb itself (not to
    /// twice the error from the body's pitch, as the other gaits do), and the
    /// fins trim the body (`BodyParams::fin_trim_gain`, up to
    /// `BodyParams::max_trim_rad` 0.7, the part beyond 0.5 rate-limited,
    /// `BodyParams::max_trim_rate_rad_per_s`): a fish at 0.7 of its top speed
    /// climbs at 44° (`shoal-census climb-angle`;
    /// 32° at 0.5). *Feeding* on muscles, 60 / 132 s (`shoal-census feeding-agility`):
    /// seeds 1–8, 202 / 469 plankton (190 / 450 with 0.5, 165 / 375 with the
    /// old fin law, 0.5 rad and climb effort 4); seeds 1–16, 420 / 956 (point
    /// masses 342 / 723 and 730 / 1487). Default reef, seeds 1–40 × 132 s: no
    /// fold, no body out of the tank. With the old fin law (2 × the error) the
    /// fins flipped from full climb to full dive from one step to the next and
    /// at 0.7 folded tail fins; at 0.8 and 1.0 bodies blew up (docs/fish-body.md,
    /// "Foraging agility").
    pub forage_max_fin_pitch_rad: f32,
}

impl Default for MotorChoiceParams {
    fn default() -> Self {
        Self {
            turn_mc_min_deg: 90.0,
            course_gain_per_rad: 3.0,
            pitch_gain: 2.0,
            max_fin_pitch_rad: 0.5,
            brake_above_fraction: 0.3,
            bob_swim_fraction: 0.15,
            bob_hz: 0.5,
            bob_lift_pitch_rad: 1.1,
            forage_max_fin_pitch_rad: 0.7,
        }
    }
}

/// The perception's tuning (`reef/perception.rs`). The paper's numbers (the 300°
/// field of view, the prey cost's β1 and β2) stay consts there.
#[derive(Clone, Debug, PartialEq)]
pub struct PerceptionParams {
    /// Radius of the sphere by which a fish's body hides what lies behind it, body
    /// lengths (0.3, chosen). The body is drawn, and rendered in the retina, as an
    /// ellipsoid 1 body length long and 0.3 across; seen from the side it covers
    /// π · 0.5 · 0.15 ≈ 0.24 square body lengths, as much as a disc of radius 0.27.
    /// 0.3 rounds that up a little for the fins.
    pub occluder_radius_body_lengths: f32,
    /// A fish swims in a school (S_k = 1 in the prey cost) when at least this many
    /// live fish of its kind and species are within
    /// [`PerceptionParams::schoolmate_radius_body_lengths`] and head within
    /// [`PerceptionParams::schoolmate_max_angle_rad`] of its heading (2, chosen: the
    /// fewest that make a group around the fish, not a pair passing by).
    pub schoolmates_for_s_k: usize,
    /// How near a schoolmate must be, body lengths of the fish (3, chosen: schooling
    /// fish keep about one body length apart, §7.2, so a fish in a school has its
    /// nearest mates within one or two; three tolerates a school loosened by a turn
    /// or a swerve).
    pub schoolmate_radius_body_lengths: f32,
    /// Largest angle between a schoolmate's heading and the fish's, radians (π/4, 45°,
    /// chosen: a school swims roughly the same way; a fish crossing its path at a
    /// right angle does not school with it).
    pub schoolmate_max_angle_rad: f32,
}

impl Default for PerceptionParams {
    fn default() -> Self {
        Self {
            occluder_radius_body_lengths: 0.3,
            schoolmates_for_s_k: 2,
            schoolmate_radius_body_lengths: 3.0,
            schoolmate_max_angle_rad: std::f32::consts::FRAC_PI_4,
        }
    }
}
