//! Readers of what a scene sets once rather than places: the camera (and
//! `mesh_camera`), `global_settings` and the background, light sources, the
//! atmosphere (sky sphere, fog, rainbow), media, photons, radiosity and the
//! path tracer's settings.

pub(crate) mod atmosphere;
pub(crate) mod camera;
pub(crate) mod lights;
pub(crate) mod media;
pub(crate) mod mesh_camera;
pub(crate) mod path_tracing;
pub(crate) mod photons;
pub(crate) mod radiosity;
