//! The class server through its real HTTP and WebSocket interface, against
//! SQLite always and against PostgreSQL when `SHOAL_CLASS_TEST_POSTGRES` holds a
//! connection URL (class/test-postgres.sh starts a throwaway cluster for it).

use std::net::SocketAddr;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use serde_json::{json, Value};
use sqlx::{AnyPool, Connection, Executor};
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};

static COUNTER: AtomicUsize = AtomicUsize::new(0);

/// A fresh database URL per test and backend.
async fn backends() -> Vec<String> {
    let n = COUNTER.fetch_add(1, Ordering::SeqCst);
    let dir = std::env::temp_dir().join(format!("shoal-class-test-{}-{n}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let file = dir.join("class.sqlite");
    let _ = std::fs::remove_file(&file);
    let mut urls = vec![format!("sqlite://{}", file.display())];
    if let Ok(admin) = std::env::var("SHOAL_CLASS_TEST_POSTGRES") {
        sqlx::any::install_default_drivers();
        let name = format!("shoal_test_{}_{n}", std::process::id());
        let mut conn = sqlx::AnyConnection::connect(&admin)
            .await
            .expect("connect to the test PostgreSQL");
        conn.execute(format!("DROP DATABASE IF EXISTS {name}").as_str())
            .await
            .expect("drop");
        conn.execute(format!("CREATE DATABASE {name}").as_str())
            .await
            .expect("create database");
        let (base, query) = admin
            .split_once('?')
            .map_or((admin.as_str(), ""), |(b, q)| (b, q));
        let slash = base.rfind('/').expect("a database path in the URL");
        let mut url = format!("{}/{name}", &base[..slash]);
        if !query.is_empty() {
            url = format!("{url}?{query}");
        }
        urls.push(url);
    }
    urls
}

struct Server {
    addr: SocketAddr,
    pool: AnyPool,
    task: tokio::task::JoinHandle<()>,
}

async fn start(url: &str, config: shoal_class::Config) -> Server {
    let pool = shoal_class::db::open(url).await.expect("open database");
    let app = shoal_class::app(pool.clone(), config);
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr");
    let task = tokio::spawn(async move {
        let _ = axum::serve(listener, app).await;
    });
    Server { addr, pool, task }
}

/// A server on the first backend whose `--dist` is a fresh folder holding `files`
/// (name, contents).
async fn start_with_dist(folder: &str, files: &[(&str, &str)]) -> Server {
    let dir = std::env::temp_dir().join(format!("{folder}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    let url = backends().await.remove(0);
    let config = shoal_class::Config {
        dist: dir,
        ..Default::default()
    };
    start(&url, config).await
}

impl Server {
    async fn stop(self) {
        self.task.abort();
        let _ = self.task.await;
        self.pool.close().await;
    }

    async fn start_class(&self, setup: Value) -> (String, String, i64) {
        let r = reqwest::Client::new()
            .post(format!("http://{}/api/classes", self.addr))
            .body(json!({"setup": setup}).to_string())
            .send()
            .await
            .expect("post");
        assert_eq!(r.status(), 201);
        let v: Value = r.json().await.expect("json");
        (
            v["code"].as_str().unwrap().to_owned(),
            v["teacher_token"].as_str().unwrap().to_owned(),
            v["seed"].as_i64().unwrap(),
        )
    }

    async fn csv(&self, code: &str, token: Option<&str>) -> (u16, String) {
        let mut req =
            reqwest::Client::new().get(format!("http://{}/api/classes/{code}/csv", self.addr));
        if let Some(t) = token {
            req = req.bearer_auth(t);
        }
        let r = req.send().await.expect("get");
        (r.status().as_u16(), r.text().await.expect("text"))
    }

    async fn client(&self) -> Client {
        let (ws, _) = tokio_tungstenite::connect_async(format!("ws://{}/ws", self.addr))
            .await
            .expect("connect");
        Client {
            ws,
            seen: Vec::new(),
            next: 0,
        }
    }
}

struct Client {
    ws: WebSocketStream<MaybeTlsStream<TcpStream>>,
    /// Every message received, in order.
    seen: Vec<Value>,
    next: usize,
}

impl Client {
    async fn recv(&mut self) -> Value {
        loop {
            let m = tokio::time::timeout(Duration::from_secs(10), self.ws.next())
                .await
                .expect("a message within 10 s")
                .expect("open")
                .expect("ok");
            if let Message::Text(t) = m {
                let v: Value = serde_json::from_str(&t).expect("json");
                self.seen.push(v.clone());
                return v;
            }
        }
    }

    async fn send_raw(&mut self, text: String) {
        self.ws
            .send(Message::Text(text.into()))
            .await
            .expect("send");
    }

    /// Sends `body` with id `id` and returns the reply to it.
    async fn ask_id(&mut self, id: &str, mut body: Value) -> Value {
        body["v"] = json!(1);
        body["id"] = json!(id);
        self.send_raw(body.to_string()).await;
        loop {
            let v = self.recv().await;
            if v["re"] == json!(id) {
                return v;
            }
        }
    }

    async fn ask(&mut self, body: Value) -> Value {
        self.next += 1;
        let id = format!("m{}", self.next);
        self.ask_id(&id, body).await
    }

    /// The next view of the class (`class` for the teacher, `you` for a student).
    async fn view(&mut self, kind: &str) -> Value {
        loop {
            let v = self.recv().await;
            if v["type"] == kind {
                return v;
            }
        }
    }
}

fn ok(v: &Value) {
    assert!(
        v["type"] == "ack" || v["type"] == "joined",
        "expected an ack, got {v}"
    );
}

fn error_code(v: &Value) -> &str {
    assert_eq!(v["type"], "error", "expected an error, got {v}");
    v["code"].as_str().unwrap()
}

async fn join(server: &Server, code: &str, nickname: &str) -> (Client, Value) {
    let mut c = server.client().await;
    let joined = c
        .ask(json!({"type": "join", "code": code, "nickname": nickname}))
        .await;
    assert_eq!(joined["type"], "joined", "{joined}");
    (c, joined)
}

async fn teacher(server: &Server, code: &str, token: &str) -> Client {
    let mut t = server.client().await;
    ok(&t
        .ask(json!({"type": "teacher", "code": code, "teacher_token": token}))
        .await);
    t
}

#[tokio::test]
async fn a_lesson_gives_the_teacher_every_prediction_and_result_in_the_csv() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, seed) = server
            .start_class(json!({"investigation": "why-school"}))
            .await;
        assert_eq!(code.len(), 6);
        assert_eq!(token.len(), 64, "256 bits of teacher token");
        let (mut ana, a) = join(&server, &code, "Ana").await;
        let (mut bo, b) = join(&server, &code, "Bo, \"the fish\"").await;
        assert_eq!(a["join_order"], 1);
        assert_eq!(b["join_order"], 2);
        assert_eq!(
            a["seed"].as_i64().unwrap(),
            seed + 1,
            "a student's seed is the class seed + join order"
        );
        assert_eq!(b["seed"].as_i64().unwrap(), seed + 2);
        assert_eq!(a["setup"]["investigation"], "why-school");
        ok(&ana.ask(json!({"type": "step", "step": "predict"})).await);
        ok(&ana
            .ask(json!({"type": "predict", "prediction": "fewer"}))
            .await);
        ok(&bo
            .ask(json!({"type": "predict", "prediction": "more"}))
            .await);
        ok(&ana.ask(json!({"type": "result", "levels": {"school": 1.0}, "values": {"lost": 3.0, "time_s": 60.0}})).await);
        ok(&bo
            .ask(json!({"type": "result", "levels": {"school": 0.0}, "values": {"lost": 7.0}}))
            .await);
        ok(&ana
            .ask(json!({"type": "explain", "answer": "together they see the shark"}))
            .await);

        let mut t = teacher(&server, &code, &token).await;
        let view = t.view("class").await;
        assert_eq!(view["roster"].as_array().unwrap().len(), 2);
        assert_eq!(view["histogram"], json!({"fewer": 1, "more": 1}));
        assert_eq!(view["roster"][0]["step"], "predict");
        assert_eq!(view["roster"][0]["answer"], "together they see the shark");

        let (status, csv) = server.csv(&code, Some(&token)).await;
        assert_eq!(status, 200);
        let rows: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
        assert_eq!(
            rows[0],
            "student,nickname,seed,school,prediction,measure,value"
        );
        assert_eq!(rows[1], format!("1,Ana,{},1,fewer,lost,3", seed + 1));
        assert_eq!(rows[2], format!("1,Ana,{},1,fewer,time_s,60", seed + 1));
        assert_eq!(
            rows[3],
            format!("2,\"Bo, \"\"the fish\"\"\",{},0,more,lost,7", seed + 2)
        );
        assert_eq!(rows.len(), 4);
        server.stop().await;
    }
}

/// A join resent after a dropped connection (its answer lost) gives back the
/// student it made, not a second one; its first token no longer works. A join
/// key is the class's: the same key in another class is another student. A
/// join without a key (an older client) still joins.
#[tokio::test]
async fn a_resent_join_gives_back_the_same_student() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, seed) = server.start_class(json!("a")).await;
        let (other, _, _) = server.start_class(json!("b")).await;
        let mut t = teacher(&server, &code, &token).await;
        let hello =
            json!({"type": "join", "code": code, "nickname": "Ana", "join_key": "k3y-of-ana"});
        let mut first = server.client().await;
        let a = first.ask_id("j1", hello.clone()).await;
        assert_eq!(a["type"], "joined", "{a}");
        drop(first);
        let mut again = server.client().await;
        let b = again.ask_id("j1", hello.clone()).await;
        assert_eq!(b["type"], "joined", "{b}");
        assert_eq!(b["join_order"], a["join_order"]);
        assert_eq!(b["seed"].as_i64().unwrap(), seed + 1);
        assert_ne!(b["student_token"], a["student_token"], "a new token");
        ok(&again
            .ask(json!({"type": "predict", "prediction": "fewer"}))
            .await);
        // Bo joins after: the next join order.
        let (_, bo) = join(&server, &code, "Bo").await;
        assert_eq!(bo["join_order"], 2);
        let roster = loop {
            let v = t.view("class").await;
            if v["roster"].as_array().unwrap().len() == 2 && v["roster"][0]["prediction"] == "fewer"
            {
                break v["roster"].clone();
            }
        };
        assert_eq!(roster[0]["nickname"], "Ana");
        // The lost answer's token is void; the new one resumes.
        let mut c = server.client().await;
        let r = c
            .ask(json!({"type": "resume", "code": code, "student_token": a["student_token"]}))
            .await;
        assert_eq!(error_code(&r), "forbidden");
        let mut c = server.client().await;
        ok(&c
            .ask(json!({"type": "resume", "code": code, "student_token": b["student_token"]}))
            .await);
        // The same key in another class: a student of that class.
        let mut c = server.client().await;
        let elsewhere = c
            .ask(
                json!({"type": "join", "code": other, "nickname": "Ana", "join_key": "k3y-of-ana"}),
            )
            .await;
        assert_eq!(elsewhere["join_order"], 1);
        // A malformed key is refused.
        let mut c = server.client().await;
        let bad = c
            .ask(json!({"type": "join", "code": code, "nickname": "Cy", "join_key": "no"}))
            .await;
        assert_eq!(error_code(&bad), "invalid");
        let (status, csv) = server.csv(&code, Some(&token)).await;
        assert_eq!(status, 200);
        assert!(csv.contains("# students: 2"), "{csv}");
        server.stop().await;
    }
}

