//! Share links: the whole setting (scene, presets, sliders, modes, counts, obstacles,
//! seed, compare layout) packed into the URL's fragment, so a teacher can send a
//! class exactly what is on the screen.
//!
//! Format: `#v1.` followed by URL-safe base64 (no padding) of the DEFLATE-compressed
//! JSON of a patch of [`Settings`]: only the settings that differ from the
//! defaults (the shorter the link, the coarser and easier to scan its QR code).
//! The patch is applied to the defaults, as `shoal.set()` applies one, so the
//! first links, which carried every setting, open as they did.
//!
//! A teacher's studio with mystery values (`settings/studio.rs`) keeps them out
//! of the readable JSON: they travel in one field, `"sealed"`, scrambled (see
//! [`seal`]). This is a classroom convention, not cryptography: the scramble's
//! key is made from the link's own text and a constant in Shoal's source, so a
//! student with developer tools and this file can undo it.
//!
//! Decoding never trusts the link: size limits on both the text and the
//! inflated JSON, a checksum on the sealed values, then the same all-or-nothing
//! validation as `shoal.set()`; any failure is a [`ShareLinkError`] with a
//! sentence for the notice, and the caller falls back to the defaults.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;

use crate::i18n::tr;
use serde_json::{Map, Value};

use crate::settings::studio::Studio;
use crate::settings::{Settings, SettingsError, Side};
use crate::tr;

/// Version tag at the start of every link's fragment.
const PREFIX: &str = "v1.";

/// Longest fragment accepted, in characters. Default 16,384: twenty times a full
/// setting with two dozen obstacles, far below what browsers keep in a URL.
pub const MAX_LINK_CHARS: usize = 16_384;

/// Largest inflated JSON accepted, in bytes. Default 65,536: a "zip bomb" link
/// cannot make the page allocate more than this.
const MAX_JSON_BYTES: usize = 65_536;

/// DEFLATE level. Default 9: links are made rarely and should be short.
const COMPRESSION_LEVEL: u8 = 9;

/// Why a link could not be opened (its Display, a sentence for the notice, is
/// the catalogue's `share-link-error-…`).
#[derive(Debug, PartialEq)]
pub enum ShareLinkError {
    TooLong(usize),
    UnknownVersion,
    NotBase64,
    NotDeflate,
    NotJson,
    /// The sealed mystery values do not unscramble (the link was cut or
    /// edited): the catalogue id of the reason.
    Sealed(&'static str),
    Invalid(SettingsError),
}

impl From<SettingsError> for ShareLinkError {
    fn from(err: SettingsError) -> Self {
        Self::Invalid(err)
    }
}

impl std::fmt::Display for ShareLinkError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match self {
            Self::TooLong(chars) => tr!("setting-link-too-long", count = *chars),
            Self::UnknownVersion => tr!("setting-link-unknown-version", tag = PREFIX),
            Self::NotBase64 => tr("setting-link-not-base64"),
            Self::NotDeflate => tr("setting-link-not-deflate"),
            Self::NotJson => tr("setting-link-not-json"),
            Self::Sealed(why) => tr!("setting-link-sealed-damaged", why = tr(why)),
            Self::Invalid(err) => tr!("setting-link-invalid", reason = err.to_string()),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for ShareLinkError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Invalid(err) => Some(err),
            _ => None,
        }
    }
}

/// The fragment (without `#`) that reopens `settings`: the settings that
/// differ from the defaults, the studio's mystery values sealed.
pub fn encode(settings: &Settings) -> String {
    // Serialising plain data cannot fail; an empty object is a safe fallback
    // that decodes to the defaults.
    let full = serde_json::to_value(settings).unwrap_or_else(|_| Value::Object(Map::new()));
    let short = pack_json(&sealed(settings, short_patch(settings, &full)).to_string());
    if decode(&short).ok().flatten().as_ref() == Some(settings) {
        return short;
    }
    // A setting the short patch could not carry exactly (none is known): every
    // setting, as the first links did, the mystery values still sealed.
    pack_json(&sealed(settings, full).to_string())
}

