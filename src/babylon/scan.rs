//! A strict, iterative JSON scanner run before serde-json-core.
//!
//! serde-json-core recurses once per nesting level (even while skipping an
//! unknown field) and reports no byte offsets, so this pass checks the
//! syntax and the depth with an explicit stack, counts the arrays the
//! loader must store (so capacity errors can name the size needed), and
//! later finds the byte offset of a location for errors found by serde.

use super::error::{Error, Item, JsonError, Location};
use super::{decode_name, Name, MAX_DEPTH};

// The container stack is a bit set (1 = array).
const _: () = assert!(MAX_DEPTH <= 64);

/// The position of the current value inside one open container.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Slot {
    /// Object member, by the key's raw bytes `json[start..end]`.
    Key(usize, usize),
    /// Array element.
    Index(usize),
}

/// One token of the document.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Event {
    /// `[` or `{`.
    Begin { array: bool },
    /// `]` or `}`, with the number of elements or members.
    End { array: bool, count: usize },
    /// A string value; `json[start..end]` is its raw (escaped) content.
    Str { start: usize, end: usize },
    /// A number; `json[start..end]` is its text.
    Num { start: usize, end: usize },
    /// `true`, `false` or `null`.
    Lit,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum State {
    /// A value is expected (at the root, after `:`, after `,` in an array).
    Value,
    /// Just after `[`: a value or `]`.
    ArrayFirst,
    /// Just after `{`: a key or `}`.
    ObjectFirst,
    /// After `,` in an object: a key.
    Key,
    /// After a key.
    Colon,
    /// After a value inside a container.
    CommaOrEnd,
    /// After the root value: only whitespace may follow.
    Done,
}

pub(crate) struct Scanner<'j> {
    json: &'j [u8],
    pos: usize,
    depth: usize,
    arrays: u64,
    slots: [Slot; MAX_DEPTH],
    counts: [usize; MAX_DEPTH],
    state: State,
    /// Length of the path of the last event's value.
    event_depth: usize,
}

/// The scanner's own error: small, because `next` returns once per token.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum ScanError {
    /// Malformed JSON at a byte offset.
    Syntax(JsonError, usize),
    /// Nesting deeper than `MAX_DEPTH`, at a byte offset.
    TooDeep(usize),
}

impl From<ScanError> for Error {
    fn from(e: ScanError) -> Self {
        match e {
            ScanError::Syntax(kind, offset) => Error::Json { kind, at: Location::scene(None).at(offset) },
            ScanError::TooDeep(offset) => Error::TooDeep { depth: MAX_DEPTH + 1, offset },
        }
    }
}

type ScanResult<T> = Result<T, ScanError>;

fn syntax(kind: JsonError, offset: usize) -> ScanError {
    ScanError::Syntax(kind, offset)
}

impl<'j> Scanner<'j> {
    pub(crate) fn new(json: &'j [u8]) -> Self {
        Self {
            json,
            pos: 0,
            depth: 0,
            arrays: 0,
            slots: [Slot::Index(0); MAX_DEPTH],
            counts: [0; MAX_DEPTH],
            state: State::Value,
            event_depth: 0,
        }
    }

    /// The path of the last event's value: one slot per enclosing container.
    pub(crate) fn path(&self) -> &[Slot] {
        &self.slots[..self.event_depth]
    }

    fn in_array(&self) -> bool {
        self.depth > 0 && self.arrays & (1 << (self.depth - 1)) != 0
    }

    fn skip_ws(&mut self) -> Option<u8> {
        while let Some(&c) = self.json.get(self.pos) {
            if matches!(c, b' ' | b'\t' | b'\n' | b'\r') {
                self.pos += 1;
            } else {
                return Some(c);
            }
        }
        None
    }

