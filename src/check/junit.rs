//! JUnit XML for CI servers, written by hand: `<testsuites>` of `<testsuite>`s of `<testcase>`s,
//! each with an optional `<failure>` or `<skipped>` and `<system-out>`, in the shape of the Ant
//! JUnit schema (`testsuite` carries `name, tests, failures, errors, skipped, time, timestamp,
//! hostname`; `timestamp` is ISO 8601 without a zone, here UTC). Every attribute value and text
//! is XML-escaped; characters XML 1.0 forbids are replaced by U+FFFD.

use std::fmt::Write as _;

/// A failed test case's failure.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// One-line message (the `message` attribute).
    pub message: String,
    /// Failure kind (the `type` attribute).
    pub kind: String,
    /// Details (the element's text).
    pub details: String,
}

/// One test case.
#[derive(Debug, Clone, PartialEq)]
pub struct TestCase {
    /// `classname` attribute.
    pub classname: String,
    /// `name` attribute.
    pub name: String,
    /// The failure, if it failed.
    pub failure: Option<Failure>,
    /// Text for `<system-out>`, if any.
    pub output: Option<String>,
    /// Why the case was skipped (the `<skipped message>`), if it was.
    pub skipped: Option<String>,
    /// Wall time of what the case judges, in seconds (`time` attribute; none when 0).
    pub time: f64,
}

/// One test suite.
#[derive(Debug, Clone, PartialEq)]
pub struct TestSuite {
    /// `name` attribute.
    pub name: String,
    /// When the suite started, ISO 8601 UTC (`YYYY-MM-DDThh:mm:ss`, a trailing `Z` is dropped
    /// for the schema's zone-less pattern).
    pub timestamp: String,
    /// Wall time of the suite in seconds (`time` attribute).
    pub time: f64,
    /// `<properties>` (name, value).
    pub properties: Vec<(String, String)>,
    /// Its test cases.
    pub cases: Vec<TestCase>,
}

impl TestSuite {
    /// Failed test cases.
    pub fn failures(&self) -> usize {
        self.cases.iter().filter(|c| c.failure.is_some()).count()
    }

    /// Skipped test cases.
    pub fn skipped(&self) -> usize {
        self.cases.iter().filter(|c| c.skipped.is_some()).count()
    }
}

/// This machine's name (the `hostname` attribute), `localhost` when it cannot be read.
fn hostname() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .or_else(|| std::env::var("HOSTNAME").ok())
        .map(|h| h.trim().to_string())
        .filter(|h| !h.is_empty())
        .unwrap_or_else(|| "localhost".into())
}

/// Escape text for an XML attribute value: `& < > " '` become entities, tab, newline and
/// carriage return become character references (attribute-value normalisation would turn them
/// into spaces otherwise), and characters XML 1.0 does not allow become U+FFFD.
pub fn escape(text: &str) -> String {
    escape_with(text, true)
}

/// Escape element content: as [`escape`], but tabs and newlines stay literal.
pub fn escape_text(text: &str) -> String {
    escape_with(text, false)
}

fn escape_with(text: &str, attribute: bool) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' if !attribute => out.push(c),
            '\t' => out.push_str("&#9;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            c if allowed_in_xml(c) => out.push(c),
            _ => out.push('\u{FFFD}'),
        }
    }
    out
}

/// XML 1.0 `Char`: `#x9 | #xA | #xD | [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF]`.
fn allowed_in_xml(c: char) -> bool {
    matches!(c, '\t' | '\n' | '\r' | '\u{20}'..='\u{D7FF}' | '\u{E000}'..='\u{FFFD}' | '\u{10000}'..)
}

