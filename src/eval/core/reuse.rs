//! Evaluating once what the clock does not touch. The frames of an animation
//! evaluate the same file with another `clock`; most of a scene (a mesh2
//! terrain in an include file, textures declared once, objects placed by a
//! loop that reads no clock) comes out the same every frame.
//!
//! Each top-level item (the items of an `#include`d file count one by one, the
//! `#include` itself does not) is a *unit*. While a unit is evaluated the
//! evaluator notes what it read and what it did:
//!
//! - the names it read from the scopes open when it began, with the stamp of
//!   the binding found (each write of a binding gives it a new stamp; see
//!   `scope.rs`), and the bindings of those scopes it wrote;
//! - whether it read a per-frame value (`clock`, `clock_delta`, `clock_on`,
//!   `frame_number`, `initial_`/`final_` `clock`/`frame`, `keyframes`,
//!   `camera_path`, the timeline), did file input or output, or reported an
//!   error: then it is *moving* and evaluated again in every frame;
//! - the `rand` streams it used (their states before and after), the built-in
//!   library items it looked at or read (the state of the pending items before
//!   and after, see `lazy.rs`), `#version`, `#default` and `light_group`
//!   changes, the objects and lights it placed, and the messages it reported.
//!
//! A unit that changes the camera, background, global settings, atmosphere or
//! timeline is evaluated every frame (these are cheap). In a later frame a
//! unit is *replayed* when it is not moving and everything it read is as it
//! was (same stamps, same stream states, same pending items, same `#version`,
//! `#default`, light groups and global settings): its writes, placed objects
//! and lights, messages and budget use are put back without evaluating it.
//! Otherwise it is evaluated as usual (and recorded again). The bindings a unit
//! evaluated again writes get new stamps, so what read them is evaluated again
//! too. The result is the scene a full evaluation gives, byte for byte; the
//! command line's `--no-eval-cache` evaluates every item of every frame.

use super::lazy::Pending;
use super::scope::Written;
use super::Evaluator;
use crate::diag::{Diagnostic, Severity};
use crate::scene::{Atmosphere, Camera, Colour, GlobalSettings, Light, Object, Texture, Timeline};
use crate::span::Span;
use crate::syntax::Sym;
use std::rc::Rc;
use std::sync::Arc;

/// What one unit did in the frame it was last evaluated.
pub(crate) struct Record {
    /// The unit's first item.
    span: Span,
    /// Scopes open when it began.
    depth: usize,
    /// Names read: stamp found (0: unbound), whether the read marked it used.
    reads: Vec<(Sym, u64, bool)>,
    /// Bindings written, as left (`None`: removed).
    writes: Vec<Written>,
    /// `rand` stream states before and after, if it used them.
    rand: Option<(Vec<u64>, Vec<u64>)>,
    /// Pending library state before, and the pending items after when changed.
    pending: Option<(u64, Option<Rc<Pending>>)>,
    /// Messages reported, in order (before merging repeats).
    diags: Vec<Diagnostic>,
    /// Objects and lights placed (and the objects' placement numbers).
    objects: Vec<Object>,
    placed: Vec<u64>,
    lights: Vec<Light>,
    /// `#version`, `#default` (its stamp) and light groups before and after.
    before: Ambient,
    after: Ambient,
    /// The default texture after.
    default_texture: Arc<Texture>,
    /// Global settings and timeline when it began.
    global: GlobalSettings,
    animation: Option<Timeline>,
    /// Loop passes, macro calls and image pixels it spent.
    loops: u64,
    macro_calls: u64,
    image_pixels: u64,
}

/// Small evaluator state a unit may read and write.
#[derive(Clone, Copy, PartialEq)]
struct Ambient {
    language_version: Option<f64>,
    default_stamp: u64,
    light_groups: u32,
}

/// Scene state a replayable unit must leave alone.
#[derive(PartialEq)]
struct Settings {
    camera: Camera,
    camera_seen: Option<Span>,
    background: Colour,
    global: GlobalSettings,
    atmosphere: Atmosphere,
    animation: Option<Timeline>,
}

/// The records kept between evaluations, by the unit's place in the order of
/// evaluation.
#[derive(Default)]
pub(crate) struct Records {
    /// The options (less the per-frame ones) the records were made with.
    fingerprint: String,
    units: Vec<Option<Rc<Record>>>,
    /// The next fresh stamp.
    pub(crate) next_stamp: u64,
    /// Units replayed and evaluated, over all evaluations.
    pub(crate) replayed: u64,
    pub(crate) evaluated: u64,
}

