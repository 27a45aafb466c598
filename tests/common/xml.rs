//! A small XML well-formedness checker for the report's SVG and XHTML-like HTML (no XML crate is
//! a dependency). Include it with `#[path = "common/xml.rs"] mod xml;`.
//!
//! Checked: one root element (before and after it only whitespace, comments, processing
//! instructions and, before it, one `<!DOCTYPE ...>`); every start tag closed by a matching end
//! tag, properly nested (or self-closed `<.../>`); names start with a letter, `_` or `:`;
//! attribute values quoted with `"` or `'`, separated by whitespace, not duplicated, without a
//! raw `<`; no raw `<` in text; every `&` starts `&amp;` `&lt;` `&gt;` `&quot;` `&apos;` or a
//! numeric reference to a valid character; no `]]>` in text; comments without `--` inside.
//! [`parse_xhtml`] also accepts HTML void elements (`<meta ...>`, `<br>`, ...) without the
//! closing slash.
#![allow(dead_code)]

/// A parsed element: name, attributes (entities resolved), child elements and its own text.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    pub name: String,
    pub attrs: Vec<(String, String)>,
    pub children: Vec<Element>,
    pub text: String,
}

impl Element {
    /// The value of an attribute.
    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    /// The value of an attribute the element must have (panics naming both otherwise).
    pub fn value(&self, name: &str) -> &str {
        self.attr(name)
            .unwrap_or_else(|| panic!("<{}> has no attribute {name}", self.name))
    }

    /// The first child element named `name`.
    pub fn child(&self, name: &str) -> Option<&Element> {
        self.children.iter().find(|c| c.name == name)
    }

    /// This element and all elements below it, depth first.
    pub fn descendants(&self) -> Vec<&Element> {
        let mut out = vec![self];
        let mut i = 0;
        while i < out.len() {
            let children = &out[i].children;
            out.extend(children.iter());
            i += 1;
        }
        out
    }

    /// How many elements named `name` are at or below this one.
    pub fn count(&self, name: &str) -> usize {
        self.descendants().iter().filter(|e| e.name == name).count()
    }
}

/// HTML elements that have no content and may be written without `/>`.
const HTML_VOID: &[&str] = &[
    "area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track",
    "wbr",
];

/// Parse an XML document (e.g. an SVG file) and return its root element.
pub fn parse_xml(doc: &str) -> Result<Element, String> {
    Parser::new(doc, &[]).document()
}

/// Parse XHTML-like HTML (a `<!DOCTYPE html>`, void elements with or without `/>`) as XML.
pub fn parse_xhtml(doc: &str) -> Result<Element, String> {
    Parser::new(doc, HTML_VOID).document()
}

struct Parser<'a> {
    s: &'a str,
    i: usize,
    void: &'a [&'a str],
}

impl<'a> Parser<'a> {
    fn new(s: &'a str, void: &'a [&'a str]) -> Self {
        Self { s, i: 0, void }
    }

    fn rest(&self) -> &'a str {
        &self.s[self.i..]
    }

    fn error(&self, what: &str) -> String {
        let line = self.s[..self.i].matches('\n').count() + 1;
        let context: String = self.rest().chars().take(40).collect();
        format!(
            "{what} at byte {} (line {line}), before {context:?}",
            self.i
        )
    }

    fn skip_ws(&mut self) -> bool {
        let trimmed = self.rest().trim_start_matches([' ', '\t', '\n', '\r']);
        let skipped = self.rest().len() != trimmed.len();
        self.i = self.s.len() - trimmed.len();
        skipped
    }

    fn eat(&mut self, token: &str) -> bool {
        if self.rest().starts_with(token) {
            self.i += token.len();
            true
        } else {
            false
        }
    }

    fn expect(&mut self, token: &str) -> Result<(), String> {
        if self.eat(token) {
            Ok(())
        } else {
            Err(self.error(&format!("expected {token:?}")))
        }
    }

