//! The class client's logic, without a socket.

use serde_json::json;

use super::outbox::Outbox;
use super::session::{Link, Session, Student, Teacher, Who, backoff_secs};
use super::view::{Incoming, parse};
use super::*;

fn student(code: &str) -> Session {
    Session::new(
        Who::Student(Student {
            code: code.to_owned(),
            nickname: "Ana".to_owned(),
            token: None,
            join_order: 0,
            seed: 0,
            setup: json!(null),
        }),
        "s1",
    )
}

fn sent(frames: &[String]) -> Vec<serde_json::Value> {
    frames
        .iter()
        .map(|f| serde_json::from_str(f).unwrap())
        .collect()
}

#[test]
fn every_message_gets_a_unique_id_and_waits_for_its_ack() {
    let mut out = Outbox::new("abc");
    let a = out.push("step", json!({"step": "look"}));
    let b = out.push("predict", json!({"prediction": "fewer"}));
    assert_eq!(a["v"], 1);
    assert_eq!(a["type"], "step");
    assert_eq!(a["step"], "look");
    assert_ne!(a["id"], b["id"]);
    assert_eq!(out.len(), 2);
    assert!(out.ack(a["id"].as_str().unwrap()));
    // A second ack of the same id (a resend's) changes nothing.
    assert!(!out.ack(a["id"].as_str().unwrap()));
    assert_eq!(out.waiting().len(), 1);
    assert_eq!(out.waiting()[0].message, b);
}

#[test]
fn a_refused_message_is_dropped_but_a_rate_limited_one_waits() {
    let mut out = Outbox::new("p");
    let a = out.push("step", json!({"step": "run"}));
    let b = out.push("result", json!({"levels": {}, "values": {"x": 1.0}}));
    assert!(
        out.refused(b["id"].as_str().unwrap(), "rate_limited")
            .is_none()
    );
    assert!(out.refused(b["id"].as_str().unwrap(), "internal").is_none());
    assert_eq!(out.len(), 2);
    let gone = out.refused(a["id"].as_str().unwrap(), "held").unwrap();
    assert_eq!(gone.message["type"], "step");
    assert_eq!(out.len(), 1);
}

#[test]
fn the_outbox_survives_a_reload_and_keeps_counting() {
    let mut s = student("K7QX2M");
    s.send("predict", json!({"prediction": "fewer"}));
    let kept = s.to_storage();
    let mut back = Session::from_storage(&kept).unwrap();
    assert_eq!(back.outbox.len(), 1);
    assert_eq!(back.link(), Link::Closed);
    let next = back.outbox.push("explain", json!({"answer": "x"}));
    assert_ne!(next["id"], back.outbox.waiting()[0].message["id"]);
    assert!(Session::from_storage("not json").is_none());
}

/// A join whose answer never came is resent, after the reconnection, with the
/// same join key (the server then gives back the student it made); a session
/// with another random prefix (another join, on a shared Chromebook say) sends
/// another key.
#[test]
fn a_join_is_resent_with_the_same_join_key() {
    let mut s = Session::new(
        Who::Student(Student {
            code: "K7QX2M".to_owned(),
            nickname: "Ana".to_owned(),
            token: None,
            join_order: 0,
            seed: 0,
            setup: json!(null),
        }),
        "q8z1x0c4v7b2",
    );
    s.connecting();
    let first = sent(&s.on_open());
    assert_eq!(first[0]["join_key"], "q8z1x0c4v7b2");
    s.on_close(1.0);
    s.connecting();
    let again = sent(&s.on_open());
    assert_eq!(again[0]["type"], "join");
    assert_eq!(again[0]["join_key"], first[0]["join_key"]);
    assert_ne!(again[0]["id"], first[0]["id"]);
    // Another session, another key; a prefix the server would refuse sends none.
    let mut other = student("K7QX2M");
    other.connecting();
    assert!(sent(&other.on_open())[0].get("join_key").is_none());
}

