//! The LM-63 parser: header, keywords, tilt, the numeric block, the angle
//! lists and the candela table, with typed, line-numbered errors.

use super::{IesFormat, IesProfile, MAX_ANGLES, MAX_VALUES, PhotometricType, Tilt};
use crate::IesError;
use crate::IesErrorKind as K;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

struct Tokens<'a> {
    toks: Vec<(&'a str, usize)>,
    pos: usize,
    last_line: usize,
}

impl<'a> Tokens<'a> {
    fn next(&mut self, field: &'static str) -> Result<(&'a str, usize), IesError> {
        match self.toks.get(self.pos) {
            Some(&t) => {
                self.pos += 1;
                Ok(t)
            }
            None => {
                Err(IesError { line: self.last_line, kind: K::UnexpectedEnd { expected: field } })
            }
        }
    }
    fn remaining(&self) -> usize {
        self.toks.len() - self.pos
    }
    fn num(&mut self, field: &'static str) -> Result<(f32, usize), IesError> {
        let (t, line) = self.next(field)?;
        match t.parse::<f32>() {
            Ok(v) if v.is_finite() => Ok((v, line)),
            _ => Err(IesError { line, kind: K::BadNumber { field, token: t.to_string() } }),
        }
    }
    fn int(&mut self, field: &'static str, lo: u32, hi: u32) -> Result<u32, IesError> {
        let (v, line) = self.num(field)?;
        if v != libm::truncf(v) || v < lo as f32 || v > hi as f32 {
            return Err(IesError { line, kind: K::OutOfRange { field, value: v } });
        }
        Ok(v as u32)
    }
    fn nonneg(&mut self, field: &'static str) -> Result<f32, IesError> {
        let (v, line) = self.num(field)?;
        if v < 0.0 {
            return Err(IesError { line, kind: K::OutOfRange { field, value: v } });
        }
        Ok(v)
    }
    fn list(&mut self, field: &'static str, n: usize) -> Result<Vec<(f32, usize)>, IesError> {
        if n > self.remaining() {
            return Err(IesError {
                line: self.last_line,
                kind: K::UnexpectedEnd { expected: field },
            });
        }
        (0..n).map(|_| self.num(field)).collect()
    }
}

fn increasing(
    field: &'static str,
    v: &[(f32, usize)],
    lo: f32,
    hi: f32,
) -> Result<Vec<f32>, IesError> {
    for (i, &(a, line)) in v.iter().enumerate() {
        if a < lo || a > hi {
            return Err(IesError { line, kind: K::OutOfRange { field, value: a } });
        }
        if i > 0 && a <= v[i - 1].0 {
            return Err(IesError { line, kind: K::NotIncreasing { field } });
        }
    }
    Ok(v.iter().map(|a| a.0).collect())
}

impl IesProfile {
    /// Parses LM-63 text given as bytes (non-UTF-8 bytes in free text, e.g.
    /// Latin-1 `°`, are replaced; numbers are ASCII).
    pub fn parse_bytes(bytes: &[u8]) -> Result<Self, IesError> {
        Self::parse(&String::from_utf8_lossy(bytes))
    }

