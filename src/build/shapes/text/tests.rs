use super::*;
use crate::build::shapes::prism::Prism;
use crate::build::Ray;
use glam::DVec3;

/// rts's own test font (see examples/assets/make_rtsblock.py): 1000 units per em;
/// `r` advance 400, xMin 80; `t` advance 400, xMin 40, xMax 360, height 650;
/// `.notdef` a 400 × 700 box with a hole; `r` then `t` kerned by −40.
const BLOCK: &[u8] = include_bytes!("../../../../examples/assets/rtsblock.ttf");

fn block() -> Font {
    Font::parse(BLOCK.to_vec()).expect("test font parses")
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

/// The 2-D bounds of prism curves (end points and control points are enough for
/// the axis-aligned glyphs tested).
fn extent(curves: &[Curve]) -> (DVec2, DVec2) {
    let prism = Prism::new(curves, 0.0, 1.0, false, false);
    let b = prism.bounds();
    (DVec2::new(b.min.x, b.min.z), DVec2::new(b.max.x, b.max.z))
}

#[test]
fn a_hand_made_contour_becomes_closed_prism_curves() {
    // A unit square drawn with a quadratic bulge on top, not closed explicitly.
    let mut b = CurveBuilder::new(0.5);
    b.move_to(0.0, 0.0);
    b.line_to(2.0, 0.0);
    b.line_to(2.0, 2.0);
    b.quad_to(1.0, 4.0, 0.0, 2.0);
    let curves = b.finish();
    assert_eq!(
        curves.len(),
        4,
        "two lines, the curve, and the closing line"
    );
    // Scaled by 0.5 with y negated: the square is x 0..1, z −1..0.
    assert_eq!(curves[0][0], DVec2::new(0.0, 0.0));
    assert_eq!(curves[0][0] + curves[0][1], DVec2::new(1.0, 0.0));
    let q = curves[2];
    let mid = q[0] + q[1] * 0.5 + q[2] * 0.25;
    assert!(close(mid.x, 0.5) && close(mid.y, -1.5), "bulge peak {mid}");
    let last = curves[3];
    assert_eq!(last[0] + last[1], DVec2::ZERO, "closes on its start");
    let prism = Prism::new(&curves, 0.0, 1.0, false, false);
    assert!(prism.inside2(DVec2::new(0.5, -0.5)));
    assert!(prism.inside2(DVec2::new(0.5, -1.4)), "inside the bulge");
    assert!(!prism.inside2(DVec2::new(0.5, -1.6)));
    assert!(!prism.inside2(DVec2::new(1.5, -0.5)));
}

#[test]
fn a_cubic_contour_and_degenerate_pieces() {
    let mut b = CurveBuilder::new(1.0);
    b.move_to(0.0, 0.0);
    b.line_to(0.0, 0.0); // zero length: dropped
    b.curve_to(0.0, 1.0, 1.0, 1.0, 1.0, 0.0);
    b.close();
    b.close(); // twice: nothing more
    let curves = b.finish();
    assert_eq!(curves.len(), 2);
    let c = curves[0];
    let end = c[0] + c[1] + c[2] + c[3];
    assert_eq!(end, DVec2::new(1.0, 0.0));
    let mid = c[0] + c[1] * 0.5 + c[2] * 0.25 + c[3] * 0.125;
    assert!(close(mid.y, -0.75), "cubic midpoint {mid}");
}

#[test]
fn layout_places_glyphs_by_advance_kerning_and_offset() {
    let mut f = block();
    let l = f.layout("rt", DVec2::ZERO);
    assert!(l.missing.is_empty());
    assert_eq!(l.glyphs.len(), 2);
    // The string starts at x = 0: everything moves left by r's xMin (0.08).
    assert!(close(l.glyphs[0].origin.x, -0.08));
    // r advances 0.4, kerned −0.04 before t.
    assert!(close(l.glyphs[1].origin.x, 0.4 - 0.04 - 0.08));
    let (lo, hi) = extent(&l.glyphs[1].curves);
    assert!((lo.x - 0.04).abs() < 1e-6 && (hi.x - 0.36).abs() < 1e-6);
    // Outline `<x, −y>`: t is 0.65 high.
    assert!((lo.y + 0.65).abs() < 1e-6 && hi.y.abs() < 1e-6);

    // "t r": no kerning across the space; the offset adds after every character.
    let l = f.layout("t r", DVec2::new(0.1, 0.2));
    assert_eq!(l.glyphs.len(), 2, "the space has no outline");
    assert!(close(l.glyphs[0].origin.x, -0.04));
    assert!(close(l.glyphs[1].origin.x, 0.4 + 0.1 + 0.25 + 0.1 - 0.04));
    assert!(close(l.glyphs[1].origin.y, 0.4));
}

#[test]
fn repeated_letters_share_one_outline() {
    let mut f = block();
    let l = f.layout("ttt", DVec2::ZERO);
    assert_eq!(l.glyphs.len(), 3);
    assert!(Arc::ptr_eq(&l.glyphs[0].curves, &l.glyphs[2].curves));
}

#[test]
fn missing_characters_are_drawn_as_glyph_zero() {
    let mut f = block();
    let l = f.layout("qЖr", DVec2::ZERO);
    assert_eq!(l.missing, vec!['q', 'Ж']);
    assert_eq!(l.glyphs.len(), 3);
    let (lo, hi) = extent(&l.glyphs[0].curves);
    assert!((hi.x - lo.x - 0.4).abs() < 1e-6 && (lo.y + 0.7).abs() < 1e-6);
    // .notdef's xMin (0.05) starts the string at 0; its advance is 0.5.
    assert!(close(l.glyphs[0].origin.x, -0.05));
    assert!(close(l.glyphs[2].origin.x, 1.0 - 0.05));
}

#[test]
fn the_block_font_renders_as_a_solid_with_a_hole() {
    // o is a ring: a ray through the middle of its hole misses, one through the
    // ring hits the front face at z = 0.
    let mut f = block();
    let l = f.layout("o", DVec2::ZERO);
    let g = &l.glyphs[0];
    let prism = Prism::new(&g.curves, 0.0, 0.5, false, false);
    let place = glyph_placement(g.origin);
    let inv = place.inverse();
    let trace = |o: DVec3| {
        let ray = Ray::new(inv.transform_point3(o), inv.transform_vector3(DVec3::Z));
        prism.nearest(&ray, 0.0, f64::INFINITY).map(|(t, _)| t)
    };
    // Centre of o: x 0.25 − 0.04 (shift), y 0.25.
    assert_eq!(trace(DVec3::new(0.21, 0.25, -1.0)), None);
    let t = trace(DVec3::new(0.21 - 0.16, 0.25, -1.0)).expect("ring");
    assert!((t - 1.0).abs() < 1e-9, "front face at z = 0, t = {t}");
    assert!(prism.inside(inv.transform_point3(DVec3::new(0.05, 0.25, 0.25))));
    assert!(!prism.inside(inv.transform_point3(DVec3::new(0.05, 0.25, 0.75))));
}

#[test]
fn bad_and_truncated_fonts_are_errors_not_panics() {
    assert!(Font::parse(Vec::new()).is_err());
    assert!(Font::parse(b"not a font at all".to_vec()).is_err());
    for n in (0..BLOCK.len()).step_by(7) {
        if let Ok(mut f) = Font::parse(BLOCK[..n].to_vec()) {
            let _ = f.layout("rtso xq", DVec2::ZERO);
        }
    }
    let mut bytes = BLOCK.to_vec();
    for i in (40..bytes.len()).step_by(13) {
        bytes[i] ^= 0x5a;
    }
    if let Ok(mut f) = Font::parse(bytes) {
        let _ = f.layout("rtso xq", DVec2::ZERO);
    }
}

/// POV-Ray's own font, when installed (CI machines have none: the test then
/// does nothing). Numbers measured with POV-Ray 3.7: `trace` and `max_extent`
/// of `text { ttf "timrom.ttf" "H" 1, 0 }` give an H 0.711 wide and 0.680 high
/// from x = 0, its left stem's inner edge at x = 0.096 (y = 0.3), and "HH"'s
/// second H 0.751 further right; "AV" is kerned to 1.278 wide.
#[test]
fn timrom_matches_povray_when_installed() {
    let Ok(data) = std::fs::read("/usr/share/povray-3.7/include/timrom.ttf") else {
        return;
    };
    let mut f = Font::parse(data).expect("timrom parses");
    let l = f.layout("HH", DVec2::ZERO);
    let width = |g: &PlacedGlyph| {
        let (lo, hi) = extent(&g.curves);
        (g.origin.x + lo.x, g.origin.x + hi.x, -lo.y)
    };
    let (x0, x1, h) = width(&l.glyphs[0]);
    assert!(x0.abs() < 1e-6 && (x1 - 0.711).abs() < 1e-6 && (h - 0.68).abs() < 1e-6);
    let (x0, x1, _) = width(&l.glyphs[1]);
    assert!((x0 - 0.751).abs() < 1e-6 && (x1 - 1.462).abs() < 1e-6);
    let l = f.layout("AV", DVec2::ZERO);
    let (_, x1, _) = width(&l.glyphs[1]);
    assert!((x1 - 1.278).abs() < 1e-6, "AV ends at {x1}");
}
