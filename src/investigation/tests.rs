//! The investigations' state machine, links, measurements and record.

use serde_json::json;

use super::catalogue::{INVESTIGATIONS, MeasurementKind, SHAPES, find};
use super::link::{
    LinkError, Request, from_url, split_patch, with_investigation, without_investigation,
};
use super::measure::{Measurement, TailBeatRun};
use super::outcome::{Chart, CurvePoint, Outcome, Row, shape_distance};
use super::*;
use crate::lab::Lab;

fn progress(id: &str) -> Progress {
    Progress::new(find(id).expect("known id"))
}

fn info() -> record::RecordInfo {
    record::RecordInfo {
        student: String::new(),
        date: "2026-11-28".into(),
        time: "14:05".into(),
        page: "https://example.org/shoal/".into(),
    }
}

fn outcome() -> Outcome {
    Outcome {
        summary: "measured 3 and 1".into(),
        verdict: "agrees".into(),
        rows: vec![
            Row {
                label: "a".into(),
                value: 3.0,
                unit: "fish",
            },
            Row {
                label: "b".into(),
                value: 1.0,
                unit: "fish",
            },
        ],
        chart: Chart::Bars {
            unit: "fish",
            whole: true,
        },
        timelines: vec![super::outcome::Timeline {
            label: "a".into(),
            points: vec![[0.0, 0.0], [90.0, 2.0], [180.0, 3.0]],
        }],
        translations: Vec::new(),
    }
}

#[test]
fn the_run_waits_for_a_committed_prediction_and_the_prediction_then_stays() {
    let mut p = progress("why-school");
    assert!(!p.can_run());
    assert_eq!(p.start_run(), Err(StepError::NoPrediction));
    p.begin();
    assert_eq!(p.step, Step::Predict);
    // Committing without choosing is refused.
    assert_eq!(p.commit(), Err(StepError::NoPrediction));
    assert_eq!(p.start_run(), Err(StepError::NoPrediction));
    assert_eq!(
        p.choose(7),
        Err(StepError::NoSuchAnswer {
            choice: 7,
            count: 3
        })
    );
    p.choose(0).unwrap();
    p.choose(1).unwrap(); // a student may change their mind before committing
    assert!(!p.can_run(), "chosen is not committed");
    p.commit().unwrap();
    assert_eq!(p.step, Step::Run);
    assert_eq!(p.prediction, Some(Prediction { choice: 1 }));
    assert!(p.can_run());
    // Locked: neither a new choice nor a second commit changes it.
    assert_eq!(p.choose(0), Err(StepError::Locked));
    assert_eq!(p.commit(), Err(StepError::Locked));
    assert_eq!(p.prediction, Some(Prediction { choice: 1 }));
    p.start_run().unwrap();
    assert!(!p.can_run(), "one run");
    // No explaining before a result.
    assert_eq!(p.advance(), Err(StepError::NoResult));
    p.finish_run(outcome());
    p.advance().unwrap();
    assert_eq!(p.step, Step::Explain);
    for _ in 0..p.investigation.prompts.len() - 1 {
        p.advance().unwrap();
        assert_eq!(p.step, Step::Explain);
    }
    p.advance().unwrap();
    assert_eq!(p.step, Step::Reveal);
    assert_eq!(p.prediction, Some(Prediction { choice: 1 }));
    let report = serde_json::to_value(p.report()).unwrap();
    assert_eq!(report["id"], "why-school");
    assert_eq!(report["step"], "reveal");
    assert_eq!(report["prediction"]["text"], "The school (Group tank)");
    assert_eq!(report["result"]["rows"][0]["value"], 3.0);
}