/// The server keeps each live class in memory and answers views from it; that
/// copy must be what the database holds. A lesson with every kind of message,
/// the teacher connected first (so the class is in memory before any change),
/// then the same views from a second server that reads the database afresh.
#[tokio::test]
async fn views_from_memory_are_the_databases() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server
            .start_class(json!({"investigation": "how-swim"}))
            .await;
        let mut t = teacher(&server, &code, &token).await;
        let _ = t.view("class").await;
        ok(&t.ask(json!({"type": "hold", "step": "predict"})).await);
        let (mut ana, a) = join(&server, &code, "  Ana ").await;
        let (mut bo, _) = join(&server, &code, "Bo").await;
        ok(&ana.ask(json!({"type": "step", "step": "predict"})).await);
        ok(&ana
            .ask(json!({"type": "predict", "prediction": "faster"}))
            .await);
        ok(&bo
            .ask(json!({"type": "predict", "prediction": " slower "}))
            .await);
        ok(&t.ask(json!({"type": "release"})).await);
        ok(&ana.ask(json!({"type": "step", "step": "run"})).await);
        // Two results, the second sent first: kept in message-id order.
        ok(&ana.ask_id("r2", json!({"type": "result", "levels": {"hz": 2.0}, "values": {"speed": 0.4, "drag": 1.5}})).await);
        ok(&ana
            .ask_id(
                "r1",
                json!({"type": "result", "levels": {"hz": 1.0}, "values": {"speed": 0.2}}),
            )
            .await);
        // A resend changes nothing.
        ok(&ana
            .ask_id(
                "r1",
                json!({"type": "result", "levels": {"hz": 1.0}, "values": {"speed": 0.2}}),
            )
            .await);
        ok(&ana
            .ask(json!({"type": "explain", "answer": "more beats, more thrust"}))
            .await);
        ok(&t.ask(json!({"type": "hold", "step": "explain"})).await);
        ok(&t.ask(json!({"type": "pause", "paused": true})).await);
        ok(&t
            .ask(json!({"type": "send_setting", "setting": {"speed": 2}}))
            .await);
        ok(&t.ask(json!({"type": "reveal", "revealed": true})).await);
        ok(&t.ask(json!({"type": "anonymise", "on": true})).await);
        let teacher_view = t.view("class").await;
        ok(&ana.ask(json!({"type": "step", "step": "explain"})).await);
        let ana_view = ana.view("you").await;
        let mut t = teacher(&server, &code, &token).await;
        let teacher_view_after = t.view("class").await;
        assert_eq!(teacher_view_after["roster"][0]["step"], "explain");
        assert_eq!(
            teacher_view["roster"][0]["results"]
                .as_array()
                .unwrap()
                .len(),
            3
        );
        assert_eq!(teacher_view["roster"][0]["results"][0]["levels"]["hz"], 1.0);
        assert_eq!(teacher_view["histogram"], json!({"faster": 1, "slower": 1}));
        assert_eq!(teacher_view["roster"][0]["runs"], 2, "two result messages");
        assert_eq!(teacher_view["roster"][1]["runs"], 0);
        server.stop().await;

        let again = start(&url, Default::default()).await;
        let mut t = teacher(&again, &code, &token).await;
        assert_eq!(
            t.view("class").await,
            teacher_view_after,
            "the teacher's view"
        );
        let mut ana = again.client().await;
        ok(&ana
            .ask(json!({"type": "resume", "code": code, "student_token": a["student_token"]}))
            .await);
        assert_eq!(ana.view("you").await, ana_view, "a student's view");
        again.stop().await;
    }
}

