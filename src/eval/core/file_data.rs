//! The text of `#read` and `#write`: values read from a file (floats as
//! expressions, vectors, strings), floats written as C's `%g`, binary integers.

use super::value::{Value, Vector};
use crate::syntax::ast::BinaryKind;

pub(super) fn skip_separators(data: &[u8], pos: &mut usize) {
    while *pos < data.len() && (data[*pos].is_ascii_whitespace() || data[*pos] == b',') {
        *pos += 1;
    }
}

fn skip_blanks(data: &[u8], pos: &mut usize) {
    while *pos < data.len() && data[*pos].is_ascii_whitespace() {
        *pos += 1;
    }
}

/// The next value of a file being read: `Ok(None)` at the end, `Err((offset, what))`
/// for something that is not a value.
pub(super) fn next_value(data: &[u8], pos: &mut usize) -> Result<Option<Value>, (usize, String)> {
    skip_separators(data, pos);
    let Some(&c) = data.get(*pos) else {
        return Ok(None);
    };
    match c {
        b'"' => {
            let start = *pos;
            *pos += 1;
            let mut s = Vec::new();
            loop {
                match data.get(*pos) {
                    None => return Err((start, "a string without its closing `\"`".into())),
                    Some(b'"') => {
                        *pos += 1;
                        break;
                    }
                    Some(b'\\') if data.get(*pos + 1).is_some() => {
                        let e = data[*pos + 1];
                        s.push(match e {
                            b'n' => b'\n',
                            b't' => b'\t',
                            b'r' => b'\r',
                            other => other,
                        });
                        *pos += 2;
                    }
                    Some(&b) => {
                        s.push(b);
                        *pos += 1;
                    }
                }
            }
            Ok(Some(Value::Str(String::from_utf8_lossy(&s).into())))
        }
        b'<' => {
            *pos += 1;
            let mut comps = Vec::new();
            loop {
                skip_blanks(data, pos);
                if data.get(*pos) == Some(&b'>') {
                    *pos += 1;
                    break;
                }
                if !comps.is_empty() {
                    if data.get(*pos) != Some(&b',') {
                        return Err((*pos, "expected `,` or `>` in a vector".into()));
                    }
                    *pos += 1;
                    skip_blanks(data, pos);
                }
                comps.push(sum(data, pos)?);
                if comps.len() > 5 {
                    return Err((*pos, "a vector has at most 5 components".into()));
                }
            }
            match comps.len() {
                0 | 1 => Err((*pos, "a vector needs 2 to 5 components".into())),
                n => {
                    debug_assert!(n <= 5);
                    Ok(Some(Value::Vector(Vector::from_slice(&comps))))
                }
            }
        }
        _ => sum(data, pos).map(|x| Some(Value::Float(x))),
    }
}

/// Numbers joined by `+ - * /`: POV-Ray reads a float as an expression, so
/// `1e-07 -0` is one value (a difference), while `1 2` are two.
fn sum(data: &[u8], pos: &mut usize) -> Result<f64, (usize, String)> {
    let mut x = product(data, pos)?;
    loop {
        let mut p = *pos;
        skip_blanks(data, &mut p);
        let op = data.get(p).copied();
        if !matches!(op, Some(b'+' | b'-')) {
            return Ok(x);
        }
        p += 1;
        skip_blanks(data, &mut p);
        let y = product(data, &mut p)?;
        *pos = p;
        x = if op == Some(b'+') { x + y } else { x - y };
    }
}

fn product(data: &[u8], pos: &mut usize) -> Result<f64, (usize, String)> {
    let mut x = number(data, pos)?;
    loop {
        let mut p = *pos;
        skip_blanks(data, &mut p);
        let op = data.get(p).copied();
        if !matches!(op, Some(b'*' | b'/')) {
            return Ok(x);
        }
        p += 1;
        skip_blanks(data, &mut p);
        let y = number(data, &mut p)?;
        *pos = p;
        x = if op == Some(b'*') { x * y } else { x / y };
    }
}

/// A number at `pos` (optional sign, digits, fraction, exponent).
fn number(data: &[u8], pos: &mut usize) -> Result<f64, (usize, String)> {
    let start = *pos;
    let mut p = *pos;
    if matches!(data.get(p), Some(b'+' | b'-')) {
        p += 1;
    }
    let digits = |p: &mut usize| {
        let s = *p;
        while data.get(*p).is_some_and(u8::is_ascii_digit) {
            *p += 1;
        }
        *p > s
    };
    let mut any = digits(&mut p);
    if data.get(p) == Some(&b'.') {
        p += 1;
        any |= digits(&mut p);
    }
    if any && matches!(data.get(p), Some(b'e' | b'E')) {
        let mut q = p + 1;
        if matches!(data.get(q), Some(b'+' | b'-')) {
            q += 1;
        }
        if digits(&mut q) {
            p = q;
        }
    }
    let text = std::str::from_utf8(&data[start..p]).unwrap_or("");
    match (any, text.parse::<f64>()) {
        (true, Ok(x)) => {
            *pos = p;
            Ok(x)
        }
        _ => {
            let found: String = String::from_utf8_lossy(&data[start..data.len().min(start + 12)])
                .chars()
                .take_while(|c| *c != '\n')
                .collect();
            Err((start, format!("expected a number, found `{found}`")))
        }
    }
}

