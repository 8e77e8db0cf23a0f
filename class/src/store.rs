//! Every read and write of a class, with its authorisation checks. Secret
//! tokens are stored only as SHA-256 hashes.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

use rand::Rng;
use serde::Serialize;
use serde_json::{json, Value};
use sha2::{Digest, Sha256};
use sqlx::{AnyPool, Row};

use crate::protocol::{Body, ErrorCode, ServerError, MAX_SETUP_BYTES, STEPS, VERSION};
use crate::Role;

/// Class codes use letters and digits that cannot be mistaken for each other.
const CODE_ALPHABET: &[u8] = b"ABCDEFGHJKMNPQRSTUVWXYZ23456789";
pub const CODE_LEN: usize = 6;

pub fn now() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs() as i64)
        .unwrap_or(0)
}

fn hash(token: &str) -> String {
    hex::encode(Sha256::digest(token.as_bytes()))
}

/// 256 random bits, hex.
fn new_token() -> String {
    let bytes: [u8; 32] = rand::thread_rng().gen();
    hex::encode(bytes)
}

fn new_code() -> String {
    let mut rng = rand::thread_rng();
    (0..CODE_LEN)
        .map(|_| CODE_ALPHABET[rng.gen_range(0..CODE_ALPHABET.len())] as char)
        .collect()
}

/// Compares two equal-length strings in time independent of where they differ.
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len()
        && a.bytes()
            .zip(b.bytes())
            .fold(0u8, |acc, (x, y)| acc | (x ^ y))
            == 0
}

#[derive(Debug, Serialize)]
pub struct Started {
    pub code: String,
    pub teacher_token: String,
    pub seed: i64,
}

pub async fn create_class(pool: &AnyPool, setup: &Value) -> Result<Started, ServerError> {
    let setup_text = setup.to_string();
    if setup_text.len() > MAX_SETUP_BYTES {
        return Err(ServerError::new(
            ErrorCode::TooLarge,
            "the setup is too large",
        ));
    }
    let token = new_token();
    let seed = i64::from(rand::thread_rng().gen::<u32>());
    for _ in 0..16 {
        let code = new_code();
        let inserted = sqlx::query(
            "INSERT INTO classes (code, teacher_hash, seed, setup, created_at) VALUES ($1, $2, $3, $4, $5) ON CONFLICT (code) DO NOTHING",
        )
        .bind(&code)
        .bind(hash(&token))
        .bind(seed)
        .bind(&setup_text)
        .bind(now())
        .execute(pool)
        .await?;
        if inserted.rows_affected() == 1 {
            return Ok(Started {
                code,
                teacher_token: token,
                seed,
            });
        }
    }
    Err(ServerError::new(
        ErrorCode::Internal,
        "no free class code; try again",
    ))
}

pub async fn check_teacher(pool: &AnyPool, code: &str, token: &str) -> Result<bool, ServerError> {
    let row = sqlx::query("SELECT teacher_hash FROM classes WHERE code = $1")
        .bind(code)
        .fetch_optional(pool)
        .await?;
    Ok(match row {
        Some(row) => same(&row.try_get::<String, _>("teacher_hash")?, &hash(token)),
        None => false,
    })
}

pub struct Joined {
    pub student_id: String,
    pub token: String,
    pub join_order: i64,
    pub seed: i64,
    pub setup: Value,
}

fn no_class() -> ServerError {
    ServerError::new(ErrorCode::NotFound, "no class with that code")
}