#[test]
fn a_student_joins_then_resumes_and_resends_everything_unacknowledged() {
    let mut s = student("K7QX2M");
    assert!(s.should_connect(0.0));
    s.connecting();
    let hello = sent(&s.on_open());
    assert_eq!(hello[0]["type"], "join");
    assert_eq!(hello[0]["nickname"], "Ana");
    // Work done before the server answered waits.
    assert!(s.send("step", json!({"step": "look"})).is_none());
    let joined = json!({"v": 1, "type": "joined", "re": hello[0]["id"], "student_token": "tok",
        "join_order": 3, "seed": 1003, "setup": {"investigation": "why-school"}});
    let resent = sent(&s.on_message(&joined.to_string(), 1.0));
    assert_eq!(s.link(), Link::Connected);
    assert_eq!(resent.len(), 1);
    assert_eq!(resent[0]["type"], "step");
    let st = s.student().unwrap();
    assert_eq!(
        (st.token.as_deref(), st.join_order, st.seed),
        (Some("tok"), 3, 1003)
    );
    // Connected: a message goes at once; its ack clears it.
    let p = sent(&[s.send("predict", json!({"prediction": "fewer"})).unwrap()]);
    s.on_message(
        &json!({"v":1,"type":"ack","re":resent[0]["id"]}).to_string(),
        1.0,
    );
    assert_eq!(s.outbox.len(), 1);
    // The connection drops before the prediction's ack.
    s.on_close(2.0);
    assert_eq!(s.link(), Link::Closed);
    assert!(!s.should_connect(2.5));
    assert!(s.should_connect(3.0));
    let r = s.send(
        "result",
        json!({"levels": {}, "values": {"caught_school": 2.0}}),
    );
    assert!(r.is_none());
    s.connecting();
    let hello = sent(&s.on_open());
    assert_eq!(hello[0]["type"], "resume");
    assert_eq!(hello[0]["student_token"], "tok");
    let resent = sent(&s.on_message(
        &json!({"v":1,"type":"ack","re":hello[0]["id"]}).to_string(),
        4.0,
    ));
    // The prediction goes again with the same id (applied once by the server),
    // then the result.
    assert_eq!(resent.len(), 2);
    assert_eq!(resent[0]["id"], p[0]["id"]);
    assert_eq!(resent[1]["type"], "result");
    for m in &resent {
        s.on_message(&json!({"v":1,"type":"ack","re":m["id"]}).to_string(), 4.0);
    }
    assert!(s.outbox.is_empty());
}

#[test]
fn a_refused_hello_ends_the_session_instead_of_retrying_forever() {
    let mut t = Session::new(
        Who::Teacher(Teacher {
            code: "K7QX2M".into(),
            token: "00".into(),
        }),
        "t",
    );
    let hello = sent(&t.on_open());
    assert_eq!(hello[0]["type"], "teacher");
    t.on_message(
        &json!({"v":1,"type":"error","re":hello[0]["id"],"code":"forbidden","message":"no"})
            .to_string(),
        0.0,
    );
    assert_eq!(t.link(), Link::Ended);
    assert_eq!(t.ended.as_deref(), Some("no"));
    t.on_close(1.0);
    assert!(!t.should_connect(100.0));
}

#[test]
fn a_rate_limited_message_is_resent_later() {
    let mut s = student("K7QX2M");
    let hello = sent(&s.on_open());
    s.on_message(
        &json!({"v":1,"type":"joined","re":hello[0]["id"],"student_token":"t","join_order":1,"seed":2})
            .to_string(),
        0.0,
    );
    let m = sent(&[s.send("step", json!({"step":"look"})).unwrap()]);
    s.on_message(
        &json!({"v":1,"type":"error","re":m[0]["id"],"code":"rate_limited","message":"slow"})
            .to_string(),
        1.0,
    );
    assert!(s.poll(2.0).is_empty());
    assert_eq!(sent(&s.poll(3.0))[0]["id"], m[0]["id"]);
    assert!(s.poll(4.0).is_empty());
    // A held step is refused for good and said.
    let h = sent(&[s.send("step", json!({"step":"explain"})).unwrap()]);
    s.on_message(
        &json!({"v":1,"type":"error","re":h[0]["id"],"code":"held","message":"held"}).to_string(),
        5.0,
    );
    assert_eq!(s.refusals.len(), 1);
    assert_eq!(s.refusals[0].kind, "step");
    assert_eq!(s.outbox.len(), 1);
}

