//! Source of truth: the report contract of docs/guide/report.md: every scene's tables
//! and verdicts and the convergence studies in `index.md`, every table also as CSV, every figure
//! as SVG, a self-contained `index.html`, timings only in `timing.md`/`timing.csv`, written whole
//! or not at all; the closed-form contact critical Courant numbers of `courant-references`.
//!
//! Proves: on a reduced set (two scenes, one study) the report has the expected files with CSV
//! headers (each scene's CSV tables are the ones a report baseline compares), `index.html` and
//! every generated SVG are well-formed XML (checker in
//! `tests/common/xml.rs`, itself shown to reject malformed markup), the stability section carries
//! the closed-form contact table for beta_s = 1e6 … 1e12, its deterministic files are identical
//! from one generation to the next (timings apart), no figure has text below 12 px, an
//! expectation failure is flagged, every table with a verdict or status leads with it (HTML and
//! Markdown), every section opens with at most 100 words, a report of given scenes says what it
//! is, and
//! `courant report` replaces the output directory whole.

use courant::pipeline::report_runs::run_for_report;
use courant::report::render;
use courant::scene::builtin::builtin_scene;
use courant::scene::studies::convergence::CONVERGENCE_STUDIES;

use crate::xml;

fn reduced() -> courant::report::Report {
    let scenes = vec![
        builtin_scene("fig1").unwrap().unwrap(),
        builtin_scene("fig6").unwrap().unwrap(),
    ];
    let studies: Vec<_> = CONVERGENCE_STUDIES
        .iter()
        .filter(|s| s.name == "fig1_co1")
        .cloned()
        .collect();
    render(&scenes, &run_for_report(&scenes, &studies, false).unwrap()).unwrap()
}