/// Adds a student to the class; with a `join_key` already used in this class,
/// gives that student back instead (a join resent after a dropped connection),
/// with a new token (the first answer may never have arrived).
pub async fn join(
    pool: &AnyPool,
    code: &str,
    nickname: &str,
    join_key: Option<&str>,
) -> Result<Joined, ServerError> {
    let nickname = nickname.trim();
    let key_hash = join_key.map(hash);
    let mut tx = pool.begin().await?;
    // A write first: it takes the class's lock, so a join and its resend are
    // applied one after the other.
    let row = sqlx::query(
        "UPDATE classes SET next_join = next_join WHERE code = $1 RETURNING seed, setup",
    )
    .bind(code)
    .fetch_optional(&mut *tx)
    .await?
    .ok_or_else(no_class)?;
    let class_seed: i64 = row.try_get("seed")?;
    let setup: String = row.try_get("setup")?;
    let setup = serde_json::from_str(&setup).unwrap_or(Value::Null);
    let token = new_token();
    let known =
        match &key_hash {
            Some(key_hash) => sqlx::query(
                "SELECT id, join_order FROM students WHERE class_code = $1 AND join_key_hash = $2",
            )
            .bind(code)
            .bind(key_hash)
            .fetch_optional(&mut *tx)
            .await?,
            None => None,
        };
    let (student_id, join_order) = if let Some(known) = known {
        // A resend: the same student, a new token.
        let student_id: String = known.try_get("id")?;
        sqlx::query("UPDATE students SET token_hash = $1 WHERE id = $2")
            .bind(hash(&token))
            .bind(&student_id)
            .execute(&mut *tx)
            .await?;
        (student_id, known.try_get("join_order")?)
    } else {
        let row = sqlx::query(
            "UPDATE classes SET next_join = next_join + 1 WHERE code = $1 RETURNING next_join",
        )
        .bind(code)
        .fetch_one(&mut *tx)
        .await?;
        let join_order: i64 = row.try_get("next_join")?;
        let student_id = new_token()[..32].to_owned();
        sqlx::query("INSERT INTO students (id, class_code, token_hash, nickname, join_order, join_key_hash) VALUES ($1, $2, $3, $4, $5, $6)")
            .bind(&student_id)
            .bind(code)
            .bind(hash(&token))
            .bind(nickname)
            .bind(join_order)
            .bind(key_hash)
            .execute(&mut *tx)
            .await?;
        (student_id, join_order)
    };
    tx.commit().await?;
    Ok(Joined {
        student_id,
        token,
        join_order,
        seed: class_seed + join_order,
        setup,
    })
}

pub async fn resume(pool: &AnyPool, code: &str, token: &str) -> Result<String, ServerError> {
    let row = sqlx::query("SELECT id FROM students WHERE token_hash = $1 AND class_code = $2")
        .bind(hash(token))
        .bind(code)
        .fetch_optional(pool)
        .await?
        .ok_or_else(|| {
            ServerError::new(ErrorCode::Forbidden, "no student with that code and token")
        })?;
    Ok(row.try_get("id")?)
}

fn sender(role: &Role) -> String {
    match role {
        Role::Teacher { code } => format!("teacher:{code}"),
        Role::Student { id, .. } => format!("student:{id}"),
    }
}

