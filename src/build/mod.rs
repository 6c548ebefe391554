//! Turns a [`Scene`] into a [`World`]: a flat list of primitives with resolved
//! transforms and textures, and a BVH over the bounded ones.
//!
//! Texture space: a texture is evaluated in the object space of the object that
//! owns it (the leaf itself, or the nearest enclosing union a texture was inherited
//! from), then through the pigment's own transform. So a union's texture does not
//! move with its children's own transforms, as in POV-Ray.

mod aabb;
pub mod accel;
pub mod csg;
pub mod mesh;
pub mod quartic;
mod ray;
mod shape;
pub mod shapes;
mod transparency;

pub use aabb::Aabb;
pub use accel::Bvh;
pub use ray::{surface_offset, Ray};
pub use shape::{Hit, PrimShape, Primitive, ShapeHit, SmoothTriangle};

use crate::scene::{
    Camera, CsgOp, GlobalSettings, Interior, Light, MeshData, Object, ObjectFlags, Scene, Shape,
    TextData, Texture, Transform,
};
use csg::{Csg, CsgLeaf, CsgNode, GroupKind};
use glam::{DMat4, DVec2, DVec3};
use mesh::MeshAccel;
use rustc_hash::FxHashMap;
use shapes::flat::Polygon;
use shapes::quadric::Frustum;
use std::sync::Arc;

/// What a ray is for, which decides the objects it can see.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    /// From the camera: `no_image` objects are invisible.
    Camera,
    /// A reflected ray: `no_reflection` objects are invisible.
    Reflected,
    /// A shadow ray: `no_shadow` objects are invisible.
    Shadow,
    /// A probe from the scene language (`trace`): every object is seen.
    Probe,
    /// Radiosity's gathering: `no_radiosity` objects are invisible.
    Radiosity,
}

impl RayKind {
    /// Whether an object with `flags` can be hit by this kind of ray.
    #[inline]
    pub fn sees(self, flags: &ObjectFlags) -> bool {
        match self {
            RayKind::Camera => !flags.no_image,
            RayKind::Reflected => !flags.no_reflection,
            RayKind::Shadow => !flags.no_shadow,
            RayKind::Probe => true,
            RayKind::Radiosity => !flags.no_radiosity,
        }
    }
}

/// A scene ready for rendering: immutable, `Send + Sync`.
#[derive(Clone, Debug)]
pub struct World {
    /// The camera.
    pub camera: Camera,
    /// Light sources.
    pub lights: Vec<Light>,
    /// Per light, the built `projected_through` object (see
    /// [`crate::scene::Light::projected_through`]); `None` for most lights.
    pub light_masks: Vec<Option<Arc<World>>>,
    /// Colour of rays that hit nothing.
    pub background: DVec3,
    /// Global settings.
    pub global: GlobalSettings,
    /// `sky_sphere` and `fog`.
    pub atmosphere: crate::scene::Atmosphere,
    /// Every primitive, bounded ones first.
    pub primitives: Arc<Vec<Primitive>>,
    /// Indices of the unbounded primitives (planes), tested on every ray.
    pub unbounded: Vec<u32>,
    /// Hierarchy over the bounded primitives.
    pub bvh: Bvh,
    /// Bounds of all bounded primitives (empty when there are none).
    pub bounds: Aabb,
    /// Whether any surface may let light through (filter, transmit or an image
    /// map in any texture layer): when not, a blocked shadow ray is dark.
    pub transparent: bool,
    /// Per primitive, whether it may let light through (see `transparent`).
    pub translucent: Vec<bool>,
    /// Whether there are media anywhere (atmospheric or in an interior).
    pub has_media: bool,
    /// Whether some interior holds media.
    pub object_media: bool,
    /// Whether rays keep track of the objects they are in (there are media or
    /// fog, which only act where every such object is hollow).
    pub tracks_interiors: bool,
    /// The primitives whose inside holds the camera's location (when
    /// `tracks_interiors` or `transparent`: media and indices of refraction).
    pub camera_inside: Vec<u32>,
}

/// Flattens `scene` and builds its acceleration structure. Unions are flattened
/// into their members; `merge`, `intersection`, `difference` and clipped objects
/// become one CSG primitive each; every distinct mesh gets one hierarchy, shared
/// by all objects that use it (instances).
pub fn build(scene: &Scene) -> World {
    build_cached(scene, &mut BuildCache::default())
}

/// Hierarchies kept from one build to the next (the frames of an animation),
/// in two levels. Below, a mesh that is the same `Arc` as in the previous
/// build keeps its BVH (every object using it is an instance of it). Above,
/// the hierarchy over the world's primitives: kept whole while their bounds are
/// the same bits in the same order (objects that do not move, seen by a moving
/// camera); when only some move, the ones whose bounds stayed the same keep a
/// tree of their own, built once, and only the moving ones' tree is built
/// again, the two joined under one root ([`Bvh::join`]). Which tree a frame
/// uses does not change its picture: at equal distances the hit goes to the
/// primitive first in the world, whatever order a tree visits them in
/// ([`World::intersect_among`]).
///
/// The primitives made of a top-level object are kept too: an object that a
/// later frame reuses unevaluated (the same [`Scene::placed`] number) has them
/// copied, not made again, and when every object is reused the list is shared.
#[derive(Default)]
pub struct BuildCache {
    meshes: FxHashMap<usize, Arc<MeshAccel>>,
    /// What the previous build made of each top-level object.
    made: Option<Made>,
    /// An empty list with room, for the next build's primitives.
    spare: Vec<Primitive>,
    /// The bounded primitives of the previous build and its hierarchy.
    top: Option<(Vec<(u32, Aabb)>, Bvh)>,
    /// The primitives that stood still in the previous build, and their tree.
    still: Option<(Vec<(u32, Aabb)>, Bvh)>,
    /// The glyph prisms of the previous build (see [`Builder::glyphs`]).
    glyphs: GlyphPrisms,
}

/// How many glyph prisms a [`BuildCache`] keeps at most.
const KEPT_GLYPHS: usize = 4096;

/// Glyph prisms by outline address and heights, each with its outline (held,
/// so the address stays that outline's while the entry lives).
type GlyphPrisms = FxHashMap<(usize, u64, u64), (Arc<[[DVec2; 4]]>, Arc<shapes::prism::Prism>)>;

/// The primitives of a build, by the top-level object they were made of.
struct Made {
    /// The objects' placement numbers ([`Scene::placed`]), in order.
    placed: Vec<u64>,
    /// Where each placement number is in `placed`.
    index: FxHashMap<u64, u32>,
    /// Per object: its bounded primitives (start, count) and its unbounded
    /// ones (start, count) in `prims`.
    ranges: Vec<[u32; 4]>,
    /// Per object: the meshes it used (their data's addresses).
    meshes: Vec<Box<[usize]>>,
    /// The world's primitives (bounded first, each part in file order), and
    /// which of them may let light through.
    prims: Arc<Vec<Primitive>>,
    translucent: Vec<bool>,
}

/// Fewest primitives standing still for the world's tree to come in two
/// levels; below, building it whole costs next to nothing.
const TWO_LEVEL_MIN: usize = 64;