#[test]
fn reconnects_back_off_to_thirty_seconds() {
    let steps: Vec<f64> = (0..8).map(backoff_secs).collect();
    assert_eq!(steps, [0.0, 1.0, 2.0, 4.0, 8.0, 16.0, 30.0, 30.0]);
    let mut s = student("K7QX2M");
    s.on_close(0.0);
    s.on_close(1.0);
    s.on_close(3.0);
    assert!((s.retry_in(3.0) - 4.0).abs() < 1e-9);
}

#[test]
fn the_hold_rule_stops_a_student_beyond_the_held_step() {
    assert!(may_go_to("explain", None));
    assert!(may_go_to("look", Some("predict")));
    assert!(may_go_to("predict", Some("predict")));
    assert!(!may_go_to("run", Some("predict")));
    assert!(!may_go_to("explain", Some("look")));
    assert!(!may_go_to("dance", Some("look")));
    use crate::investigation::Step;
    assert_eq!(class_step(Step::Intro), "look");
    assert_eq!(class_step(Step::Reveal), "explain");
    let mut s = student("K7QX2M");
    s.on_message(
        &json!({"type":"you","state":{"held_step":"predict","paused":false,"setting":null,"revealed":false},
            "me":{"join_order":1,"nickname":"Ana","seed":5,"step":"predict","prediction":null,"answer":null,"results":[]},
            "histogram":null}).to_string(),
        0.0,
    );
    assert!(s.may_go_to("predict"));
    assert!(!s.may_go_to("run"));
}