    /// Skip past `end`; the skipped text is returned.
    fn until(&mut self, end: &str, what: &str) -> Result<&'a str, String> {
        let at = self
            .rest()
            .find(end)
            .ok_or_else(|| self.error(&format!("unterminated {what}")))?;
        let skipped = &self.rest()[..at];
        self.i += at + end.len();
        Ok(skipped)
    }

    fn name(&mut self) -> Result<String, String> {
        let len = self
            .rest()
            .find(|c: char| !(c.is_alphanumeric() || "_:.-".contains(c)))
            .unwrap_or(self.rest().len());
        let name = &self.rest()[..len];
        if !name.starts_with(|c: char| c.is_alphabetic() || c == '_' || c == ':') {
            return Err(self.error("bad or missing name"));
        }
        self.i += len;
        Ok(name.to_string())
    }

    /// Comments and processing instructions (and, if allowed, a doctype); true if one was read.
    fn misc(&mut self, doctype: bool) -> Result<bool, String> {
        if self.eat("<!--") {
            let body = self.until("-->", "comment")?;
            if body.contains("--") || body.ends_with('-') {
                return Err(self.error("`--` inside a comment"));
            }
        } else if self.eat("<?") {
            self.name()?;
            self.until("?>", "processing instruction")?;
        } else if doctype && self.eat("<!DOCTYPE") {
            let body = self.until(">", "doctype")?;
            if body.contains('<') || body.contains('[') {
                return Err(self.error("doctype with an internal subset"));
            }
        } else {
            return Ok(false);
        }
        Ok(true)
    }

    fn document(mut self) -> Result<Element, String> {
        let mut doctype = true;
        loop {
            self.skip_ws();
            let was_doctype = self.rest().starts_with("<!DOCTYPE");
            if !self.misc(doctype)? {
                break;
            }
            doctype &= !was_doctype;
        }
        if !self.rest().starts_with('<') {
            return Err(self.error("expected the root element"));
        }
        let root = self.element()?;
        loop {
            self.skip_ws();
            if !self.misc(false)? {
                break;
            }
        }
        if !self.rest().is_empty() {
            return Err(self.error("content after the root element"));
        }
        Ok(root)
    }

    /// Character data up to (not including) `stop`, with entities resolved.
    fn chars_until(&mut self, stop: char) -> Result<String, String> {
        let end = self
            .rest()
            .find(stop)
            .ok_or_else(|| self.error("unterminated text"))?;
        let raw = &self.rest()[..end];
        if stop != '<' && raw.contains('<') {
            return Err(self.error("raw `<` in an attribute value"));
        }
        if stop == '<' && raw.contains("]]>") {
            return Err(self.error("`]]>` in text"));
        }
        let value = unescape(raw).map_err(|e| self.error(&e))?;
        self.i += end;
        Ok(value)
    }

    fn element(&mut self) -> Result<Element, String> {
        // Open elements, innermost last; each finished element is appended to its parent.
        let mut stack: Vec<Element> = Vec::new();
        loop {
            // At a start tag.
            self.expect("<")?;
            let name = self.name()?;
            let mut element = Element {
                name,
                attrs: Vec::new(),
                children: Vec::new(),
                text: String::new(),
            };
            let empty = loop {
                let spaced = self.skip_ws();
                if self.eat("/>") {
                    break true;
                }
                if self.eat(">") {
                    break self
                        .void
                        .contains(&element.name.to_ascii_lowercase().as_str());
                }
                if !spaced {
                    return Err(self.error("attributes must be separated by whitespace"));
                }
                let attr = self.name()?;
                self.skip_ws();
                self.expect("=")?;
                self.skip_ws();
                let quote = if self.eat("\"") {
                    '"'
                } else if self.eat("'") {
                    '\''
                } else {
                    return Err(self.error(&format!("unquoted value of `{attr}`")));
                };
                let value = self.chars_until(quote)?;
                self.i += 1;
                if element.attr(&attr).is_some() {
                    return Err(self.error(&format!("duplicate attribute `{attr}`")));
                }
                element.attrs.push((attr, value));
            };
            stack.push(element);
            let mut close = empty;
            // Content until the next start tag (or the end of the outermost element).
            loop {
                if close {
                    let done = stack.pop().expect("an element is open");
                    match stack.last_mut() {
                        Some(parent) => parent.children.push(done),
                        None => return Ok(done),
                    }
                    close = false;
                }
                if self.rest().is_empty() {
                    let open = &stack.last().expect("an element is open").name;
                    return Err(self.error(&format!("<{open}> is never closed")));
                }
                if self.eat("</") {
                    let name = self.name()?;
                    self.skip_ws();
                    self.expect(">")?;
                    let open = &stack.last().expect("an element is open").name;
                    if *open != name {
                        return Err(self.error(&format!("<{open}> closed by </{name}>")));
                    }
                    close = true;
                } else if self.eat("<![CDATA[") {
                    let data = self.until("]]>", "CDATA section")?;
                    let top = stack.last_mut().expect("an element is open");
                    top.text.push_str(data);
                } else if self.rest().starts_with('<') {
                    if !self.misc(false)? {
                        break;
                    }
                } else if self.rest().contains('<') {
                    let text = self.chars_until('<')?;
                    stack.last_mut().expect("an element is open").text += &text;
                } else {
                    let open = &stack.last().expect("an element is open").name;
                    return Err(self.error(&format!("<{open}> is never closed")));
                }
            }
        }
    }
}

/// Resolve the five predefined entities and numeric character references.
fn unescape(raw: &str) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = raw;
    while let Some(amp) = rest.find('&') {
        out.push_str(&rest[..amp]);
        let semi = rest[amp..]
            .find(';')
            .map(|s| s + amp)
            .ok_or("`&` without `;`")?;
        let entity = &rest[amp + 1..semi];
        let c = match entity {
            "amp" => '&',
            "lt" => '<',
            "gt" => '>',
            "quot" => '"',
            "apos" => '\'',
            _ => {
                let digits = |d: &str, radix: u32| {
                    (!d.is_empty() && d.chars().all(|c| c.is_digit(radix)))
                        .then(|| u32::from_str_radix(d, radix).ok())
                        .flatten()
                };
                let code = if let Some(hex) = entity.strip_prefix("#x") {
                    digits(hex, 16)
                } else if let Some(dec) = entity.strip_prefix('#') {
                    digits(dec, 10)
                } else {
                    return Err(format!("unknown entity &{entity};"));
                };
                code.filter(|&c| c != 0)
                    .and_then(char::from_u32)
                    .ok_or(format!("bad character reference &{entity};"))?
            }
        };
        out.push(c);
        rest = &rest[semi + 1..];
    }
    out.push_str(rest);
    Ok(out)
}