/// The hierarchy over `items` (this build's bounded primitives), reusing what
/// `cache` holds from the previous build (see [`BuildCache`]); leaves the
/// cache ready for the next.
fn world_tree(items: Vec<(u32, Aabb)>, cache: &mut BuildCache) -> Bvh {
    let previous = cache.top.take();
    let still = cache.still.take();
    let bvh = match &previous {
        Some((old, bvh)) if same_bounds(old, &items) => {
            cache.still = still;
            bvh.clone()
        }
        Some((old, _)) if old.len() == items.len() => {
            let (standing, moving): (Vec<_>, Vec<_>) =
                items.iter().zip(old).partition(|(x, y)| same_item(x, y));
            let standing: Vec<(u32, Aabb)> = standing.into_iter().map(|(x, _)| *x).collect();
            let moving: Vec<(u32, Aabb)> = moving.into_iter().map(|(x, _)| *x).collect();
            // Two levels pay when most of the world stands still.
            if standing.len() >= TWO_LEVEL_MIN && moving.len() * 4 <= standing.len() {
                let tree = match still {
                    Some((kept, tree)) if same_bounds(&kept, &standing) => tree,
                    _ => Bvh::build(&standing),
                };
                let joined = tree.join(&Bvh::build(&moving));
                cache.still = Some((standing, tree));
                joined.unwrap_or_else(|| Bvh::build(&items))
            } else {
                Bvh::build(&items)
            }
        }
        _ => Bvh::build(&items),
    };
    cache.top = Some((items, bvh.clone()));
    bvh
}

/// Whether two primitives' bounds are the same bits for the same index.
fn same_item((i, x): &(u32, Aabb), (j, y): &(u32, Aabb)) -> bool {
    let bits = |x: &Aabb| {
        let (lo, hi) = (x.min.to_array(), x.max.to_array());
        [lo, hi].map(|v| v.map(f64::to_bits))
    };
    i == j && bits(x) == bits(y)
}

/// Whether two lists of primitive bounds are the same bits (a hierarchy built
/// over one is the hierarchy built over the other).
fn same_bounds(a: &[(u32, Aabb)], b: &[(u32, Aabb)]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same_item(x, y))
}

/// [`build`], reusing the mesh hierarchies of the previous build in `cache`.
pub fn build_cached(scene: &Scene, cache: &mut BuildCache) -> World {
    let mut b = Builder {
        previous: std::mem::take(&mut cache.meshes),
        previous_glyphs: std::mem::take(&mut cache.glyphs),
        ..Builder::default()
    };
    let default_texture = Arc::new(Texture::default());
    let inherited = Inherited {
        texture: default_texture,
        texture_space: None,
        interior: None,
        flags: ObjectFlags::default(),
    };
    let known = scene.placed.len() == scene.objects.len();
    let mut previous = cache.made.take().filter(|_| known);
    // Every object as in the previous build: its primitives, shared. Or the
    // same objects in the same places but a few placed again (the moving
    // ones), each into as many primitives as before: those are written over
    // in the list no world holds any more.
    let same = previous.as_mut().is_some_and(|m| {
        if m.placed == scene.placed {
            for keys in &m.meshes {
                b.keep_meshes(keys);
            }
            true
        } else {
            b.update_in_place(scene, &inherited, m)
        }
    });
    let (prims, translucent, made) = match previous {
        Some(m) if same => (m.prims.clone(), m.translucent.clone(), m),
        previous => {
            let spare = std::mem::take(&mut cache.spare);
            let made = b.flatten_all(scene, &inherited, previous.as_ref(), spare);
            // The previous list's memory takes the next build's primitives
            // (a fresh one would be paged in again every frame).
            if let Some(mut v) = previous.and_then(|m| Arc::try_unwrap(m.prims).ok()) {
                v.clear();
                cache.spare = v;
            }
            (made.prims.clone(), made.translucent.clone(), made)
        }
    };
    if known {
        cache.made = Some(made);
    }
    // The glyphs used now, and as many of the others as fit under the cap
    // (a text made again and again keeps its letters between builds).
    let mut glyphs = std::mem::take(&mut b.glyphs);
    for (k, v) in b.previous_glyphs.drain() {
        if glyphs.len() >= KEPT_GLYPHS {
            break;
        }
        glyphs.entry(k).or_insert(v);
    }
    cache.glyphs = glyphs;
    cache.meshes = b
        .meshes
        .iter()
        .map(|(k, v)| (*k as usize, v.clone()))
        .collect();
    let items: Vec<(u32, Aabb)> = prims
        .iter()
        .enumerate()
        .filter_map(|(i, p)| p.bounds.map(|b| (i as u32, b)))
        .collect();
    let unbounded = (items.len() as u32..prims.len() as u32).collect();
    let bvh = world_tree(items, cache);
    let with_media = |i: &Option<Arc<Interior>>| i.as_ref().is_some_and(|i| !i.media.is_empty());
    let object_media = prims.iter().any(|p| {
        with_media(&p.interior)
            || matches!(&p.shape, PrimShape::Csg(c) if c.leaves.iter().any(|l| with_media(&l.interior)))
    });
    let has_media = object_media || !scene.atmosphere.media.is_empty();
    let tracks_interiors =
        has_media || !scene.atmosphere.fogs.is_empty() || !scene.atmosphere.rainbows.is_empty();
    let mut world = World {
        camera: scene.camera.clone(),
        lights: scene.lights.clone(),
        light_masks: light_masks(scene),
        background: scene.background.rgb,
        global: scene.global.clone(),
        atmosphere: scene.atmosphere.clone(),
        bounds: bvh.bounds(),
        transparent: translucent.iter().any(|&t| t),
        translucent,
        primitives: prims,
        unbounded,
        bvh,
        has_media,
        object_media,
        tracks_interiors,
        camera_inside: Vec::new(),
    };
    // Also for refraction: a camera inside glass sees out through its index.
    if tracks_interiors || world.transparent {
        let at = world.camera.location;
        world.camera_inside = (0..world.primitives.len() as u32)
            .filter(|&i| {
                let p = &world.primitives[i as usize];
                p.bounds
                    .is_none_or(|b| at.cmpge(b.min).all() && at.cmple(b.max).all())
                    && p.inside(at)
            })
            .collect();
    }
    world
}

/// The `projected_through` objects of `scene`'s lights, each built on its own.
fn light_masks(scene: &Scene) -> Vec<Option<Arc<World>>> {
    scene
        .lights
        .iter()
        .map(|l| {
            l.projected_through.as_ref().map(|o| {
                let only = Scene {
                    objects: vec![(**o).clone()],
                    ..Scene::default()
                };
                Arc::new(build(&only))
            })
        })
        .collect()
}

/// What a child takes from its enclosing objects.
#[derive(Clone)]
struct Inherited {
    texture: Arc<Texture>,
    /// `world_from_owner` of the object the texture belongs to.
    texture_space: Option<Transform>,
    interior: Option<Arc<Interior>>,
    flags: ObjectFlags,
}

fn or_flags(a: ObjectFlags, b: ObjectFlags) -> ObjectFlags {
    ObjectFlags {
        no_shadow: a.no_shadow || b.no_shadow,
        no_image: a.no_image || b.no_image,
        no_reflection: a.no_reflection || b.no_reflection,
        inverse: a.inverse != b.inverse,
        hollow: a.hollow || b.hollow,
        double_illuminate: a.double_illuminate || b.double_illuminate,
        no_radiosity: a.no_radiosity || b.no_radiosity,
        // A CSG child's own importance wins over its parent's.
        importance: b.importance.or(a.importance),
        // Nested groups inherit the outer groups' lights; the innermost group
        // says whether the scene's lights count too.
        light_groups: a.light_groups | b.light_groups,
        global_lights: b.global_lights.or(a.global_lights),
        photons: crate::scene::ObjectPhotons::inherit(a.photons, b.photons),
    }
}

