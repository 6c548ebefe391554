//! Counters of rays traced, kept per task and summed, so they are the same for any
//! number of threads.

use std::ops::AddAssign;

/// How many rays of each kind were traced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayStats {
    /// Rays from the camera.
    pub camera: u64,
    /// Mirror-reflected rays.
    pub reflected: u64,
    /// Refracted or transmitted rays.
    pub transmitted: u64,
    /// Shadow rays towards lights.
    pub shadow: u64,
    /// Radiosity's gathering rays.
    pub radiosity: u64,
}

impl RayStats {
    /// All rays together.
    pub fn total(&self) -> u64 {
        self.camera + self.reflected + self.transmitted + self.shadow + self.radiosity
    }
}

impl AddAssign for RayStats {
    fn add_assign(&mut self, o: RayStats) {
        self.camera += o.camera;
        self.reflected += o.reflected;
        self.transmitted += o.transmitted;
        self.shadow += o.shadow;
        self.radiosity += o.radiosity;
    }
}