#[test]
fn every_investigation_sets_up_through_the_settings_and_has_what_a_lesson_needs() {
    assert_eq!(INVESTIGATIONS.len(), 5);
    for inv in &INVESTIGATIONS {
        let settings = setup_settings(inv).unwrap_or_else(|e| panic!("{}: {e}", inv.id));
        assert!(settings.validate().is_ok(), "{}", inv.id);
        assert!((5..=15).contains(&inv.minutes), "{}", inv.id);
        assert!((2..=3).contains(&inv.prompts.len()), "{}", inv.id);
        assert!(!inv.reveal.text().is_empty() && !inv.reference.text().is_empty());
        if let MeasurementKind::Sweep { design } = inv.measurement {
            let plan = crate::experiment::Design::from_json(design)
                .and_then(|d| d.validate())
                .unwrap_or_else(|e| panic!("{}: {e}", inv.id));
            assert!(plan.seeds.len() >= 2, "an interval needs two seeds");
        }
    }
    let school = setup_settings(find("why-school").unwrap()).unwrap();
    assert!(school.compare);
    assert_eq!(
        school.left.preset,
        crate::settings::tank::Preset::Individual
    );
    assert_eq!(school.right.preset, crate::settings::tank::Preset::Group);
    assert_eq!(school.left.fish_count, school.right.fish_count);
    assert_eq!((school.left.sharks, school.right.sharks), (1, 1));
    let ids: Vec<&str> = list().iter().map(|e| e.id).collect();
    assert_eq!(
        ids,
        ["why-school", "leader", "which-urge", "how-swim", "learning"]
    );
}

#[test]
fn links_open_known_investigations_and_name_the_known_ones_otherwise() {
    let url = "http://127.0.0.1:8080/?investigation=leader#v1.abc";
    assert_eq!(from_url(url).unwrap().unwrap().id, "leader");
    assert!(from_url("http://x/?bench#v1.abc").is_none());
    assert!(from_url("http://x/#?investigation=leader").is_none());
    let err = from_url("http://x/?a=1&investigation=nope")
        .unwrap()
        .unwrap_err();
    let text = err.to_string();
    assert!(text.contains("'nope'"), "{text}");
    for inv in &INVESTIGATIONS {
        assert!(text.contains(inv.id), "{text}");
    }
    assert_eq!(
        without_investigation("http://x/?a=1&investigation=leader"),
        "http://x/?a=1"
    );
    assert_eq!(
        without_investigation("http://x/?investigation=leader"),
        "http://x/"
    );
    assert_eq!(
        with_investigation("http://x/?investigation=leader", "how-swim"),
        "http://x/?investigation=how-swim"
    );
    // set(): the id is split off; the settings stay; a bad id refuses it all.
    let (request, rest) = split_patch(&json!({"investigation": "which-urge", "speed": 2})).unwrap();
    assert_eq!(request, Request::Open(find("which-urge").unwrap()));
    assert_eq!(rest, json!({"speed": 2}));
    assert_eq!(
        split_patch(&json!({"investigation": null})).unwrap().0,
        Request::Close
    );
    assert!(matches!(
        split_patch(&json!({"investigation": "nope", "speed": 2})),
        Err(LinkError::UnknownId { .. })
    ));
    assert!(matches!(
        split_patch(&json!({"investigation": 3})),
        Err(LinkError::NotAnId(_))
    ));
    assert_eq!(split_patch(&json!({"speed": 2})).unwrap().0, Request::None);
}

#[test]
fn a_sketch_is_closest_to_a_curve_of_its_own_shape() {
    let points: Vec<CurvePoint> = (0..6)
        .map(|k| {
            let u = f64::from(k) / 5.0;
            let y = SHAPES[2].at(u);
            CurvePoint {
                x: 20.0 * f64::from(k),
                mean: y,
                low: y,
                high: y,
            }
        })
        .collect();
    let d: Vec<f64> = SHAPES
        .iter()
        .map(|s| shape_distance(s, &points, 1.0))
        .collect();
    assert!(d[2] < 1e-9);
    assert!(
        d.iter().enumerate().all(|(k, &v)| k == 2 || v > 0.05),
        "{d:?}"
    );
    let verdict = super::outcome::curve_verdict(&SHAPES, 0, &points, 1.0);
    assert!(verdict.contains(SHAPES[2].name.text()), "{verdict}");
}