    /// Parses LM-63 text.
    pub fn parse(text: &str) -> Result<Self, IesError> {
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim()));
        let first = text.lines().next().unwrap_or("").trim();
        let format = if first.starts_with("IESNA:LM-63-2002") {
            IesFormat::Lm63_2002
        } else if first.starts_with("IESNA:LM-63-1995") || first.starts_with("IESNA:LM-63") {
            IesFormat::Lm63_1995
        } else if first.starts_with("IESNA91") {
            IesFormat::Lm63_1991
        } else {
            IesFormat::Lm63_1986
        };
        if format != IesFormat::Lm63_1986 {
            lines.next();
        }
        let mut keywords = Vec::new();
        let (tilt_line, tilt_value) = loop {
            let Some((n, l)) = lines.next() else {
                return Err(IesError { line: text.lines().count(), kind: K::MissingTilt });
            };
            if let Some(rest) = l.strip_prefix("TILT") {
                let v = rest.trim_start().strip_prefix('=').unwrap_or(rest).trim();
                break (n, v);
            }
            if format != IesFormat::Lm63_1986
                && l.starts_with('[')
                && let Some(end) = l.find(']')
            {
                keywords.push((l[1..end].to_string(), l[end + 1..].trim().to_string()));
            }
        };
        let mut toks = Vec::new();
        let mut last_line = tilt_line;
        for (n, l) in lines {
            last_line = n;
            toks.extend(
                l.split(|c: char| c.is_whitespace() || c == ',')
                    .filter(|t| !t.is_empty())
                    .map(|t| (t, n)),
            );
        }
        let mut t = Tokens { toks, pos: 0, last_line };

        let tilt = match tilt_value {
            "NONE" => Tilt::None,
            "INCLUDE" => {
                let geometry = t.int("tilt lamp-to-luminaire geometry", 1, 3)?;
                let n = t.int("tilt angle count", 0, MAX_ANGLES as u32)? as usize;
                let angles = t.list("tilt angles", n)?.into_iter().map(|a| a.0).collect();
                let factors = t.list("tilt factors", n)?.into_iter().map(|a| a.0).collect();
                Tilt::Include { geometry, angles, factors }
            }
            "" => return Err(IesError { line: tilt_line, kind: K::MissingTilt }),
            file => Tilt::File(file.to_string()),
        };

        let lamps = t.int("number of lamps", 0, u32::MAX / 2)?;
        let (lumens_per_lamp, lumens_line) = t.num("lumens per lamp")?;
        if lumens_per_lamp < 0.0 && lumens_per_lamp != -1.0 {
            return Err(IesError {
                line: lumens_line,
                kind: K::OutOfRange { field: "lumens per lamp", value: lumens_per_lamp },
            });
        }
        let multiplier = t.nonneg("candela multiplier")?;
        let nv = t.int("number of vertical angles", 1, MAX_ANGLES as u32)? as usize;
        let nh = t.int("number of horizontal angles", 1, MAX_ANGLES as u32)? as usize;
        let ptype_line = t.toks.get(t.pos).map_or(t.last_line, |x| x.1);
        let photometric_type = match t.int("photometric type", 1, 3)? {
            1 => PhotometricType::C,
            2 => PhotometricType::B,
            _ => PhotometricType::A,
        };
        let units = t.int("units type", 1, 2)?;
        let opening = [t.num("width")?.0, t.num("length")?.0, t.num("height")?.0];
        let ballast_factor = t.nonneg("ballast factor")?;
        let ballast_lamp_factor = t.nonneg("ballast-lamp photometric factor")?;
        let input_watts = t.num("input watts")?.0;
        if nv * nh > MAX_VALUES {
            return Err(IesError { line: ptype_line, kind: K::TooLarge { values: nv * nh } });
        }
        let (vlo, hlo) =
            if photometric_type == PhotometricType::C { (0.0, 0.0) } else { (-90.0, -180.0) };
        let vertical = increasing("vertical angles", &t.list("vertical angles", nv)?, vlo, 180.0)?;
        let hraw = t.list("horizontal angles", nh)?;
        let horizontal = increasing("horizontal angles", &hraw, hlo, 360.0)?;
        let craw = t.list("candela values", nv * nh)?;
        for &(c, line) in &craw {
            if c < 0.0 {
                return Err(IesError {
                    line,
                    kind: K::OutOfRange { field: "candela value", value: c },
                });
            }
        }
        let candela: Vec<f32> = craw.iter().map(|c| c.0).collect();

        if photometric_type == PhotometricType::C {
            let (first, last) = (horizontal[0], horizontal[nh - 1]);
            let ok = if first == 90.0 { last == 270.0 } else { first == 0.0 };
            if !ok {
                return Err(IesError { line: hraw[0].1, kind: K::HorizontalRange { first, last } });
            }
        }

        let scale = multiplier
            * ballast_factor
            * if format == IesFormat::Lm63_2002 { 1.0 } else { ballast_lamp_factor };
        let mut p = IesProfile {
            format,
            keywords,
            tilt,
            lamps,
            lumens_per_lamp,
            multiplier,
            photometric_type,
            units,
            opening,
            ballast_factor,
            ballast_lamp_factor,
            input_watts,
            vertical,
            horizontal,
            candela,
            table: Vec::new(),
            max_candela: 0.0,
        };
        // Finite multipliers can overflow f32 together (then a zero candela
        // value times the infinite scale is NaN, which `max` would skip), and
        // finite candela values times a finite scale can overflow too (both
        // found by fuzz/ies_parse).
        if !scale.is_finite() {
            return Err(IesError {
                line: ptype_line,
                kind: K::OutOfRange {
                    field: "candela multiplier times ballast factors",
                    value: scale,
                },
            });
        }
        p.build_table(scale);
        if !p.max_candela.is_finite() {
            return Err(IesError {
                line: ptype_line,
                kind: K::OutOfRange {
                    field: "candela values times multipliers",
                    value: p.max_candela,
                },
            });
        }
        Ok(p)
    }

    /// Flattens to the lookup layout; a full 0–x° (x < 360) type C table
    /// gets a copy of its 0° column at 360° so interpolation wraps.
    fn build_table(&mut self, scale: f32) {
        let (nv, nh) = (self.vertical.len(), self.horizontal.len());
        let last = self.horizontal[nh - 1];
        let wrap = self.is_type_c() && self.horizontal[0] == 0.0 && last > 180.0 && last < 360.0;
        let nh_t = nh + wrap as usize;
        let mut t = Vec::with_capacity(2 + nv + nh_t + nv * nh_t);
        t.push(nv as f32);
        t.push(nh_t as f32);
        t.extend_from_slice(&self.vertical);
        t.extend_from_slice(&self.horizontal);
        if wrap {
            t.push(360.0);
        }
        t.extend(self.candela.iter().map(|c| c * scale));
        if wrap {
            t.extend(self.candela[..nv].iter().map(|c| c * scale));
        }
        self.max_candela = t[2 + nv + nh_t..].iter().fold(0.0f32, |m, &c| m.max(c));
        self.table = t;
    }
}
