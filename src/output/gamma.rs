//! Transfer functions between working colours and file values.

/// How file values encode linear light.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Gamma {
    /// The sRGB curve (POV-Ray 3.7's default `File_Gamma` for PNG: a flat 0.5 grey
    /// under `assumed_gamma 1.0` is written as 188/255, 48192/65535).
    #[default]
    Srgb,
    /// A pure power law: the file holds `linear^(1/g)`; `Power(1.0)` is linear.
    Power(f64),
}

impl Gamma {
    /// Linear light in [0, 1] to a file value in [0, 1].
    pub fn encode(self, linear: f64) -> f64 {
        let v = linear.clamp(0.0, 1.0);
        match self {
            Gamma::Srgb if v <= 0.0031308 => 12.92 * v,
            Gamma::Srgb if v >= 1.0 => 1.0,
            Gamma::Srgb => 1.055 * v.powf(1.0 / 2.4) - 0.055,
            Gamma::Power(1.0) => v,
            Gamma::Power(g) => v.powf(1.0 / g),
        }
    }
}

/// Why a `--gamma` value was rejected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseGammaError(pub String);

impl std::fmt::Display for ParseGammaError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "invalid gamma `{}`: expected `srgb` or a positive number",
            self.0
        )
    }
}

impl std::error::Error for ParseGammaError {}

impl std::str::FromStr for Gamma {
    type Err = ParseGammaError;

    /// `srgb` (any case) or a positive number such as `1.0` or `2.2`.
    fn from_str(s: &str) -> Result<Gamma, ParseGammaError> {
        let t = s.trim();
        if t.eq_ignore_ascii_case("srgb") {
            return Ok(Gamma::Srgb);
        }
        match t.parse::<f64>() {
            Ok(g) if g.is_finite() && g > 0.0 => Ok(Gamma::Power(g)),
            _ => Err(ParseGammaError(s.to_string())),
        }
    }
}

/// A working-space value under `assumed_gamma` (`None` meaning 1.0, as POV-Ray 3.7
/// does when the scene says nothing) to linear light; negatives become 0.
pub fn decode_working(value: f64, assumed_gamma: Option<f64>) -> f64 {
    let v = value.max(0.0);
    match assumed_gamma {
        None => v,
        Some(1.0) => v,
        Some(g) => v.powf(g),
    }
}

/// The file value in [0, 1] for working value `value`:
/// `encode(decode_assumed(value))`, clamped.
pub fn to_file(value: f64, assumed_gamma: Option<f64>, gamma: Gamma) -> f64 {
    gamma
        .encode(decode_working(value, assumed_gamma).min(1.0))
        .clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn povray_grey_values() {
        // POV-Ray 3.7, `rgb 0.5`, ambient 1, default File_Gamma:
        // assumed_gamma 1.0 → 188 (8-bit) / 48192 (16-bit); assumed_gamma 2.2 → 128.
        let q8 = |v: f64| (v * 255.0).round() as u8;
        let q16 = |v: f64| (v * 65535.0).round() as u16;
        assert_eq!(q8(to_file(0.5, Some(1.0), Gamma::Srgb)), 188);
        assert_eq!(q16(to_file(0.5, Some(1.0), Gamma::Srgb)), 48192);
        assert_eq!(q8(to_file(0.5, None, Gamma::Srgb)), 188);
        assert_eq!(q8(to_file(0.5, Some(2.2), Gamma::Srgb)), 128);
        // File_Gamma 1.0 gives linear values: 128 and, under assumed_gamma 2.2, 55.
        assert_eq!(q8(to_file(0.5, Some(1.0), Gamma::Power(1.0))), 128);
        assert_eq!(q8(to_file(0.5, Some(2.2), Gamma::Power(1.0))), 55);
        // File_Gamma 2.2 → 186.
        assert_eq!(q8(to_file(0.5, Some(1.0), Gamma::Power(2.2))), 186);
    }

    #[test]
    fn parses() {
        assert_eq!("sRGB".parse(), Ok(Gamma::Srgb));
        assert_eq!("1.0".parse(), Ok(Gamma::Power(1.0)));
        assert_eq!(" 2.2".parse(), Ok(Gamma::Power(2.2)));
        assert!("0".parse::<Gamma>().is_err());
        assert!("linear"
            .parse::<Gamma>()
            .unwrap_err()
            .to_string()
            .contains("linear"));
    }

    #[test]
    fn clamps() {
        assert_eq!(to_file(-3.0, None, Gamma::Srgb), 0.0);
        assert_eq!(to_file(7.0, Some(2.2), Gamma::Srgb), 1.0);
        assert_eq!(to_file(f64::NAN, None, Gamma::Power(1.0)), 0.0);
    }
}
