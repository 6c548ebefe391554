//! Decimal numbers to `f64`, the common case first: a number with at most 15
//! significant digits and a small power of ten (`-3.5200`, `0.941`, `1e-3`) is
//! exactly `digits × 10^e` or `digits ÷ 10^e` in one correctly rounded `f64`
//! operation (both operands are exact doubles). Anything else (more digits, a
//! large exponent) goes to the standard library's parser, which is exact for
//! every input. Both give the same bits; the fast case only skips the general
//! machinery, which mesh data pays once per number.

/// The powers of ten that are exact in an `f64`.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The value of `text`, digits with an optional point and exponent as the
/// grammar's `number` takes them (no sign), or `None` when it is not such a
/// number or does not fit in a finite `f64`.
pub fn parse(text: &str) -> Option<f64> {
    match prefix(text.as_bytes()) {
        Some((end, value)) if end == text.len() => value,
        _ => None,
    }
}

/// The number at the start of `b` as the grammar's `number` reads it (digits
/// with an optional point, then an exponent when digits follow the `e` and
/// its sign): where it ends, and its value (`None` when it does not fit in a
/// finite `f64`). `None` when no number starts there.
pub fn prefix(b: &[u8]) -> Option<(usize, Option<f64>)> {
    let digit = |i: usize| b.get(i).map(|c| c.wrapping_sub(b'0')).filter(|d| *d <= 9);
    let mut mantissa: u64 = 0;
    let mut i = 0;
    while let Some(d) = digit(i) {
        mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
        i += 1;
    }
    let whole = i;
    let mut fraction = 0;
    if b.get(i) == Some(&b'.') {
        i += 1;
        let start = i;
        while let Some(d) = digit(i) {
            mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
            i += 1;
        }
        fraction = i - start;
        if whole == 0 && fraction == 0 {
            return None; // a lone `.`
        }
    } else if whole == 0 {
        return None;
    }
    let mut scale = -(fraction.min(1 << 20) as i32);
    if let Some(b'e' | b'E') = b.get(i) {
        let mut j = i + 1;
        let negative = match b.get(j) {
            Some(b'-') => {
                j += 1;
                true
            }
            Some(b'+') => {
                j += 1;
                false
            }
            _ => false,
        };
        let start = j;
        let mut e: i32 = 0;
        while let Some(d) = digit(j) {
            e = e.saturating_mul(10).saturating_add(i32::from(d));
            j += 1;
        }
        if j > start {
            i = j;
            scale = scale.saturating_add(if negative { -e } else { e });
        }
    }
    // At most 15 digits in all: below 2^53, so exact as an f64, and one
    // multiplication or division by an exact power of ten rounds correctly.
    // (More digits, leading zeros among them, take the general parser.)
    let m = mantissa as f64;
    let fast = match scale {
        _ if whole + fraction > 15 => None,
        0 => Some(m),
        1..=22 => Some(m * POW10[scale as usize]),
        -22..=-1 => Some(m / POW10[(-scale) as usize]),
        _ if mantissa == 0 => Some(0.0),
        _ => None,
    };
    let value = fast.or_else(|| {
        std::str::from_utf8(&b[..i])
            .ok()?
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
    });
    Some((i, value))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fast_case_gives_the_standard_bits() {
        let cases = [
            "0",
            "1",
            "3.5200",
            "0.941",
            ".5",
            "2.",
            "1e2",
            "1E+2",
            "2.5e-3",
            "123456789012345",
            "0.000000000000001",
            "9007199254740991",
            "1e22",
            "1e23",
            "0.1",
            "0.3",
            "1.7976931348623157e308",
            "4.9e-324",
            "12345.678901234567",
            "0e999",
            "000000000000000000001.5",
            "1.0000000000000000000001",
        ];
        for c in cases {
            let want: f64 = c.parse().unwrap();
            assert_eq!(parse(c).map(f64::to_bits), Some(want.to_bits()), "{c}");
        }
    }

    proptest::proptest! {
        #[test]
        fn any_decimal_gives_the_standard_bits(
            whole in "[0-9]{0,12}",
            frac in proptest::option::of("[0-9]{0,12}"),
            exp in proptest::option::of(-40i32..40),
        ) {
            let mut t = whole.clone();
            if let Some(f) = &frac {
                t.push('.');
                t.push_str(f);
            }
            if let Some(e) = exp {
                t.push_str(&format!("e{e}"));
            }
            let want = t.parse::<f64>().ok().filter(|v| v.is_finite());
            proptest::prop_assert_eq!(parse(&t).map(f64::to_bits), want.map(f64::to_bits), "{}", t);
        }
    }

    #[test]
    fn non_numbers_and_overflow_are_refused() {
        for c in ["", ".", "e5", "1e", "1e+", "1x", "2e999", "1.2.3"] {
            assert_eq!(parse(c), None, "{c}");
        }
    }
}