/// Steps `lab` and advances `m` until it ends (at most `max_steps`).
fn run_on_lab(m: &mut Measurement, p: &Progress, lab: &mut Lab, max_steps: u64) -> Outcome {
    let mut steps = 0;
    loop {
        if let Some(o) = m.advance(p, lab, 0.05, 0.0) {
            return o;
        }
        assert!(steps < max_steps, "the run did not end");
        lab.step(60);
        steps += 60;
    }
}

#[test]
fn why_school_measures_catches_in_both_tanks_and_they_follow_the_settings() {
    let inv = find("why-school").unwrap();
    let mut catches = Vec::new();
    for right_preset in ["group", "individual"] {
        let mut p = Progress::new(inv);
        p.choose(1).unwrap();
        p.commit().unwrap();
        p.start_run().unwrap();
        let mut settings = setup_settings(inv).unwrap();
        settings
            .apply_patch(&json!({"right": {"preset": right_preset}}))
            .unwrap();
        let mut lab = Lab::new(settings);
        let mut m = Measurement::start(inv, &mut lab).unwrap();
        assert!(!lab.settings().paused, "the run plays");
        let o = run_on_lab(&mut m, &p, &mut lab, 200 * 60);
        assert!(
            lab.settings().paused,
            "paused at the end for the class to look"
        );
        assert!(o.summary.contains("180"), "{}", o.summary);
        // The catches plot: each tank's count grows to what was measured.
        assert_eq!(o.timelines.len(), 2);
        for (t, row) in o.timelines.iter().zip(&o.rows) {
            assert_eq!(t.points.last().unwrap()[1], row.value);
            assert!(t.points.windows(2).all(|w| w[1][1] >= w[0][1]));
        }
        catches.push((o.rows[0].value, o.rows[1].value));
    }
    let (group, alone) = (catches[0], catches[1]);
    // The left tanks are the same run: the same catches.
    assert_eq!(group.0, alone.0);
    // The right tank differs in its preset only, and so does what it measured.
    assert_ne!(group.1, alone.1, "{catches:?}");
    eprintln!("catches (loners, school / loners): {catches:?}");
}

#[test]
fn how_swim_measures_faster_swimming_at_faster_beats_up_to_three_hertz() {
    static SLOW_FAST: [f64; 2] = [1.0, 3.0];
    let mut run = TailBeatRun::new(&SLOW_FAST, 30.0);
    run.run_to_end();
    let v = run.speeds();
    assert_eq!(v.len(), 2);
    assert!(v[0] > 0.05 && v[1] > 2.0 * v[0], "{v:?} BL/s");
    // Another frequency is another measurement.
    static OTHER: [f64; 1] = [2.0];
    let mut other = TailBeatRun::new(&OTHER, 30.0);
    other.run_to_end();
    assert!(other.speeds()[0] > v[0] && other.speeds()[0] < v[1]);
}

#[test]
fn which_urge_runs_the_experiment_engine_and_overlays_the_sketch() {
    let inv = find("which-urge").unwrap();
    let mut p = Progress::new(inv);
    p.choose(2).unwrap();
    p.commit().unwrap();
    p.start_run().unwrap();
    let mut lab = Lab::new(setup_settings(inv).unwrap());
    let mut m = Measurement::start(inv, &mut lab).unwrap();
    let o = loop {
        if let Some(o) = m.advance(&p, &mut lab, 1.0, 0.0) {
            break o;
        }
    };
    let Chart::Curve { points, .. } = &o.chart else {
        panic!("a curve");
    };
    assert_eq!(points.len(), 6);
    assert!(points.iter().all(|q| q.low <= q.mean && q.mean <= q.high));
    assert!(
        points[5].mean > points[0].mean + 0.2,
        "alignment orders the school: {points:?}"
    );
    assert!(o.verdict.contains(SHAPES[2].name.text()), "{}", o.verdict);
    eprintln!("which-urge: {points:?}\n{}", o.verdict);
}