/// Applies one message once: a resent client message id gets the stored reply.
/// Returns the reply and what the message changed.
pub(crate) async fn apply(
    pool: &AnyPool,
    role: &Role,
    client_id: &str,
    body: &Body,
) -> Result<(Value, Effect), ServerError> {
    let who = sender(role);
    let code = role.code();
    if let Some(row) =
        sqlx::query("SELECT reply FROM processed WHERE sender = $1 AND client_id = $2")
            .bind(&who)
            .bind(client_id)
            .fetch_optional(pool)
            .await?
    {
        let reply: String = row.try_get("reply")?;
        return Ok((
            serde_json::from_str(&reply).unwrap_or(Value::Null),
            Effect::Resent,
        ));
    }
    let is_teacher = matches!(role, Role::Teacher { .. });
    if body.is_teachers() != is_teacher {
        return Err(ServerError::new(
            ErrorCode::Forbidden,
            if is_teacher {
                "that is a student's message"
            } else {
                "that is a teacher's message"
            },
        ));
    }
    let reply = json!({"v": VERSION, "type": "ack", "re": client_id});
    let mut tx = pool.begin().await?;
    let class = sqlx::query(
        // A write first, so SQLite takes its write lock at once (waiting
        // for another writer instead of failing on a stale read snapshot)
        // and PostgreSQL orders one class's messages.
        "UPDATE classes SET next_join = next_join WHERE code = $1 RETURNING held_step",
    )
    .bind(code)
    .fetch_optional(&mut *tx)
    .await?
    .ok_or_else(no_class)?;
    let held: Option<String> = class.try_get("held_step")?;
    let student = match role {
        Role::Student { id, .. } => id.as_str(),
        Role::Teacher { .. } => "",
    };
    let step_allowed = |step: &str| match &held {
        Some(h) => step_index(step) <= step_index(h),
        None => true,
    };
    let effect = match body {
        Body::Step { step } => {
            if !step_allowed(step) {
                return Err(ServerError::new(
                    ErrorCode::Held,
                    "the teacher is holding the class at an earlier step",
                ));
            }
            sqlx::query("UPDATE students SET step = $1 WHERE id = $2")
                .bind(step)
                .bind(student)
                .execute(&mut *tx)
                .await?;
            Effect::Step(step.clone())
        }
        Body::Predict { prediction } => {
            sqlx::query("UPDATE students SET prediction = $1 WHERE id = $2")
                .bind(prediction.trim())
                .bind(student)
                .execute(&mut *tx)
                .await?;
            Effect::Prediction(prediction.trim().to_owned())
        }
        Body::Result { levels, values } => {
            let levels = serde_json::to_string(levels).unwrap_or_default();
            let mut stored = Vec::new();
            for (measure, value) in values {
                sqlx::query("INSERT INTO results (student_id, client_id, levels, measure, value) VALUES ($1, $2, $3, $4, $5)")
                    .bind(student)
                    .bind(client_id)
                    .bind(&levels)
                    .bind(measure)
                    .bind(*value)
                    .execute(&mut *tx)
                    .await?;
                stored.push(StoredResult {
                    client_id: client_id.to_owned(),
                    levels: levels.clone(),
                    measure: measure.clone(),
                    value: *value,
                });
            }
            Effect::Results(stored)
        }
        Body::Explain { answer } => {
            sqlx::query("UPDATE students SET answer = $1 WHERE id = $2")
                .bind(answer)
                .bind(student)
                .execute(&mut *tx)
                .await?;
            Effect::Answer(answer.clone())
        }
        Body::Hold { step } => {
            sqlx::query("UPDATE classes SET held_step = $1 WHERE code = $2")
                .bind(step.clone())
                .bind(code)
                .execute(&mut *tx)
                .await?;
            Effect::Held(step.clone())
        }
        Body::Release {} => {
            let next = match &held {
                Some(h) => STEPS.get(step_index(h) + 1).map(|s| (*s).to_owned()),
                None => None,
            };
            sqlx::query("UPDATE classes SET held_step = $1 WHERE code = $2")
                .bind(next.clone())
                .bind(code)
                .execute(&mut *tx)
                .await?;
            Effect::Held(next)
        }
        Body::Pause { paused } => {
            sqlx::query("UPDATE classes SET paused = $1 WHERE code = $2")
                .bind(i64::from(*paused))
                .bind(code)
                .execute(&mut *tx)
                .await?;
            Effect::Paused(*paused)
        }
        Body::SendSetting { setting } => {
            sqlx::query("UPDATE classes SET setting = $1 WHERE code = $2")
                .bind(setting.to_string())
                .bind(code)
                .execute(&mut *tx)
                .await?;
            Effect::Setting(setting.to_string())
        }
        Body::Reveal { revealed } => {
            sqlx::query("UPDATE classes SET revealed = $1 WHERE code = $2")
                .bind(i64::from(*revealed))
                .bind(code)
                .execute(&mut *tx)
                .await?;
            Effect::Revealed(*revealed)
        }
        Body::Anonymise { on } => {
            sqlx::query("UPDATE classes SET anonymise = $1 WHERE code = $2")
                .bind(i64::from(*on))
                .bind(code)
                .execute(&mut *tx)
                .await?;
            Effect::Anonymise(*on)
        }
        Body::DeleteClass {} => {
            drop(tx);
            delete_class(pool, code).await?;
            return Ok((reply, Effect::Deleted));
        }
        Body::Join { .. } | Body::Resume { .. } | Body::Teacher { .. } => {
            return Err(ServerError::new(
                ErrorCode::Invalid,
                "this connection has already said who it is",
            ));
        }
    };
    sqlx::query(
        "INSERT INTO processed (class_code, sender, client_id, reply) VALUES ($1, $2, $3, $4)",
    )
    .bind(code)
    .bind(&who)
    .bind(client_id)
    .bind(reply.to_string())
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok((reply, effect))
}