/// What the evaluator does with units in this evaluation.
#[derive(Default)]
pub(crate) struct Reuse {
    /// Whether units are journaled and replayed.
    pub(crate) on: bool,
    pub(crate) records: Records,
    /// Units met so far in this evaluation.
    next: usize,
}

/// Evaluator state when a unit began.
struct Start {
    ordinal: usize,
    span: Span,
    depth: usize,
    ambient: Ambient,
    settings: Settings,
    default_texture: Arc<Texture>,
    rand: Vec<u64>,
    pending: u64,
    deprecated: bool,
    objects: usize,
    lights: usize,
    loops: u64,
    macro_calls: u64,
    image_pixels: u64,
}

/// The options with the per-frame ones left out, as text.
fn fingerprint(o: &crate::eval::EvalOptions) -> String {
    let o = crate::eval::EvalOptions {
        clock: 0.0,
        clock_delta: 0.0,
        clock_on: false,
        frame_number: 0.0,
        initial_frame: 0.0,
        final_frame: 0.0,
        initial_clock: 0.0,
        final_clock: 0.0,
        interrupt: Default::default(),
        ..o.clone()
    };
    format!("{o:?}")
}

impl Reuse {
    /// Units off (until [`Evaluator::start_units`]), with `records` from the
    /// last evaluation.
    pub(crate) fn new(records: Records) -> Reuse {
        Reuse {
            on: false,
            records,
            next: 0,
        }
    }
}

impl Records {
    /// Forgets the records when the options changed.
    pub(crate) fn begin(&mut self, options: &crate::eval::EvalOptions) {
        let f = fingerprint(options);
        if f != self.fingerprint {
            self.units.clear();
            self.fingerprint = f;
        }
    }
}