#[test]
fn the_record_holds_the_prediction_the_numbers_and_escaped_answers() {
    let mut p = progress("why-school");
    p.choose(1).unwrap();
    p.commit().unwrap();
    p.start_run().unwrap();
    p.finish_run(outcome());
    p.explanations[0] = "the shark <script>alert(1)</script> & \"friends\"".into();
    p.advance().unwrap();
    let html = record::html(std::slice::from_ref(&p), &info());
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert!(html.contains("The school (Group tank) (locked before the run)"));
    assert!(html.contains("measured 3 and 1"));
    assert!(html.contains("<td class=\"n\">3</td>"));
    assert!(html.contains("&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;friends&quot;"));
    assert!(
        !html.contains("<script"),
        "no scripts, and none smuggled in"
    );
    assert!(html.contains("<svg"), "the plot inline");
    assert!(
        !html.contains("src=") && !html.contains("href="),
        "self-contained"
    );
    assert!(!html.contains("What scientists found"), "not revealed yet");
    let csv = record::csv(std::slice::from_ref(&p), &info());
    assert!(
        csv.contains("investigation,label,value,unit\nwhy-school,a,3,fish\nwhy-school,b,1,fish\n")
    );
    assert!(csv.contains("# why-school: predicted \"The school (Group tank)\""));
}

/// The cause behind *Why do fish school?*: the same two tanks (40 fish, one
/// shark, 180 s from the start) differing only in the urges, loners
/// (*Individual*) against a school (*Group*), over seeds 1–10. Measured (the
/// browser's runs, which the native ones equal since the libm change): loners
/// 78, school 31; the school lost clearly fewer on 8 seeds, as many on 1 and
/// more on 1, so the claim is for the sum. (A 200-fish, two-shark
/// version of this test asked for 1.5× per minute after a settling half
/// minute; over seeds 1–6 it measured 1.15×, and it was replaced by this one,
/// the setting students run.)
#[test]
fn the_school_loses_fewer_fish_than_the_loners_over_ten_seeds() {
    let (mut loners, mut school) = (0, 0);
    for seed in 1..=10u64 {
        let mut s = setup_settings(find("why-school").unwrap()).unwrap();
        s.apply_patch(&json!({"seed": seed, "paused": false}))
            .unwrap();
        let mut lab = Lab::new(s);
        lab.step(180 * 60);
        let c: Vec<u64> = lab.runs().iter().map(|r| r.metrics().catches).collect();
        println!("seed {seed}: loners {}, school {}", c[0], c[1]);
        loners += c[0];
        school += c[1];
    }
    println!("total: loners {loners}, school {school}");
    assert!(
        loners as f64 >= 1.3 * school as f64,
        "loners {loners}, school {school}"
    );
}

/// *Learning to swim* on a 90-try drill, its race stepped `chunk` steps
/// between two frames.
fn learning_outcome(chunk: u32) -> Outcome {
    let inv = find("learning").unwrap();
    let mut p = Progress::new(inv);
    p.choose(0).unwrap();
    p.commit().unwrap();
    p.start_run().unwrap();
    let mut settings = setup_settings(inv).unwrap();
    // A short drill, so the test is quick: the copies are saved at the paper's
    // share of it.
    settings
        .apply_patch(&json!({"learning": {"annealing_steps": 90}}))
        .unwrap();
    let mut lab = Lab::new(settings);
    let mut m = Measurement::start(inv, &mut lab).unwrap();
    assert!(lab.settings().learning.training, "the run trains");
    assert!(
        m.advance(&p, &mut lab, 0.01, 0.0).is_none(),
        "no race before practice"
    );
    lab.train(90).unwrap();
    loop {
        if let Some(o) = m.advance(&p, &mut lab, 0.01, 0.0) {
            break o;
        }
        lab.step(chunk);
    }
}