/// The settings of `full` (the JSON of `settings`) that differ from the
/// defaults, as a patch. A tank whose preset is not the default's names it,
/// and differs from that preset's values (a patch loads a preset it names
/// before its other values).
fn short_patch(settings: &Settings, full: &Value) -> Value {
    let mut base = Settings::default();
    for side in Side::BOTH {
        let preset = settings.tank(side).preset;
        if preset != base.tank(side).preset {
            base.tank_mut(side).load_preset(preset);
        }
    }
    let mut base = serde_json::to_value(&base).unwrap_or_default();
    // The defaults leave the (empty) studio out; its fields differ one by one.
    if let Value::Object(base) = &mut base {
        base.insert(
            "studio".to_owned(),
            serde_json::to_value(Studio::default()).unwrap_or_default(),
        );
    }
    let mut patch = difference(&base, full).unwrap_or_else(|| Value::Object(Map::new()));
    for side in Side::BOTH {
        let preset = settings.tank(side).preset;
        if preset != Settings::default().tank(side).preset
            && let Value::Object(patch) = &mut patch
        {
            let tank = patch
                .entry(side.name())
                .or_insert_with(|| Value::Object(Map::new()));
            if let (Value::Object(tank), Ok(name)) = (tank, serde_json::to_value(preset)) {
                tank.insert("preset".to_owned(), name);
            }
        }
    }
    patch
}

/// What of `full` differs from `base`: objects compared key by key, other
/// values whole (a list of obstacles is one value). `None` when nothing does.
fn difference(base: &Value, full: &Value) -> Option<Value> {
    match (base, full) {
        (Value::Object(base), Value::Object(full)) => {
            let out: Map<String, Value> = full
                .iter()
                .filter_map(|(key, value)| {
                    let differs = match base.get(key) {
                        Some(was) => difference(was, value),
                        None => Some(value.clone()),
                    };
                    differs.map(|d| (key.clone(), d))
                })
                .collect();
            (!out.is_empty()).then_some(Value::Object(out))
        }
        _ => (base != full).then(|| full.clone()),
    }
}

/// The top-level field that carries a studio's mystery values, scrambled.
const SEALED: &str = "sealed";

/// Bytes of checksum before the sealed values (3: four base64 characters).
const CHECK_BYTES: usize = 3;

/// The constant mixed into the scramble's key (changing it would stop every
/// shared link with a mystery value from opening).
const SEAL_CONSTANT: &[u8] = b"shoal studio mystery values, v1"; // words: a key for the scramble, never shown

/// `patch` (a link's JSON for `settings`) with the studio's mystery values
/// moved out of their places into one sealed field (all of them, even those
/// equal to the defaults: a value missing from the link would say it is the
/// default). Without mystery values, `patch` unchanged.
fn sealed(settings: &Settings, mut patch: Value) -> Value {
    let keys = settings.studio.sealed_keys();
    if keys.is_empty() {
        return patch;
    }
    let full = serde_json::to_value(settings).unwrap_or_default();
    let mut values = Vec::new();
    for key in &keys {
        let path: Vec<&str> = key.split('.').collect();
        values.push(value_at(&full, &path).cloned().unwrap_or(Value::Null));
        remove_at(&mut patch, &path);
    }
    // A preset that is a mystery because a weight is would name the mix: it
    // is left out, and follows the weights when the link opens.
    for key in settings.studio.mystery_keys() {
        remove_at(&mut patch, &key.split('.').collect::<Vec<_>>());
    }
    if let Value::Object(map) = &mut patch {
        let key = seal_key(&settings.studio.question, &keys);
        map.insert(
            SEALED.to_owned(),
            Value::String(seal(&Value::Array(values).to_string(), key)),
        );
    }
    patch
}