    /// The next event and its byte offset, `None` at the end of a valid
    /// document.
    pub(crate) fn next(&mut self) -> ScanResult<Option<(Event, usize)>> {
        loop {
            let c = self.skip_ws();
            let at = self.pos;
            match self.state {
                State::Done => {
                    return match c {
                        Some(_) => Err(syntax(JsonError::TrailingCharacters, at)),
                        None => Ok(None),
                    };
                }
                State::Value | State::ArrayFirst => {
                    let Some(c) = c else {
                        let kind =
                            if self.state == State::ArrayFirst { JsonError::EofWhileParsingList } else { JsonError::EofWhileParsingValue };
                        return Err(syntax(kind, at));
                    };
                    if c == b']' && self.in_array() {
                        if self.state == State::Value {
                            return Err(syntax(JsonError::TrailingComma, at));
                        }
                        return Ok(Some(self.close(true)));
                    }
                    return self.value(c).map(Some);
                }
                State::ObjectFirst | State::Key => match c {
                    Some(b'}') if self.state == State::ObjectFirst => return Ok(Some(self.close(false))),
                    Some(b'}') => return Err(syntax(JsonError::TrailingComma, at)),
                    Some(b'"') => {
                        let (start, end) = self.string()?;
                        let d = self.depth - 1;
                        self.slots[d] = Slot::Key(start, end);
                        self.counts[d] += 1;
                        self.state = State::Colon;
                    }
                    None if self.state == State::ObjectFirst => return Err(syntax(JsonError::EofWhileParsingObject, at)),
                    None => return Err(syntax(JsonError::EofWhileParsingValue, at)),
                    Some(_) => return Err(syntax(JsonError::KeyMustBeAString, at)),
                },
                State::Colon => match c {
                    Some(b':') => {
                        self.pos += 1;
                        self.state = State::Value;
                    }
                    None => return Err(syntax(JsonError::EofWhileParsingObject, at)),
                    Some(_) => return Err(syntax(JsonError::ExpectedColon, at)),
                },
                State::CommaOrEnd => {
                    let array = self.in_array();
                    match (c, array) {
                        (Some(b','), true) => {
                            self.pos += 1;
                            self.state = State::Value;
                        }
                        (Some(b','), false) => {
                            self.pos += 1;
                            self.state = State::Key;
                        }
                        (Some(b']'), true) => return Ok(Some(self.close(true))),
                        (Some(b'}'), false) => return Ok(Some(self.close(false))),
                        (None, true) => return Err(syntax(JsonError::EofWhileParsingList, at)),
                        (None, false) => return Err(syntax(JsonError::EofWhileParsingObject, at)),
                        (Some(_), true) => return Err(syntax(JsonError::ExpectedListCommaOrEnd, at)),
                        (Some(_), false) => return Err(syntax(JsonError::ExpectedObjectCommaOrEnd, at)),
                    }
                }
            }
        }
    }

    /// Starts a value whose first byte is `c`.
    fn value(&mut self, c: u8) -> ScanResult<(Event, usize)> {
        let at = self.pos;
        if self.in_array() {
            let d = self.depth - 1;
            self.slots[d] = Slot::Index(self.counts[d]);
            self.counts[d] += 1;
        }
        self.event_depth = self.depth;
        let event = match c {
            b'{' | b'[' => {
                if self.depth == MAX_DEPTH {
                    return Err(ScanError::TooDeep(at));
                }
                let array = c == b'[';
                if array {
                    self.arrays |= 1 << self.depth;
                } else {
                    self.arrays &= !(1 << self.depth);
                }
                self.counts[self.depth] = 0;
                self.depth += 1;
                self.pos += 1;
                self.state = if array { State::ArrayFirst } else { State::ObjectFirst };
                return Ok((Event::Begin { array }, at));
            }
            b'"' => {
                let (start, end) = self.string()?;
                Event::Str { start, end }
            }
            b'-' | b'0'..=b'9' => {
                let (start, end) = self.number()?;
                Event::Num { start, end }
            }
            b't' => self.literal(b"true")?,
            b'f' => self.literal(b"false")?,
            b'n' => self.literal(b"null")?,
            _ => return Err(syntax(JsonError::ExpectedSomeValue, at)),
        };
        self.after_value();
        Ok((event, at))
    }

    fn after_value(&mut self) {
        self.state = if self.depth == 0 { State::Done } else { State::CommaOrEnd };
    }

    fn close(&mut self, array: bool) -> (Event, usize) {
        let at = self.pos;
        self.pos += 1;
        self.depth -= 1;
        let count = self.counts[self.depth];
        self.event_depth = self.depth;
        self.after_value();
        (Event::End { array, count }, at)
    }

    fn literal(&mut self, word: &[u8]) -> ScanResult<Event> {
        let at = self.pos;
        if self.json.get(at..at + word.len()) != Some(word) {
            return Err(syntax(JsonError::ExpectedSomeIdent, at));
        }
        self.pos += word.len();
        Ok(Event::Lit)
    }

