//! The web pages of scenes (docs/html.md): every embedded scene's player,
//! detection and time-of-collision page reach no network; the study page
//! neither, with its chart's hover details and its tables' sort keys; a
//! 600-step player under 3 MB; `--every` thins the frames and the page says
//! so; each frame's label is that frame's numbers; the predict tolerance is
//! the app's, carried as data (page.js does not restate it).

use crate::html_pages::network_urls;
use contact_lab::commands::simulate_html::{record, render, scene_page};
use contact_lab::format::Fmt;
use contact_lab::lesson::Lesson;
use contact_lab::physics::step::Simulation;
use contact_lab::render::html;
use contact_lab::trace::Plane;

/// Every embedded scene (lessons/scenes/), loaded.
fn scenes() -> Vec<Lesson> {
    contact_lab::lesson::embedded::scene_ids()
        .into_iter()
        .map(|id| Lesson::load(id).expect("embedded scene is valid"))
        .filter(|l| l.simulation.is_some())
        .collect()
}

fn sim_of(lesson: &Lesson) -> Simulation<f64> {
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let scene = lesson.simulation.clone().unwrap();
    Simulation::new(world, lesson.sim_params().unwrap(), scene.materials)
}

/// The page's frame data (`<script type="application/json" id="frames">`).
fn frames_data(page: &str) -> serde_json::Value {
    let open = "<script type=\"application/json\" id=\"frames\">";
    let start = page.find(open).expect("the frames' data") + open.len();
    let end = start + page[start..].find("</script>").unwrap();
    serde_json::from_str(&page[start..end].replace("<\\/", "</")).unwrap()
}

#[test]
fn no_player_page_reaches_the_network_and_each_has_its_controls() {
    let all = scenes();
    assert!(all.len() > 10, "{} scenes", all.len());
    for lesson in &all {
        let page = scene_page(lesson, Some(12), 1, Some(3)).unwrap();
        assert!(
            network_urls(&page).is_empty(),
            "{}: {:?}",
            lesson.id,
            network_urls(&page)
        );
        for label in ["play", "pause", "step", "step back", "frame", "speed"] {
            assert!(
                page.contains(&format!("aria-label=\"{label}\"")),
                "{}: no control named {label}",
                lesson.id
            );
        }
        let data = frames_data(&page);
        assert_eq!(
            data["frames"].as_array().unwrap().len(),
            13,
            "{}",
            lesson.id
        );
        assert_eq!(data["traced"], 3, "{}", lesson.id);
        assert!(
            page.contains("id=\"trace\""),
            "{}: step 3's iterations",
            lesson.id
        );
        assert!(page.contains("class=\"film nojs-only\""), "{}", lesson.id);
        assert!(!page.contains("<?xml"), "{}", lesson.id);
    }
}

#[test]
fn a_600_step_player_is_under_3_mb() {
    let lesson = Lesson::load("stack-5").unwrap();
    assert_eq!(lesson.simulation.as_ref().unwrap().steps, 600);
    let page = scene_page(&lesson, None, 1, None).unwrap();
    assert_eq!(frames_data(&page)["frames"].as_array().unwrap().len(), 601);
    assert!(page.len() < 3_000_000, "{} bytes", page.len());
    assert!(page.len() > 300_000, "{} bytes", page.len());
}

#[test]
fn every_thins_the_frames_and_the_page_says_so() {
    let lesson = Lesson::load("stack-5").unwrap();
    let page = scene_page(&lesson, Some(60), 10, None).unwrap();
    let data = frames_data(&page);
    let steps: Vec<u64> = (data["frames"].as_array().unwrap().iter())
        .map(|f| f["step"].as_u64().unwrap())
        .collect();
    assert_eq!(steps, [0, 10, 20, 30, 40, 50, 60]);
    assert!(
        page.contains("<code>--every 10</code>"),
        "the page states the thinning"
    );
    assert!(page.contains("holds 7 frames"));
    // The traced step is kept though --every skips it.
    let page = scene_page(&lesson, Some(60), 10, Some(15)).unwrap();
    let data = frames_data(&page);
    let steps: Vec<u64> = (data["frames"].as_array().unwrap().iter())
        .map(|f| f["step"].as_u64().unwrap())
        .collect();
    assert_eq!(steps, [0, 10, 15, 20, 30, 40, 50, 60]);
}

#[test]
fn each_frame_label_is_that_frames_numbers() {
    let lesson = Lesson::load("ball-drop").unwrap();
    let fmt = Fmt::new(6);
    let rec = record(&lesson, sim_of(&lesson), (90, 3), None, &fmt, &mut |_| {});
    let page = render(&rec, (90, 3), Plane::Xy, &fmt);
    let data = frames_data(&page);
    let frames = data["frames"].as_array().unwrap();
    assert_eq!(frames.len(), rec.run.frames.len());
    let mut moved = false;
    for (k, (shown, f)) in frames.iter().zip(&rec.run.frames).enumerate() {
        assert_eq!(shown["step"].as_u64().unwrap(), f.step);
        // JSON's reading of a float may differ in its last bit.
        let t = shown["t"].as_f64().unwrap();
        assert!(
            (t - f.time).abs() <= 1e-12 * f.time.abs().max(1.0),
            "{t} {}",
            f.time
        );
        let want = format!(
            "frame {} of {} · step {} · t = {} s · E = {} J",
            k + 1,
            frames.len(),
            f.step,
            fmt.num(f.time),
            fmt.num(f.kinetic_energy + f.potential_energy)
        );
        assert_eq!(shown["label"].as_str().unwrap(), want);
        moved |= k > 0 && shown["svg"] != frames[k - 1]["svg"];
    }
    assert!(moved, "the ball's picture changes from frame to frame");
}