/// Collects primitives; keeps one hierarchy per distinct mesh.
#[derive(Default)]
struct Builder {
    prims: Vec<Primitive>,
    meshes: FxHashMap<*const MeshData, Arc<MeshAccel>>,
    /// Hierarchies of the previous build, by mesh address.
    previous: FxHashMap<usize, Arc<MeshAccel>>,
    /// Glyph prisms by outline address and heights, shared by repeated letters.
    glyphs: GlyphPrisms,
    /// The glyph prisms of earlier builds, taken over when used again (letters
    /// made again and again, measured with `min_extent` each time, or a union
    /// that `trace` builds again as it grows, keep their prisms).
    previous_glyphs: GlyphPrisms,
    /// The meshes (data addresses) used since last taken.
    used: Vec<usize>,
}

impl Builder {
    fn mesh(&mut self, m: &Arc<MeshData>) -> Arc<MeshAccel> {
        self.used.push(Arc::as_ptr(m) as usize);
        self.meshes
            .entry(Arc::as_ptr(m))
            .or_insert_with(|| {
                self.previous
                    .get(&(Arc::as_ptr(m) as usize))
                    .cloned()
                    .unwrap_or_else(|| Arc::new(MeshAccel::new(m.clone())))
            })
            .clone()
    }

    /// Keeps the previous build's hierarchies of the meshes at `keys` (used by
    /// primitives reused from it) for the next build.
    fn keep_meshes(&mut self, keys: &[usize]) {
        for k in keys {
            if let Some(m) = self.previous.get(k) {
                self.meshes.insert(*k as *const MeshData, m.clone());
            }
        }
    }

    /// Makes `m` what [`Builder::flatten_all`] would make of `scene` by writing
    /// the primitives of the objects placed again over their predecessors',
    /// when it can: no world shares `m`'s list any more, `scene` has as many
    /// objects, each placed at the same position as before or newly placed, and
    /// each newly placed one makes as many bounded and unbounded primitives as
    /// the one it replaces. `false` (and `m` untouched) otherwise.
    fn update_in_place(&mut self, scene: &Scene, inherited: &Inherited, m: &mut Made) -> bool {
        if m.placed.len() != scene.placed.len() || Arc::get_mut(&mut m.prims).is_none() {
            return false;
        }
        // (object, its primitives and whether each may let light through, its meshes)
        let mut fresh = Vec::new();
        for (k, (&now, &then)) in scene.placed.iter().zip(&m.placed).enumerate() {
            if now == then {
                continue;
            }
            if m.index.contains_key(&now) {
                return false; // an object reused elsewhere: the order changed
            }
            self.flatten(&scene.objects[k], None, inherited);
            let prims: Vec<Primitive> = self.prims.drain(..).collect();
            let see = transparency::translucent(&prims);
            let keys = std::mem::take(&mut self.used).into_boxed_slice();
            let [_, bn, _, un] = m.ranges[k];
            let bounded = prims.iter().filter(|p| p.bounds.is_some()).count();
            if bounded != bn as usize || prims.len() - bounded != un as usize {
                return false;
            }
            fresh.push((k, prims, see, keys));
        }
        let Some(list) = Arc::get_mut(&mut m.prims) else {
            return false;
        };
        for (k, prims, see, keys) in fresh {
            let [bs, _, us, _] = m.ranges[k].map(|x| x as usize);
            let (mut b, mut u) = (bs, us);
            for (p, t) in prims.into_iter().zip(see) {
                let at = if p.bounds.is_some() { &mut b } else { &mut u };
                list[*at] = p;
                m.translucent[*at] = t;
                *at += 1;
            }
            m.index.remove(&m.placed[k]);
            m.index.insert(scene.placed[k], k as u32);
            m.placed[k] = scene.placed[k];
            m.meshes[k] = keys;
        }
        for keys in &m.meshes {
            self.keep_meshes(keys);
        }
        true
    }

    /// The primitives of `scene`'s objects, bounded ones first (each part in
    /// file order, the bounded ones in `room`'s memory), with what the next
    /// build needs to reuse them; the primitives of an object `previous` holds
    /// are copied from it.
    fn flatten_all(
        &mut self,
        scene: &Scene,
        inherited: &Inherited,
        previous: Option<&Made>,
        room: Vec<Primitive>,
    ) -> Made {
        let n = scene.objects.len();
        let mut bounded = room;
        bounded.reserve(n);
        let mut unbounded: Vec<Primitive> = Vec::new();
        let (mut see_b, mut see_u) = (Vec::with_capacity(n), Vec::new());
        let mut made = Made {
            placed: scene.placed.clone(),
            index: FxHashMap::default(),
            ranges: Vec::with_capacity(n),
            meshes: Vec::with_capacity(n),
            prims: Arc::default(),
            translucent: Vec::new(),
        };
        made.index.reserve(n);
        for (k, obj) in scene.objects.iter().enumerate() {
            let placed = scene.placed.get(k).copied();
            let (b0, u0) = (bounded.len(), unbounded.len());
            let old = previous
                .zip(placed)
                .and_then(|(m, p)| m.index.get(&p).map(|&j| (m, j as usize)));
            let keys = match old {
                Some((m, j)) => {
                    let [bs, bn, us, un] = m.ranges[j].map(|x| x as usize);
                    bounded.extend_from_slice(&m.prims[bs..bs + bn]);
                    unbounded.extend_from_slice(&m.prims[us..us + un]);
                    see_b.extend_from_slice(&m.translucent[bs..bs + bn]);
                    see_u.extend_from_slice(&m.translucent[us..us + un]);
                    self.keep_meshes(&m.meshes[j]);
                    m.meshes[j].clone()
                }
                None => {
                    self.flatten(obj, None, inherited);
                    let see = transparency::translucent(&self.prims);
                    for (p, t) in self.prims.drain(..).zip(see) {
                        if p.bounds.is_some() {
                            bounded.push(p);
                            see_b.push(t);
                        } else {
                            unbounded.push(p);
                            see_u.push(t);
                        }
                    }
                    std::mem::take(&mut self.used).into_boxed_slice()
                }
            };
            if let Some(p) = placed {
                made.index.insert(p, k as u32);
            }
            made.ranges.push([
                b0 as u32,
                (bounded.len() - b0) as u32,
                u0 as u32,
                (unbounded.len() - u0) as u32,
            ]);
            made.meshes.push(keys);
        }
        // The unbounded ones come after all the bounded ones.
        let nb = bounded.len() as u32;
        for r in &mut made.ranges {
            r[2] += nb;
        }
        bounded.append(&mut unbounded);
        see_b.append(&mut see_u);
        made.prims = Arc::new(bounded);
        made.translucent = see_b;
        made
    }