#[test]
fn report_has_sections_tables_and_deterministic_content() {
    let (a, b) = (reduced(), reduced());
    assert!(a.passed);
    let names: Vec<&str> = a.files.iter().map(|f| f.0.as_str()).collect();
    for expected in [
        "index.md",
        "timing.md",
        "timing.csv",
        "fig1/summary.csv",
        "fig1/norms.csv",
        "fig6/summary.csv",
        "convergence/fig1_co1.csv",
        "work_precision/fig5_contact.csv",
        "timing.work_precision.csv",
    ] {
        assert!(
            names.contains(&expected),
            "{expected} missing from {names:?}"
        );
    }
    // Every scene table is one `courant check --baseline <report>` compares (REPORT_TABLES).
    for scene in ["fig1", "fig6"] {
        assert!(names.contains(&format!("{scene}/expectations.csv").as_str()));
        for name in &names {
            if let Some(file) = name.strip_prefix(&format!("{scene}/")) {
                assert!(
                    file.ends_with(".svg")
                        || courant::compare::files::REPORT_TABLES.contains(&file),
                    "{name} is a scene table a report baseline would not compare"
                );
            }
        }
    }
    let index = &a.files.iter().find(|f| f.0 == "index.md").unwrap().1;
    assert!(
        index.contains("## fig1")
            && index.contains("## fig6")
            && index.contains("## Convergence studies")
    );
    // One expectations table per scene (no second list of the same verdicts), and the headline
    // counts exactly the verdict cells of the page: the scenes' expectations tables and the
    // convergence order tables (rows with a band) and the checks of other codes' committed results.
    assert!(index.contains("[`fig1/expectations.csv`]"));
    assert!(!index.contains("Expectations:"), "no second list");
    let cells: usize = a
        .files
        .iter()
        .filter(|(name, _)| {
            name.ends_with("/expectations.csv")
                || name.ends_with(".orders.csv")
                || name.ends_with(".checks.csv")
        })
        .map(|(_, csv)| {
            csv.lines()
                .skip(1)
                .filter(|l| {
                    ["pass", "FAIL", "finding"]
                        .iter()
                        .any(|w| l.contains(&format!(",{w},")) || l.ends_with(&format!(",{w}")))
                })
                .count()
        })
        .sum();
    assert_eq!(a.tally.total(), cells, "headline against the verdict cells");
    assert!(
        index.contains(&format!(
            "{} verdicts: {} pass",
            a.tally.total(),
            a.tally.passed
        )),
        "headline"
    );
    assert!(!index.contains("wall_time"), "timings stay out of index.md");
    let cpu = &a
        .files
        .iter()
        .find(|f| f.0 == "timing.work_precision.csv")
        .unwrap()
        .1;
    assert!(cpu.starts_with("study,method,Co,N,steps,l1,wall_time_s,time_over_floor\n"));
    // The force-evaluation floor (docs/guide/report.md): measured in this run, so every timed
    // run states its time over it, a positive number.
    for line in cpu.lines().skip(1) {
        let ratio: f64 = line.rsplit(',').next().unwrap().parse().unwrap();
        assert!(
            ratio > 0.0 && ratio.is_finite(),
            "time_over_floor of {line}"
        );
    }
    let timing = &a.files.iter().find(|f| f.0 == "timing.md").unwrap().1;
    assert!(
        timing.contains("## Time over the force-evaluation floor") && timing.contains("t_f = ")
    );
    assert!(
        index.contains("force-evaluation floor"),
        "index.md defines the floor"
    );
    assert!(
        cpu.contains("fig5_contact,lagrange-multiplier,")
            && cpu.contains("fig5_contact,cd-penalty-bs2500,"),
        "contact schemes timed"
    );
    let html = &a.files.iter().find(|f| f.0 == "index.html").unwrap().1;
    assert!(html.starts_with("<!DOCTYPE html>") && html.trim_end().ends_with("</html>"));
    let page = xml::parse_xhtml(html).unwrap_or_else(|e| panic!("index.html: {e}"));
    assert_eq!(page.name, "html");
    let head_body: Vec<&str> = page.children.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(head_body, ["head", "body"]);
    let svgs: Vec<&(String, String)> = a.files.iter().filter(|f| f.0.ends_with(".svg")).collect();
    let inline = svgs.iter().filter(|f| !f.0.starts_with("timing")).count();
    assert!(inline >= 4, "figures of fig1, fig6, the study: {svgs:?}");
    assert_eq!(
        page.count("figure"),
        inline,
        "every figure but the timing plots is inline in index.html"
    );
    let body = &page.children[1];
    for figure in body
        .descendants()
        .into_iter()
        .filter(|e| e.name == "figure")
    {
        let names: Vec<&str> = figure.children.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["svg", "figcaption"]);
    }
    for (name, svg) in &svgs {
        let root = xml::parse_xml(svg).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(root.name, "svg", "{name}");
        assert_eq!(
            root.attr("xmlns"),
            Some("http://www.w3.org/2000/svg"),
            "{name}"
        );
        assert!(root.children.len() > 1, "{name}: an empty drawing");
    }
    for tag in ["table", "tr", "ul", "p", "h2", "figure", "svg"] {
        let (open, close) = (
            html.matches(&format!("<{tag}>")).count() + html.matches(&format!("<{tag} ")).count(),
            html.matches(&format!("</{tag}>")).count(),
        );
        assert_eq!(
            open, close,
            "<{tag}> opened {open} times, closed {close} times"
        );
    }
    assert!(
        !html.contains("src=\"http") && !html.contains("href=\"http"),
        "no network resources are loaded"
    );
    assert!(!html.contains("<script"), "no scripts");
    // A verdict is read first: every table with a verdict or status column leads with it, in
    // both renderings.
    let status = ["verdict", "status", "agrees"];
    let mut led = 0;
    for head in html.split("<tr><th>").skip(1) {
        let columns: Vec<&str> = head[..head.find("</tr>").unwrap()]
            .trim_end_matches("</th>")
            .split("</th><th>")
            .collect();
        if columns.iter().any(|c| status.contains(c)) {
            assert!(
                status.contains(&columns[0]),
                "html table leads with {columns:?}"
            );
            led += 1;
        }
    }
    let lines: Vec<&str> = index.lines().collect();
    for pair in lines.windows(2) {
        if pair[1].starts_with("|---") {
            let columns: Vec<&str> = pair[0]
                .trim_matches('|')
                .split(" | ")
                .map(str::trim)
                .collect();
            if columns.iter().any(|c| status.contains(c)) {
                assert!(
                    status.contains(&columns[0]),
                    "markdown table leads with {columns:?}"
                );
            }
        }
    }
    assert!(led >= 3, "summary, expectations and order tables: {led}");
    // Every section opens with a short paragraph; its details follow its tables.
    let blocks: Vec<&str> = index.split("\n\n").collect();
    for pair in blocks.windows(2) {
        if pair[0].starts_with("## ") && !pair[1].starts_with(['!', '[', '|', '-', '#']) {
            let words = pair[1].split_whitespace().count();
            assert!(words <= 100, "{} opens with {words} words", pair[0]);
        }
    }
    // A report of the built-in set says so.
    assert!(index.contains("Every built-in scene of courant"));
    let closed_forms = &a
        .files
        .iter()
        .find(|f| f.0 == "stability/contact_closed_forms.csv")
        .expect("closed-form contact table in the stability section")
        .1;
    let mut reader = csv::Reader::from_reader(closed_forms.as_bytes());
    assert_eq!(
        reader.headers().unwrap(),
        vec![
            "beta_s",
            "r",
            "cr_closed_form",
            "cr_limit",
            "scaled_difference",
            "scaled_first_order"
        ]
    );
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    let keys: Vec<(f64, String)> = rows
        .iter()
        .map(|r| {
            (
                r[0].parse().unwrap(),
                r[1].parse::<f64>().map_or("-".into(), |r| r.to_string()),
            )
        })
        .collect();
    let mut expected = Vec::new();
    for r in ["-", "0.25", "1", "4"] {
        for beta_s in [1e6, 1e8, 1e10, 1e12] {
            expected.push((beta_s, r.to_string()));
        }
    }
    assert_eq!(keys, expected);
    for row in &rows {
        let number = |i: usize| -> f64 { row[i].parse().unwrap() };
        let (beta_s, cr, limit) = (number(0), number(2), number(3));
        let (scaled, scaled_first_order) = (number(4), number(5));
        assert!(
            (cr / limit - 1.0).abs() < 1e-9 + 4.0 / beta_s && scaled.abs() < 4.0,
            "{row:?}: Cr far from its large-beta_s limit"
        );
        assert!(
            (scaled - scaled_first_order).abs() <= 1e-3 * scaled_first_order.abs(),
            "{row:?}: beta_s (Cr/limit - 1) is its first-order term to 3 digits"
        );
    }
    assert!(
        index.contains("stability/contact_closed_forms.csv")
            && index.contains("closed forms themselves up to beta_s = 1e12"),
        "the stability text points to the table"
    );
    for (name, text) in &a.files {
        if name.ends_with(".csv") {
            let mut reader = csv::Reader::from_reader(text.as_bytes());
            let width = reader.headers().unwrap().len();
            assert!(width >= 2, "{name}");
            assert!(
                reader.records().all(|r| r.unwrap().len() == width),
                "{name}: ragged rows"
            );
        }
        if name.ends_with(".svg") {
            // Legible at the 640 px the report shows a chart at: no text below 12 px (ticks,
            // legends, axis descriptions and titles).
            for size in text.split("font-size=\"").skip(1) {
                let px: f64 = size[..size.find('"').unwrap()].parse().unwrap();
                assert!(px >= 12.0, "{name}: text at {px} px");
            }
        }
        if !name.starts_with("timing") {
            let other = &b.files.iter().find(|f| &f.0 == name).unwrap().1;
            assert_eq!(text, other, "{name} differs between two generations");
        }
    }
}