fn step_index(step: &str) -> usize {
    STEPS.iter().position(|s| *s == step).unwrap_or(0)
}

struct ClassRow {
    seed: i64,
    setup: String,
    held_step: Option<String>,
    paused: bool,
    revealed: bool,
    anonymise: bool,
    setting: Option<String>,
}

async fn class_row(pool: &AnyPool, code: &str) -> Result<ClassRow, ServerError> {
    let row = sqlx::query("SELECT seed, setup, held_step, paused, revealed, anonymise, setting FROM classes WHERE code = $1")
        .bind(code)
        .fetch_optional(pool)
        .await?
        .ok_or_else(no_class)?;
    Ok(ClassRow {
        seed: row.try_get("seed")?,
        setup: row.try_get("setup")?,
        held_step: row.try_get("held_step")?,
        paused: row.try_get::<i64, _>("paused")? != 0,
        revealed: row.try_get::<i64, _>("revealed")? != 0,
        anonymise: row.try_get::<i64, _>("anonymise")? != 0,
        setting: row.try_get("setting")?,
    })
}

struct StudentRow {
    id: String,
    nickname: String,
    join_order: i64,
    step: String,
    prediction: Option<String>,
    answer: Option<String>,
}

async fn students(pool: &AnyPool, code: &str) -> Result<Vec<StudentRow>, ServerError> {
    let rows = sqlx::query("SELECT id, nickname, join_order, step, prediction, answer FROM students WHERE class_code = $1 ORDER BY join_order")
        .bind(code)
        .fetch_all(pool)
        .await?;
    rows.iter()
        .map(|row| {
            Ok(StudentRow {
                id: row.try_get("id")?,
                nickname: row.try_get("nickname")?,
                join_order: row.try_get("join_order")?,
                step: row.try_get("step")?,
                prediction: row.try_get("prediction")?,
                answer: row.try_get("answer")?,
            })
        })
        .collect()
}

/// One stored result of a student: the message it came in, its levels (JSON),
/// the measure and the value.
#[derive(Clone, Debug)]
pub(crate) struct StoredResult {
    client_id: String,
    levels: String,
    measure: String,
    value: f64,
}

/// Each student's results, by student id, in (message id, measure) order.
async fn results(
    pool: &AnyPool,
    code: &str,
) -> Result<BTreeMap<String, Vec<StoredResult>>, ServerError> {
    let rows = sqlx::query(
        "SELECT r.student_id, r.client_id, r.levels, r.measure, r.value FROM results r JOIN students s ON s.id = r.student_id WHERE s.class_code = $1",
    )
    .bind(code)
    .fetch_all(pool)
    .await?;
    let mut out: BTreeMap<String, Vec<StoredResult>> = BTreeMap::new();
    for row in &rows {
        out.entry(row.try_get("student_id")?)
            .or_default()
            .push(StoredResult {
                client_id: row.try_get("client_id")?,
                levels: row.try_get("levels")?,
                measure: row.try_get("measure")?,
                value: row.try_get("value")?,
            });
    }
    // Sorted here, not by the database, so that SQLite, PostgreSQL (whatever its
    // collation) and the copy in memory agree.
    for list in out.values_mut() {
        sort_results(list);
    }
    Ok(out)
}

fn sort_results(list: &mut [StoredResult]) {
    list.sort_by(|a, b| (&a.client_id, &a.measure).cmp(&(&b.client_id, &b.measure)));
}

fn histogram(students: &[StudentRow]) -> BTreeMap<String, usize> {
    let mut h = BTreeMap::new();
    for s in students {
        if let Some(p) = &s.prediction {
            *h.entry(p.clone()).or_insert(0) += 1;
        }
    }
    h
}

/// How many runs a student reported: each `result` message is one run, however
/// many measures it carries.
fn runs(list: Option<&Vec<StoredResult>>) -> usize {
    list.into_iter()
        .flatten()
        .map(|r| r.client_id.as_str())
        .collect::<BTreeSet<_>>()
        .len()
}

