//! Reading the fields of a TOML file with errors that name the file, the
//! line and the field. Every format the crate reads by hand (scenes,
//! gestures) checks its values here, so they are worded one way:
//!
//! ```text
//! tasks/x.toml:16: field `objects[0].mass`: -0.12 is out of range (>= 0)
//! g.toml:9: unknown field `postion`, expected one of `t`, `pos`, ... (at `postion = [0.0, 0.0]`)
//! ```

use serde::de::DeserializeOwned;
use std::fmt::Display;

/// A file whose text does not parse, or whose values make no sense.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FieldError {
    /// TOML syntax, or text that does not fit the format (an unknown key, a
    /// wrong type, a missing field): toml's message and the line it points at.
    #[error("{origin}{}: {message}", at_line(*.line))]
    Syntax { origin: String, line: Option<usize>, message: String },
    /// A value that parses but cannot be used.
    #[error("{origin}{}: field `{field}`: {problem}", at_line(*.line))]
    Value { origin: String, line: Option<usize>, field: String, problem: String },
}

fn at_line(line: Option<usize>) -> String {
    line.map(|l| format!(":{l}")).unwrap_or_default()
}

/// One file's text and the name its errors carry.
#[derive(Debug, Clone, Copy)]
pub struct FieldReader<'a> {
    text: &'a str,
    origin: &'a str,
}

impl<'a> FieldReader<'a> {
    pub fn new(text: &'a str, origin: &'a str) -> Self {
        Self { text, origin }
    }

