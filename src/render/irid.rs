//! `irid { }`: thin-film interference. The light reaching a surface is tinted by
//! `1 + amount · cos(phase / period)` per colour channel, the phase growing with
//! the film's thickness and the cosines of the light's and the viewer's angles
//! of incidence. The periods were measured on POV-Ray 3.7 renders (default
//! `irid_wavelength`): a film of thickness 0.36, 0.26 and 0.24 seen and lit
//! head-on brings red, green and blue back to their start.

use crate::pattern::noise::turbulence;
use crate::scene::Finish;
use glam::DVec3;
use std::f64::consts::PI;

/// The thickness (head-on, lit head-on) at which each channel's interference
/// completes one cycle.
const PERIOD: DVec3 = DVec3::new(0.36, 0.26, 0.24);

/// The colour `light` of a light seen through `f`'s iridescent film at texture
/// point `tp`, for unit normal `n`, unit direction `l` to the light and unit ray
/// direction `d`; `light` itself when the finish has no `irid`.
pub fn tint(f: &Finish, light: DVec3, n: DVec3, l: DVec3, d: DVec3, tp: DVec3) -> DVec3 {
    let irid = &f.irid;
    if irid.amount == 0.0 {
        return light;
    }
    let mut thickness = irid.thickness;
    if irid.turbulence != 0.0 {
        thickness *= turbulence(tp, 5, 0.5, 2.0) * irid.turbulence;
    }
    let cosines = n.dot(l).abs() + n.dot(d).abs();
    let phase = PI * thickness * cosines;
    let k = DVec3::new(
        (phase / PERIOD.x).cos(),
        (phase / PERIOD.y).cos(),
        (phase / PERIOD.z).cos(),
    );
    light * (DVec3::ONE + irid.amount * k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Irid;

    #[test]
    fn head_on_film_cycles_with_the_measured_periods() {
        let f = Finish {
            irid: Irid {
                amount: 1.0,
                thickness: 0.18,
                turbulence: 0.0,
            },
            ..Finish::default()
        };
        let c = tint(
            &f,
            DVec3::ONE,
            DVec3::NEG_Z,
            DVec3::NEG_Z,
            DVec3::Z,
            DVec3::ZERO,
        );
        // Half of red's period: red is gone.
        assert!(c.x.abs() < 1e-9, "{c}");
        let plain = Finish::default();
        assert_eq!(
            tint(
                &plain,
                DVec3::ONE,
                DVec3::Z,
                DVec3::Z,
                DVec3::Z,
                DVec3::ZERO
            ),
            DVec3::ONE
        );
    }
}