fn results_json(list: Option<&Vec<StoredResult>>) -> Value {
    Value::Array(
        list.into_iter()
            .flatten()
            .map(|r| {
                json!({"levels": serde_json::from_str::<Value>(&r.levels).unwrap_or(Value::Null), "measure": r.measure, "value": r.value})
            })
            .collect(),
    )
}

/// A live class as the views need it: its row, its students in join order and
/// their results. The server keeps one in memory per class with a connection
/// (`crate::AppState::view`), loaded once and then changed by each committed
/// message, so a view costs no database read.
pub(crate) struct ClassState {
    class: ClassRow,
    students: Vec<StudentRow>,
    results: BTreeMap<String, Vec<StoredResult>>,
}

/// Reads a class from the database.
pub(crate) async fn load(pool: &AnyPool, code: &str) -> Result<ClassState, ServerError> {
    Ok(ClassState {
        class: class_row(pool, code).await?,
        students: students(pool, code).await?,
        results: results(pool, code).await?,
    })
}

/// What a committed message changed, for the copy in memory.
#[derive(Debug)]
pub(crate) enum Effect {
    /// A resent message: answered from the stored reply, nothing changed.
    Resent,
    Step(String),
    Prediction(String),
    Results(Vec<StoredResult>),
    Answer(String),
    Held(Option<String>),
    Paused(bool),
    Setting(String),
    Revealed(bool),
    Anonymise(bool),
    Deleted,
}

impl ClassState {
    /// Takes in what `role`'s committed message changed.
    pub(crate) fn apply(&mut self, role: &Role, effect: Effect) {
        let student = match role {
            Role::Student { id, .. } => self.students.iter_mut().find(|s| s.id == *id),
            Role::Teacher { .. } => None,
        };
        match (effect, student) {
            (Effect::Step(step), Some(s)) => s.step = step,
            (Effect::Prediction(p), Some(s)) => s.prediction = Some(p),
            (Effect::Answer(a), Some(s)) => s.answer = Some(a),
            (Effect::Results(new), Some(s)) => {
                let list = self.results.entry(s.id.clone()).or_default();
                list.extend(new);
                sort_results(list);
            }
            (Effect::Held(step), _) => self.class.held_step = step,
            (Effect::Paused(on), _) => self.class.paused = on,
            (Effect::Setting(setting), _) => self.class.setting = Some(setting),
            (Effect::Revealed(on), _) => self.class.revealed = on,
            (Effect::Anonymise(on), _) => self.class.anonymise = on,
            _ => {}
        }
    }

    /// Takes in a student who has just joined.
    pub(crate) fn add_student(&mut self, joined: &Joined, nickname: &str) {
        if self.students.iter().any(|s| s.id == joined.student_id) {
            return;
        }
        self.students.push(StudentRow {
            id: joined.student_id.clone(),
            nickname: nickname.trim().to_owned(),
            join_order: joined.join_order,
            step: STEPS[0].to_owned(),
            prediction: None,
            answer: None,
        });
        self.students.sort_by_key(|s| s.join_order);
    }

    /// What `role` may see of its class now: the teacher everything, a student
    /// their own record and what the teacher has revealed or sent.
    pub(crate) fn view(&self, code: &str, role: &Role) -> Result<Value, ServerError> {
        let class = &self.class;
        if let Role::Student { id, .. } = role {
            return self.student_view(id);
        }
        let roster: Vec<Value> = self
            .students
            .iter()
            .map(|s| {
                json!({
                    "join_order": s.join_order,
                    "nickname": (!class.anonymise).then_some(&s.nickname),
                    "seed": class.seed + s.join_order,
                    "step": s.step,
                    "prediction": s.prediction,
                    "answer": s.answer,
                    "results": results_json(self.results.get(&s.id)),
                    "runs": runs(self.results.get(&s.id)),
                })
            })
            .collect();
        Ok(
            json!({"v": VERSION, "type": "class", "code": code, "seed": class.seed,
                  "setup": serde_json::from_str::<Value>(&class.setup).unwrap_or(Value::Null),
                  "anonymise": class.anonymise, "state": state_json(class), "roster": roster,
                  "histogram": histogram(&self.students)}),
        )
    }