/// The scramble of a studio's mystery values: `text` (the JSON list of their
/// values, in the order of [`Studio::sealed_keys`]) after a 3-byte checksum
/// (the low bytes of FNV-1a, 32 bits: a damaged value passes one time in 16
/// million; the link's base64 and DEFLATE catch most damage first), XORed with a stream of bytes (SplitMix64) seeded with
/// `key`, in URL-safe base64. Enough that decoding the link as far as its
/// JSON shows no number; no secret.
pub fn seal(text: &str, key: u64) -> String {
    let mut bytes = fnv1a32(text.as_bytes()).to_le_bytes()[..CHECK_BYTES].to_vec();
    bytes.extend_from_slice(text.as_bytes());
    scramble(&mut bytes, key);
    URL_SAFE_NO_PAD.encode(bytes)
}

/// [`seal`] undone; the reason (a catalogue id) when `sealed` does not
/// unscramble to what was sealed with `key`.
pub fn unseal(sealed: &str, key: u64) -> Result<String, &'static str> {
    let mut bytes = URL_SAFE_NO_PAD
        .decode(sealed)
        .map_err(|_| "setting-link-sealed-not-base64")?;
    if bytes.len() < CHECK_BYTES {
        return Err("setting-link-sealed-short");
    }
    scramble(&mut bytes, key);
    let (sum, text) = bytes.split_at(CHECK_BYTES);
    if sum != &fnv1a32(text).to_le_bytes()[..CHECK_BYTES] {
        return Err("setting-link-sealed-checksum");
    }
    String::from_utf8(text.to_vec()).map_err(|_| "setting-link-sealed-checksum")
}

/// The scramble's key: the constant, the teacher's question and the controls
/// whose values are mysteries, so that two lessons with the same number
/// scramble it differently.
fn seal_key(question: &str, mysteries: &[String]) -> u64 {
    let mut text = SEAL_CONSTANT.to_vec();
    text.push(0);
    text.extend_from_slice(question.as_bytes());
    for key in mysteries {
        text.push(0);
        text.extend_from_slice(key.as_bytes());
    }
    fnv1a64(&text)
}

/// XORs `bytes` with SplitMix64's stream from `seed` (its own inverse).
fn scramble(bytes: &mut [u8], seed: u64) {
    let mut state = seed;
    for chunk in bytes.chunks_mut(8) {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        for (byte, k) in chunk.iter_mut().zip(z.to_le_bytes()) {
            *byte ^= k;
        }
    }
}

fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xCBF2_9CE4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01B3)
    })
}