#[tokio::test]
async fn a_student_cannot_use_another_classs_code() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code_a, _, _) = server.start_class(json!("a")).await;
        let (code_b, token_b, _) = server.start_class(json!("b")).await;
        let (_, joined) = join(&server, &code_a, "Ana").await;
        let student_token = joined["student_token"].as_str().unwrap();
        // Their own class takes the token back …
        let mut c = server.client().await;
        ok(&c
            .ask(json!({"type": "resume", "code": code_a, "student_token": student_token}))
            .await);
        // … another class does not.
        let mut c = server.client().await;
        let r = c
            .ask(json!({"type": "resume", "code": code_b, "student_token": student_token}))
            .await;
        assert_eq!(error_code(&r), "forbidden");
        // A code that is no class.
        let mut c = server.client().await;
        let r = c
            .ask(json!({"type": "join", "code": "ZZZZZZ", "nickname": "Eve"}))
            .await;
        assert_eq!(error_code(&r), "not_found");
        // Class B's roster never got Ana.
        let mut t = teacher(&server, &code_b, &token_b).await;
        let view = t.view("class").await;
        assert_eq!(view["roster"].as_array().unwrap().len(), 0);
        server.stop().await;
    }
}

#[tokio::test]
async fn a_guessed_or_forged_teacher_token_is_refused() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (code_b, token_b, _) = server.start_class(json!("b")).await;
        let forged = "0".repeat(64);
        for (c, t) in [
            (&code, forged.as_str()),
            (&code, ""),
            (&code, token_b.as_str()),
            (&code_b, token.as_str()),
        ] {
            let mut client = server.client().await;
            let r = client
                .ask(json!({"type": "teacher", "code": c, "teacher_token": t}))
                .await;
            assert!(matches!(error_code(&r), "forbidden" | "invalid"), "{r}");
            assert_eq!(server.csv(c, Some(t)).await.0, 403);
        }
        assert_eq!(server.csv(&code, None).await.0, 403);
        // The real token works (so the refusals above are about the token).
        assert_eq!(server.csv(&code, Some(&token)).await.0, 200);
        let stored: String = sqlx::query_scalar("SELECT teacher_hash FROM classes WHERE code = $1")
            .bind(&code)
            .fetch_one(&server.pool)
            .await
            .unwrap();
        assert_ne!(stored, token, "only the token's hash is stored");
        server.stop().await;
    }
}