    /// The glyphs of a `text` at `world_from_obj`: one prism each, placed by
    /// [`shapes::text::glyph_placement`]. A negative thickness gives, as in
    /// POV-Ray 3.7, only the two faces at z = thickness and z = 0: two flat
    /// prisms per glyph, no walls and no inside.
    fn glyphs(
        &mut self,
        text: &TextData,
        world_from_obj: Option<&Transform>,
    ) -> Vec<(PrimShape, Option<Transform>)> {
        let t = text.thickness;
        let heights: &[(f64, f64)] = if t < 0.0 {
            &[(t, t), (0.0, 0.0)]
        } else {
            &[(0.0, t)]
        };
        let mut out = Vec::new();
        for (curves, origin) in &text.glyphs {
            let Some(place) = Transform::from_matrix(shapes::text::glyph_placement(*origin)) else {
                continue;
            };
            let place = match world_from_obj {
                Some(w) => place.then(w),
                None => place,
            };
            for &(h0, h1) in heights {
                let key = (
                    Arc::as_ptr(curves) as *const DVec2 as usize,
                    h0.to_bits(),
                    h1.to_bits(),
                );
                let previous = &mut self.previous_glyphs;
                let prism = self
                    .glyphs
                    .entry(key)
                    .or_insert_with(|| {
                        previous.remove(&key).unwrap_or_else(|| {
                            let prism = shapes::prism::Prism::new(curves, h0, h1, false, false);
                            (curves.clone(), Arc::new(prism))
                        })
                    })
                    .1
                    .clone();
                out.push((PrimShape::Prism(prism), Some(place)));
            }
        }
        out
    }

    /// The placement and inheritance of `obj` under a parent at `parent`.
    fn here(
        obj: &Object,
        parent: Option<&Transform>,
        inh: &Inherited,
    ) -> (Option<Transform>, Inherited) {
        let world_from_obj = match (obj.transform.as_deref(), parent) {
            (None, p) => p.copied(),
            (Some(t), None) => Some(*t),
            (Some(t), Some(p)) => Some(t.then(p)),
        };
        let here = Inherited {
            texture: obj.texture.clone().unwrap_or_else(|| inh.texture.clone()),
            texture_space: if obj.texture.is_some() {
                world_from_obj
            } else {
                inh.texture_space
            },
            interior: match &obj.interior {
                // A media's densities are kept in the object's frame: placed in
                // the world here, so the renderer evaluates them at world points.
                Some(i) if !i.media.is_empty() && world_from_obj.is_some() => {
                    let mut own = (**i).clone();
                    if let Some(w) = &world_from_obj {
                        for m in &mut own.media {
                            m.transform(w);
                        }
                    }
                    Some(Arc::new(own))
                }
                Some(i) => Some(i.clone()),
                None => inh.interior.clone(),
            },
            flags: or_flags(inh.flags, obj.flags),
        };
        (world_from_obj, here)
    }

    /// Appends the primitives of `obj`, whose parent maps to world by `parent`.
    /// Unions are walked with a stack of their own, not by recursion, in file
    /// order.
    fn flatten(&mut self, obj: &Object, parent: Option<&Transform>, inh: &Inherited) {
        let mut todo: Vec<(&Object, Option<Transform>, Inherited)> =
            vec![(obj, parent.copied(), inh.clone())];
        while let Some((obj, parent, inh)) = todo.pop() {
            let (world_from_obj, here) = Builder::here(obj, parent.as_ref(), &inh);
            if obj.clipped_by.is_some() || matches!(obj.shape, Shape::Csg { .. }) {
                self.flatten_csg(obj, parent.as_ref(), &inh, &here);
                continue;
            }
            if let Shape::Union { children } = &obj.shape {
                for c in children.iter().rev() {
                    todo.push((c, world_from_obj, here.clone()));
                }
                continue;
            }
            if let Shape::Text(text) = &obj.shape {
                for (shape, transform) in self.glyphs(text, world_from_obj.as_ref()) {
                    self.prims.push(primitive(shape, transform, &here));
                }
                continue;
            }
            let (shape, transform) = self.leaf_shape(&obj.shape, world_from_obj);
            self.prims.push(primitive(shape, transform, &here));
        }
    }

    /// Appends `obj`, a CSG object or a clipped one, as one CSG primitive.
    fn flatten_csg(
        &mut self,
        obj: &Object,
        parent: Option<&Transform>,
        inh: &Inherited,
        here: &Inherited,
    ) {
        let mut leaves = Vec::new();
        // The object's own inverse is in `here.flags`; the tree takes it.
        let inner = Inherited {
            flags: ObjectFlags {
                inverse: false,
                ..here.flags
            },
            ..here.clone()
        };
        let mut own = obj.clone();
        own.flags.inverse = false;
        let mut root = self.csg_node(&own, parent, inh, &mut leaves);
        if here.flags.inverse {
            root.invert(&mut leaves);
        }
        let csg = Csg::new(leaves, root);
        let shape = PrimShape::Csg(Arc::new(csg));
        let mut p = primitive(shape, None, &inner);
        p.flags.inverse = false;
        if p.bounds.is_some_and(|b| b.is_empty()) {
            return; // an intersection of disjoint parts: nothing to see
        }
        self.prims.push(p);
    }

    /// The CSG node for `obj` under a parent at `parent` (`inverse` is handled in
    /// the tree, not in the leaves' flags).
    fn csg_node(
        &mut self,
        obj: &Object,
        parent: Option<&Transform>,
        inh: &Inherited,
        leaves: &mut Vec<CsgLeaf>,
    ) -> CsgNode {
        let (world_from_obj, mut here) = Builder::here(obj, parent, inh);
        let own_inverse = obj.flags.inverse;
        here.flags.inverse = false;
        let mut node = match &obj.shape {
            Shape::Union { children } => CsgNode::Group {
                kind: GroupKind::Union,
                children: children
                    .iter()
                    .map(|c| self.csg_node(c, world_from_obj.as_ref(), &here, leaves))
                    .collect(),
                inverse: false,
            },
            Shape::Csg { op, children } => {
                let mut nodes: Vec<CsgNode> = children
                    .iter()
                    .map(|c| self.csg_node(c, world_from_obj.as_ref(), &here, leaves))
                    .collect();
                let kind = match op {
                    CsgOp::Merge => GroupKind::Merge,
                    CsgOp::Intersection => GroupKind::Intersection,
                    CsgOp::Difference => {
                        for n in nodes.iter_mut().skip(1) {
                            n.invert(leaves);
                        }
                        GroupKind::Intersection
                    }
                };
                CsgNode::Group {
                    kind,
                    children: nodes,
                    inverse: false,
                }
            }
            Shape::Text(text) => CsgNode::Group {
                kind: GroupKind::Union,
                children: self
                    .glyphs(text, world_from_obj.as_ref())
                    .into_iter()
                    .map(|(shape, transform)| {
                        leaves.push(leaf(primitive(shape, transform, &here)));
                        CsgNode::Leaf(leaves.len() as u32 - 1)
                    })
                    .collect(),
                inverse: false,
            },
            shape => {
                let (shape, transform) = self.leaf_shape(shape, world_from_obj);
                let p = primitive(shape, transform, &here);
                leaves.push(leaf(p));
                CsgNode::Leaf(leaves.len() as u32 - 1)
            }
        };
        if let Some(clips) = &obj.clipped_by {
            let clips = clips
                .iter()
                .map(|c| self.csg_node(c, world_from_obj.as_ref(), &here, leaves))
                .collect();
            node = CsgNode::Clip {
                object: Box::new(node),
                clips,
                inverse: false,
            };
        }
        if own_inverse {
            node.invert(leaves);
        }
        node
    }