    pub fn origin(&self) -> &'a str {
        self.origin
    }

    /// Deserializes the whole file; syntax and shape errors name the line
    /// and quote it.
    pub fn parse<T: DeserializeOwned>(&self) -> Result<T, FieldError> {
        toml::from_str(self.text).map_err(|e| {
            let line = e.span().map(|s| self.line(s.start));
            let quoted = line
                .and_then(|l| self.text.lines().nth(l - 1))
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .map(|s| format!(" (at `{s}`)"))
                .unwrap_or_default();
            let field =
                e.span().and_then(|s| self.field_at(s.start)).map(|f| format!("field `{f}`: ")).unwrap_or_default();
            FieldError::Syntax {
                origin: self.origin.to_owned(),
                line,
                message: format!("{field}{}{quoted}", e.message().trim_end()),
            }
        })
    }

    /// The field whose value starts at byte `offset`, as the scene checks
    /// name fields (`table.size`, `objects[2].step`, `hands[0].keys[3].pos`):
    /// the key written before `=` on that line, under the table headers
    /// above it, each `[[array]]` header counted. `None` when the line has
    /// no `KEY =` before the offset (the error is not about one value).
    pub fn field_at(&self, offset: usize) -> Option<String> {
        let offset = offset.min(self.text.len());
        let line_start = self.text[..offset].rfind('\n').map_or(0, |i| i + 1);
        let (key, _) = self.text[line_start..offset].split_once('=')?;
        let key = key.trim();
        if key.is_empty() || key.starts_with('[') || key.contains(['"', '\'', ' ']) {
            return None;
        }
        // Each array-of-tables seen so far, with how many entries it has.
        let mut counts: Vec<(String, usize)> = Vec::new();
        let mut table = String::new();
        for line in self.text[..line_start].lines() {
            let t = line.trim();
            if let Some(name) = t.strip_prefix("[[").and_then(|r| r.split_once("]]")).map(|(n, _)| n.trim()) {
                // A new entry of `name` starts every array nested in it afresh.
                counts.retain(|(n, _)| !n.starts_with(&format!("{name}.")));
                match counts.iter_mut().find(|(n, _)| n == name) {
                    Some((_, c)) => *c += 1,
                    None => counts.push((name.to_owned(), 1)),
                }
                name.clone_into(&mut table);
            } else if let Some(name) = t.strip_prefix('[').and_then(|r| r.split_once(']')).map(|(n, _)| n.trim()) {
                name.clone_into(&mut table);
            }
        }
        let mut path = Vec::new();
        let mut prefix = String::new();
        for part in table.split('.').filter(|p| !p.is_empty()) {
            prefix = if prefix.is_empty() { part.to_owned() } else { format!("{prefix}.{part}") };
            match counts.iter().find(|(n, _)| *n == prefix) {
                Some((_, c)) => path.push(format!("{part}[{}]", c - 1)),
                None => path.push(part.to_owned()),
            }
        }
        path.push(key.to_owned());
        Some(path.join("."))
    }

    /// The 1-based line of a byte offset.
    pub fn line(&self, offset: usize) -> usize {
        let end = offset.min(self.text.len());
        // Pieces between newlines = newlines + 1 = the line number.
        self.text.as_bytes()[..end].split(|&b| b == b'\n').count()
    }

    /// An error about `field`, at the line of byte offset `at` when known.
    /// Where `field` is written in the table that starts at `span`: the
    /// offset of the line `KEY = ...` for the field's last key (`radius` of
    /// `goal.radius`, `object` of `goal.targets[0].object`), looked for from
    /// the table's start to the next table header (a TOML table's span is
    /// its header), so an error names the line of the bad value; the
    /// table's start when the key is not written there (a missing key, a
    /// default).
    pub fn key_offset(&self, span: &std::ops::Range<usize>, field: &str) -> usize {
        let key = field.rsplit('.').next().unwrap_or(field);
        let key = key.split('[').next().unwrap_or(key);
        let Some(rest) = self.text.get(span.start..) else { return span.start };
        let mut offset = span.start;
        for (i, line) in rest.split_inclusive('\n').enumerate() {
            let t = line.trim_start();
            if i > 0 && t.starts_with('[') {
                break;
            }
            if let Some(after) = t.strip_prefix(key)
                && after.trim_start().starts_with('=')
            {
                return offset + (line.len() - t.len());
            }
            offset += line.len();
        }
        span.start
    }

    pub fn error(&self, at: Option<usize>, field: impl Into<String>, problem: impl Into<String>) -> FieldError {
        FieldError::Value {
            origin: self.origin.to_owned(),
            line: at.map(|o| self.line(o)),
            field: field.into(),
            problem: problem.into(),
        }
    }

    /// A value (a count, an index) within `lo..=hi`.
    pub fn in_range<T>(&self, at: Option<usize>, field: &str, v: T, lo: T, hi: T) -> Result<T, FieldError>
    where
        T: Copy + PartialOrd + Display,
    {
        if v >= lo && v <= hi {
            return Ok(v);
        }
        Err(self.error(at, field, format!("{v} is out of range ({lo}..={hi})")))
    }

    /// A finite number within `lo..=hi`. A bound at or beyond `f32::MAX`
    /// in size counts as no bound: the message then says `>= lo` or `<= hi`.
    pub fn number<T>(&self, at: Option<usize>, field: &str, v: T, lo: T, hi: T) -> Result<T, FieldError>
    where
        T: Copy + PartialOrd + Display + Into<f64>,
    {
        if !v.into().is_finite() {
            return Err(self.error(at, field, format!("must be a finite number, got {v}")));
        }
        if v >= lo && v <= hi {
            return Ok(v);
        }
        let unbounded = |b: T| b.into().abs() >= f64::from(f32::MAX);
        let (lo_h, hi_h) = (human(lo.into()), human(hi.into()));
        let range = match (unbounded(lo), unbounded(hi)) {
            (false, false) => format!("{lo_h}..={hi_h}"),
            (false, true) => format!(">= {lo_h}"),
            (true, false) => format!("<= {hi_h}"),
            (true, true) => unreachable!("a finite number lies within unbounded limits"),
        };
        Err(self.error(at, field, format!("{} is out of range ({range})", human(v.into()))))
    }

    /// A finite number greater than 0.
    pub fn positive<T>(&self, at: Option<usize>, field: &str, v: T) -> Result<T, FieldError>
    where
        T: Copy + PartialOrd + Display + Into<f64>,
    {
        if !v.into().is_finite() {
            return Err(self.error(at, field, format!("must be a finite number, got {v}")));
        }
        if v.into() <= 0.0 {
            return Err(self.error(at, field, format!("{} must be greater than 0", human(v.into()))));
        }
        Ok(v)
    }
}