    /// Scans a string starting at the opening quote; returns the raw
    /// content's range.
    fn string(&mut self) -> ScanResult<(usize, usize)> {
        self.pos += 1;
        let start = self.pos;
        let mut ascii = true;
        loop {
            let Some(&c) = self.json.get(self.pos) else {
                return Err(syntax(JsonError::EofWhileParsingString, self.pos));
            };
            match c {
                b'"' => break,
                b'\\' => {
                    let esc = self.pos;
                    match self.json.get(self.pos + 1) {
                        Some(b'"' | b'\\' | b'/' | b'b' | b'f' | b'n' | b'r' | b't') => self.pos += 2,
                        Some(b'u') => {
                            match self.json.get(self.pos + 2..self.pos + 6) {
                                Some(h) if h.iter().all(u8::is_ascii_hexdigit) => {}
                                Some(_) => return Err(syntax(JsonError::InvalidEscapeSequence, esc)),
                                None if self.json[self.pos + 2..].iter().all(u8::is_ascii_hexdigit) => {
                                    return Err(syntax(JsonError::EofWhileParsingString, self.json.len()));
                                }
                                None => return Err(syntax(JsonError::InvalidEscapeSequence, esc)),
                            }
                            self.pos += 6;
                        }
                        Some(_) => return Err(syntax(JsonError::InvalidEscapeSequence, esc)),
                        None => return Err(syntax(JsonError::EofWhileParsingString, self.json.len())),
                    }
                }
                _ => {
                    ascii &= c < 0x80;
                    self.pos += 1;
                }
            }
        }
        let end = self.pos;
        self.pos += 1;
        if !ascii {
            if let Err(e) = core::str::from_utf8(&self.json[start..end]) {
                return Err(syntax(JsonError::InvalidUnicodeCodePoint, start + e.valid_up_to()));
            }
        }
        Ok((start, end))
    }

    /// Scans a number (RFC 8259 grammar); returns its range.
    fn number(&mut self) -> ScanResult<(usize, usize)> {
        let start = self.pos;
        let digits = |s: &mut Self| -> ScanResult<()> {
            match s.json.get(s.pos) {
                Some(c) if c.is_ascii_digit() => {}
                Some(_) => return Err(syntax(JsonError::InvalidNumber, s.pos)),
                None => return Err(syntax(JsonError::EofWhileParsingNumber, s.pos)),
            }
            while s.json.get(s.pos).is_some_and(u8::is_ascii_digit) {
                s.pos += 1;
            }
            Ok(())
        };
        if self.json[self.pos] == b'-' {
            self.pos += 1;
        }
        if self.json.get(self.pos) == Some(&b'0') {
            self.pos += 1;
        } else {
            digits(self)?;
        }
        if self.json.get(self.pos) == Some(&b'.') {
            self.pos += 1;
            digits(self)?;
        }
        if matches!(self.json.get(self.pos), Some(b'e' | b'E')) {
            self.pos += 1;
            if matches!(self.json.get(self.pos), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            digits(self)?;
        }
        // `01`, `1.2.3`, `1x`: a number glued to more number-like text.
        if self.json.get(self.pos).is_some_and(|c| c.is_ascii_alphanumeric() || matches!(c, b'.' | b'+' | b'-')) {
            return Err(syntax(JsonError::InvalidNumber, self.pos));
        }
        Ok((start, self.pos))
    }
}

/// True if `slot` is the object key `name` (compared raw, without decoding
/// escapes, as serde-json-core compares keys).
fn key_is(json: &[u8], slot: &Slot, name: &str) -> bool {
    matches!(*slot, Slot::Key(s, e) if &json[s..e] == name.as_bytes())
}

/// The value of a number token, if it is one.
fn number_value(json: &[u8], event: Event) -> Option<f64> {
    match event {
        Event::Num { start, end } => core::str::from_utf8(&json[start..end]).ok()?.parse().ok(),
        _ => None,
    }
}

/// A string token decoded into a name, truncated if too long (used only for
/// messages; the serde pass rejects long names).
fn string_value(json: &[u8], event: Event) -> Option<Name> {
    match event {
        Event::Str { start, end } => {
            let raw = core::str::from_utf8(&json[start..end]).ok()?;
            let mut name = Name::new();
            let _ = decode_name(raw, &mut name);
            Some(name)
        }
        _ => None,
    }
}

/// A mesh's geometry as the pre-scan sees it, once its object has ended.
#[derive(Clone, Debug, Default)]
pub(crate) struct MeshPlan {
    /// Position in the `meshes` array.
    pub index: usize,
    /// Its name (for messages).
    pub name: Name,
    /// Byte offset of its geometry (`vertices` or `positions`), or of the
    /// mesh object.
    pub offset: usize,
    /// Vertex count.
    pub vertices: usize,
    /// Floats per vertex of the legacy `vertices` array (6, 8 or 10), or 0
    /// for separate arrays.
    pub stride: usize,
    /// Whether texture coordinates are stored.
    pub has_uvs: bool,
    /// Index count.
    pub indices: usize,
}

/// What the pre-scan learns about a mesh while inside its object.
#[derive(Default)]
struct MeshScan {
    object_offset: usize,
    name: Name,
    /// (value count, offset) of each geometry array.
    vertices: Option<(usize, usize)>,
    positions: Option<(usize, usize)>,
    normals: Option<(usize, usize)>,
    uvs: Option<(usize, usize)>,
    indices: Option<(usize, usize)>,
    /// (value, offset) of `uvCount`.
    uv_count: Option<(f64, usize)>,
}

const GEOMETRY: [&str; 5] = ["vertices", "positions", "normals", "uvs", "indices"];

impl MeshScan {
    fn array(&mut self, field: usize) -> &mut Option<(usize, usize)> {
        match field {
            0 => &mut self.vertices,
            1 => &mut self.positions,
            2 => &mut self.normals,
            3 => &mut self.uvs,
            _ => &mut self.indices,
        }
    }