#[test]
fn the_views_parse_as_the_server_sends_them() {
    let class = json!({"v":1,"type":"class","code":"K7QX2M","seed":100,"setup":{"investigation":"why-school"},
        "anonymise":true,"state":{"held_step":null,"paused":true,"setting":{"fish":20},"revealed":false},
        "roster":[{"join_order":1,"nickname":null,"seed":101,"step":"run","prediction":"fewer","answer":"",
            "results":[{"levels":{},"measure":"caught_school","value":2.0}]}],
        "histogram":{"fewer":1}});
    let Incoming::Class(view) = parse(&class.to_string()) else {
        panic!("not a class view");
    };
    assert_eq!(view.code, "K7QX2M");
    assert!(view.anonymise && view.state.paused);
    assert_eq!(view.roster[0].nickname, None);
    assert_eq!(view.roster[0].results[0].value, 2.0);
    assert_eq!(view.histogram["fewer"], 1);
    let you = json!({"type":"you","state":{"held_step":"look","paused":false,"setting":null,"revealed":true},
        "me":{"join_order":2,"nickname":"<b>Bo</b>","seed":102,"step":null,"prediction":null,"answer":null,"results":[]},
        "histogram":{"fewer":3,"more":1}});
    let Incoming::You(you) = parse(&you.to_string()) else {
        panic!("not a you view");
    };
    assert_eq!(you.me.nickname.as_deref(), Some("<b>Bo</b>"));
    assert_eq!(you.histogram.unwrap()["more"], 1);
    assert!(matches!(parse("{"), Incoming::Unreadable(_)));
    assert!(matches!(
        parse(r#"{"type":"class","code":5}"#),
        Incoming::Unreadable(_)
    ));
    assert!(matches!(
        parse(r#"{"type":"ack"}"#),
        Incoming::Unreadable(_)
    ));
    assert!(view::is_class_server(
        r#"{"server":"shoal-class","protocol":1}"#
    ));
    assert!(!view::is_class_server(
        "<!doctype html><title>Shoal</title>"
    ));
    assert!(!view::is_class_server(
        r#"{"server":"shoal-class","protocol":2}"#
    ));
}

fn with_results(join_order: i64, values: &[f64]) -> view::StudentRecord {
    view::StudentRecord {
        join_order,
        results: values
            .iter()
            .map(|v| view::ResultRow {
                levels: Default::default(),
                measure: "caught".into(),
                value: *v,
            })
            .collect(),
        ..Default::default()
    }
}

#[test]
fn the_pooled_result_keeps_its_interval_within_the_measure() {
    let roster = vec![
        with_results(2, &[0.0]),
        with_results(1, &[0.0, 1.0]),
        with_results(3, &[0.0]),
        with_results(4, &[]),
    ];
    let pooled = stats::pooled(&roster);
    assert_eq!(pooled.len(), 1);
    let p = &pooled[0];
    assert_eq!((p.n, p.students), (4, 3));
    assert!((p.mean - 0.25).abs() < 1e-12);
    // A count cannot be negative: a t interval would go below 0.
    assert!(p.low >= 0.0 && p.high <= 1.0 && p.low <= p.mean && p.mean <= p.high);
    assert_eq!(p.values, [0.0, 1.0, 0.0, 0.0]);
    let one = stats::pooled(&[with_results(1, &[7.0])]);
    assert!(one[0].low.is_nan());
    // Three students whose runs measured the same (the browser test's class):
    // the plain mean rounds a last bit below the value; the pooled one does not.
    let v = 0.757_527_998_571_215_3;
    let same: Vec<_> = (1..=3).map(|k| with_results(k, &[v])).collect();
    let p = &stats::pooled(&same)[0];
    assert!(
        p.min <= p.low && p.low <= p.mean && p.mean <= p.high && p.high <= p.max,
        "{p:?}"
    );
    assert!(stats::pooled(&[]).is_empty());
}

#[test]
fn the_histogram_lists_the_most_chosen_first() {
    let h = [
        ("more".to_string(), 1),
        ("fewer".to_string(), 3),
        ("same".to_string(), 0),
    ]
    .into_iter()
    .collect();
    assert_eq!(
        stats::histogram_bars(&h),
        [("fewer".to_string(), 3), ("more".to_string(), 1)]
    );
    let roster = vec![
        view::StudentRecord {
            step: Some("run".into()),
            ..Default::default()
        },
        view::StudentRecord::default(),
    ];
    assert_eq!(stats::step_counts(&roster), ([0, 0, 1, 0], 1));
}

#[test]
fn codes_and_nicknames_are_checked_as_the_server_checks_them() {
    assert_eq!(normalise_code(" k7q-x2m ").as_deref(), Some("K7QX2M"));
    assert_eq!(normalise_code("K7QX20"), None); // no zero
    assert_eq!(normalise_code("K7QX2"), None);
    assert_eq!(normalise_nickname("  Ana "), Some("Ana".into()));
    assert_eq!(normalise_nickname("   "), None);
    assert_eq!(normalise_nickname(&"x".repeat(25)), None);
    assert_eq!(normalise_nickname("a\u{7}b"), None);
}

#[test]
fn an_investigation_s_outcome_reports_named_measured_numbers() {
    use crate::investigation::{Chart, INVESTIGATIONS, Outcome, outcome::Row};
    let why = INVESTIGATIONS
        .iter()
        .find(|i| i.id == "why-school")
        .unwrap();
    let outcome = Outcome {
        summary: String::new(),
        verdict: String::new(),
        rows: vec![
            Row {
                label: "a".into(),
                value: 7.0,
                unit: "",
            },
            Row {
                label: "b".into(),
                value: 3.0,
                unit: "",
            },
        ],
        chart: Chart::Bars {
            unit: "",
            whole: true,
        },
        timelines: Vec::new(),
        translations: Vec::new(),
    };
    let values = result_values(why, &outcome);
    assert_eq!(values["caught_loners"], 7.0);
    assert_eq!(values["caught_school"], 3.0);
    let other = INVESTIGATIONS
        .iter()
        .find(|i| {
            i.id != "why-school"
                && !matches!(
                    i.measurement,
                    crate::investigation::MeasurementKind::AlignmentOnOff { .. }
                )
        })
        .unwrap();
    assert_eq!(
        result_values(other, &outcome).keys().collect::<Vec<_>>(),
        ["row1", "row2"]
    );
}