/// A number as people read it: as written for ordinary magnitudes
/// (`0.5`, `120`), in scientific notation past them (`1e30`, `1e-30`),
/// never hundreds of digits. An `f32` widened to `f64` is first rounded
/// back to the `f32`'s own shortest digits (`0.1`, not `0.10000000149`).
pub fn human(v: f64) -> String {
    #[expect(clippy::cast_possible_truncation, reason = "only to test whether v is an f32 widened")]
    let narrow = v as f32;
    let a = v.abs();
    let scientific = a != 0.0 && !(1e-4..1e7).contains(&a);
    match (f64::from(narrow) == v, scientific) {
        (true, true) => format!("{narrow:e}"),
        (true, false) => format!("{narrow}"),
        (false, true) => format!("{v:e}"),
        (false, false) => format!("{v}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "a = 1\nb = 2.5\n";

    #[test]
    fn a_value_is_named_by_its_key_under_the_headers_above_it() {
        let text = "name = \"x\"\n[table]\nsize = [1, 2]\n[[hands]]\nid = 1\n[[hands.keys]]\nt = 0\n\
                    [[hands.keys]]\npos = [0, 0]\n[[hands]]\nid = 2\n[[hands.keys]]\npos = [1, 1]\n";
        let r = FieldReader::new(text, "f.toml");
        let at = |needle: &str, nth: usize| text.match_indices(needle).nth(nth).expect(needle).0 + needle.len();
        assert_eq!(r.field_at(at("name = ", 0)).as_deref(), Some("name"));
        assert_eq!(r.field_at(at("size = ", 0)).as_deref(), Some("table.size"));
        assert_eq!(r.field_at(at("pos = ", 0)).as_deref(), Some("hands[0].keys[1].pos"));
        assert_eq!(r.field_at(at("pos = ", 1)).as_deref(), Some("hands[1].keys[0].pos"));
        assert_eq!(r.field_at(text.find("[table]").expect("header")), None, "no key before a header");
    }

    #[test]
    fn errors_name_file_line_and_field() {
        let r = FieldReader::new(TEXT, "f.toml");
        let at = Some(TEXT.find("b =").expect("b"));
        assert_eq!(
            r.number(at, "b", 2.5_f64, 0.0, 1.0).expect_err("out").to_string(),
            "f.toml:2: field `b`: 2.5 is out of range (0..=1)"
        );
        assert_eq!(
            r.number(at, "b", -1.0_f32, 0.0, f32::INFINITY).expect_err("out").to_string(),
            "f.toml:2: field `b`: -1 is out of range (>= 0)"
        );
        assert_eq!(
            r.number(at, "b", -1.0_f64, 0.0, f64::MAX).expect_err("out").to_string(),
            "f.toml:2: field `b`: -1 is out of range (>= 0)"
        );
        assert_eq!(
            r.number(None, "b", f64::NAN, 0.0, 1.0).expect_err("nan").to_string(),
            "f.toml: field `b`: must be a finite number, got NaN"
        );
        assert_eq!(
            r.positive(at, "b", 0.0_f32).expect_err("zero").to_string(),
            "f.toml:2: field `b`: 0 must be greater than 0"
        );
        assert_eq!(
            r.in_range(at, "n", 0_u32, 1, 100).expect_err("n").to_string(),
            "f.toml:2: field `n`: 0 is out of range (1..=100)"
        );
        assert_eq!(r.number(at, "b", 0.5_f64, 0.0, 1.0), Ok(0.5));
        assert_eq!(
            r.number(at, "b", 1e30_f32, 0.001, 10.0).expect_err("huge").to_string(),
            "f.toml:2: field `b`: 1e30 is out of range (0.001..=10)"
        );
        assert_eq!(
            r.positive(at, "b", -1e-30_f64).expect_err("tiny").to_string(),
            "f.toml:2: field `b`: -1e-30 must be greater than 0"
        );
    }

    #[test]
    fn syntax_errors_quote_the_line() {
        #[derive(serde::Deserialize, Debug)]
        #[serde(deny_unknown_fields)]
        #[allow(dead_code)]
        struct F {
            a: i64,
        }
        let e = FieldReader::new(TEXT, "f.toml").parse::<F>().expect_err("b is unknown").to_string();
        assert!(e.starts_with("f.toml:2: unknown field `b`"), "{e}");
        assert!(e.ends_with("(at `b = 2.5`)"), "{e}");
    }
}