#[test]
fn no_detection_or_time_of_collision_page_reaches_the_network() {
    let mut toi_pages = 0;
    for lesson in scenes() {
        let sim = sim_of(&lesson);
        let trace = contact_lab::session::detect_trace(&sim, &lesson, 0, Plane::Xy, None);
        let page = html::detect::document(&trace, &Fmt::new(6));
        assert!(network_urls(&page).is_empty(), "{}: detect", lesson.id);
        let method = contact_lab::physics::detect::ToiMethod::Bisection;
        let Ok(toi) = contact_lab::session::toi_trace(&sim, &lesson, 1, method, None) else {
            continue;
        };
        let pictures: Vec<Option<String>> = (0..toi.pairs.len())
            .map(|k| {
                contact_lab::session::toi_picture(&sim, &lesson, &toi, k)
                    .map(|p| contact_lab::render::toi_svg::svg(&p, Plane::Xy))
            })
            .collect();
        let page = html::toi::document(&toi, &pictures, &Fmt::new(6));
        assert!(
            network_urls(&page).is_empty(),
            "{}: toi {:?}",
            lesson.id,
            network_urls(&page)
        );
        let tests: usize = (toi.pairs.iter().take(html::detect::PAIRS))
            .map(|p| p.record.tests().len().min(html::toi::TESTS) + 1)
            .sum();
        assert_eq!(
            page.matches("data-step ").count(),
            1 + tests,
            "{}",
            lesson.id
        );
        toi_pages += usize::from(!toi.pairs.is_empty());
    }
    assert!(toi_pages > 3, "{toi_pages} scenes with a pair to search");
}

#[test]
fn the_study_page_has_hover_details_and_sort_keys_and_no_network() {
    use contact_lab::study::sweep;
    let o = sweep::Options {
        timed: false,
        repeats: 1,
        quick: true,
        grid: Vec::new(),
    };
    let spec = sweep::SceneSpec {
        lesson: Lesson::load("ball-drop").unwrap(),
        seconds: 0.25,
        reference_solver: contact_lab::physics::Solver::SequentialImpulse,
    };
    let study = sweep::study(&[spec], &o, &mut |_, _| {});
    let page = html::study::document(&study, &Fmt::new(3));
    assert!(network_urls(&page).is_empty(), "{:?}", network_urls(&page));
    let rows = &study.scenes[0].rows;
    let drawn = rows.iter().filter(|r| r.failure.is_none()).count();
    assert!(
        page.matches("<g class=\"tip\"><title>").count() >= drawn.min(1),
        "hover details on the chart's marks"
    );
    for r in rows {
        let keys = html::study::sort_keys(r, study.timed);
        assert_eq!(
            keys.len(),
            contact_lab::render::study::headers(study.timed).len()
        );
        // A key is the number its cell shows.
        assert_eq!(keys[2], Some(r.work_per_second));
        assert_eq!(keys[3], Some(r.error_vs_reference));
    }
    assert_eq!(page.matches("<table class=\"sortable\">").count(), 1);
    assert_eq!(
        page.matches(" data-sort=").count(),
        rows.len() * (contact_lab::render::study::headers(study.timed).len() - 2)
    );
}

#[test]
fn the_predict_tolerance_is_the_apps_carried_as_data() {
    use contact_lab::exercise::answer::MIN_DECIMALS;
    use contact_lab::lesson::printed::{LAST_DIGIT_UNITS, RELATIVE};
    let lesson = Lesson::load("lecture-2").unwrap();
    let page = html::solve::document(
        &[contact_lab::worked_solution(&lesson, 0)],
        &Fmt::new(6),
        None,
    );
    let open = "<body data-tolerance=\"";
    let start = page.find(open).unwrap() + open.len();
    let end = start + page[start..].find('"').unwrap();
    let rule: serde_json::Value =
        serde_json::from_str(&page[start..end].replace("&quot;", "\"")).unwrap();
    assert_eq!(rule["last_digit_units"].as_f64(), Some(LAST_DIGIT_UNITS));
    assert_eq!(rule["min_decimals"].as_u64(), Some(u64::from(MIN_DECIMALS)));
    assert_eq!(rule["relative"].as_f64(), Some(RELATIVE));
    let script = include_str!("../../src/render/html/page.js");
    for restated in ["1e-3", "0.001", "decimals, 4)", "2 * Math.pow"] {
        assert!(
            !script.contains(restated),
            "page.js restates the tolerance: {restated}"
        );
    }
}
