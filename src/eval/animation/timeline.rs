//! `animation { … }` (ours): the timeline a scene carries, so `rts render` renders
//! the sequence without options.
//!
//! ```text
//! animation {
//!   frames 144            // frames 1 … 144   (or `frames 0, 143`: first and last)
//!   fps 24                // frames per second (default 24)
//!   duration 6            // instead of `frames`: seconds; frames = duration · fps + 1
//!                         // (the first frame at 0 s, the last at 6 s; cyclic: no + 1)
//!   clock_range 0, 1      // clock at the first and the last frame (default 0, 1)
//!   cyclic                // POV-Ray's +KC: the last frame stops one step short
//!   motion_blur 0.5, 8    // shutter open half a frame, 8 instants averaged
//! }
//! ```

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::{Evaluator, R};
use crate::scene::Timeline;
use crate::span::Span;

/// Keywords valid in `animation { }`.
pub(crate) const ANIMATION_ITEMS: &[&str] = &[
    "frames",
    "fps",
    "duration",
    "clock_range",
    "cyclic",
    "motion_blur",
];

/// The most frames a timeline may have.
pub const MAX_FRAMES: i64 = 1_000_000;

impl Evaluator<'_> {
    /// The timeline keyframes refer to: the command line's, else the scene's
    /// `animation { }` read so far, else the default (frames 1…1, clock 0…1).
    pub(crate) fn timeline(&self) -> Timeline {
        self.moving();
        self.options
            .timeline
            .clone()
            .or_else(|| self.scene.animation.clone())
            .unwrap_or_default()
    }

    /// Whether the scene is being evaluated with a timeline (from the command
    /// line or an `animation { }` already read).
    pub(crate) fn has_timeline(&self) -> bool {
        self.moving();
        self.options.timeline.is_some() || self.scene.animation.is_some()
    }

    fn positive(&mut self, c: &mut Cursor, what: &str) -> R<(f64, Span)> {
        let (v, s) = c.value(what)?;
        let f = self.to_float(&v, s)?;
        if !(f.is_finite() && f > 0.0) {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                s,
                format!("{what} must be positive, found {f}"),
            )
            .into());
        }
        Ok((f, s))
    }

    fn whole(&mut self, c: &mut Cursor, what: &str) -> R<(i64, Span)> {
        let (v, s) = c.value(what)?;
        let f = self.to_float(&v, s)?;
        if !(f.is_finite() && f.fract() == 0.0 && f.abs() <= MAX_FRAMES as f64) {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                s,
                format!("{what} must be a whole number within ±{MAX_FRAMES}, found {f}"),
            )
            .into());
        }
        Ok((f as i64, s))
    }

    /// `animation { … }` at top level: records the scene's timeline.
    pub(crate) fn animation_block(&mut self, c: &mut Cursor) -> R<()> {
        let mut t = Timeline {
            span: Some(c.span),
            ..Timeline::default()
        };
        let mut duration: Option<(f64, Span)> = None;
        let mut frames_span: Option<Span> = None;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("frames", span) => c.once("frames", span).and_then(|_| {
                    frames_span = Some(span);
                    let (a, sa) = self.whole(c, "the number of frames")?;
                    if matches!(c.peek(), Some(Tok::Comma(_))) {
                        c.comma();
                        let (b, sb) = self.whole(c, "the last frame's number")?;
                        if b < a {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                sb,
                                format!("the last frame ({b}) comes before the first ({a})"),
                            )
                            .with_secondary(sa, "first frame")
                            .with_help("write `frames FIRST, LAST` with FIRST <= LAST")
                            .into());
                        }
                        t.initial_frame = a;
                        t.final_frame = b;
                    } else {
                        if a < 1 {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                sa,
                                format!("an animation needs at least one frame, found {a}"),
                            )
                            .into());
                        }
                        t.initial_frame = 1;
                        t.final_frame = a;
                    }
                    Ok(())
                }),
                Tok::Kw("fps", span) => c.once("fps", span).and_then(|_| {
                    t.fps = self.positive(c, "the frame rate")?.0;
                    Ok(())
                }),
                Tok::Kw("duration", span) => c.once("duration", span).and_then(|_| {
                    duration = Some(self.positive(c, "the duration in seconds")?);
                    Ok(())
                }),
                Tok::Kw("clock_range", span) => c.once("clock_range", span).and_then(|_| {
                    t.initial_clock = self.take_float(c, "the clock at the first frame")?;
                    c.comma();
                    t.final_clock = self.take_float(c, "the clock at the last frame")?;
                    Ok(())
                }),
                Tok::Kw("cyclic", span) => c.once("cyclic", span).map(|_| t.cyclic = true),
                Tok::Kw("motion_blur", span) => c.once("motion_blur", span).and_then(|_| {
                    let (v, s) = c.value("the shutter (a fraction of a frame, 0 to 1)")?;
                    let sh = self.to_float(&v, s)?;
                    if !(0.0..=1.0).contains(&sh) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("the shutter is a fraction of a frame from 0 to 1, found {sh}"),
                        )
                        .into());
                    }
                    t.shutter = sh;
                    if matches!(c.peek(), Some(Tok::Comma(_))) {
                        c.comma();
                        let (n, ns) = self.whole(c, "the number of time samples")?;
                        if !(1..=256).contains(&n) {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                ns,
                                format!("motion blur takes 1 to 256 time samples, found {n}"),
                            )
                            .into());
                        }
                        t.motion_samples = n as u32;
                    }
                    Ok(())
                }),
                other => Err(self.unexpected(c, &other, ANIMATION_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if let Some((d, ds)) = duration {
            if let Some(fs) = frames_span {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    ds,
                    "give either `frames` or `duration`, not both",
                )
                .with_secondary(fs, "frames given here")
                .with_help("`duration` sets the number of frames from the frame rate")
                .into());
            }
            // Frames at 0, 1/fps, … D seconds: both ends, unless cyclic (the
            // frame at D would be the first again).
            let steps = ((d * t.fps).round() as i64).clamp(1, MAX_FRAMES - 1);
            t.initial_frame = 1;
            t.final_frame = steps + i64::from(!t.cyclic);
        }
        if let Some(prev) = self.scene.animation.as_ref().and_then(|a| a.span) {
            self.warn(
                Diagnostic::warning(
                    codes::DUPLICATE_PARAMETER,
                    c.span,
                    "a second `animation { }` replaces the first",
                )
                .with_secondary(prev, "first timeline")
                .with_help("keep one timeline"),
            );
        }
        self.scene.animation = Some(t);
        Ok(())
    }
}