#[tokio::test]
async fn a_student_cannot_send_teacher_messages() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        ok(&ana
            .ask(json!({"type": "predict", "prediction": "fewer"}))
            .await);
        for m in [
            json!({"type": "reveal", "revealed": true}),
            json!({"type": "hold", "step": "look"}),
            json!({"type": "pause", "paused": true}),
            json!({"type": "anonymise", "on": true}),
            json!({"type": "send_setting", "setting": {"speed": 9}}),
            json!({"type": "delete_class"}),
            json!({"type": "teacher", "code": code, "teacher_token": token}),
        ] {
            let r = ana.ask(m.clone()).await;
            assert!(
                matches!(error_code(&r), "forbidden" | "invalid"),
                "{m} -> {r}"
            );
        }
        let mut t = teacher(&server, &code, &token).await;
        let view = t.view("class").await;
        assert_eq!(view["state"]["revealed"], false);
        assert_eq!(view["state"]["paused"], false);
        assert_eq!(view["state"]["held_step"], Value::Null);
        assert_eq!(view["state"]["setting"], Value::Null);
        // The same messages from the teacher do change the class.
        ok(&t.ask(json!({"type": "pause", "paused": true})).await);
        let view = t.view("class").await;
        assert_eq!(view["state"]["paused"], true);
        server.stop().await;
    }
}