/// Render the suites as a JUnit XML document; `time` is the wall time of the whole run (the
/// suites may have run in parallel, so it is not the sum of theirs).
pub fn render(name: &str, suites: &[TestSuite], time: f64) -> String {
    let tests: usize = suites.iter().map(|s| s.cases.len()).sum();
    let failures: usize = suites.iter().map(TestSuite::failures).sum();
    let skipped: usize = suites.iter().map(TestSuite::skipped).sum();
    let host = escape(&hostname());
    let mut xml = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    // Writing to a String cannot fail.
    let _ = writeln!(
        xml,
        "<testsuites name=\"{}\" tests=\"{tests}\" failures=\"{failures}\" errors=\"0\" skipped=\"{skipped}\" time=\"{time:.3}\">",
        escape(name)
    );
    for suite in suites {
        let _ = writeln!(
            xml,
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"{}\" time=\"{:.3}\" timestamp=\"{}\" hostname=\"{host}\">",
            escape(&suite.name),
            suite.cases.len(),
            suite.failures(),
            suite.skipped(),
            suite.time,
            escape(suite.timestamp.trim_end_matches('Z')),
        );
        if !suite.properties.is_empty() {
            xml.push_str("    <properties>\n");
            for (name, value) in &suite.properties {
                let _ = writeln!(
                    xml,
                    "      <property name=\"{}\" value=\"{}\"/>",
                    escape(name),
                    escape(value)
                );
            }
            xml.push_str("    </properties>\n");
        }
        for case in &suite.cases {
            let _ = write!(
                xml,
                "    <testcase classname=\"{}\" name=\"{}\"",
                escape(&case.classname),
                escape(&case.name)
            );
            if case.time > 0.0 {
                // Microseconds: a run of a small case takes well under a millisecond, which
                // three decimals would show as 0.000.
                let _ = write!(xml, " time=\"{:.6}\"", case.time);
            }
            if case.failure.is_none() && case.output.is_none() && case.skipped.is_none() {
                xml.push_str("/>\n");
                continue;
            }
            xml.push_str(">\n");
            if let Some(f) = &case.failure {
                let _ = writeln!(
                    xml,
                    "      <failure message=\"{}\" type=\"{}\">{}</failure>",
                    escape(&f.message),
                    escape(&f.kind),
                    escape_text(&f.details)
                );
            }
            if let Some(why) = &case.skipped {
                let _ = writeln!(xml, "      <skipped message=\"{}\"/>", escape(why));
            }
            if let Some(out) = &case.output {
                let _ = writeln!(xml, "      <system-out>{}</system-out>", escape_text(out));
            }
            xml.push_str("    </testcase>\n");
        }
        xml.push_str("  </testsuite>\n");
    }
    xml.push_str("</testsuites>\n");
    xml
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup_quotes_whitespace_and_forbidden_characters() {
        assert_eq!(
            escape("a < b && c > \"d\" 'e'"),
            "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;"
        );
        assert_eq!(escape("x\ny\tz\u{1}§"), "x&#10;y&#9;z\u{FFFD}§");
        assert_eq!(escape_text("x\ny\r<"), "x\ny&#13;&lt;");
    }

    #[test]
    fn renders_counts_and_failures() {
        let suite = TestSuite {
            name: "s<1>".into(),
            timestamp: "2026-11-24T11:08:06Z".into(),
            time: 1.25,
            properties: vec![("source".into(), "a & b".into())],
            cases: vec![
                TestCase {
                    classname: "s".into(),
                    name: "ok".into(),
                    failure: None,
                    output: None,
                    skipped: None,
                    time: 0.0,
                },
                TestCase {
                    classname: "s".into(),
                    name: "not kept".into(),
                    failure: None,
                    output: None,
                    skipped: Some("a report does not keep it".into()),
                    time: 0.0,
                },
                TestCase {
                    classname: "s".into(),
                    name: "bad".into(),
                    failure: Some(Failure {
                        message: "1 > 0".into(),
                        kind: "expectation".into(),
                        details: "x".into(),
                    }),
                    output: None,
                    skipped: None,
                    time: 0.0,
                },
            ],
        };
        let xml = render("all", &[suite], 1.25);
        assert!(
            xml.contains("tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\" time=\"1.250\"")
        );
        assert!(xml.contains("timestamp=\"2026-11-24T11:08:06\" hostname=\""));
        assert!(xml.contains("<skipped message=\"a report does not keep it\"/>"));
        assert!(xml.contains("<testsuite name=\"s&lt;1&gt;\""));
        assert!(xml.contains("<property name=\"source\" value=\"a &amp; b\"/>"));
        assert!(xml.contains("<testcase classname=\"s\" name=\"ok\"/>"));
        assert!(xml.contains("<failure message=\"1 &gt; 0\" type=\"expectation\">x</failure>"));
    }
}
