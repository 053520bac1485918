//! One self-contained HTML document: a title, where the result came from, a table of contents and numbered
//! sections. No script, no external file: the styles are inline, the figures are inline SVG, so the file reads the
//! same offline and prints with each figure kept whole on its page (`break-inside: avoid`).

use super::blocks::escape;
use crate::provenance::utc_now;
use std::fmt::Write as _;

/// A section of the page: its anchor, heading and body (HTML).
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// The anchor the table of contents links to (unique in the page).
    pub id: String,
    /// The heading, as text.
    pub heading: String,
    /// The body, as HTML.
    pub body: String,
    /// Sub-sections, listed under it in the table of contents.
    pub children: Vec<Section>,
}

impl Section {
    /// A section without sub-sections.
    pub fn new(id: impl Into<String>, heading: impl Into<String>, body: String) -> Self {
        Self { id: id.into(), heading: heading.into(), body, children: Vec::new() }
    }
}

/// The page: title, a lead paragraph (HTML), the facts of where it came from, and the sections.
#[derive(Debug, Clone, PartialEq)]
pub struct Page {
    /// The document's title.
    pub title: String,
    /// The paragraph under the title (HTML), or empty.
    pub lead: String,
    /// (what, value) rows: the command, version, commit, date, folder.
    pub facts: Vec<(String, String)>,
    /// The sections, in order.
    pub sections: Vec<Section>,
}

/// Screen and print styles: one column of readable width, tables with their units, figures scaled to the column;
/// in print no figure or table row is split across pages and each study starts a page.
const STYLE: &str = r#"
:root { color-scheme: light; }
body { font-family: "DejaVu Sans", "Segoe UI", Helvetica, Arial, sans-serif; color: #1d1d1d; margin: 0 auto;
       max-width: 62rem; padding: 1.5rem 2rem 4rem; line-height: 1.45; }
h1 { font-size: 1.7rem; margin-bottom: .3rem; }
h2 { font-size: 1.35rem; border-bottom: 1px solid #ccc; padding-bottom: .2rem; margin-top: 2.4rem; }
h3 { font-size: 1.1rem; margin-top: 1.8rem; }
.lead { color: #3c3c3c; margin-top: 0; }
div.table { overflow-x: auto; }
table { border-collapse: collapse; margin: .6rem 0 1rem; font-size: .9rem; }
th, td { border: 1px solid #d0d0d0; padding: .25rem .55rem; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.facts th { width: 9rem; }
code, pre { font-family: "DejaVu Sans Mono", Menlo, Consolas, monospace; font-size: .85rem; }
pre { background: #f7f7f7; border: 1px solid #e0e0e0; padding: .7rem; overflow-x: auto; white-space: pre-wrap; }
figure { margin: 1.2rem 0; }
figure svg { width: 100%; height: auto; border: 1px solid #e4e4e4; }
figcaption { font-size: .9rem; color: #3c3c3c; margin-top: .3rem; }
.warnings { background: #fff6e0; border-left: 4px solid #e0a100; padding: .5rem 1rem; }
.none { color: #5a5a5a; }
nav.toc { background: #fafafa; border: 1px solid #e0e0e0; padding: .5rem 1.2rem; }
nav.toc ol { margin: .3rem 0; padding-left: 1.4rem; }
@media print {
  body { max-width: none; padding: 0; font-size: 10pt; }
  nav.toc { page-break-after: always; break-after: page; }
  section.study { break-before: page; }
  figure, pre, .warnings { break-inside: avoid; page-break-inside: avoid; }
  div.table { overflow: visible; }
  table { font-size: 7.5pt; }
  tr { break-inside: avoid; }
  h2, h3, h4 { break-after: avoid; page-break-after: avoid; }
  a { color: inherit; text-decoration: none; }
}
"#;

impl Page {
    /// The whole document.
    pub fn html(&self) -> String {
        let mut out = String::with_capacity(self.sections.iter().map(|s| s.body.len() + 256).sum::<usize>() + 8192);
        let _ = write!(
            out,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
             <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
             <meta name=\"generator\" content=\"frictrack {}\">\n<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n",
            env!("CARGO_PKG_VERSION"),
            escape(&self.title)
        );
        let _ = writeln!(out, "<header>\n<h1>{}</h1>", escape(&self.title));
        if !self.lead.is_empty() {
            let _ = writeln!(out, "<p class=\"lead\">{}</p>", self.lead);
        }
        let _ = writeln!(out, "<table class=\"facts\">");
        for (what, value) in &self.facts {
            let _ = writeln!(out, "<tr><th>{}</th><td>{value}</td></tr>", escape(what));
        }
        let _ = writeln!(out, "</table>\n</header>");
        out.push_str(&self.contents());
        for (i, section) in self.sections.iter().enumerate() {
            write_section(&mut out, section, &format!("{}", i + 1), 2);
        }
        let written = utc_now();
        let _ = writeln!(
            out,
            "<footer><p class=\"none\">Report written {written} by frictrack {}.</p></footer>\n</body>\n</html>",
            env!("CARGO_PKG_VERSION")
        );
        out
    }

    /// The table of contents: every section and sub-section, numbered, linked to its anchor.
    fn contents(&self) -> String {
        let mut out = String::from("<nav class=\"toc\" aria-label=\"Contents\">\n<strong>Contents</strong>\n<ol>\n");
        for section in &self.sections {
            let _ = write!(out, "<li><a href=\"#{}\">{}</a>", section.id, escape(&section.heading));
            if !section.children.is_empty() {
                out.push_str("\n<ol>\n");
                for child in &section.children {
                    let _ = writeln!(out, "<li><a href=\"#{}\">{}</a></li>", child.id, escape(&child.heading));
                }
                out.push_str("</ol>\n");
            }
            out.push_str("</li>\n");
        }
        out.push_str("</ol>\n</nav>\n");
        out
    }
}

/// One section (at heading `level`, numbered `number`) with its sub-sections.
fn write_section(out: &mut String, section: &Section, number: &str, level: usize) {
    let class = if level == 2 && !section.children.is_empty() { " class=\"study\"" } else { "" };
    let _ = writeln!(
        out,
        "<section id=\"{}\"{class}>\n<h{level}>{number}. {}</h{level}>\n{}",
        section.id,
        escape(&section.heading),
        section.body
    );
    for (i, child) in section.children.iter().enumerate() {
        write_section(out, child, &format!("{number}.{}", i + 1), level + 1);
    }
    out.push_str("</section>\n");
}