#[tokio::test]
async fn a_student_sees_only_their_own_record_until_the_teacher_reveals() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        let (mut bo, _) = join(&server, &code, "Borislav").await;
        ok(&bo
            .ask(json!({"type": "predict", "prediction": "more"}))
            .await);
        ok(&bo
            .ask(json!({"type": "explain", "answer": "secret answer of Bo"}))
            .await);
        ok(&bo
            .ask(json!({"type": "result", "levels": {}, "values": {"lost": 5.0}}))
            .await);
        ok(&ana
            .ask(json!({"type": "predict", "prediction": "fewer"}))
            .await);
        let mine = ana.view("you").await;
        assert_eq!(mine["me"]["nickname"], "Ana");
        assert_eq!(mine["histogram"], Value::Null, "hidden before the reveal");
        let mut t = teacher(&server, &code, &token).await;
        ok(&t.ask(json!({"type": "reveal", "revealed": true})).await);
        ok(&t
            .ask(json!({"type": "send_setting", "setting": {"fish": 30}}))
            .await);
        // Ana receives the reveal and the setting live.
        let mut last = ana.view("you").await;
        while last["histogram"] == Value::Null || last["state"]["setting"] == Value::Null {
            last = ana.view("you").await;
        }
        assert_eq!(last["histogram"], json!({"fewer": 1, "more": 1}));
        assert_eq!(last["state"]["setting"], json!({"fish": 30}));
        // Nothing Ana ever received names Bo or carries his answer or result.
        let everything = serde_json::to_string(&ana.seen).unwrap();
        assert!(!everything.contains("Borislav"), "{everything}");
        assert!(!everything.contains("secret answer"));
        assert!(!everything.contains("\"value\":5.0"));
        // Bo's token, sent by Ana's connection for Ana's class, is Bo's record only
        // through a resume; Ana's own connection keeps seeing Ana.
        let r = ana
            .ask(json!({"type": "resume", "code": code, "student_token": "x"}))
            .await;
        assert_eq!(error_code(&r), "invalid");
        server.stop().await;
    }
}