    /// Checks the geometry's shape and returns the plan.
    fn finish(self, index: usize) -> Result<MeshPlan, Error> {
        let at = |field: &'static str, offset: usize| {
            let mut l = Location::item(Item::Mesh(index)).field(field).at(offset);
            l.set_name(&self.name);
            l
        };
        let mut plan = MeshPlan { index, name: self.name.clone(), offset: self.object_offset, ..MeshPlan::default() };
        if let Some((len, offset)) = self.vertices {
            if self.positions.is_some() || self.normals.is_some() || self.uvs.is_some() {
                return Err(Error::Invalid { at: at("vertices", offset), problem: "both legacy `vertices` and separate vertex arrays" });
            }
            let uv_count = match self.uv_count {
                None => 0,
                Some((v, _)) if v == 0.0 || v == 1.0 || v == 2.0 => v as usize,
                Some((_, o)) => return Err(Error::Invalid { at: at("uvCount", o), problem: "uvCount must be 0, 1 or 2" }),
            };
            let stride = 6 + 2 * uv_count;
            if len % stride != 0 {
                return Err(Error::Stride { at: at("vertices", offset), len, stride });
            }
            plan.vertices = len / stride;
            plan.stride = stride;
            plan.has_uvs = uv_count > 0;
            plan.offset = offset;
        } else {
            if let Some((len, offset)) = self.positions {
                if len % 3 != 0 {
                    return Err(Error::Stride { at: at("positions", offset), len, stride: 3 });
                }
                plan.vertices = len / 3;
                plan.offset = offset;
            }
            let n = plan.vertices;
            for (field, array, stride) in [("normals", self.normals, 3), ("uvs", self.uvs, 2)] {
                if let Some((len, offset)) = array {
                    if len % stride != 0 {
                        return Err(Error::Stride { at: at(field, offset), len, stride });
                    }
                    if len / stride != n {
                        return Err(Error::AttributeLength { at: at(field, offset), len: len / stride, expected: n });
                    }
                }
            }
            plan.has_uvs = self.uvs.is_some();
        }
        if plan.vertices > 1 << 16 {
            return Err(Error::TooManyVertices {
                at: at(if plan.stride > 0 { "vertices" } else { "positions" }, plan.offset),
                count: plan.vertices,
            });
        }
        if let Some((len, offset)) = self.indices {
            if len % 3 != 0 {
                return Err(Error::IndexCount { at: at("indices", offset), count: len });
            }
            plan.indices = len;
        }
        Ok(plan)
    }
}

/// What the pre-scan found in the whole file.
#[derive(Debug, Default)]
pub(crate) struct Survey {
    pub meshes: usize,
    pub materials: usize,
    /// Point and directional lights (the others are skipped).
    pub lights: usize,
    pub vertices: usize,
    pub uvs: usize,
    pub indices: usize,
    /// `activeCamera` (or `activeCameraID`), decoded.
    pub active_camera: Option<Name>,
}

const SECTIONS: [&str; 4] = ["meshes", "materials", "lights", "cameras"];