impl Evaluator<'_> {
    /// Notes that the unit being evaluated read a per-frame value (or did
    /// something that is not replayed).
    pub(crate) fn moving(&self) {
        self.moving.set(true);
    }

    fn ambient(&self) -> Ambient {
        Ambient {
            language_version: self.language_version,
            default_stamp: self.default_stamp,
            light_groups: self.light_groups,
        }
    }

    fn settings(&self) -> Settings {
        Settings {
            camera: self.scene.camera.clone(),
            camera_seen: self.camera_seen,
            background: self.scene.background,
            global: self.scene.global.clone(),
            atmosphere: self.scene.atmosphere.clone(),
            animation: self.scene.animation.clone(),
        }
    }

    /// Whether `items` (a top-level item and the texture blocks it takes) are
    /// a unit: journaling is on, no unit is being evaluated, and the item is
    /// not an `#include` (whose items are units themselves).
    pub(crate) fn is_unit(&self, item: &crate::syntax::ast::Item) -> bool {
        use crate::syntax::ast::{DirectiveKind, Item};
        self.reuse.on
            && self.macro_depth == 0
            && !self.scope.journaling()
            && !matches!(item, Item::Directive(d) if matches!(d.kind, DirectiveKind::Include(_)))
    }

    /// Runs the unit starting with the item at `span`: replays its record when
    /// it may, else runs `eval` (which evaluates and places it) and records it.
    // Not inlined: its state would enlarge `expand`'s frame, which deep macro
    // recursion repeats.
    #[inline(never)]
    pub(crate) fn unit(&mut self, span: Span, eval: impl FnOnce(&mut Self)) {
        let ordinal = self.reuse.next;
        self.reuse.next += 1;
        let record = self
            .reuse
            .records
            .units
            .get(ordinal)
            .and_then(Option::as_ref)
            .filter(|r| r.span == span)
            .cloned();
        if let Some(r) = record {
            if self.may_replay(&r) {
                self.replay(&r);
                self.reuse.records.replayed += 1;
                return;
            }
        }
        self.reuse.records.evaluated += 1;
        let start = self.begin_unit(ordinal, span);
        eval(self);
        self.end_unit(start);
    }

    #[inline(never)]
    fn begin_unit(&mut self, ordinal: usize, span: Span) -> Start {
        self.moving.set(false);
        self.pending.touched.set(false);
        self.unit_diags = Some(Vec::new());
        self.scope.begin_journal();
        Start {
            ordinal,
            span,
            depth: self.scope.depth(),
            ambient: self.ambient(),
            settings: self.settings(),
            default_texture: self.default_texture.clone(),
            rand: self.rand_streams.clone(),
            pending: self.pending.state,
            deprecated: !self.deprecated.is_empty(),
            objects: self.scene.objects.len(),
            lights: self.scene.lights.len(),
            loops: self.loop_iterations,
            macro_calls: self.spent.macro_calls,
            image_pixels: self.image_pixels,
        }
    }

    #[inline(never)]
    fn end_unit(&mut self, s: Start) {
        let diags = self.unit_diags.take().unwrap_or_default();
        let Some((journal, writes)) = self.scope.end_journal() else {
            return;
        };
        if !Arc::ptr_eq(&s.default_texture, &self.default_texture) {
            self.default_stamp = self.scope.fresh_stamp();
        }
        let settings = self.settings();
        let cacheable = !self.moving.get()
            && !journal.opaque
            && !self.stopped
            && !s.deprecated
            && self.deprecated.is_empty()
            && self.written.is_empty()
            && self.open_writes.is_empty()
            && self.files_seen.is_empty()
            && !diags.iter().any(|d| d.severity == Severity::Error)
            && self.scope.depth() == s.depth
            && settings == s.settings;
        let units = &mut self.reuse.records.units;
        if units.len() <= s.ordinal {
            units.resize_with(s.ordinal + 1, || None);
        }
        if !cacheable {
            units[s.ordinal] = None;
            return;
        }
        let pending = self.pending.touched.get().then(|| {
            let after = (self.pending.state != s.pending).then(|| Rc::new(self.pending.clone()));
            (s.pending, after)
        });
        let rand = (self.rand_streams != s.rand).then(|| (s.rand, self.rand_streams.clone()));
        let record = Record {
            span: s.span,
            depth: s.depth,
            reads: journal
                .reads
                .iter()
                .map(|(n, (stamp, used))| (*n, *stamp, *used))
                .collect(),
            writes,
            rand,
            pending,
            diags,
            objects: self.scene.objects[s.objects..].to_vec(),
            placed: self.scene.placed[s.objects..].to_vec(),
            lights: self.scene.lights[s.lights..].to_vec(),
            before: s.ambient,
            after: self.ambient(),
            default_texture: self.default_texture.clone(),
            global: s.settings.global,
            animation: s.settings.animation,
            loops: self.loop_iterations - s.loops,
            macro_calls: self.spent.macro_calls - s.macro_calls,
            image_pixels: self.image_pixels - s.image_pixels,
        };
        self.reuse.records.units[s.ordinal] = Some(Rc::new(record));
    }

    /// Whether replaying `r` now gives what evaluating its unit would.
    fn may_replay(&self, r: &Record) -> bool {
        let o = self.options;
        r.depth == self.scope.depth()
            && r.before == self.ambient()
            && self.deprecated.is_empty()
            && self.written.is_empty()
            && self.open_writes.is_empty()
            && self.files_seen.is_empty()
            && r.global == self.scene.global
            && r.animation == self.scene.animation
            && r.rand.as_ref().is_none_or(|(b, _)| *b == self.rand_streams)
            && r.pending
                .as_ref()
                .is_none_or(|(b, _)| *b == self.pending.state)
            && self.loop_iterations + r.loops <= o.max_loop_iterations
            && self.spent.macro_calls + r.macro_calls <= o.max_macro_calls
            && self.image_pixels + r.image_pixels <= o.max_image_pixels
            && r.reads
                .iter()
                .all(|(n, stamp, _)| self.scope.stamp_of(*n) == *stamp)
    }

    /// Puts back what the unit of `r` did.
    fn replay(&mut self, r: &Record) {
        for (n, _, used) in &r.reads {
            if *used {
                self.scope.get(*n);
            }
        }
        for (frame, name, b) in &r.writes {
            self.scope.restore(*frame, *name, b.as_ref());
        }
        if let Some((_, after)) = &r.rand {
            self.rand_streams.clone_from(after);
        }
        if let Some((_, Some(after))) = &r.pending {
            self.pending = (**after).clone();
        }
        for d in &r.diags {
            self.record(d.clone());
        }
        self.scene.objects.extend(r.objects.iter().cloned());
        self.scene.placed.extend_from_slice(&r.placed);
        self.scene.lights.extend(r.lights.iter().cloned());
        self.language_version = r.after.language_version;
        self.default_stamp = r.after.default_stamp;
        self.default_texture = r.default_texture.clone();
        self.light_groups = r.after.light_groups;
        self.loop_iterations += r.loops;
        self.spent.macro_calls += r.macro_calls;
        self.image_pixels += r.image_pixels;
    }
}