fn fnv1a32(bytes: &[u8]) -> u32 {
    bytes.iter().fold(0x811C_9DC5, |h, &b| {
        (h ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

/// A link's JSON with its sealed mystery values put back in their places
/// (the link's studio says which controls they belong to).
fn unsealed(mut value: Value) -> Result<Value, ShareLinkError> {
    let Value::Object(map) = &mut value else {
        return Ok(value);
    };
    let Some(sealed) = map.remove(SEALED) else {
        return Ok(value);
    };
    let sealed = sealed
        .as_str()
        .ok_or(ShareLinkError::Sealed("setting-link-sealed-not-base64"))?;
    let mut studio = Studio::default();
    if let Some(patch) = map.get("studio") {
        studio
            .apply_patch(patch)
            .map_err(|err| ShareLinkError::Invalid(err.into()))?;
    }
    let keys = studio.sealed_keys();
    let text = unseal(sealed, seal_key(&studio.question, &keys)).map_err(ShareLinkError::Sealed)?;
    let values = match serde_json::from_str::<Value>(&text) {
        Ok(Value::Array(values)) if values.len() == keys.len() => values,
        _ => return Err(ShareLinkError::Sealed("setting-link-sealed-mismatch")),
    };
    for (key, v) in keys.iter().zip(values) {
        let path: Vec<&str> = key.split('.').collect();
        if !insert_at(&mut value, &path, v) {
            return Err(ShareLinkError::Sealed("setting-link-sealed-mismatch"));
        }
    }
    Ok(value)
}

fn value_at<'a>(root: &'a Value, path: &[&str]) -> Option<&'a Value> {
    path.iter()
        .try_fold(root, |v, key| v.as_object()?.get(*key))
}

/// Removes the value at `path`, and the objects it leaves empty.
fn remove_at(root: &mut Value, path: &[&str]) {
    let Value::Object(map) = root else {
        return;
    };
    match path {
        [] => {}
        [last] => {
            map.remove(*last);
        }
        [first, rest @ ..] => {
            if let Some(inner) = map.get_mut(*first) {
                remove_at(inner, rest);
                if inner.as_object().is_some_and(Map::is_empty) {
                    map.remove(*first);
                }
            }
        }
    }
}

/// Puts `value` at `path`, making objects on the way; `false` if a value
/// that is not an object stands in the way.
fn insert_at(root: &mut Value, path: &[&str], value: Value) -> bool {
    let Value::Object(map) = root else {
        return false;
    };
    match path {
        [] => false,
        [last] => {
            map.insert((*last).to_owned(), value);
            true
        }
        [first, rest @ ..] => insert_at(
            map.entry(*first)
                .or_insert_with(|| Value::Object(Map::new())),
            rest,
            value,
        ),
    }
}

/// `json` packed as a link's text: the version tag, then URL-safe base64 of its
/// DEFLATE-compressed bytes (share links and experiment links).
pub fn pack_json(json: &str) -> String {
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), COMPRESSION_LEVEL);
    format!("{PREFIX}{}", URL_SAFE_NO_PAD.encode(packed))
}

/// The JSON a link's text (with or without a leading `#`) packs, checked for
/// size at every stage; `Ok(None)` for an empty text. Only unpacked: what the
/// JSON asks for is the caller's to validate.
pub fn unpack_json(text: &str) -> Result<Option<serde_json::Value>, ShareLinkError> {
    let text = text.trim().trim_start_matches('#');
    if text.is_empty() {
        return Ok(None);
    }
    if text.len() > MAX_LINK_CHARS {
        return Err(ShareLinkError::TooLong(text.len()));
    }
    let body = text
        .strip_prefix(PREFIX)
        .ok_or(ShareLinkError::UnknownVersion)?;
    let packed = URL_SAFE_NO_PAD
        .decode(body)
        .map_err(|_| ShareLinkError::NotBase64)?;
    let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, MAX_JSON_BYTES)
        .map_err(|_| ShareLinkError::NotDeflate)?;
    serde_json::from_slice(&json)
        .map(Some)
        .map_err(|_| ShareLinkError::NotJson)
}

/// The settings a fragment (with or without the leading `#`) describes. An empty
/// fragment gives `Ok(None)`: no link, use the defaults.
pub fn decode(fragment: &str) -> Result<Option<Settings>, ShareLinkError> {
    let Some(value) = unpack_json(fragment)? else {
        return Ok(None);
    };
    let value = unsealed(value)?;
    let mut settings = Settings::default();
    settings.apply_patch(&value)?;
    Ok(Some(settings))
}

/// The value of the query parameter `key` in a page address (`?key=value`,
/// before any `#`), if it has one.
pub fn query_value<'a>(url: &'a str, key: &str) -> Option<&'a str> {
    let before_fragment = url.split('#').next().unwrap_or_default();
    let (_, query) = before_fragment.split_once('?')?;
    query.split('&').find_map(|part| {
        let (k, value) = part.split_once('=').unwrap_or((part, ""));
        (k == key).then(|| value.trim())
    })
}