/// Checks syntax and depth, counts what must be stored, validates each
/// mesh's geometry shape and hands its plan to `on_mesh`.
pub(crate) fn survey(json: &[u8], on_mesh: &mut dyn FnMut(&MeshPlan)) -> Result<Survey, Error> {
    let mut sc = Scanner::new(json);
    let mut survey = Survey::default();
    let mut seen = [false; SECTIONS.len()];
    let mut mesh: Option<MeshScan> = None;
    let mut light_type: Option<f64> = None;
    let mut active_id: Option<Name> = None;
    while let Some((event, offset)) = sc.next()? {
        let path = sc.path();
        match path {
            [s] => {
                if let Some(k) = SECTIONS.iter().position(|n| key_is(json, s, n)) {
                    match event {
                        Event::Begin { .. } if seen[k] => {
                            return Err(Error::Invalid { at: Location::scene(Some(SECTIONS[k])).at(offset), problem: "duplicate field" });
                        }
                        Event::Begin { .. } => seen[k] = true,
                        Event::End { array: true, count } => match k {
                            0 => survey.meshes = count,
                            1 => survey.materials = count,
                            _ => {}
                        },
                        _ => {}
                    }
                } else if key_is(json, s, "activeCamera") {
                    survey.active_camera = string_value(json, event);
                } else if key_is(json, s, "activeCameraID") {
                    active_id = string_value(json, event);
                }
            }
            [s, Slot::Index(i)] if key_is(json, s, "meshes") => match event {
                Event::Begin { array: false } => mesh = Some(MeshScan { object_offset: offset, ..MeshScan::default() }),
                Event::End { array: false, .. } => {
                    if let Some(m) = mesh.take() {
                        let plan = m.finish(*i)?;
                        survey.vertices += plan.vertices;
                        survey.uvs += if plan.has_uvs { plan.vertices } else { 0 };
                        survey.indices += plan.indices;
                        on_mesh(&plan);
                    }
                }
                _ => {}
            },
            [s, Slot::Index(i), f] if key_is(json, s, "meshes") => {
                let Some(m) = mesh.as_mut() else { continue };
                if key_is(json, f, "name") {
                    if let Some(name) = string_value(json, event) {
                        m.name = name;
                    }
                } else if key_is(json, f, "uvCount") {
                    m.uv_count = number_value(json, event).map(|v| (v, offset));
                } else if let Some(g) = GEOMETRY.iter().position(|n| key_is(json, f, n)) {
                    match event {
                        Event::Begin { array: true } if m.array(g).is_some() => {
                            let mut at = Location::item(Item::Mesh(*i)).field(GEOMETRY[g]).at(offset);
                            at.set_name(&m.name);
                            return Err(Error::Invalid { at, problem: "duplicate field" });
                        }
                        Event::Begin { array: true } => *m.array(g) = Some((0, offset)),
                        Event::End { array: true, count } => {
                            if let Some((len, _)) = m.array(g) {
                                *len = count;
                            }
                        }
                        _ => {}
                    }
                }
            }
            [s, Slot::Index(_)] if key_is(json, s, "lights") => match event {
                Event::Begin { array: false } => light_type = None,
                Event::End { array: false, .. } => {
                    if matches!(light_type, Some(t) if t == 0.0 || t == 1.0) {
                        survey.lights += 1;
                    }
                }
                _ => {}
            },
            [s, Slot::Index(_), f] if key_is(json, s, "lights") && key_is(json, f, "type") => light_type = number_value(json, event),
            _ => {}
        }
    }
    if survey.active_camera.is_none() {
        survey.active_camera = active_id;
    }
    Ok(survey)
}