#[test]
fn learning_races_the_copies_saved_while_practising() {
    let o = learning_outcome(10);
    assert_eq!(o.rows.len(), 6, "{:?}", o.rows);
    assert!(o.rows[0].label.contains("after 1 tries"), "{:?}", o.rows[0]);
    assert!(o.rows[5].label.contains("after 90 tries"));
    // The measured distances, and the verdict quotes them.
    let last = o.rows[5].value;
    assert!(last > o.rows[0].value, "{:?}", o.rows);
    assert!(o.summary.contains(&format!("{last:.2} m")), "{}", o.summary);
    // However many steps a frame gives the race the student watches, the
    // numbers are those of the race at 7.4 s (the browser's slow frames once
    // read it at 7.5 s and later).
    let values = |o: &Outcome| o.rows.iter().map(|r| r.value).collect::<Vec<_>>();
    assert_eq!(values(&learning_outcome(37)), values(&o));
    assert!(o.summary.starts_with("After 7.4 s"), "{}", o.summary);
}

#[test]
fn leader_measures_polarization_with_alignment_on_and_off_and_the_fish_inspected() {
    let inv = find("leader").unwrap();
    let mut p = Progress::new(inv);
    p.choose(1).unwrap();
    p.commit().unwrap();
    p.start_run().unwrap();
    let mut lab = Lab::new(setup_settings(inv).unwrap());
    let mut m = Measurement::start(inv, &mut lab).unwrap();
    // Let the school form, then the student clicks fish 5.
    lab.step(600);
    let mut s = lab.settings().clone();
    s.left.selected = Some(5);
    lab.apply_settings(s);
    lab.step(1);
    let mut alignment_off = false;
    let o = loop {
        if let Some(o) = m.advance(&p, &mut lab, 0.01, 0.0) {
            break o;
        }
        let (on, _) = m.alignment().unwrap().means();
        if !alignment_off && on.is_some() && lab.runs()[0].time_secs() > 30.0 {
            // Enough measured with alignment on: the student turns it off.
            let mut s = lab.settings().clone();
            s.left.alignment = 0.0;
            lab.apply_settings(s);
            alignment_off = true;
        }
        assert!(lab.runs()[0].time_secs() < 120.0, "the run did not end");
        lab.step(15);
    };
    assert!(alignment_off);
    let on = o.rows[0].value;
    let off = o.rows[1].value;
    // The sign only: two 10 s windows of one run are noisy (measured on this
    // seed, 60 fish: on 0.58, off 0.42; the effect over seeds and levels is
    // the experiment engine's dose-response, docs/experiments.md).
    assert!(on > off, "alignment orders the school: on {on}, off {off}");
    assert_eq!(o.rows[2].label, "neighbours fish 5 heeded");
    assert!((1.0..=7.0).contains(&o.rows[2].value), "{:?}", o.rows[2]);
    assert!(o.verdict.contains("agrees"), "{}", o.verdict);
}

#[test]
fn every_text_an_investigation_names_exists_in_every_language() {
    use crate::i18n::{Lang, has};
    let mut count = 0;
    for inv in &INVESTIGATIONS {
        for text in inv.texts() {
            for lang in Lang::ALL {
                assert!(
                    has(lang, text.id()),
                    "{}: {} is not in locales/{}",
                    inv.id,
                    text.id(),
                    lang.code()
                );
            }
            count += 1;
        }
    }
    assert!(count > 50, "{count} texts");
}