    /// The primitive shape of a non-group `shape` and the transform it keeps
    /// (triangles are baked into world space).
    fn leaf_shape(
        &mut self,
        shape: &Shape,
        world_from_obj: Option<Transform>,
    ) -> (PrimShape, Option<Transform>) {
        let to_world = |p: DVec3| world_from_obj.map_or(p, |t| t.point(p));
        let shape = match shape {
            Shape::Sphere { center, radius } => PrimShape::Sphere {
                center: *center,
                radius: *radius,
            },
            Shape::Plane { normal, distance } => PrimShape::Plane {
                normal: *normal,
                distance: *distance,
            },
            Shape::Box { min, max } => PrimShape::Box {
                min: min.min(*max),
                max: max.max(*min),
            },
            Shape::Triangle { vertices, .. } => {
                let v = vertices.map(to_world);
                let (a, e1, e2) = (v[0], v[1] - v[0], v[2] - v[0]);
                return (PrimShape::Triangle { a, e1, e2 }, None);
            }
            Shape::SmoothTriangle {
                vertices, normals, ..
            } => {
                let v = vertices.map(to_world);
                let n = normals.map(|n| {
                    world_from_obj
                        .map_or(n, |t| t.normal(n))
                        .normalize_or_zero()
                });
                let (a, e1, e2) = (v[0], v[1] - v[0], v[2] - v[0]);
                return (
                    PrimShape::SmoothTriangle(Box::new(SmoothTriangle {
                        a,
                        e1,
                        e2,
                        normals: n,
                    })),
                    None,
                );
            }
            Shape::Cylinder {
                base,
                cap,
                radius,
                open,
            } => frustum(*base, *radius, *cap, *radius, *open),
            Shape::Cone {
                base,
                base_radius,
                cap,
                cap_radius,
                open,
            } => frustum(*base, *base_radius, *cap, *cap_radius, *open),
            Shape::Torus { major, minor } => PrimShape::Torus {
                major: *major,
                minor: *minor,
            },
            Shape::Disc {
                center,
                normal,
                radius,
                hole,
            } => PrimShape::Disc {
                center: *center,
                normal: *normal,
                r2: radius * radius,
                hole2: hole * hole,
            },
            Shape::Polygon { points } => match Polygon::new(points) {
                Some(p) => PrimShape::Polygon(Arc::new(p)),
                None => empty(),
            },
            Shape::Quadric { coefficients } => {
                PrimShape::Quadric(shapes::surface::Quadric(*coefficients))
            }
            Shape::Poly {
                order,
                coefficients,
            } => match shapes::poly::Poly::new(*order, coefficients) {
                Some(p) => PrimShape::Poly(Arc::new(p)),
                None => empty(),
            },
            Shape::Polyhedron { planes } => PrimShape::Polyhedron(planes.clone().into()),
            Shape::Prism {
                curves,
                heights,
                conic,
                open,
            } => PrimShape::Prism(Arc::new(shapes::prism::Prism::new(
                curves, heights[0], heights[1], *conic, *open,
            ))),
            Shape::Lathe { curves } => {
                PrimShape::Lathe(Arc::new(shapes::lathe::Lathe::new(curves)))
            }
            Shape::Sor { points, open } => {
                PrimShape::Sor(Arc::new(shapes::sor::Sor::new(points, *open)))
            }
            Shape::Mesh(m) => PrimShape::Mesh(self.mesh(m)),
            Shape::Blob(data) => PrimShape::Blob(Arc::new(shapes::blob::Blob::new(
                data,
                world_from_obj.as_ref(),
            ))),
            Shape::Superellipsoid { e, n } => {
                PrimShape::Superellipsoid(shapes::superellipsoid::Superellipsoid::new(*e, *n))
            }
            Shape::Isosurface(i) => PrimShape::Isosurface(i.clone()),
            Shape::Julia(j) => PrimShape::Julia(j.clone()),
            Shape::SphereSweep(s) => {
                match shapes::sweep::SphereSweep::new(s.spline, &s.points, s.tolerance) {
                    Some(s) => PrimShape::SphereSweep(Arc::new(s)),
                    None => empty(),
                }
            }
            Shape::Union { .. } | Shape::Csg { .. } | Shape::Text(_) => empty(),
        };
        (shape, world_from_obj)
    }
}

/// A CSG leaf of primitive `p`: a surface, not inverted.
fn leaf(p: Primitive) -> CsgLeaf {
    CsgLeaf {
        shape: p.shape,
        transform: p.transform,
        texture: p.texture,
        texture_from_world: p.texture_from_world,
        interior: p.interior,
        inverse: false,
        flip: false,
        surface: true,
        bounds: p.bounds,
    }
}

/// A shape nothing hits (degenerate input the evaluator already warned about).
fn empty() -> PrimShape {
    PrimShape::Sphere {
        center: DVec3::ZERO,
        radius: 0.0,
    }
}

fn frustum(base: DVec3, r0: f64, cap: DVec3, r1: f64, open: bool) -> PrimShape {
    Frustum::new(base, r0, cap, r1, open).map_or_else(empty, PrimShape::Frustum)
}

fn primitive(shape: PrimShape, transform: Option<Transform>, inh: &Inherited) -> Primitive {
    let transform = transform.filter(|t| *t != Transform::IDENTITY);
    Primitive {
        bounds: Primitive::compute_bounds(&shape, transform.as_ref()),
        shape,
        transform,
        texture: inh.texture.clone(),
        texture_from_world: inh.texture_space.map(|t| t.inverse),
        interior: inh.interior.clone(),
        flags: inh.flags,
    }
}

/// What the shader needs to know about a hit.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceHit<'a> {
    /// The world-space point hit.
    pub p: DVec3,
    /// Unit world-space geometric normal, outward for closed shapes (not flipped to
    /// face the ray). Secondary rays leave along this one.
    pub geo_normal: DVec3,
    /// Unit world-space shading normal before any `normal { }` perturbation: the
    /// geometric normal, or the interpolated one of a smooth triangle.
    pub normal: DVec3,
    /// The shape's own surface coordinates, for `uv_mapping`; `None` for shapes
    /// without a uv parameterisation.
    pub uv: Option<DVec2>,
    /// The texture in force.
    pub texture: &'a Arc<Texture>,
    /// Maps world points into the texture's space.
    pub texture_from_world: Option<&'a DMat4>,
    /// The interior in force; `None` is POV-Ray's default.
    pub interior: Option<&'a Arc<Interior>>,
    /// The primitive's flags.
    pub flags: ObjectFlags,
    /// The primitive's index in [`World::primitives`].
    pub prim: u32,
    /// A `blob` whose components have textures of their own, and the point in
    /// its space: the shader blends the components' textures there.
    pub blob: Option<(&'a shapes::blob::Blob, DVec3)>,
}