    /// A student's view: their own row and results, and the class's prediction
    /// counts once revealed.
    fn student_view(&self, id: &str) -> Result<Value, ServerError> {
        let class = &self.class;
        let me = self.students.iter().find(|s| s.id == id).ok_or_else(|| {
            ServerError::new(
                ErrorCode::Forbidden,
                "this student is no longer in the class",
            )
        })?;
        let histogram = if class.revealed {
            json!(histogram(&self.students))
        } else {
            Value::Null
        };
        Ok(
            json!({"v": VERSION, "type": "you", "state": state_json(class),
                  "me": {"join_order": me.join_order, "nickname": me.nickname,
                         "seed": class.seed + me.join_order, "step": me.step,
                         "prediction": me.prediction, "answer": me.answer,
                         "results": results_json(self.results.get(&me.id))},
                  "histogram": histogram}),
        )
    }
}

fn state_json(class: &ClassRow) -> Value {
    json!({
        "held_step": class.held_step,
        "paused": class.paused,
        "setting": class.setting.as_deref().and_then(|s| serde_json::from_str::<Value>(s).ok()),
        "revealed": class.revealed,
    })
}

fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// The class's tidy CSV: one row per student × result × measure.
pub async fn class_csv(pool: &AnyPool, code: &str) -> Result<String, ServerError> {
    let class = class_row(pool, code).await?;
    let students = students(pool, code).await?;
    let results = results(pool, code).await?;
    let mut level_keys = BTreeSet::new();
    for list in results.values() {
        for r in list {
            if let Ok(map) = serde_json::from_str::<BTreeMap<String, f64>>(&r.levels) {
                level_keys.extend(map.into_keys());
            }
        }
    }
    let mut out = String::new();
    let _ = writeln!(out, "# Shoal class: {code}"); // words: a CSV comment line, English like the experiment CSV
    let _ = writeln!(out, "# setup: {}", class.setup.replace(['\n', '\r'], " "));
    let _ = writeln!(
        out,
        "# class seed: {} (a student's seed is the class seed + their join order)",
        class.seed
    );
    let _ = writeln!(out, "# students: {}", students.len());
    out.push_str("student,nickname,seed");
    for key in &level_keys {
        out.push(',');
        out.push_str(&csv_field(key));
    }
    out.push_str(",prediction,measure,value\n");
    for s in &students {
        for StoredResult {
            levels,
            measure,
            value,
            ..
        } in results.get(&s.id).into_iter().flatten()
        {
            let levels: BTreeMap<String, f64> = serde_json::from_str(levels).unwrap_or_default();
            let _ = write!(
                out,
                "{},{},{}",
                s.join_order,
                csv_field(&s.nickname),
                class.seed + s.join_order
            );
            for key in &level_keys {
                out.push(',');
                if let Some(v) = levels.get(key) {
                    let _ = write!(out, "{v}");
                }
            }
            let _ = writeln!(
                out,
                ",{},{},{value}",
                csv_field(s.prediction.as_deref().unwrap_or("")),
                csv_field(measure)
            );
        }
    }
    Ok(out)
}

pub async fn delete_class(pool: &AnyPool, code: &str) -> Result<(), ServerError> {
    let mut tx = pool.begin().await?;
    sqlx::query(
        "DELETE FROM results WHERE student_id IN (SELECT id FROM students WHERE class_code = $1)",
    )
    .bind(code)
    .execute(&mut *tx)
    .await?;
    sqlx::query("DELETE FROM processed WHERE class_code = $1")
        .bind(code)
        .execute(&mut *tx)
        .await?;
    sqlx::query("DELETE FROM students WHERE class_code = $1")
        .bind(code)
        .execute(&mut *tx)
        .await?;
    sqlx::query("DELETE FROM classes WHERE code = $1")
        .bind(code)
        .execute(&mut *tx)
        .await?;
    tx.commit().await?;
    Ok(())
}

pub async fn delete_older_than(pool: &AnyPool, cutoff: i64) -> Result<u64, sqlx::Error> {
    let rows = sqlx::query("SELECT code FROM classes WHERE created_at < $1")
        .bind(cutoff)
        .fetch_all(pool)
        .await?;
    let mut n = 0;
    for row in &rows {
        let code: String = row.try_get("code")?;
        if delete_class(pool, &code).await.is_ok() {
            n += 1;
        }
    }
    Ok(n)
}