/// 1-based line and column of a byte offset.
pub(super) fn line_col(data: &[u8], at: usize) -> (usize, usize) {
    let before = &data[..at.min(data.len())];
    let line = before.iter().filter(|b| **b == b'\n').count() + 1;
    let col = before.iter().rev().take_while(|b| **b != b'\n').count() + 1;
    (line, col)
}

/// C's `%g`: six significant digits, exponent form for very large or small values,
/// trailing zeros removed. POV-Ray writes floats this way.
pub(super) fn format_g(x: f64) -> String {
    if x.is_nan() {
        return "nan".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.into();
    }
    if x == 0.0 {
        return if x.is_sign_negative() { "-0" } else { "0" }.into();
    }
    let e = format!("{x:.5e}");
    let (mant, exp) = e.split_once('e').expect("exponent form");
    let exp: i32 = exp.parse().expect("exponent");
    if !(-4..6).contains(&exp) {
        let mant = trim_zeros(mant);
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{mant}e{sign}{:02}", exp.abs())
    } else {
        let decimals = (5 - exp).max(0) as usize;
        trim_zeros(&format!("{x:.decimals$}")).to_string()
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// Appends `x` as a binary integer of kind `k`, rounded and clamped to its range
/// (POV-Ray's behaviour).
pub(super) fn write_binary(out: &mut Vec<u8>, k: BinaryKind, x: f64) {
    let r = x.round();
    let clamp = |lo: f64, hi: f64| if r.is_nan() { 0.0 } else { r.clamp(lo, hi) };
    match k {
        BinaryKind::U8 => out.push(clamp(0.0, 255.0) as u8),
        BinaryKind::S8 => out.push(clamp(-128.0, 127.0) as i8 as u8),
        BinaryKind::U16Be => out.extend((clamp(0.0, 65535.0) as u16).to_be_bytes()),
        BinaryKind::U16Le => out.extend((clamp(0.0, 65535.0) as u16).to_le_bytes()),
        BinaryKind::S16Be => out.extend((clamp(-32768.0, 32767.0) as i16).to_be_bytes()),
        BinaryKind::S16Le => out.extend((clamp(-32768.0, 32767.0) as i16).to_le_bytes()),
        BinaryKind::S32Be => out.extend((clamp(-2147483648.0, 2147483647.0) as i32).to_be_bytes()),
        BinaryKind::S32Le => out.extend((clamp(-2147483648.0, 2147483647.0) as i32).to_le_bytes()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_are_written_as_c_writes_percent_g() {
        for (x, s) in [
            (1.5, "1.5"),
            (1.0 / 3.0, "0.333333"),
            (123456789.0, "1.23457e+08"),
            (1e-7, "1e-07"),
            (-0.0, "-0"),
            (-4500.0, "-4500"),
            (100000.0, "100000"),
            (1000000.0, "1e+06"),
            (0.0001, "0.0001"),
            (0.00001234, "1.234e-05"),
            (12.0, "12"),
        ] {
            assert_eq!(format_g(x), s, "{x}");
        }
    }

    #[test]
    fn values_are_read_in_order_and_the_end_is_seen_past_trailing_commas() {
        let data = b"1.25, <1,2,3>, \"a\\\"b\", -7\n, 5e1 ,\n";
        let mut pos = 0;
        let mut got = Vec::new();
        while let Some(v) = next_value(data, &mut pos).unwrap() {
            got.push(format!("{v:?}"));
        }
        assert_eq!(got.len(), 5);
        assert!(got[2].contains("a\\\"b"), "{}", got[2]);
        let mut p = 0;
        assert!(next_value(b"  abc", &mut p).is_err());
        // As in POV-Ray, a float is an expression: `1e-07 -0` is one value.
        let mut p = 0;
        let mut n = 0;
        while next_value(b"1.2 1e-07 -0 <1, 2*3> 4/2", &mut p)
            .unwrap()
            .is_some()
        {
            n += 1;
        }
        assert_eq!(n, 4);
    }

    #[test]
    fn binary_integers_are_rounded_and_clamped() {
        let mut out = Vec::new();
        for (k, x) in [
            (BinaryKind::U8, 65.0),
            (BinaryKind::U8, 300.0),
            (BinaryKind::S8, -1.0),
            (BinaryKind::U8, 1.7),
            (BinaryKind::S16Le, -2.0),
            (BinaryKind::U16Be, 258.0),
            (BinaryKind::S32Le, 1.0),
        ] {
            write_binary(&mut out, k, x);
        }
        assert_eq!(
            out,
            [0x41, 0xff, 0xff, 0x02, 0xfe, 0xff, 0x01, 0x02, 0x01, 0, 0, 0]
        );
    }
}