#[test]
fn an_investigation_speaks_spanish() {
    use crate::i18n::{Lang, with_lang};
    let inv = find("which-urge").unwrap();
    let points = [
        CurvePoint {
            x: 0.0,
            mean: 0.25,
            low: 0.2,
            high: 0.3,
        },
        CurvePoint {
            x: 100.0,
            mean: 0.9,
            low: 0.85,
            high: 0.95,
        },
    ];
    with_lang(Lang::Es, || {
        assert_eq!(inv.title.text(), "¿Qué impulso forma un cardumen?");
        assert_eq!(
            crate::tr!("inv-curve-point", value = crate::i18n::num(0.25, 2), x = 20),
            "0,25 en 20"
        );
        let verdict = super::outcome::curve_verdict(&SHAPES, 0, &points, 1.0);
        assert!(verdict.starts_with("Tu dibujo, «Plana"), "{verdict}");
        let err = from_url("http://x/?investigation=nope")
            .unwrap()
            .unwrap_err();
        assert!(
            err.to_string().contains("no existe la investigación"),
            "{err}"
        );
        let mut p = Progress::new(inv);
        assert!(
            p.start_run()
                .unwrap_err()
                .to_string()
                .starts_with("primero confirma")
        );
        p.choose(1).unwrap();
        p.commit().unwrap();
        let rows = vec![Row {
            label: "polarización".into(),
            value: 0.5,
            unit: "0-1",
        }];
        p.finish_run(Outcome {
            summary: "x".into(),
            verdict: "y".into(),
            rows,
            chart: Chart::Bars {
                unit: "0-1",
                whole: false,
            },
            timelines: Vec::new(),
            translations: Vec::new(),
        });
        let html = record::html(std::slice::from_ref(&p), &info());
        assert!(html.contains("<html lang=\"es\">"));
        assert!(html.contains("Mi predicción"), "{html}");
        assert!(html.contains("<td class=\"n\">0,500</td>"), "{html}");
        let csv = record::csv(std::slice::from_ref(&p), &info());
        assert!(
            csv.contains("predicción \"Una línea recta hacia arriba\""),
            "{csv}"
        );
        // The CSV's numbers stay machine-readable.
        assert!(csv.contains("which-urge,polarización,0.5,0-1"), "{csv}");
    });
}

#[test]
fn a_result_follows_the_language_it_is_read_in() {
    use crate::i18n::{Lang, with_lang};
    let mut lab = Lab::new(setup_settings(find("how-swim").unwrap()).unwrap());
    let mut p = progress("how-swim");
    p.choose(1).unwrap();
    p.commit().unwrap();
    let mut m = Measurement::TailBeat(Box::new(TailBeatRun::new(&[1.0, 2.0], 2.0)));
    let o = with_lang(Lang::En, || run_on_lab(&mut m, &p, &mut lab, 10_000));
    assert!(
        o.localized().summary.starts_with("Measured speed"),
        "{}",
        o.summary
    );
    with_lang(Lang::Es, || {
        let es = o.localized();
        assert!(
            es.summary.starts_with("Se midió la velocidad"),
            "{}",
            es.summary
        );
        assert!(es.verdict.starts_with("Tu dibujo"), "{}", es.verdict);
        assert!(
            es.rows[0].label.contains("coletazos por segundo (Hz) 1"),
            "{:?}",
            es.rows[0]
        );
    });
}

#[test]
fn a_name_becomes_a_file_name_safe_on_every_system() {
    use record::slug;
    assert_eq!(slug("Ana Pérez"), "ana-perez");
    assert_eq!(slug("  José   Ñúñez-Díaz  "), "jose-nunez-diaz");
    assert_eq!(slug("Ærøskøbing Straße"), "aeroskobing-strasse");
    assert_eq!(slug("../../etc/passwd"), "etc-passwd");
    assert_eq!(slug("a:b*c?d\"e<f>g|h"), "a-b-c-d-e-f-g-h");
    assert_eq!(slug("李小龙"), "", "nothing of it left");
    assert_eq!(slug(""), "");
    assert_eq!(slug("---"), "");
    let long = slug(&"x".repeat(500));
    assert_eq!(long.len(), 40, "bounded");
    let long = slug(&"ab ".repeat(100));
    assert!(long.len() <= 40 && !long.ends_with('-'), "{long}");
    for name in ["Zoë O'Brien", "Łukasz", "名前 Ann", "tab\there"] {
        let s = slug(name);
        assert!(
            s.chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'),
            "{name}: {s}"
        );
    }
}

#[test]
fn the_record_file_is_named_by_investigation_student_and_date() {
    let mut one = progress("why-school");
    one.choose(1).unwrap();
    one.commit().unwrap();
    let mut info = info();
    info.student = "Ana Pérez".into();
    assert_eq!(
        record::file_name(std::slice::from_ref(&one), &info, "html"),
        "shoal-why-school-ana-perez-2026-11-28.html"
    );
    let mut two = progress("leader");
    two.choose(0).unwrap();
    two.commit().unwrap();
    assert_eq!(
        record::file_name(&[one.clone(), two], &info, "csv"),
        "shoal-investigations-ana-perez-2026-11-28.csv"
    );
    // Another student's file differs by the name alone.
    info.student = "Luis".into();
    assert_eq!(
        record::file_name(std::slice::from_ref(&one), &info, "html"),
        "shoal-why-school-luis-2026-11-28.html"
    );
    info.student = "   ".into();
    assert_eq!(
        record::file_name(std::slice::from_ref(&one), &info, "html"),
        "shoal-why-school-2026-11-28.html"
    );
}