/// Source of truth: the report contract "a report of user scenes says what it is". Proves: a
/// report of one scene given by name, without the studies, names its scene and how to regenerate
/// it, and does not claim to be the built-in report.
#[test]
fn a_report_of_given_scenes_says_what_it_is() {
    let scenes = vec![builtin_scene("fig6").unwrap().unwrap()];
    let report = render(&scenes, &run_for_report(&scenes, &[], true).unwrap()).unwrap();
    let index = &report.files.iter().find(|f| f.0 == "index.md").unwrap().1;
    assert!(
        index.contains("A report of 1 scene(s) given to `courant report`: fig6."),
        "{index}"
    );
    assert!(!index.contains("Every built-in scene"));
    assert!(!index.contains("cargo run --release -- report"));
}

#[test]
fn xml_checker_rejects_malformed_markup() {
    for bad in [
        "<a><b></a></b>",
        "<a x=\"1 < 2\"/>",
        "<a x=1/>",
        "<a x=\"1\"y=\"2\"/>",
        "<a x=\"1\" x=\"2\"/>",
        "<a>&nope;</a>",
        "<a>&#0;</a>",
        "<a>AT&T</a>",
        "<a>1 < 2</a>",
        "<a>",
        "<a></a><b/>",
        "<a><!-- a -- b --></a>",
        "<meta charset=\"utf-8\">",
    ] {
        assert!(xml::parse_xml(bad).is_err(), "accepted {bad:?}");
    }
    assert!(xml::parse_xhtml("<p>line<br>break</p>").is_ok());
    assert!(xml::parse_xhtml("<p><meta></meta></p>").is_err());
    let ok = xml::parse_xml(
        "<?xml version=\"1.0\"?>\n<!-- c --><a x='&lt;&#10;'>t &amp; u<b/><![CDATA[<&]]></a>",
    )
    .unwrap();
    assert_eq!((ok.attr("x"), ok.text.as_str()), (Some("<\n"), "t & u<&"));
    assert_eq!(ok.count("b"), 1);
}

#[test]
fn courant_report_replaces_the_output_directory_whole() {
    let dir = std::env::temp_dir().join(format!("courant-report-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("old")).unwrap();
    std::fs::write(dir.join("old/stale.txt"), "stale").unwrap();
    // A previous courant output (its manifest lists the stale file): replaced whole.
    std::fs::write(
        dir.join("old").join(courant::io::manifest::MANIFEST),
        courant::io::manifest::manifest_text(["stale.txt"]),
    )
    .unwrap();
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(["report", "--out", dir.join("old").to_str().unwrap()])
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(0));
    assert!(dir.join("old/index.md").exists());
    assert!(
        !dir.join("old/stale.txt").exists(),
        "the previous report is replaced whole"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