impl World {
    /// The surface facts at `hit`, found along `ray`.
    pub fn surface(&self, ray: &Ray, hit: &Hit) -> SurfaceHit<'_> {
        let prim = &self.primitives[hit.prim as usize];
        let p = ray.at(hit.t);
        let (shape, transform, mut texture, mut texture_from_world, interior, flip) =
            match &prim.shape {
                PrimShape::Csg(c) => {
                    let l = &c.leaves[hit.leaf as usize];
                    (
                        &l.shape,
                        l.transform.as_ref(),
                        &l.texture,
                        l.texture_from_world.as_ref(),
                        l.interior.as_ref(),
                        l.flip,
                    )
                }
                s => (
                    s,
                    prim.transform.as_ref(),
                    &prim.texture,
                    prim.texture_from_world.as_ref(),
                    prim.interior.as_ref(),
                    false,
                ),
            };
        let local = transform.map_or(p, |t| t.inverse.transform_point3(p));
        let to_world = |n: DVec3| {
            let n = transform.map_or(n, |t| t.normal(n)).normalize();
            if flip {
                -n
            } else {
                n
            }
        };
        let geo_normal = to_world(shape.normal(local, hit.sub));
        let normal = shape
            .shading_normal(local, hit.sub)
            .map_or(geo_normal, to_world);
        if let PrimShape::Mesh(m) = shape {
            // A triangle's own texture lives in the mesh's object space.
            let d = &m.data;
            if let Some(&[k, ..]) = d.texture_indices.get(hit.sub as usize) {
                if let Some(t) = d.textures.get(k as usize) {
                    texture = t;
                    texture_from_world = transform.map(|t| &t.inverse);
                }
            }
        }
        let blob = match shape {
            PrimShape::Blob(b) if b.textured() => Some((&**b, local)),
            _ => None,
        };
        SurfaceHit {
            blob,
            p,
            geo_normal,
            normal,
            // uv costs trigonometry per hit: only for textures that look it up.
            uv: if texture.uses_uv() {
                shape.uv(local, hit.sub)
            } else {
                None
            },
            texture,
            texture_from_world,
            interior,
            flags: prim.flags,
            prim: hit.prim,
        }
    }

    /// The nearest hit in `(t_min, t_max)` among primitives `kind` can see.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64, kind: RayKind) -> Option<Hit> {
        self.intersect_among(&self.bvh, ray, t_min, t_max, kind)
    }

    /// This world's bounded primitives as a [`Bvh::flat`] list (`None` when
    /// there are none or too many), for [`World::intersect_among`].
    pub fn flat_bvh(&self) -> Option<Bvh> {
        let items: Vec<(u32, Aabb)> = self
            .primitives
            .iter()
            .enumerate()
            .filter_map(|(i, p)| p.bounds.map(|b| (i as u32, b)))
            .collect();
        Bvh::flat(&items)
    }

    /// [`World::intersect`] with `bvh` (over this world's bounded primitives,
    /// such as a [`Bvh::flat`] list) in place of the world's own hierarchy.
    pub fn intersect_among(
        &self,
        bvh: &Bvh,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        kind: RayKind,
    ) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_max = t_max;
        let found = |i: u32, (t, leaf, sub): ShapeHit| Hit {
            t,
            prim: i,
            leaf,
            sub,
        };
        for &i in &self.unbounded {
            let p = &self.primitives[i as usize];
            if kind.sees(&p.flags) {
                if let Some(h) = p.intersect(ray, t_min, t_max) {
                    t_max = h.0;
                    best = Some(found(i, h));
                }
            }
        }
        // At equal distances the primitive first in the world wins (an unbounded
        // one, tested above, before any in the tree), whatever order the tree
        // visits them in: a world built in two levels ([`BuildCache`]) sees
        // what one built whole sees.
        let bounded = self.primitives.len() - self.unbounded.len();
        bvh.traverse(ray, t_min, t_max, |i, t_max| {
            let p = &self.primitives[i as usize];
            if kind.sees(&p.flags) {
                let ties = best.is_some_and(|b| (b.prim as usize) < bounded && i < b.prim);
                let reach = if ties { t_max.next_up() } else { t_max };
                if let Some(h) = p.intersect(ray, t_min, reach) {
                    let nearer = best.is_none_or(|b| h.0 < b.t || (ties && h.0 <= b.t));
                    if nearer {
                        best = Some(found(i, h));
                        return Some(h.0);
                    }
                }
            }
            Some(t_max)
        });
        best
    }

    /// Whether any shadow-casting primitive lies on `ray` within `(t_min, t_max)`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.occluded_among(&self.bvh, ray, t_min, t_max)
    }

    /// [`World::occluded`] with `bvh` in place of the world's own hierarchy (see
    /// [`World::intersect_among`]).
    pub fn occluded_among(&self, bvh: &Bvh, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let kind = RayKind::Shadow;
        let hit_by = |i: u32| {
            let p = &self.primitives[i as usize];
            kind.sees(&p.flags) && p.intersect(ray, t_min, t_max).is_some()
        };
        if self.unbounded.iter().any(|&i| hit_by(i)) {
            return true;
        }
        bvh.any(ray, t_min, t_max, hit_by)
    }

    /// [`World::occluded`] that first tests primitive `hint` (any index; ones out
    /// of range are skipped) and leaves in `hint` the primitive that blocked the
    /// ray. The answer does not depend on `hint`, only the time it takes.
    pub fn occluded_hinted(&self, ray: &Ray, t_min: f64, t_max: f64, hint: &mut u32) -> bool {
        let kind = RayKind::Shadow;
        self.first_blocker(ray, t_min, t_max, hint, |i| {
            let p = &self.primitives[i as usize];
            kind.sees(&p.flags) && p.intersect(ray, t_min, t_max).is_some()
        })
    }

    /// Walks a shadow ray in `(t_min, t_max)` once: `true` (blocked) as soon as a
    /// shadow-casting surface that lets no light through is met (see
    /// [`World::translucent`]); every crossing of the surfaces that may let light
    /// through goes to `visit`, in no particular order, and `visit` returning
    /// `false` ends the walk as blocked too. `hint` as in
    /// [`World::occluded_hinted`] (an opaque blocker; only opaque ones are kept).
    ///
    /// One traversal for what took one to find the blockers plus one per
    /// see-through surface, nearest first: the filters multiply, so their order
    /// does not matter.
    pub fn shadow_crossings(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        hint: &mut u32,
        mut visit: impl FnMut(Hit) -> bool,
    ) -> bool {
        let see_through = |i: u32| self.translucent.get(i as usize).copied().unwrap_or(true);
        let mut blocks = |i: u32| {
            let p = &self.primitives[i as usize];
            if !RayKind::Shadow.sees(&p.flags) {
                return false;
            }
            if !see_through(i) {
                return p.intersect(ray, t_min, t_max).is_some();
            }
            let mut t0 = t_min;
            while let Some((t, leaf, sub)) = p.intersect(ray, t0, t_max) {
                if !visit(Hit {
                    t,
                    prim: i,
                    leaf,
                    sub,
                }) {
                    return true;
                }
                t0 = t + surface_offset(ray.at(t));
            }
            false
        };
        // A see-through hint would have its crossings visited twice.
        if (*hint as usize) < self.primitives.len() && !see_through(*hint) && blocks(*hint) {
            return true;
        }
        let mut found = self.unbounded.iter().copied().find(|&i| blocks(i));
        if found.is_none() {
            self.bvh.traverse(ray, t_min, t_max, |i, t_max| {
                if blocks(i) {
                    found = Some(i);
                    return None;
                }
                Some(t_max)
            });
        }
        match found {
            Some(i) => {
                if !see_through(i) {
                    *hint = i;
                }
                true
            }
            None => false,
        }
    }

    /// Whether `blocks` holds for some primitive the ray's interval may reach:
    /// `hint` first, then the unbounded primitives, then the hierarchy. The one
    /// found is left in `hint`.
    fn first_blocker(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        hint: &mut u32,
        mut blocks: impl FnMut(u32) -> bool,
    ) -> bool {
        if (*hint as usize) < self.primitives.len() && blocks(*hint) {
            return true;
        }
        if let Some(&i) = self.unbounded.iter().find(|&&i| blocks(i)) {
            *hint = i;
            return true;
        }
        let mut found = None;
        self.bvh.any(ray, t_min, t_max, |i| {
            let yes = blocks(i);
            if yes {
                found = Some(i);
            }
            yes
        });
        if let Some(i) = found {
            *hint = i;
        }
        found.is_some()
    }

    /// Whether world point `p` is inside any object, by POV-Ray's rules (see
    /// [`Primitive::inside`]): what refraction uses to decide which medium a ray
    /// is in. Cost: one bounds test per bounded primitive plus the unbounded ones.
    pub fn inside(&self, p: DVec3) -> bool {
        self.inside_which(p).next().is_some()
    }

    /// The primitives whose inside holds world point `p`.
    pub fn inside_which(&self, p: DVec3) -> impl Iterator<Item = &Primitive> + '_ {
        self.primitives.iter().filter(move |prim| {
            // An inverted solid's inside is everything outside its bounds.
            (prim.flags.inverse
                || prim
                    .bounds
                    .is_none_or(|b| p.cmpge(b.min).all() && p.cmple(b.max).all()))
                && prim.inside(p)
        })
    }

    /// [`World::intersect`] by testing every primitive: the reference the BVH is
    /// checked against.
    pub fn intersect_brute_force(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        kind: RayKind,
    ) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        for (i, p) in self.primitives.iter().enumerate() {
            if kind.sees(&p.flags) {
                if let Some((t, leaf, sub)) = p.intersect(ray, t_min, best.map_or(t_max, |h| h.t)) {
                    best = Some(Hit {
                        t,
                        prim: i as u32,
                        leaf,
                        sub,
                    });
                }
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Colour, Finish, Pattern, Pigment};
    use crate::span::Span;

    fn obj(shape: Shape) -> Object {
        Object::new(shape, Span::default())
    }

    fn red() -> Arc<Texture> {
        Arc::new(Texture {
            pigment: Pigment {
                pattern: Pattern::Solid(Colour::rgb(1.0, 0.0, 0.0)),
                transform: None,
            },
            finish: Finish::default(),
            ..Texture::default()
        })
    }

    #[test]
    fn unions_compose_transforms_and_inherit_textures_and_flags() {
        let child = Object {
            transform: Some(Arc::new(Transform::scale(DVec3::splat(2.0)))),
            ..obj(Shape::Sphere {
                center: DVec3::X,
                radius: 1.0,
            })
        };
        let plain = obj(Shape::Box {
            min: DVec3::ZERO,
            max: DVec3::ONE,
        });
        let mut inner = obj(Shape::Union {
            children: vec![child, plain].into(),
        });
        inner.flags.no_shadow = true;
        let outer = Object {
            transform: Some(Arc::new(Transform::translate(DVec3::Y * 10.0))),
            texture: Some(red()),
            ..obj(Shape::Union {
                children: vec![inner].into(),
            })
        };
        let untextured = obj(Shape::Plane {
            normal: DVec3::Y,
            distance: 0.0,
        });
        let scene = Scene {
            objects: vec![untextured, outer],
            ..Scene::default()
        };
        let w = build(&scene);
        assert_eq!(w.primitives.len(), 3);
        assert_eq!(w.unbounded, vec![2]);
        // Scale first, then the union's translate: centre (2, 10, 0), radius 2.
        let s = &w.primitives[0];
        let b = s.bounds.unwrap();
        assert!((b.min - DVec3::new(0.0, 8.0, -2.0)).length() < 1e-12);
        assert!((b.max - DVec3::new(4.0, 12.0, 2.0)).length() < 1e-12);
        assert_eq!(*s.texture, *red());
        assert!(s.flags.no_shadow);
        // Texture space is the union's: world → union is translate(-10 y).
        let m = s.texture_from_world.unwrap();
        assert_eq!(m.transform_point3(DVec3::new(1.0, 10.0, 0.0)), DVec3::X);
        // The plane keeps POV-Ray's default texture: black, ambient 0.1, diffuse 0.6.
        let plane = &w.primitives[2];
        assert_eq!(*plane.texture, Texture::default());
        assert_eq!(plane.texture.finish.diffuse, 0.6);
        assert!(!plane.flags.no_shadow);
        assert_eq!(w.bounds, b.union(&w.primitives[1].bounds.unwrap()));
    }

    /// "ox" in rts's block font, 0.5 deep, scaled by 2 and moved up by 1:
    /// one primitive per glyph; rays through the o's hole miss; the glyphs are a
    /// solid, also as the second operand of a `difference`.
    #[test]
    fn text_is_one_prism_per_glyph_and_a_solid() {
        let font = include_bytes!("../../examples/assets/rtsblock.ttf");
        let mut f = shapes::text::Font::parse(font.to_vec()).expect("font");
        let layout = f.layout("ox", DVec2::ZERO);
        let text = Shape::Text(Arc::new(TextData {
            glyphs: layout
                .glyphs
                .into_iter()
                .map(|g| (g.curves, g.origin))
                .collect(),
            thickness: 0.5,
        }));
        let place = Transform::scale(DVec3::splat(2.0)).then(&Transform::translate(DVec3::Y));
        let word = Object {
            transform: Some(Arc::new(place)),
            ..obj(text.clone())
        };
        let w = build(&Scene {
            objects: vec![word],
            ..Scene::default()
        });
        assert_eq!(w.primitives.len(), 2);
        // The o: 0.04..0.46 em from its origin, moved left by its xMin (0.04);
        // ring from x 0.04 to 0.15 (em), hole around 0.21 at y 0.25.
        let at = |x: f64, y: f64| DVec3::new(2.0 * x, 1.0 + 2.0 * y, -5.0);
        let ray = |p: DVec3| Ray::new(p, DVec3::Z);
        let hit = w.intersect(&ray(at(0.05, 0.25)), 0.0, f64::INFINITY, RayKind::Camera);
        let hit = hit.expect("the o's ring");
        assert!((hit.t - 5.0).abs() < 1e-9, "front at z = 0: t = {}", hit.t);
        let n = w.primitives[hit.prim as usize].shape.clone();
        assert!(matches!(n, PrimShape::Prism(_)));
        assert!(w
            .intersect(&ray(at(0.21, 0.25)), 0.0, f64::INFINITY, RayKind::Camera)
            .is_none());
        assert!(w.inside(DVec3::new(0.1, 1.5, 0.5)));
        assert!(!w.inside(DVec3::new(0.1, 1.5, 1.5)), "behind: z > 2 × 0.5");
        assert!(!w.inside(DVec3::new(0.42, 1.5, 0.5)), "in the hole");
        // A slab minus the text: the ring is carved out, the hole stays.
        let slab = obj(Shape::Box {
            min: DVec3::new(-1.0, 0.0, 0.2),
            max: DVec3::new(3.0, 3.0, 0.4),
        });
        let carved = obj(Shape::Csg {
            op: CsgOp::Difference,
            children: vec![
                slab,
                Object {
                    transform: Some(Arc::new(place)),
                    ..obj(text.clone())
                },
            ]
            .into(),
        });
        let w = build(&Scene {
            objects: vec![carved],
            ..Scene::default()
        });
        assert!(!w.inside(DVec3::new(0.1, 1.5, 0.3)), "carved ring");
        assert!(w.inside(DVec3::new(0.42, 1.5, 0.3)), "the o's hole is slab");
        assert!(w
            .intersect(&ray(at(0.05, 0.25)), 0.0, f64::INFINITY, RayKind::Camera)
            .is_none());
        let hit = w.intersect(&ray(at(0.21, 0.25)), 0.0, f64::INFINITY, RayKind::Camera);
        assert!((hit.expect("the slab in the hole").t - 5.2).abs() < 1e-9);
        // A negative thickness: the two faces only (POV-Ray 3.7), not a solid.
        let Shape::Text(data) = &text else {
            unreachable!()
        };
        let flat = Shape::Text(Arc::new(TextData {
            thickness: -0.5,
            ..(**data).clone()
        }));
        let w = build(&Scene {
            objects: vec![obj(flat)],
            ..Scene::default()
        });
        assert_eq!(w.primitives.len(), 4);
        assert!(!w.inside(DVec3::new(0.05, 0.25, -0.25)));
        let r = Ray::new(DVec3::new(0.05, 0.25, -5.0), DVec3::Z);
        let hit = w.intersect(&r, 0.0, f64::INFINITY, RayKind::Camera);
        assert!((hit.expect("front face").t - 4.5).abs() < 1e-9);
        let side = Ray::new(DVec3::new(-1.0, 0.25, -0.25), DVec3::X);
        assert!(w
            .intersect(&side, 0.0, f64::INFINITY, RayKind::Camera)
            .is_none());
    }

    /// A row of spheres, each twice (same place, same size: every hit of one is
    /// at the distance of the other's), and one more at `x` on its own.
    fn spheres_and_one_at(x: f64) -> Scene {
        let mut objects = Vec::new();
        for k in 0..80 {
            let center = DVec3::new((k % 10) as f64, (k / 10) as f64, 0.0);
            for _ in 0..2 {
                objects.push(obj(Shape::Sphere {
                    center,
                    radius: 0.4,
                }));
            }
        }
        objects.push(obj(Shape::Sphere {
            center: DVec3::new(x, 3.5, -1.0),
            radius: 0.45,
        }));
        Scene {
            objects,
            ..Scene::default()
        }
    }

    #[test]
    fn a_world_built_in_two_levels_sees_what_one_built_whole_sees() {
        let mut cache = BuildCache::default();
        for frame in 0..4 {
            let scene = spheres_and_one_at(frame as f64 * 0.7);
            let kept = build_cached(&scene, &mut cache);
            let whole = build(&scene);
            // From the second frame on, the 160 that stand still keep a tree.
            let still = cache.still.as_ref().map_or(0, |(s, _)| s.len());
            assert_eq!(still, if frame == 0 { 0 } else { 160 }, "frame {frame}");
            for i in 0..40 {
                for j in 0..30 {
                    let at = DVec3::new(i as f64 * 0.25 - 0.5, j as f64 * 0.3 - 0.5, -5.0);
                    let ray = Ray::new(at, DVec3::new(0.01, 0.02, 1.0).normalize());
                    let hit = |w: &World| {
                        w.intersect(&ray, 1e-6, f64::INFINITY, RayKind::Camera)
                            .map(|h| (h.t.to_bits(), h.prim))
                    };
                    let brute = whole
                        .intersect_brute_force(&ray, 1e-6, f64::INFINITY, RayKind::Camera)
                        .map(|h| h.t.to_bits());
                    assert_eq!(hit(&kept), hit(&whole), "frame {frame}, ray {i} {j}");
                    assert_eq!(hit(&kept).map(|h| h.0), brute);
                    // Of two spheres in the same place, the first is seen.
                    if let Some((_, p)) = hit(&kept) {
                        if (p as usize) < 160 {
                            assert_eq!(p % 2, 0, "frame {frame}, ray {i} {j}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn objects_reused_by_a_later_frame_keep_their_primitives() {
        // Frame 1 places everything; frame 2 reuses all but the last object (the
        // moving sphere, placed again), frame 3 reuses everything.
        let mut first = spheres_and_one_at(0.0);
        first.objects.push(obj(Shape::Plane {
            normal: DVec3::Y,
            distance: -1.0,
        }));
        first.placed = (1..=first.objects.len() as u64).collect();
        let mut second = spheres_and_one_at(2.0);
        second.objects.push(first.objects[161].clone());
        second.placed = first.placed.clone();
        second.placed[160] = 1000;
        let mut cache = BuildCache::default();
        let one = build_cached(&first, &mut cache);
        let two = build_cached(&second, &mut cache);
        let three = build_cached(&second, &mut cache);
        assert!(Arc::ptr_eq(&two.primitives, &three.primitives));
        assert!(!Arc::ptr_eq(&one.primitives, &two.primitives));
        for (world, scene) in [(&one, &first), (&two, &second), (&three, &second)] {
            let fresh = build(scene);
            assert_eq!(world.primitives.len(), fresh.primitives.len());
            assert_eq!(world.unbounded, fresh.unbounded);
            assert_eq!(world.unbounded, vec![161]);
            assert_eq!(world.translucent, fresh.translucent);
            for (a, b) in world.primitives.iter().zip(fresh.primitives.iter()) {
                assert_eq!(a.bounds, b.bounds);
                assert_eq!(format!("{:?}", a.shape), format!("{:?}", b.shape));
            }
        }
        // The moved sphere is where the second scene puts it.
        let moved = two.primitives[160].bounds.unwrap();
        assert!((moved.min.x - (2.0 - 0.45)).abs() < 1e-9);
        // Without placement numbers nothing is reused.
        let plain = Scene {
            placed: Vec::new(),
            ..second.clone()
        };
        let four = build_cached(&plain, &mut cache);
        assert!(!Arc::ptr_eq(&four.primitives, &three.primitives));
        drop((one, two, three, four));

        // Frame after frame, each world dropped before the next is built (as a
        // sequence does): the moving sphere's primitive is written over in the
        // same list.
        let mut cache = BuildCache::default();
        let mut list = None;
        for frame in 0..4 {
            let mut s = spheres_and_one_at(frame as f64);
            s.placed = first.placed[..161].to_vec();
            s.placed[160] = 2000 + frame;
            let w = build_cached(&s, &mut cache);
            let fresh = build(&s);
            for (a, b) in w.primitives.iter().zip(fresh.primitives.iter()) {
                assert_eq!(a.bounds, b.bounds, "frame {frame}");
            }
            let at = Arc::as_ptr(&w.primitives) as usize;
            if frame > 0 {
                assert_eq!(Some(at), list, "frame {frame}: a new list");
            }
            list = Some(at);
        }
    }

    #[test]
    fn world_is_send_and_sync() {
        fn check<T: Send + Sync>() {}
        check::<World>();
    }
}