#[test]
fn the_local_date_reads_as_a_date() {
    let (date, time) = record::local_now();
    let d: Vec<&str> = date.split('-').collect();
    assert_eq!(d.len(), 3, "{date}");
    assert!(d[0].parse::<u32>().unwrap() >= 2024, "{date}");
    assert!((1..=12).contains(&d[1].parse::<u32>().unwrap()), "{date}");
    assert!((1..=31).contains(&d[2].parse::<u32>().unwrap()), "{date}");
    let t: Vec<u32> = time.split(':').map(|x| x.parse().unwrap()).collect();
    assert!(t[0] < 24 && t[1] < 60, "{time}");
}

/// The record is ready to hand in: the student's name (escaped), the date
/// and time, the seed and the link that opens the same run again; the link
/// read back through the links' parsers gives the investigation and the very
/// settings the run started from.
#[test]
fn the_record_names_the_student_the_date_the_seed_and_a_link_that_reruns_it() {
    let inv = find("why-school").unwrap();
    let mut lab = Lab::new(setup_settings(inv).unwrap());
    let mut settings = lab.settings().clone();
    settings.seed = 17;
    settings.speed = 8.0;
    lab.apply_settings(settings);
    let mut p = Progress::new(inv);
    p.choose(1).unwrap();
    p.commit().unwrap();
    p.start_run().unwrap();
    // As the window starts it (ui/investigation_panel.rs: start_run).
    let _m = Measurement::start(inv, &mut lab).unwrap();
    p.run_settings = Some(lab.settings().clone());
    p.finish_run(outcome());
    let mut info = info();
    info.student = "Ana <b>Pérez</b> & co".into();
    let html = record::html(std::slice::from_ref(&p), &info);
    assert!(
        html.contains("Ana &lt;b&gt;Pérez&lt;/b&gt; &amp; co, 2026-11-28 at 14:05"),
        "{html}"
    );
    assert!(!html.contains("<b>Pérez"), "the name escaped");
    assert!(html.contains("Seed: 17."), "{html}");
    let href = html
        .split("<a href=\"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .expect("a link in the record")
        .replace("&amp;", "&");
    assert!(href.starts_with("https://example.org/shoal/?investigation=why-school#v1."));
    // The link reruns: the same investigation on the same settings.
    assert_eq!(from_url(&href), Some(Ok(inv)));
    let fragment = href.split_once('#').unwrap().1;
    let reopened = crate::settings::share_link::decode(fragment)
        .unwrap()
        .expect("settings in the link");
    assert_eq!(&reopened, p.run_settings.as_ref().unwrap());
    assert_eq!(reopened.seed, 17);
    // A second run on another seed gives another link: the link carries it.
    let mut q = p.clone();
    let mut other = reopened.clone();
    other.seed = 18;
    q.run_settings = Some(other);
    assert_ne!(q.rerun_link(&info.page), p.rerun_link(&info.page));

    let csv = record::csv(std::slice::from_ref(&p), &info);
    assert!(
        csv.contains("# Ana <b>Pérez</b> & co, 2026-11-28 at 14:05"),
        "{csv}"
    );
    assert!(
        csv.contains(&format!("# why-school: seed 17; run it again: {href}")),
        "{csv}"
    );
    // No name: said so.
    let anonymous = record::html(std::slice::from_ref(&p), &super::tests::info());
    assert!(anonymous.contains("No name given, 2026-11-28 at 14:05"));
}

#[test]
fn an_experiment_records_its_replicate_seeds() {
    let p = progress("which-urge");
    assert_eq!(p.seeds(), vec![1, 2, 3]);
    let q = progress("how-swim");
    assert!(q.seeds().is_empty(), "no run yet");
}

#[test]
fn a_count_s_axis_is_marked_in_whole_numbers() {
    use super::outcome::whole_ticks;
    assert_eq!(whole_ticks(9.49, 5), vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
    assert_eq!(whole_ticks(3.0, 5), vec![0.0, 1.0, 2.0, 3.0]);
    assert_eq!(whole_ticks(0.2, 5), vec![0.0, 1.0]);
    assert_eq!(
        whole_ticks(47.0, 5),
        vec![0.0, 10.0, 20.0, 30.0, 40.0, 50.0]
    );
    for max in [0.5, 1.0, 2.7, 9.49, 12.6, 33.0, 101.0, 999.0] {
        let ticks = whole_ticks(max, 5);
        assert!(ticks.iter().all(|t| t.fract() == 0.0), "{max}: {ticks:?}");
        assert!(*ticks.last().unwrap() >= max, "{max}: {ticks:?}");
        assert!(ticks.len() <= 6, "{max}: {ticks:?}");
    }
    // The record's bars of fish caught: whole marks, not quarters of 9.49.
    let mut p = progress("why-school");
    p.choose(1).unwrap();
    p.commit().unwrap();
    let mut o = outcome();
    o.rows[0].value = 8.0;
    let svg = record::svg(&p, &o);
    let marks: Vec<&str> = svg
        .split("text-anchor=\"end\">")
        .skip(1)
        .map(|t| t.split('<').next().unwrap())
        .collect();
    assert_eq!(marks, ["0", "2", "4", "6", "8", "10"], "{svg}");
    // The same bars in metres keep their quarter marks (a length, not a count).
    o.chart = Chart::Bars {
        unit: "m",
        whole: false,
    };
    let svg = record::svg(&p, &o);
    assert!(svg.contains(">2.30<"), "{svg}");
}

/// Every explain prompt that names a plot ("the catches plot", "the
/// measured curve", "your sketch") is shown with it, and a prompt shows the
/// plot it names, not another one.
#[test]
fn an_explain_prompt_shows_the_plot_it_refers_to() {
    for inv in &INVESTIGATIONS {
        for prompt in inv.prompts {
            let words =
                crate::i18n::with_lang(crate::i18n::Lang::En, || prompt.text().to_lowercase());
            let names_plot = ["plot", "curve", "sketch", "bars", "copies"]
                .iter()
                .any(|w| words.contains(w));
            if names_plot {
                assert_ne!(prompt.shows, Shows::Words, "{}: {words}", inv.id);
            }
            if words.contains("catches plot") {
                assert_eq!(prompt.shows, Shows::Timelines, "{}: {words}", inv.id);
            }
        }
    }
    // The cause: the same result, the prompt on show decides.
    let mut p = progress("why-school");
    p.choose(1).unwrap();
    p.commit().unwrap();
    p.start_run().unwrap();
    assert_eq!(p.explain_shows(), Shows::Words, "not explaining yet");
    p.finish_run(outcome());
    p.advance().unwrap();
    assert_eq!(p.step, Step::Explain);
    assert_eq!(p.explain_shows(), Shows::Timelines, "the catches plot");
    p.advance().unwrap();
    assert_eq!(p.explain_shows(), Shows::Words);
    // No timelines measured: the result's chart instead of nothing.
    let mut q = progress("why-school");
    q.choose(1).unwrap();
    q.commit().unwrap();
    q.start_run().unwrap();
    let mut o = outcome();
    o.timelines.clear();
    q.finish_run(o);
    q.advance().unwrap();
    assert_eq!(q.explain_shows(), Shows::Result);
    let mut c = progress("which-urge");
    c.choose(0).unwrap();
    c.commit().unwrap();
    c.start_run().unwrap();
    c.finish_run(outcome());
    c.advance().unwrap();
    assert_eq!(
        c.explain_shows(),
        Shows::Result,
        "the curve with the sketch"
    );
}
