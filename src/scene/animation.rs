//! The timeline of an animated scene: which frames exist and the `clock` value of
//! each, as POV-Ray defines them (`Initial_Frame`, `Final_Frame`, `Initial_Clock`,
//! `Final_Clock`, `Cyclic_Animation`), plus the frame rate (ours).

use crate::span::Span;

/// Frames per second when neither the scene nor the command line says.
pub const DEFAULT_FPS: f64 = 24.0;

/// A scene's timeline: written in the file as `animation { … }` and overridden by
/// the command line.
#[derive(Clone, Debug, PartialEq)]
pub struct Timeline {
    /// First frame number (POV-Ray's `Initial_Frame`, `+KFI`).
    pub initial_frame: i64,
    /// Last frame number (POV-Ray's `Final_Frame`, `+KFF`).
    pub final_frame: i64,
    /// `clock` at the first frame (`Initial_Clock`, `+KI`).
    pub initial_clock: f64,
    /// `clock` at the last frame (`Final_Clock`, `+KF`); with `cyclic`, at the
    /// frame after the last, so the last frame is not a copy of the first.
    pub final_clock: f64,
    /// Frames per second (for keys in seconds and for GIF/APNG/MP4 timing).
    pub fps: f64,
    /// POV-Ray's `Cyclic_Animation` (`+KC`).
    pub cyclic: bool,
    /// Motion blur: the shutter stays open for this fraction of the time from one
    /// frame to the next, starting at the frame's time (0: no motion blur).
    pub shutter: f64,
    /// Motion blur: how many instants within the shutter interval are rendered and
    /// averaged.
    pub motion_samples: u32,
    /// Where the scene declared it, if it did.
    pub span: Option<Span>,
}

impl Default for Timeline {
    fn default() -> Self {
        Timeline {
            initial_frame: 1,
            final_frame: 1,
            initial_clock: 0.0,
            final_clock: 1.0,
            fps: DEFAULT_FPS,
            cyclic: false,
            shutter: 0.0,
            motion_samples: 8,
            span: None,
        }
    }
}

impl Timeline {
    /// How many frames the timeline has.
    pub fn frame_count(&self) -> i64 {
        (self.final_frame - self.initial_frame + 1).max(0)
    }

    /// The denominator of POV-Ray's clock formula: frame steps from the first frame
    /// to the frame whose clock is `final_clock`.
    fn steps(&self) -> i64 {
        self.final_frame - self.initial_frame + i64::from(self.cyclic)
    }

    /// `clock` at `frame`: `initial_clock + (final_clock - initial_clock) ·
    /// (frame - initial_frame) / (final_frame - initial_frame [+ 1 when cyclic])`.
    pub fn clock_of(&self, frame: i64) -> f64 {
        let steps = self.steps();
        if steps <= 0 {
            return self.initial_clock;
        }
        let f = (frame - self.initial_frame) as f64 / steps as f64;
        self.initial_clock + (self.final_clock - self.initial_clock) * f
    }

    /// `clock` at a fractional frame (used for motion-blur time samples).
    pub fn clock_at(&self, frame: f64) -> f64 {
        let steps = self.steps();
        if steps <= 0 {
            return self.initial_clock;
        }
        let f = (frame - self.initial_frame as f64) / steps as f64;
        self.initial_clock + (self.final_clock - self.initial_clock) * f
    }

    /// `clock_delta`: the clock step between two frames (0 for a single frame).
    pub fn clock_delta(&self) -> f64 {
        let steps = self.steps();
        if steps <= 0 {
            0.0
        } else {
            (self.final_clock - self.initial_clock) / steps as f64
        }
    }

    /// The clock value `seconds` after the first frame.
    pub fn clock_of_seconds(&self, seconds: f64) -> f64 {
        self.clock_at(self.initial_frame as f64 + seconds * self.fps)
    }

    /// The clock value of a (possibly fractional) frame number.
    pub fn clock_of_frame(&self, frame: f64) -> f64 {
        self.clock_at(frame)
    }

    /// `final_frame` as the scene sees it: POV-Ray reports one more when cyclic.
    pub fn reported_final_frame(&self) -> i64 {
        self.final_frame + i64::from(self.cyclic)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clock_matches_povray() {
        // povray +KFI1 +KFF5 +SF3 +EF3: clock 0.5, clock_delta 0.25.
        let t = Timeline {
            final_frame: 5,
            ..Timeline::default()
        };
        assert_eq!(t.clock_of(3), 0.5);
        assert_eq!(t.clock_delta(), 0.25);
        // With +KC: clock 0.4, clock_delta 0.2, final_frame reported as 6.
        let c = Timeline {
            cyclic: true,
            ..t.clone()
        };
        assert!((c.clock_of(3) - 0.4).abs() < 1e-12);
        assert!((c.clock_delta() - 0.2).abs() < 1e-12);
        assert_eq!(c.reported_final_frame(), 6);
        // +KFI0 +KFF4 +KI2 +KF3, frame 4: clock 3, clock_delta 0.25.
        let k = Timeline {
            initial_frame: 0,
            final_frame: 4,
            initial_clock: 2.0,
            final_clock: 3.0,
            ..Timeline::default()
        };
        assert_eq!(k.clock_of(4), 3.0);
        assert_eq!(k.clock_delta(), 0.25);
        assert_eq!(k.frame_count(), 5);
    }
}
