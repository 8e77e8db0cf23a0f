//! Whom a change wakes: a student's step or prediction reaches the teacher's
//! dashboard but not the other students' connections (their views did not
//! change), until the teacher reveals the prediction counts; then every
//! prediction reaches every student. Against SQLite, through the real server.

use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use serde_json::{json, Value};
use tokio_tungstenite::tungstenite::Message;

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn next(ws: &mut Ws, within: Duration) -> Option<Value> {
    loop {
        match tokio::time::timeout(within, ws.next()).await {
            Ok(Some(Ok(Message::Text(t)))) => return serde_json::from_str(t.as_str()).ok(),
            Ok(Some(Ok(_))) => continue,
            _ => return None,
        }
    }
}

/// Sends a message and returns the view that follows its ack.
async fn ask(ws: &mut Ws, id: &str, mut body: Value) -> Value {
    body["v"] = json!(1);
    body["id"] = json!(id);
    ws.send(Message::text(body.to_string())).await.unwrap();
    let reply = next(ws, Duration::from_secs(10)).await.expect("a reply");
    assert_eq!(reply["re"], json!(id), "{reply}");
    assert_ne!(reply["type"], "error", "{reply}");
    next(ws, Duration::from_secs(10)).await.expect("a view")
}

/// Reads until nothing arrives for `quiet`; returns the last view read.
async fn settle(ws: &mut Ws, quiet: Duration) -> Option<Value> {
    let mut last = None;
    while let Some(v) = next(ws, quiet).await {
        last = Some(v);
    }
    last
}

#[tokio::test]
async fn a_students_change_wakes_the_other_students_only_once_counts_are_revealed() {
    let dir = std::env::temp_dir().join(format!("shoal-class-fanout-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("class.sqlite");
    let _ = std::fs::remove_file(&file);
    let pool = shoal_class::db::open(&format!("sqlite://{}", file.display()))
        .await
        .unwrap();
    let app = shoal_class::app(pool, shoal_class::Config::default());
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    tokio::spawn(async move {
        let _ = axum::serve(listener, app).await;
    });
    let started: Value = reqwest::Client::new()
        .post(format!("http://{addr}/api/classes"))
        .json(&json!({"setup": {"investigation": "why-school"}}))
        .send()
        .await
        .unwrap()
        .json()
        .await
        .unwrap();
    let code = started["code"].as_str().unwrap();
    let url = format!("ws://{addr}/ws");
    let connect = || async {
        tokio_tungstenite::connect_async(url.as_str())
            .await
            .unwrap()
            .0
    };
    let mut teacher = connect().await;
    ask(
        &mut teacher,
        "t1",
        json!({"type": "teacher", "code": code, "teacher_token": started["teacher_token"]}),
    )
    .await;
    let mut ana = connect().await;
    ask(
        &mut ana,
        "a1",
        json!({"type": "join", "code": code, "nickname": "Ana"}),
    )
    .await;
    let mut bo = connect().await;
    ask(
        &mut bo,
        "b1",
        json!({"type": "join", "code": code, "nickname": "Bo"}),
    )
    .await;
    let quiet = Duration::from_millis(400);
    settle(&mut teacher, quiet).await;
    settle(&mut ana, quiet).await;

    // Ana's step and prediction: the teacher sees them, Bo hears nothing.
    ask(&mut ana, "a2", json!({"type": "step", "step": "predict"})).await;
    ask(
        &mut ana,
        "a3",
        json!({"type": "predict", "prediction": "fewer"}),
    )
    .await;
    let dashboard = settle(&mut teacher, quiet)
        .await
        .expect("the dashboard is updated");
    assert_eq!(dashboard["histogram"], json!({"fewer": 1}));
    assert_eq!(dashboard["roster"][0]["step"], "predict");
    assert_eq!(
        settle(&mut bo, quiet).await,
        None,
        "Bo's view did not change"
    );

    // The reveal reaches Bo, and from then on every prediction does.
    ask(
        &mut teacher,
        "t2",
        json!({"type": "reveal", "revealed": true}),
    )
    .await;
    let seen = settle(&mut bo, quiet).await.expect("the reveal reaches Bo");
    assert_eq!(seen["histogram"], json!({"fewer": 1}));
    settle(&mut ana, quiet).await;
    ask(
        &mut ana,
        "a4",
        json!({"type": "predict", "prediction": "more"}),
    )
    .await;
    let seen = settle(&mut bo, quiet)
        .await
        .expect("a revealed prediction reaches Bo");
    assert_eq!(seen["histogram"], json!({"more": 1}));
    assert_eq!(seen["me"]["nickname"], "Bo");
    // Ana's result still reaches only the teacher.
    ask(
        &mut ana,
        "a5",
        json!({"type": "result", "levels": {"school": 1}, "values": {"lost": 3}}),
    )
    .await;
    assert_eq!(settle(&mut bo, quiet).await, None);
    let dashboard = settle(&mut teacher, quiet)
        .await
        .expect("the result reaches the dashboard");
    assert_eq!(dashboard["roster"][0]["results"][0]["value"], json!(3.0));
}