#[tokio::test]
async fn an_oversized_message_is_refused_and_the_connection_goes_on() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, _, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        let big = "x".repeat(20 * 1024);
        let r = ana.ask(json!({"type": "explain", "answer": big})).await;
        assert_eq!(error_code(&r), "too_large", "{r}");
        let long = "y".repeat(3000);
        let r = ana.ask(json!({"type": "explain", "answer": long})).await;
        assert_eq!(error_code(&r), "invalid", "{r}");
        let r = ana
            .ask(json!({"type": "result", "levels": {}, "values": {"lost": "many"}}))
            .await;
        assert_eq!(error_code(&r), "invalid", "{r}");
        let r = ana.ask(json!({"type": "step", "step": "dance"})).await;
        assert_eq!(error_code(&r), "invalid", "{r}");
        ana.send_raw("not json".into()).await;
        assert_eq!(error_code(&ana.recv().await), "invalid");
        // A big POST body too.
        let r = reqwest::Client::new()
            .post(format!("http://{}/api/classes", server.addr))
            .body(json!({"setup": "z".repeat(20 * 1024)}).to_string())
            .send()
            .await
            .unwrap();
        assert!(r.status().is_client_error());
        // Still usable afterwards.
        ok(&ana.ask(json!({"type": "explain", "answer": "short"})).await);
        server.stop().await;
    }
}

#[tokio::test]
async fn a_flood_over_the_rate_limit_is_refused() {
    for url in backends().await {
        let config = shoal_class::Config {
            burst: 5.0,
            per_second: 1.0,
            ..Default::default()
        };
        let server = start(&url, config).await;
        let (code, _, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        for i in 0..40 {
            ana.send_raw(json!({"v": 1, "id": format!("f{i}"), "type": "predict", "prediction": format!("p{i}")}).to_string()).await;
        }
        let (mut acks, mut limited) = (0, 0);
        while acks + limited < 40 {
            let v = ana.recv().await;
            match v["type"].as_str() {
                Some("ack") => acks += 1,
                Some("error") if v["code"] == "rate_limited" => limited += 1,
                _ => {}
            }
        }
        assert!(acks <= 6, "{acks} accepted");
        assert!(limited >= 34, "{limited} refused");
        server.stop().await;
        // The same flood under the default limit is accepted whole (the limit is the cause).
        let server = start(&url, Default::default()).await;
        let (code, _, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        for i in 0..20 {
            ana.send_raw(json!({"v": 1, "id": format!("f{i}"), "type": "predict", "prediction": format!("p{i}")}).to_string()).await;
        }
        let mut acks = 0;
        while acks < 20 {
            let v = ana.recv().await;
            assert_ne!(v["type"], "error", "{v}");
            if v["type"] == "ack" {
                acks += 1;
            }
        }
        server.stop().await;
    }
}

#[tokio::test]
async fn a_resent_message_is_counted_once() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (mut ana, joined) = join(&server, &code, "Ana").await;
        let result = json!({"type": "result", "levels": {"school": 1.0}, "values": {"lost": 3.0}});
        let first = ana.ask_id("run-1", result.clone()).await;
        ok(&first);
        let again = ana.ask_id("run-1", result.clone()).await;
        assert_eq!(first, again, "the same ack");
        // Resent after a reconnect (the network dropped before the ack arrived).
        drop(ana);
        let mut back = server.client().await;
        ok(&back
            .ask(json!({"type": "resume", "code": code, "student_token": joined["student_token"]}))
            .await);
        assert_eq!(back.ask_id("run-1", result.clone()).await, first);
        // A new id is a new run.
        ok(&back.ask_id("run-2", result).await);
        let (_, csv) = server.csv(&code, Some(&token)).await;
        let rows = csv.lines().filter(|l| !l.starts_with('#')).count() - 1;
        assert_eq!(rows, 2, "{csv}");
        server.stop().await;
    }
}

