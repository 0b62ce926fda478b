//! The review page: a small HTML shell around the browser bundle built from `web/` (three.js for the
//! 3D view, uPlot for the plots, our `web/src/` app; `npm run build` there writes `web/dist/`, which is
//! committed so that building ergocell needs no Node.js). The bundle is embedded in the binary, so the
//! server reads no file but the recording and a report works offline, mailed as one file.
//!
//! The app reads `window.ERGOCELL_REVIEW_DATA` when present (the report), else fetches
//! `api/review.json` (the server).

use crate::ReviewData;

/// The app bundle (`web/dist/review.js`).
pub const REVIEW_JS: &str = include_str!("../../web/dist/review.js");
/// Its stylesheet (`web/dist/review.css`).
pub const REVIEW_CSS: &str = include_str!("../../web/dist/review.css");
/// The licences of the vendored libraries in the bundle.
pub const THIRD_PARTY_LICENSES: &str = include_str!("../../web/dist/THIRD_PARTY_LICENSES.txt");

/// Escapes text for HTML element content and attribute values.
pub fn escape_html(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// JSON safe inside a `<script>` element: `<`, `>`, `&` and the JS line separators escaped
/// (`</script>` or `<!--` in a label cannot end the element).
pub fn script_json(data: &ReviewData) -> Result<String, serde_json::Error> {
    let json = serde_json::to_string(data)?;
    Ok(json
        .replace('<', "\\u003c")
        .replace('>', "\\u003e")
        .replace('&', "\\u0026")
        .replace('\u{2028}', "\\u2028")
        .replace('\u{2029}', "\\u2029"))
}

/// A bundle's text made safe to inline in a `<script>` element.
fn inline_script(js: &str) -> String {
    js.replace("</script", "<\\/script")
}

fn title(data: &ReviewData) -> String {
    let labels: Vec<&str> = data.sessions.iter().map(|s| s.label.as_str()).collect();
    format!("ergocell review — {}", labels.join(" vs "))
}

/// The page `ergocell review` serves: links `assets/review.css`, `assets/review.js`; the app fetches
/// `api/review.json`.
pub fn served_page(data: &ReviewData) -> String {
    format!(
        "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\">\
<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\
<title>{}</title><link rel=\"stylesheet\" href=\"assets/review.css\"></head>\
<body><div id=\"app\"></div><script src=\"assets/review.js\"></script></body></html>\n",
        escape_html(&title(data))
    )
}

/// The report's Content-Security-Policy: its own inline script and style, nothing fetched from
/// anywhere (a mailed report cannot phone home, whatever a recording holds).
pub const REPORT_CSP: &str = "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:; base-uri 'none'; form-action 'none'";

/// The self-contained report: the data, the stylesheet and the bundle inlined, nothing fetched.
pub fn report_page(data: &ReviewData) -> Result<String, serde_json::Error> {
    let json = script_json(data)?;
    Ok(format!(
        "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\">\
<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\
<meta http-equiv=\"Content-Security-Policy\" content=\"{REPORT_CSP}\">\
<title>{}</title><style>{}</style></head>\
<body><div id=\"app\"></div><script>window.ERGOCELL_REVIEW_DATA = {json};</script>\
<script>{}</script>\n<!-- Third-party licences of the embedded libraries:\n{}\n-->\n</body></html>\n",
        escape_html(&title(data)),
        REVIEW_CSS.replace("</style", "<\\/style"),
        inline_script(REVIEW_JS),
        THIRD_PARTY_LICENSES.replace("--", "- -"),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::{Facts, Frames, Robot, SessionReview, Source};

    fn session(label: &str) -> SessionReview {
        SessionReview {
            label: label.to_owned(),
            source: Source {
                file: label.to_owned(),
                bytes: 0,
                messages: 0,
                complete: true,
                problems: vec![],
            },
            facts: Facts {
                height_m: None,
                height_uncertainty_m: None,
                height_class: None,
                decision_basis: None,
                class_probability: None,
                expected_rula_cost: None,
                trajectory_sha256: None,
                approved_by: vec![],
                states: vec![],
                parts_taken: vec![],
            },
            landmarks: vec![],
            bones: vec![],
            up: [0.0, 0.0, 1.0],
            frames: Frames::default(),
            robot: Robot::default(),
            warnings: vec![],
            regions: vec![],
            angles: vec![],
            summary: ergocell_ergonomics::summary::SummaryBuilder::new(1).finish(),
            findings: crate::findings::Findings {
                action_level_secs: [0.0; 4],
                unscored_secs: 0.0,
                worst_moments: vec![],
                regions: vec![],
                dwell_s: 2.0,
            },
            overview: None,
        }
    }

    #[test]
    fn a_hostile_label_cannot_break_out_of_the_title_or_the_data_script() {
        let data = ReviewData::new(vec![session("</script><script>alert(1)</script><!--")]);
        let page = report_page(&data).unwrap();
        assert_eq!(page.matches("<script>").count(), 2, "only our two scripts");
        assert!(!page.contains("alert(1)</script>"));
        let served = served_page(&data);
        assert!(served.contains("&lt;/script&gt;"));
        // The escaped JSON still parses to the same label.
        let json = script_json(&data).unwrap();
        let v: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert_eq!(
            v["sessions"][0]["label"],
            "</script><script>alert(1)</script><!--"
        );
    }

    #[test]
    fn the_report_inlines_everything_and_links_nothing() {
        let page = report_page(&ReviewData::new(vec![session("a.mcap")])).unwrap();
        assert!(!page.contains("<script src"), "no external script");
        assert!(!page.contains("<link"), "no external stylesheet");
        assert!(page.contains("window.ERGOCELL_REVIEW_DATA = {"));
    }
}