/// The address without its `key` parameter (and without a `?` left empty).
pub fn without_query(url: &str, key: &str) -> String {
    let (address, query) = match url.split_once('?') {
        Some((a, q)) => (a, q),
        None => return url.to_owned(),
    };
    let kept: Vec<&str> = query
        .split('&')
        .filter(|part| !part.is_empty() && part.split('=').next() != Some(key))
        .collect();
    if kept.is_empty() {
        address.to_owned()
    } else {
        format!("{address}?{}", kept.join("&"))
    }
}

/// `url` with `?key=value` (replacing any `key` it had). `value` must already be
/// safe in a URL (an id, or packed link text).
pub fn with_query(url: &str, key: &str, value: &str) -> String {
    let base = without_query(url, key);
    let sep = if base.contains('?') { '&' } else { '?' };
    format!("{base}{sep}{key}={value}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Scene;
    use crate::settings::tank::{Preset, TankSettings};
    use crate::sim::boids::control_mode::ControlMode;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_tank(rng: &mut ChaCha8Rng) -> TankSettings {
        let preset = Preset::ALL[rng.random_range(0..Preset::ALL.len())];
        let mut tank = TankSettings::with_preset(preset);
        if preset == Preset::Custom || rng.random_bool(0.3) {
            for w in TankSettings::WEIGHTS {
                w.set(&mut tank, f32::from(rng.random_range(0u8..=100)));
            }
            tank.vision_distance_m = rng.random_range(0.5..=12.0);
            tank.vision_angle_deg = rng.random_range(0.0..=360.0);
            tank.max_speed_m_per_s = rng.random_range(0.1..=3.0);
            tank.max_force_m_per_s2 = rng.random_range(0.1..=10.0);
            tank.personal_space_m = rng.random_range(0.1..=3.0);
            tank.wander = f32::from(rng.random_range(0u8..=100));
            tank.clear_sight_m = rng.random_range(0.0..=12.0);
            tank.distant_pull = f32::from(rng.random_range(0u8..=100));
            tank.min_speed_m_per_s = rng.random_range(0.0..=1.0);
            tank.preset = tank.matching_preset();
        }
        tank.mode = ControlMode::ALL[rng.random_range(0..4)];
        tank.preset = tank.matching_preset();
        tank.fish_count = rng.random_range(0..=20_000);
        tank.sharks = rng.random_range(0..=crate::settings::tank::SHARKS_MAX);
        tank.stingrays = rng.random_range(0..=crate::settings::tank::STINGRAYS_MAX);
        tank.selected = (tank.fish_count > 0 && rng.random_bool(0.5))
            .then(|| rng.random_range(0..tank.fish_count));
        tank
    }

    fn random_settings(rng: &mut ChaCha8Rng) -> Settings {
        Settings {
            paused: rng.random_bool(0.5),
            seed: u64::from(rng.random::<u32>()),
            speed: rng.random_range(0.25..=8.0),
            scene: Scene::ALL[rng.random_range(0..Scene::ALL.len())],
            compare: rng.random_bool(0.5),
            show_vision: rng.random_bool(0.5),
            left: random_tank(rng),
            right: random_tank(rng),
            physics: random_physics(rng),
            reef: random_reef(rng),
            learning: crate::settings::learning::LearningSettings {
                species: if rng.random_bool(0.5) {
                    crate::sim::BodySpecies::Fish
                } else {
                    crate::sim::BodySpecies::Shark
                },
                annealing_steps: rng.random_range(90..=20_000),
                training: rng.random_bool(0.5),
                controller: if rng.random_bool(0.5) {
                    crate::sim::learning::learning_lab::ControllerChoice::Learned
                } else {
                    crate::sim::learning::learning_lab::ControllerChoice::HandTuned
                },
            },
            predation: crate::settings::PredationSettings {
                confusion: rng.random_bool(0.5),
                joint_flight: rng.random_bool(0.5),
            },
            studio: Default::default(),
        }
    }

    fn random_reef(rng: &mut ChaCha8Rng) -> crate::settings::reef::ReefSettings {
        use crate::settings::reef::*;
        use crate::sim::reef::demos::ReefScene;
        use crate::sim::reef::world::ReefBodyKind;
        let mut reef = ReefSettings {
            demo: ReefScene::ALL[rng.random_range(0..ReefScene::ALL.len())],
            body: if rng.random_bool(0.5) {
                ReefBodyKind::Physical
            } else {
                ReefBodyKind::PointMass
            },
            prey_count: rng
                .random_bool(0.5)
                .then(|| rng.random_range(0..=REEF_PREY_MAX)),
            food_count: rng
                .random_bool(0.5)
                .then(|| rng.random_range(0..=REEF_FOOD_MAX)),
            visibility_m: rng.random_range(VISIBILITY_MIN_M..=VISIBILITY_MAX_M),
            current_m_per_s: rng.random_range(0.0..=REEF_CURRENT_MAX_M_PER_S),
            selected: None,
            follow: rng.random_bool(0.5),
            show_vision: rng.random_bool(0.5),
            overlay: ReefOverlay::ALL[rng.random_range(0..3)],
            name_tags: rng.random_bool(0.5),
            traits: Default::default(),
        };
        for kind in crate::sim::reef::mind::FishKind::ALL {
            let traits = reef.traits.of_mut(kind);
            for number in &crate::sim::reef::mind::habits::MindTraits::NUMBERS {
                let crate::settings::number::Number::F32(t) = number else {
                    panic!("{}: a trait is an f32", number.key());
                };
                if rng.random_bool(0.3) {
                    t.set(traits, rng.random_range(t.range.bounds()));
                }
            }
        }
        let animals = reef.animal_count() as u32;
        reef.selected = (animals > 0 && rng.random_bool(0.5)).then(|| rng.random_range(0..animals));
        reef
    }

    fn random_physics(rng: &mut ChaCha8Rng) -> crate::settings::physics::PhysicsSettings {
        use crate::settings::physics::*;
        let fish_count = rng.random_range(1..=PHYSICS_FISH_MAX);
        let sharks = rng.random_range(0..=PHYSICS_SHARKS_MAX);
        let selected = rng
            .random_bool(0.5)
            .then(|| rng.random_range(0..fish_count + sharks));
        PhysicsSettings {
            fish_count,
            sharks,
            behaviour: crate::sim::PhysicsBehaviour::ALL[rng.random_range(0..3)],
            current_m_per_s: rng.random_range(0.0..=CURRENT_MAX_M_PER_S),
            selected,
            hand_control: selected.is_some() && rng.random_bool(0.5),
            hand_speed: rng.random_range(0.0..=1.0),
            hand_pitch_deg: rng.random_range(-HAND_PITCH_MAX_DEG..=HAND_PITCH_MAX_DEG),
            turn_angle_deg: rng.random_range(-TURN_MAX_DEG..=TURN_MAX_DEG),
            follow: selected.is_some() && rng.random_bool(0.5),
            show_body: rng.random_bool(0.5),
            show_forces: rng.random_bool(0.5),
        }
    }

    #[test]
    fn settings_to_link_to_settings_is_the_identity() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut all = vec![Settings::default()];
        all.extend((0..300).map(|_| random_settings(&mut rng)));
        for settings in all {
            assert!(settings.validate().is_ok());
            let link = encode(&settings);
            assert!(link.len() < 2000, "short enough to paste: {}", link.len());
            let back = decode(&format!("#{link}")).unwrap().unwrap();
            assert_eq!(back, settings, "{link}");
        }
    }

    #[test]
    fn edited_rocks_ledges_and_pillars_survive_the_link() {
        for seed in 1..6 {
            let world = crate::sim::World::new(crate::sim::WorldConfig {
                seed,
                fish_count: 0,
                ..Default::default()
            });
            let mut settings = Settings::default();
            settings.left.obstacles = Some(world.obstacles().to_vec());
            settings.right.obstacles = Some(Vec::new());
            assert!(settings.validate().is_ok());
            let back = decode(&encode(&settings)).unwrap().unwrap();
            assert_eq!(back, settings);
        }
    }

    #[test]
    fn an_empty_fragment_means_no_link() {
        assert_eq!(decode(""), Ok(None));
        assert_eq!(decode("#"), Ok(None));
    }

    #[test]
    fn damaged_links_give_a_clear_error() {
        let link = encode(&Settings::default());
        assert_eq!(decode("hello"), Err(ShareLinkError::UnknownVersion));
        assert_eq!(decode("v1.***"), Err(ShareLinkError::NotBase64));
        assert!(matches!(
            decode(&link[..link.len() / 2]),
            Err(ShareLinkError::NotDeflate | ShareLinkError::NotBase64)
        ));
        let not_json = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(b"{]", 6));
        assert_eq!(
            decode(&format!("v1.{not_json}")),
            Err(ShareLinkError::NotJson)
        );
        let too_fast = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            br#"{"speed": 1000}"#,
            6,
        ));
        let err = decode(&format!("v1.{too_fast}")).unwrap_err();
        assert!(err.to_string().contains("speed"), "{err}");
        assert!(matches!(
            decode(&"v1.A".repeat(MAX_LINK_CHARS)),
            Err(ShareLinkError::TooLong(_))
        ));
    }

    #[test]
    fn a_zip_bomb_is_refused() {
        let huge = format!("{{\"seed\": 1{}}}", " ".repeat(10 * MAX_JSON_BYTES));
        let packed =
            URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(huge.as_bytes(), 9));
        assert!(packed.len() < MAX_LINK_CHARS);
        assert_eq!(
            decode(&format!("v1.{packed}")),
            Err(ShareLinkError::NotDeflate)
        );
    }

    #[test]
    fn a_thousand_random_and_mutated_links_never_panic_and_stay_valid() {
        let mut rng = ChaCha8Rng::seed_from_u64(99);
        let alphabet: Vec<char> =
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_.#%v"
                .chars()
                .collect();
        for round in 0..1000 {
            let text = if round % 2 == 0 {
                // Random text, sometimes with a valid prefix.
                let len = rng.random_range(0..400);
                let body: String = (0..len)
                    .map(|_| alphabet[rng.random_range(0..alphabet.len())])
                    .collect();
                if rng.random_bool(0.5) {
                    format!("v1.{body}")
                } else {
                    body
                }
            } else {
                // A real link with a few characters flipped, cut or added.
                let mut chars: Vec<char> = encode(&random_settings(&mut rng)).chars().collect();
                for _ in 0..rng.random_range(1..4) {
                    let at = rng.random_range(0..chars.len());
                    match rng.random_range(0..3) {
                        0 => chars[at] = alphabet[rng.random_range(0..alphabet.len())],
                        1 => chars.truncate(at.max(1)),
                        _ => chars.insert(at, alphabet[rng.random_range(0..alphabet.len())]),
                    }
                }
                chars.into_iter().collect()
            };
            if let Ok(Some(settings)) = decode(&text) {
                assert!(settings.validate().is_ok(), "{text}");
            }
        }
    }

    #[test]
    fn tampered_json_is_refused_by_the_same_rules_as_set() {
        let pack = |json: &str| {
            format!(
                "v1.{}",
                URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 6))
            )
        };
        for json in [
            r#"{"left": {"fish_count": 1e9}}"#,
            r#"{"right": {"alignment": -5}}"#,
            r#"{"scene": "moon"}"#,
            r#"{"wormhole": true}"#,
            r#"[1, 2, 3]"#,
        ] {
            assert!(decode(&pack(json)).is_err(), "{json}");
        }
        let ok = decode(&pack(r#"{"scene": "boids", "compare": true}"#))
            .unwrap()
            .unwrap();
        assert!(ok.compare);
    }
}