#[tokio::test]
async fn a_server_restart_loses_no_committed_prediction_or_result() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let mut tokens = Vec::new();
        for i in 0..5 {
            let (mut c, joined) = join(&server, &code, &format!("S{i}")).await;
            ok(&c
                .ask(json!({"type": "predict", "prediction": format!("guess {i}")}))
                .await);
            ok(&c
                .ask(json!({"type": "result", "levels": {}, "values": {"lost": f64::from(i)}}))
                .await);
            tokens.push(joined["student_token"].as_str().unwrap().to_owned());
        }
        let (_, before) = server.csv(&code, Some(&token)).await;
        server.stop().await;
        let server = start(&url, Default::default()).await;
        let (status, after) = server.csv(&code, Some(&token)).await;
        assert_eq!(status, 200);
        assert_eq!(before, after);
        assert_eq!(after.lines().filter(|l| l.contains("guess")).count(), 5);
        // Students resume with their tokens and a resent message stays counted once.
        let mut c = server.client().await;
        ok(&c
            .ask(json!({"type": "resume", "code": code, "student_token": tokens[0]}))
            .await);
        let me = c.view("you").await;
        assert_eq!(me["me"]["prediction"], "guess 0");
        server.stop().await;
    }
}

#[tokio::test]
async fn holding_the_class_stops_students_at_a_step_until_released() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        let mut t = teacher(&server, &code, &token).await;
        ok(&t.ask(json!({"type": "hold", "step": "predict"})).await);
        ok(&ana.ask(json!({"type": "step", "step": "predict"})).await);
        assert_eq!(
            error_code(&ana.ask(json!({"type": "step", "step": "run"})).await),
            "held"
        );
        ok(&t.ask(json!({"type": "release"})).await);
        ok(&ana.ask(json!({"type": "step", "step": "run"})).await);
        assert_eq!(
            error_code(&ana.ask(json!({"type": "step", "step": "explain"})).await),
            "held"
        );
        ok(&t.ask(json!({"type": "hold", "step": null})).await);
        ok(&ana.ask(json!({"type": "step", "step": "explain"})).await);
        server.stop().await;
    }
}

#[tokio::test]
async fn expired_classes_are_deleted_and_recent_ones_kept() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        ok(&ana
            .ask(json!({"type": "predict", "prediction": "fewer"}))
            .await);
        tokio::time::sleep(Duration::from_millis(1100)).await;
        assert_eq!(
            shoal_class::delete_expired(&server.pool, 1).await.unwrap(),
            0
        );
        assert_eq!(server.csv(&code, Some(&token)).await.0, 200);
        assert_eq!(
            shoal_class::delete_expired(&server.pool, 0).await.unwrap(),
            1
        );
        assert_eq!(server.csv(&code, Some(&token)).await.0, 403);
        let left: i64 = sqlx::query_scalar("SELECT COUNT(*) FROM students")
            .fetch_one(&server.pool)
            .await
            .unwrap();
        assert_eq!(left, 0);
        server.stop().await;
    }
}

/// The web app asks `/api/info` at start to know that a class server serves it
/// (a static copy answers with `index.html` or nothing, and the app then hides
/// its class features).
#[tokio::test]
async fn the_info_route_names_the_server_and_its_protocol() {
    let index = ("index.html", "<!doctype html><title>Shoal</title>");
    let server = start_with_dist("shoal-class-info", &[index]).await;
    let r = reqwest::get(format!("http://{}/api/info", server.addr))
        .await
        .unwrap();
    assert_eq!(r.status(), 200);
    assert!(r.headers()["content-type"]
        .to_str()
        .unwrap()
        .starts_with("application/json"));
    let v: Value = r.json().await.unwrap();
    assert_eq!(v, json!({"server": "shoal-class", "protocol": 1}));
    server.stop().await;
}

