//! Image file formats, chosen by the output file's extension or `--format`.

use std::path::Path;

/// An image file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// PNG, 8 or 16 bits per channel, gamma-encoded (`.png`).
    Png,
    /// Binary PPM (P6), 8 or 16 bits per channel, gamma-encoded (`.ppm`).
    Ppm,
    /// OpenEXR, 32-bit float linear light (`.exr`).
    Exr,
    /// Radiance RGBE, linear light (`.hdr`).
    Hdr,
}

impl Format {
    /// Every format, in the order help texts list them.
    pub const ALL: [Format; 4] = [Format::Png, Format::Ppm, Format::Exr, Format::Hdr];

    /// The usual file extension, lower case without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Png => "png",
            Format::Ppm => "ppm",
            Format::Exr => "exr",
            Format::Hdr => "hdr",
        }
    }

    /// Whether the file holds linear floating-point light.
    pub fn is_float(self) -> bool {
        matches!(self, Format::Exr | Format::Hdr)
    }

    /// The format `path`'s extension names (any case), if it is one.
    pub fn from_path(path: &Path) -> Option<Format> {
        path.extension()?.to_str()?.parse().ok()
    }
}

/// Why a format name was rejected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseFormatError(pub String);

impl std::fmt::Display for ParseFormatError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "unknown image format `{}`: expected png, ppm, exr or hdr",
            self.0
        )
    }
}

impl std::error::Error for ParseFormatError {}

impl std::str::FromStr for Format {
    type Err = ParseFormatError;

    /// `png`, `ppm` (also `pnm`), `exr` or `hdr`, any case.
    fn from_str(s: &str) -> Result<Format, ParseFormatError> {
        match s.trim().to_ascii_lowercase().as_str() {
            "png" => Ok(Format::Png),
            "ppm" | "pnm" => Ok(Format::Ppm),
            "exr" => Ok(Format::Exr),
            "hdr" => Ok(Format::Hdr),
            _ => Err(ParseFormatError(s.to_string())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn from_extension() {
        assert_eq!(Format::from_path(Path::new("a/b.EXR")), Some(Format::Exr));
        assert_eq!(Format::from_path(Path::new("x.ppm")), Some(Format::Ppm));
        assert_eq!(Format::from_path(Path::new("x.jpg")), None);
        assert_eq!(Format::from_path(Path::new("x")), None);
        for f in Format::ALL {
            assert_eq!(f.extension().parse(), Ok(f));
        }
    }
}