/// The byte offset of `at`'s value in a document that scans cleanly (the
/// element if it exists, else the field, else the item).
pub(crate) fn locate(json: &[u8], at: &Location) -> Option<usize> {
    enum Seg<'a> {
        Key(&'a str),
        Index(usize),
    }
    let mut target: [Seg<'_>; 8] = core::array::from_fn(|_| Seg::Index(0));
    let mut n = 0;
    let section = match at.item {
        Item::Scene => None,
        Item::Mesh(i) => Some(("meshes", i)),
        Item::Material(i) => Some(("materials", i)),
        Item::Camera(i) => Some(("cameras", i)),
        Item::Light(i) => Some(("lights", i)),
    };
    if let Some((key, i)) = section {
        target[0] = Seg::Key(key);
        target[1] = Seg::Index(i);
        n = 2;
    }
    let mut lengths: [usize; 3] = [n, n, n];
    if let Some(field) = at.field {
        for part in field.split('.') {
            if n < target.len() - 1 {
                target[n] = Seg::Key(part);
                n += 1;
            }
        }
    }
    lengths[1] = n;
    if let Some(e) = at.element {
        target[n] = Seg::Index(e);
        n += 1;
    }
    lengths[0] = n;
    for len in lengths {
        let mut sc = Scanner::new(json);
        while let Ok(Some((event, offset))) = sc.next() {
            if matches!(event, Event::End { .. }) {
                continue;
            }
            let path = sc.path();
            let same = path.len() == len
                && path.iter().zip(&target[..len]).all(|(slot, seg)| match (slot, seg) {
                    (Slot::Index(a), Seg::Index(b)) => a == b,
                    (s @ Slot::Key(..), Seg::Key(k)) => key_is(json, s, k),
                    _ => false,
                });
            if same {
                return Some(offset);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn events(json: &str) -> Result<usize, ScanError> {
        let mut sc = Scanner::new(json.as_bytes());
        let mut n = 0;
        while sc.next()?.is_some() {
            n += 1;
        }
        Ok(n)
    }

    fn kind(json: &str) -> (JsonError, usize) {
        match events(json) {
            Err(ScanError::Syntax(kind, offset)) => (kind, offset),
            other => panic!("{json}: {other:?}"),
        }
    }

    #[test]
    fn accepts_valid_json() {
        assert_eq!(events(r#" {"a": [1, -2.5e3, true, null, "x\"\u00e9"], "b": {}} "#).unwrap(), 11);
        assert_eq!(events("0").unwrap(), 1);
        assert_eq!(events("[[]]").unwrap(), 4);
    }

    #[test]
    fn rejects_invalid_json_with_offsets() {
        assert_eq!(kind(""), (JsonError::EofWhileParsingValue, 0));
        assert_eq!(kind("[1,]"), (JsonError::TrailingComma, 3));
        assert_eq!(kind(r#"{"a":1,}"#), (JsonError::TrailingComma, 7));
        assert_eq!(kind("[1 2]"), (JsonError::ExpectedListCommaOrEnd, 3));
        assert_eq!(kind(r#"{"a" 1}"#), (JsonError::ExpectedColon, 5));
        assert_eq!(kind("{1:2}"), (JsonError::KeyMustBeAString, 1));
        assert_eq!(kind("[01]"), (JsonError::InvalidNumber, 2));
        assert_eq!(kind("[1.]"), (JsonError::InvalidNumber, 3));
        assert_eq!(kind("[-"), (JsonError::EofWhileParsingNumber, 2));
        assert_eq!(kind("[tru]"), (JsonError::ExpectedSomeIdent, 1));
        assert_eq!(kind(r#"["\x"]"#), (JsonError::InvalidEscapeSequence, 2));
        assert_eq!(kind(r#"["abc"#), (JsonError::EofWhileParsingString, 5));
        assert_eq!(kind("{} x"), (JsonError::TrailingCharacters, 3));
        assert_eq!(kind("[NaN]"), (JsonError::ExpectedSomeValue, 1));
        let bad = [b'[', b'"', b'a', 0xff, b'"', b']'];
        let mut sc = Scanner::new(&bad);
        sc.next().unwrap();
        assert_eq!(sc.next(), Err(ScanError::Syntax(JsonError::InvalidUnicodeCodePoint, 3)));
    }

    #[test]
    fn depth_is_bounded() {
        let mut s = std::string::String::new();
        for _ in 0..MAX_DEPTH {
            s.push('[');
        }
        for _ in 0..MAX_DEPTH {
            s.push(']');
        }
        assert!(events(&s).is_ok());
        let deeper = std::format!("[{s}]");
        assert_eq!(events(&deeper), Err(ScanError::TooDeep(MAX_DEPTH)));
    }

    #[test]
    fn locate_finds_nested_values() {
        let json = br#"{"meshes":[{"name":"a"},{"name":"b","positions":[1,2,3]}]}"#;
        let mut at = Location::item(Item::Mesh(1)).field("positions");
        at.element = Some(2);
        let o = locate(json, &at).unwrap();
        assert_eq!(json[o], b'3');
        at.element = Some(7);
        assert_eq!(json[locate(json, &at).unwrap()], b'[');
    }
}