#[tokio::test]
async fn every_response_carries_the_strict_csp() {
    let index = ("index.html", "<!doctype html><title>Shoal</title>");
    let server = start_with_dist("shoal-class-dist", &[index]).await;
    for path in ["/", "/index.html", "/api/classes/XXXXXX/csv"] {
        let r = reqwest::get(format!("http://{}{path}", server.addr))
            .await
            .unwrap();
        let csp = r
            .headers()
            .get("content-security-policy")
            .unwrap()
            .to_str()
            .unwrap()
            .to_owned();
        assert!(
            csp.starts_with(
                "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; connect-src 'self'"
            ),
            "{csp}"
        );
        if path != "/api/classes/XXXXXX/csv" {
            assert!(r.text().await.unwrap().contains("Shoal"));
        }
    }
    server.stop().await;
}

/// The app's files go out as the build's brotli copy to a browser that accepts
/// brotli (the copy's bytes, `Content-Encoding: br`), and as themselves otherwise.
#[tokio::test]
async fn the_app_s_files_go_out_precompressed_where_the_browser_accepts_it() {
    let files = [
        ("index.html", "<!doctype html><title>Shoal</title>"),
        ("app.js", "the file itself"),
        ("app.js.br", "its brotli copy"),
    ];
    let server = start_with_dist("shoal-class-br", &files).await;
    let client = reqwest::Client::new();
    let get = |encoding: &'static str| {
        client
            .get(format!("http://{}/app.js", server.addr))
            .header("accept-encoding", encoding)
            .send()
    };
    let r = get("gzip, deflate, br").await.unwrap();
    assert_eq!(
        r.headers()
            .get("content-encoding")
            .map(|v| v.to_str().unwrap().to_owned()),
        Some("br".to_owned())
    );
    assert_eq!(r.bytes().await.unwrap().as_ref(), b"its brotli copy");
    let r = get("identity").await.unwrap();
    assert!(r.headers().get("content-encoding").is_none());
    assert_eq!(r.text().await.unwrap(), "the file itself");
    server.stop().await;
}

#[tokio::test]
async fn students_writing_at_once_lose_nothing() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let mut tasks = Vec::new();
        for i in 0..12 {
            let (mut c, _) = join(&server, &code, &format!("S{i}")).await;
            tasks.push(tokio::spawn(async move {
                ok(&c.ask(json!({"type": "predict", "prediction": "fewer"})).await);
                for run in 0..5 {
                    let r = c.ask(json!({"type": "result", "levels": {"run": f64::from(run)}, "values": {"lost": 1.0}})).await;
                    ok(&r);
                }
            }));
        }
        for t in tasks {
            t.await.expect("a student's task");
        }
        let (_, csv) = server.csv(&code, Some(&token)).await;
        assert_eq!(
            csv.lines().filter(|l| l.contains(",lost,")).count(),
            60,
            "{csv}"
        );
        server.stop().await;
    }
}

#[tokio::test]
async fn anonymise_hides_nicknames_from_the_dashboard_but_not_the_csv() {
    for url in backends().await {
        let server = start(&url, Default::default()).await;
        let (code, token, _) = server.start_class(json!("a")).await;
        let (mut ana, _) = join(&server, &code, "Ana").await;
        ok(&ana
            .ask(json!({"type": "result", "levels": {}, "values": {"lost": 2.0}}))
            .await);
        let mut t = teacher(&server, &code, &token).await;
        assert_eq!(t.view("class").await["roster"][0]["nickname"], "Ana");
        ok(&t.ask(json!({"type": "anonymise", "on": true})).await);
        let view = t.view("class").await;
        assert_eq!(view["anonymise"], true);
        assert_eq!(view["roster"][0]["nickname"], Value::Null);
        assert_eq!(view["roster"][0]["join_order"], 1);
        assert!(server.csv(&code, Some(&token)).await.1.contains(",Ana,"));
        ok(&t.ask(json!({"type": "anonymise", "on": false})).await);
        assert_eq!(t.view("class").await["roster"][0]["nickname"], "Ana");
        server.stop().await;
    }
}
