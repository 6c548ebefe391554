//! The one documentation table for the language's words: every reserved keyword, colour
//! keyword, directive, built-in function and constant, with a one-line description.
//! Hover shows it; a test checks it covers the grammar's keywords and the evaluator's
//! built-ins, and that each word is described in
//! `docs/language.md`.

/// What kind of word a [`Doc`] describes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DocKind {
    /// A reserved keyword (block or parameter).
    Keyword,
    /// A directive, written after `#`.
    Directive,
    /// A built-in function.
    Function,
    /// A built-in constant.
    Constant,
}

/// The documentation of one word.
#[derive(Clone, Copy, Debug)]
pub struct Doc {
    /// The word.
    pub name: &'static str,
    /// What it is.
    pub kind: DocKind,
    /// How it is written, e.g. `sphere { CENTER, RADIUS … }` or `vcross(A, B)`.
    pub syntax: &'static str,
    /// What it means.
    pub summary: &'static str,
}

const fn kw(name: &'static str, syntax: &'static str, summary: &'static str) -> Doc {
    Doc {
        name,
        kind: DocKind::Keyword,
        syntax,
        summary,
    }
}

const fn dir(name: &'static str, syntax: &'static str, summary: &'static str) -> Doc {
    Doc {
        name,
        kind: DocKind::Directive,
        syntax,
        summary,
    }
}

const fn func(name: &'static str, syntax: &'static str, summary: &'static str) -> Doc {
    Doc {
        name,
        kind: DocKind::Function,
        syntax,
        summary,
    }
}

const fn constant(name: &'static str, syntax: &'static str, summary: &'static str) -> Doc {
    Doc {
        name,
        kind: DocKind::Constant,
        syntax,
        summary,
    }
}

/// The table, one entry per word.
pub const DOCS: &[Doc] = &[
    // ------------------------------------------------------------------ directives
    dir(
        "declare",
        "#declare NAME = VALUE;",
        "Binds NAME globally (or updates the innermost existing binding).",
    ),
    dir(
        "local",
        "#local NAME = VALUE;",
        "Binds NAME in the current macro call or include file only.",
    ),
    dir(
        "undef",
        "#undef NAME",
        "Removes the innermost binding of NAME.",
    ),
    dir(
        "if",
        "#if (COND) … #elseif (COND) … #else … #end",
        "Evaluates the first branch whose condition is not zero.",
    ),
    dir("elseif", "#elseif (COND)", "Another condition of an #if."),
    dir("else", "#else", "The branch taken when no condition held."),
    dir(
        "end",
        "#end",
        "Closes #if, #ifdef, #ifndef, #switch, #while, #for and #macro.",
    ),
    dir(
        "ifdef",
        "#ifdef (NAME) … #end",
        "Evaluates the body when NAME is declared.",
    ),
    dir(
        "ifndef",
        "#ifndef (NAME) … #end",
        "Evaluates the body when NAME is not declared (include guards).",
    ),
    dir(
        "switch",
        "#switch (V) #case (A) … #break #range (L, H) … #else … #end",
        "Chooses clauses by value.",
    ),
    dir(
        "case",
        "#case (V)",
        "A #switch clause taken when the value equals V.",
    ),
    dir(
        "range",
        "#range (LOW, HIGH)",
        "A #switch clause taken when LOW ≤ value ≤ HIGH.",
    ),
    dir("break", "#break", "Ends a #switch clause."),
    dir(
        "while",
        "#while (COND) … #end",
        "Repeats the body while COND is not zero.",
    ),
    dir(
        "for",
        "#for (I, START, END [, STEP]) … #end",
        "Repeats the body with I from START to END inclusive.",
    ),
    dir(
        "macro",
        "#macro NAME(A, optional B) … #end",
        "Defines a macro; a call expands its body with the arguments bound.",
    ),
    dir(
        "include",
        "#include \"FILE\"",
        "Reads FILE (its folder, the scene's folder, -I folders, then the built-in library).",
    ),
    dir("debug", "#debug STRING", "Prints STRING as a note."),
    dir("warning", "#warning STRING", "Reports STRING as a warning."),
    dir("error", "#error STRING", "Stops with STRING as an error."),
    dir(
        "default",
        "#default { texture { … } }",
        "Sets the texture of objects that give none.",
    ),
    dir(
        "version",
        "#version 3.7;",
        "The POV-Ray language version the scene is written for.",
    ),
    dir(
        "fopen",
        "#fopen NAME \"FILE\" read|write|append",
        "Opens a file under NAME for #read or #write (written files reach the disk only when rendering).",
    ),
    dir("fclose", "#fclose NAME", "Closes a file opened by #fopen."),
    dir(
        "read",
        "#read (NAME, VAR, …)",
        "Reads the file's next floats, vectors and strings into variables; at the end of the data NAME becomes undefined.",
    ),
    dir(
        "write",
        "#write (NAME, ITEM, …)",
        "Writes strings, floats (as %g), vectors and binary integers (uint8 V, sint16le V, …) to a file opened for writing.",
    ),
    // ------------------------------------------------------------------ colours and values
    kw(
        "color",
        "color rgb <R, G, B> | color red R green G …",
        "A colour (also spelt `colour`).",
    ),
    kw(
        "colour",
        "colour rgb <R, G, B>",
        "A colour (also spelt `color`).",
    ),
    kw(
        "rgb",
        "rgb <R, G, B>",
        "A colour from red, green and blue (a float gives a grey).",
    ),
    kw(
        "rgbf",
        "rgbf <R, G, B, F>",
        "A colour with filter (tinted transparency).",
    ),
    kw(
        "rgbt",
        "rgbt <R, G, B, T>",
        "A colour with transmit (untinted transparency).",
    ),
    kw(
        "rgbft",
        "rgbft <R, G, B, F, T>",
        "A colour with filter and transmit.",
    ),
    kw(
        "srgb",
        "srgb <R, G, B>",
        "A colour given in sRGB-encoded components.",
    ),
    kw("srgbf", "srgbf <R, G, B, F>", "An sRGB colour with filter."),
    kw(
        "srgbt",
        "srgbt <R, G, B, T>",
        "An sRGB colour with transmit.",
    ),
    kw(
        "srgbft",
        "srgbft <R, G, B, F, T>",
        "An sRGB colour with filter and transmit.",
    ),
    kw("red", "color red R", "The red component of a colour."),
    kw("green", "color green G", "The green component of a colour."),
    kw("blue", "color blue B", "The blue component of a colour."),
    kw(
        "gray",
        "color gray G",
        "Sets red, green and blue to G (also `grey`).",
    ),
    kw(
        "grey",
        "color grey G",
        "Sets red, green and blue to G (also `gray`).",
    ),
    kw(
        "filter",
        "filter F",
        "Filtered transparency: light passes tinted by the colour.",
    ),
    kw(
        "transmit",
        "transmit T",
        "Transmitted transparency: light passes untinted.",
    ),
    kw(
        "array",
        "array[N] { A, B, … }",
        "An array of N values (more dimensions with more `[N]`).",
    ),
    // ------------------------------------------------------------------ objects
    kw("sphere", "sphere { CENTER, RADIUS … }", "A sphere."),
    kw(
        "plane",
        "plane { NORMAL, DISTANCE … }",
        "An infinite plane; its inside is opposite the normal.",
    ),
    kw(
        "box",
        "box { CORNER1, CORNER2 … }",
        "An axis-aligned box between two corners.",
    ),
    kw(
        "cylinder",
        "cylinder { BASE, CAP, RADIUS [open] … }",
        "A cylinder; `open` leaves out the end caps. In a light source: a cylindrical light.",
    ),
    kw(
        "cone",
        "cone { BASE, R1, CAP, R2 [open] … }",
        "A truncated cone.",
    ),
    kw(
        "torus",
        "torus { MAJOR, MINOR … }",
        "A torus around the y axis.",
    ),
    kw(
        "disc",
        "disc { CENTER, NORMAL, RADIUS [, HOLE] … }",
        "A flat disc, optionally with a hole.",
    ),
    kw("triangle", "triangle { A, B, C … }", "A triangle."),
    kw(
        "smooth_triangle",
        "smooth_triangle { A, NA, B, NB, C, NC … }",
        "A triangle with a normal at each corner.",
    ),
    kw(
        "polygon",
        "polygon { N, P1, P2, … }",
        "A flat polygon of N points (closed sub-polygons make holes).",
    ),
    kw(
        "quadric",
        "quadric { <A,B,C>, <D,E,F>, <G,H,I>, J … }",
        "A second-order surface.",
    ),
    kw(
        "poly",
        "poly { ORDER, <C1, C2, …> [sturm] … }",
        "The surface where a polynomial of order 2 to 4 in x, y, z is zero.",
    ),
    kw(
        "cubic",
        "cubic { <20 coefficients> [sturm] … }",
        "A third-order polynomial surface (poly { 3, … }).",
    ),
    kw(
        "quartic",
        "quartic { <35 coefficients> [sturm] … }",
        "A fourth-order polynomial surface (poly { 4, … }), e.g. a torus.",
    ),
    kw(
        "sturm",
        "sturm",
        "Accepted on poly, cubic, quartic, torus, prism, lathe, sor and blob: rts's root solvers are always the careful ones.",
    ),
    kw(
        "mesh",
        "mesh { triangle { … } … }",
        "A mesh of triangles, or obj_file / ply_file.",
    ),
    kw(
        "mesh2",
        "mesh2 { vertex_vectors { … } face_indices { … } … }",
        "An indexed triangle mesh.",
    ),
    kw(
        "polyhedron",
        "polyhedron { … }",
        "A closed polyhedral mesh (rts addition).",
    ),
    kw(
        "height_field",
        "height_field { png \"FILE\" [smooth] [water_level W] … }",
        "A height field from a grey image.",
    ),
    kw(
        "obj_file",
        "mesh { obj_file \"FILE\" }",
        "Reads a Wavefront OBJ file into a mesh (rts addition).",
    ),
    kw(
        "ply_file",
        "mesh { ply_file \"FILE\" }",
        "Reads a PLY file into a mesh (rts addition).",
    ),
    kw(
        "object",
        "object { NAME … }",
        "An instance of a declared object, with modifiers.",
    ),
    kw(
        "union",
        "union { OBJECTS … }",
        "CSG union: all the objects as one.",
    ),
    kw(
        "merge",
        "merge { OBJECTS … }",
        "A union without inner surfaces (for transparent objects).",
    ),
    kw(
        "intersection",
        "intersection { OBJECTS … }",
        "CSG intersection: what is inside every object.",
    ),
    kw(
        "difference",
        "difference { OBJECT, OBJECTS … }",
        "CSG difference: the first object minus the others.",
    ),
    kw(
        "clipped_by",
        "clipped_by { OBJECT }",
        "Cuts away the parts of an object outside the given shape.",
    ),
    kw(
        "bounded_by",
        "bounded_by { OBJECT }",
        "A bounding shape (a hint; rts builds its own BVH).",
    ),
    kw(
        "inverse",
        "inverse",
        "Swaps an object's inside and outside.",
    ),
    kw(
        "hollow",
        "hollow",
        "Marks an object as hollow (for media and fog inside).",
    ),
    kw(
        "open",
        "open",
        "Leaves out the end caps of a cylinder, cone, prism or sor.",
    ),
    kw("no_shadow", "no_shadow", "The object casts no shadows."),
    kw(
        "no_image",
        "no_image",
        "The object is invisible to camera rays.",
    ),
    kw(
        "no_reflection",
        "no_reflection",
        "The object does not appear in reflections.",
    ),
    kw(
        "double_illuminate",
        "double_illuminate",
        "Lights both sides of the object's surface.",
    ),
    kw(
        "inside_vector",
        "inside_vector <V>",
        "A direction that tells inside from outside for a mesh.",
    ),
    kw(
        "vertex_vectors",
        "vertex_vectors { N, <V>, … }",
        "The vertices of a mesh2.",
    ),
    kw(
        "normal_vectors",
        "normal_vectors { N, <V>, … }",
        "The normals of a mesh2.",
    ),
    kw(
        "uv_vectors",
        "uv_vectors { N, <U, V>, … }",
        "The uv coordinates of a mesh2.",
    ),
    kw(
        "face_indices",
        "face_indices { N, <A, B, C>, … }",
        "The triangles of a mesh2 as vertex indices.",
    ),
    kw(
        "normal_indices",
        "normal_indices { N, <A, B, C>, … }",
        "Normal indices per triangle of a mesh2.",
    ),
    kw(
        "uv_indices",
        "uv_indices { N, <A, B, C>, … }",
        "uv indices per triangle of a mesh2.",
    ),
    kw(
        "texture_list",
        "texture_list { N, texture { … } … }",
        "The textures a mesh2's faces refer to.",
    ),
    kw("smooth", "smooth", "Smooths a height field's normals."),
    kw(
        "water_level",
        "water_level W",
        "Cuts a height field below W (0 to 1).",
    ),
    kw("png", "png \"FILE\"", "A PNG image file."),
    kw("jpeg", "jpeg \"FILE\"", "A JPEG image file."),
    kw("exr", "exr \"FILE\"", "An OpenEXR image file."),
    // ------------------------------------------------------------------ transforms
    kw("translate", "translate <V>", "Moves by V."),
    kw(
        "rotate",
        "rotate <X, Y, Z>",
        "Rotates by degrees about x, then y, then z.",
    ),
    kw(
        "scale",
        "scale <V> | scale S",
        "Scales by V (a float scales uniformly).",
    ),
    kw(
        "matrix",
        "matrix <12 floats>",
        "An affine transform given as a 4×3 matrix.",
    ),
    kw(
        "transform",
        "transform { … } | transform NAME",
        "A transform, or a declared one applied (`inverse` reverses it).",
    ),
    // ------------------------------------------------------------------ textures
    kw(
        "texture",
        "texture { pigment { … } normal { … } finish { … } }",
        "An object's surface: pigment, normal and finish; or a pattern of whole textures (`checker texture { … } texture { … }`, `PATTERN texture_map { … }`).",
    ),
    kw(
        "pigment",
        "pigment { COLOUR | PATTERN … }",
        "The surface colour, plain or a pattern.",
    ),
    kw(
        "finish",
        "finish { ambient … diffuse … phong … reflection … }",
        "How the surface reacts to light.",
    ),
    kw(
        "normal",
        "normal { PATTERN [BUMP_SIZE] … }",
        "Bumps the surface normal with a pattern.",
    ),
    kw(
        "interior",
        "interior { ior … fade_distance … }",
        "What is inside a transparent object.",
    ),
    kw(
        "material",
        "material { [M] texture { … } interior { … } }",
        "A texture and interior declared and applied together.",
    ),
    kw(
        "uv_mapping",
        "uv_mapping",
        "Maps the pattern with the object's uv coordinates.",
    ),
    kw(
        "color_map",
        "color_map { [V COLOUR] … }",
        "Colours of a pattern by value (also `colour_map`).",
    ),
    kw(
        "colour_map",
        "colour_map { [V COLOUR] … }",
        "Colours of a pattern by value (also `color_map`).",
    ),
    kw(
        "pigment_map",
        "pigment_map { [V pigment { … }] … }",
        "Pigments of a pattern by value.",
    ),
    kw(
        "texture_map",
        "texture { PATTERN texture_map { [V pigment { … } finish { … }] [V Texture_Name] … } }",
        "Whole textures of a pattern by value: between entries both are shaded and blended.",
    ),
    kw(
        "image_map",
        "image_map { png \"FILE\" [map_type N] [interpolate N] [once] }",
        "An image as a pigment.",
    ),
    kw(
        "map_type",
        "map_type N",
        "Image projection: 0 planar, 1 spherical, 2 cylindrical, 5 torus.",
    ),
    kw(
        "interpolate",
        "interpolate N",
        "Image interpolation: 2 bilinear, 4 normalized distance.",
    ),
    kw(
        "gamma",
        "gamma G",
        "After an image_map's file name: decode its pixels as value^G (3.7 scenes decode PNG and JPEG from sRGB otherwise).",
    ),
    kw(
        "once",
        "once",
        "Shows an image map once instead of tiling it.",
    ),
    kw(
        "all",
        "filter all F | transmit all T",
        "Sets filter or transmit for every colour of an image.",
    ),
    // patterns
    kw(
        "checker",
        "checker COLOUR, COLOUR",
        "A 3-D checkerboard of unit cubes (in a texture: `checker texture { … } texture { … }`).",
    ),
    kw(
        "hexagon",
        "hexagon COLOUR, COLOUR, COLOUR",
        "Hexagons in the x-z plane.",
    ),
    kw(
        "square",
        "square COLOUR, COLOUR, COLOUR, COLOUR",
        "Unit squares in the x-z plane, in blocks of four entries.",
    ),
    kw(
        "triangular",
        "triangular COLOUR × 6",
        "Equilateral triangles of side 1 in the x-z plane; six entries round each vertex.",
    ),
    kw(
        "brick",
        "brick COLOUR, COLOUR brick_size <V> mortar M",
        "A brick wall pattern.",
    ),
    kw(
        "brick_size",
        "brick_size <V>",
        "The size of the bricks of a brick pattern.",
    ),
    kw(
        "mortar",
        "mortar M",
        "The width of the mortar of a brick pattern.",
    ),
    kw(
        "gradient",
        "gradient <V>",
        "A ramp along V, repeating every unit.",
    ),
    kw("radial", "radial", "Values by angle around the y axis."),
    kw("onion", "onion", "Concentric spheres."),
    kw("leopard", "leopard", "Regular spots."),
    kw("spotted", "spotted", "Noise spots."),
    kw("bozo", "bozo", "Smooth noise."),
    kw(
        "marble",
        "marble",
        "Marble veins: a turbulent ramp along x.",
    ),
    kw("wood", "wood", "Wood rings around the z axis."),
    kw("granite", "granite", "Fractal noise like granite."),
    kw("agate", "agate", "Turbulent agate bands."),
    kw(
        "agate_turb",
        "agate_turb T",
        "The turbulence of the agate pattern.",
    ),
    kw(
        "wrinkles",
        "wrinkles",
        "Wrinkled noise (mostly for normals).",
    ),
    kw(
        "ripples",
        "ripples",
        "Concentric ripples (mostly for normals).",
    ),
    kw("waves", "waves", "Concentric waves (mostly for normals)."),
    kw("bumps", "bumps", "Noise bumps (mostly for normals)."),
    kw("dents", "dents", "Dents (mostly for normals)."),
    kw("bump_size", "bump_size S", "The depth of a normal pattern."),
    kw(
        "turbulence",
        "turbulence T",
        "Stirs a pattern with noise; in a fog, varies its thickness.",
    ),
    kw(
        "octaves",
        "octaves N",
        "Noise octaves of turbulence (default 6).",
    ),
    kw(
        "omega",
        "omega W",
        "Amplitude factor between octaves of turbulence (default 0.5).",
    ),
    kw(
        "lambda",
        "lambda L",
        "Frequency factor between octaves of turbulence (default 2).",
    ),
    kw(
        "frequency",
        "frequency F",
        "How often a pattern's colour map repeats.",
    ),
    kw("phase", "phase P", "Shifts a pattern's colour map."),
    kw("ramp_wave", "ramp_wave", "Wave form: a ramp (the default)."),
    kw("triangle_wave", "triangle_wave", "Wave form: up and down."),
    kw("sine_wave", "sine_wave", "Wave form: a sine."),
    kw("scallop_wave", "scallop_wave", "Wave form: scallops."),
    kw("cubic_wave", "cubic_wave", "Wave form: a smooth step."),
    kw("poly_wave", "poly_wave E", "Wave form: a power E."),
    kw(
        "noise_generator",
        "noise_generator N",
        "Which noise function: 1, 2 or 3 (default 2).",
    ),
    // finish
    kw(
        "ambient",
        "ambient A",
        "Light the surface gives without any light source (default 0.1).",
    ),
    kw(
        "diffuse",
        "diffuse D [, BACK]",
        "How much direct light is scattered (default 0.6); BACK: how much light from behind the surface shows through (default 0).",
    ),
    kw(
        "brilliance",
        "brilliance B",
        "How fast diffuse light falls off with angle (default 1).",
    ),
    kw("phong", "phong P", "Phong highlight strength."),
    kw(
        "phong_size",
        "phong_size S",
        "Phong highlight tightness (default 40).",
    ),
    kw(
        "specular",
        "specular S",
        "Blinn specular highlight strength.",
    ),
    kw(
        "roughness",
        "roughness R",
        "Size of the specular highlight (default 0.05).",
    ),
    kw(
        "metallic",
        "metallic [M]",
        "Tints highlights (or reflection) with the surface colour.",
    ),
    kw(
        "reflection",
        "reflection R | reflection { MIN, MAX fresnel falloff metallic }",
        "Mirror reflection.",
    ),
    kw(
        "emission",
        "emission E",
        "Light the surface emits (not lighting other objects).",
    ),
    kw(
        "conserve_energy",
        "conserve_energy",
        "Reduces diffuse and transmission where reflection is strong.",
    ),
    kw(
        "crand",
        "crand C",
        "Random graininess of the surface colour.",
    ),
    kw(
        "fresnel",
        "fresnel",
        "Angle-dependent reflection from the interior's ior.",
    ),
    kw(
        "falloff",
        "falloff F",
        "Reflection falloff exponent; in a spotlight, the outer cone angle.",
    ),
    kw(
        "exponent",
        "exponent E",
        "A fractal pattern's exponent (mandel, julia: 2 to 33); also POV-Ray's reflection and light falloff exponent.",
    ),
    kw(
        "irid",
        "irid { A thickness T turbulence U }",
        "Iridescence in a finish: thin-film interference colours of amount A.",
    ),
    kw("thickness", "thickness T", "The film thickness of irid (default 0)."),
    kw(
        "reflection_exponent",
        "reflection_exponent E",
        "Non-linear reflection (POV-Ray 3.5 form of `reflection { … exponent E }`): the reflected colour is raised to 1/E.",
    ),
    // interior
    kw(
        "ior",
        "ior N",
        "Index of refraction (1 air, 1.33 water, 1.5 glass).",
    ),
    kw(
        "fade_distance",
        "fade_distance D",
        "Distance at which light inside fades (interior) or from a light.",
    ),
    kw(
        "fade_power",
        "fade_power P",
        "How light fades with distance (1 linear, 2 physical).",
    ),
    kw(
        "fade_color",
        "fade_color COLOUR",
        "The colour light fades to inside (also `fade_colour`).",
    ),
    kw(
        "fade_colour",
        "fade_colour COLOUR",
        "The colour light fades to inside (also `fade_color`).",
    ),
    kw(
        "caustics",
        "caustics C",
        "Fakes caustics by brightening light through the object.",
    ),
    kw(
        "dispersion",
        "dispersion D",
        "Splits light by wavelength (ior varies by colour).",
    ),
    kw(
        "dispersion_samples",
        "dispersion_samples N",
        "How many wavelengths a dispersing interior samples (read; dispersion is not rendered yet).",
    ),
    // camera
    kw(
        "camera",
        "camera { location <L> look_at <T> angle A … }",
        "The camera: where it stands, what it looks at, its projection.",
    ),
    kw(
        "perspective",
        "perspective",
        "Projection: a pinhole camera (the default).",
    ),
    kw("orthographic", "orthographic", "Projection: parallel rays."),
    kw(
        "cells",
        "cells",
        "Pattern: one random value for each unit cube.",
    ),
    kw(
        "density_file",
        "density_file df3 \"FILE\" [interpolate 0|1|2]",
        "Pattern: values from a DF3 voxel file over the unit cube (0 outside); interpolate 1 trilinear, 2 tricubic.",
    ),
    kw("df3", "density_file df3 \"FILE\"", "The DF3 voxel format of a density_file."),
    kw(
        "mesh_camera",
        "mesh_camera { RAYS DISTRIBUTION MESH… [smooth] }",
        "Camera whose rays start on the faces of meshes (POV-Ray 3.7): distribution 0 one mesh per ray, 1 all meshes as one, 2 meshes side by side, 3 by uv (texture baking).",
    ),
    kw("fisheye", "fisheye", "Projection: a spherical fisheye."),
    kw(
        "ultra_wide_angle",
        "ultra_wide_angle",
        "Projection: up to 360° wide.",
    ),
    kw(
        "panoramic",
        "panoramic",
        "Projection: a cylindrical panorama.",
    ),
    kw(
        "spherical",
        "spherical",
        "Projection: latitude-longitude (environment maps).",
    ),
    kw("location", "location <L>", "Where the camera stands."),
    kw("look_at", "look_at <T>", "The point the camera looks at."),
    kw(
        "up",
        "up <V>",
        "The camera's up vector (default y); in fog, the up direction.",
    ),
    kw(
        "right",
        "right <V>",
        "The camera's right vector (its length sets the aspect ratio).",
    ),
    kw(
        "direction",
        "direction <V>",
        "The camera's viewing direction (its length sets the zoom).",
    ),
    kw("sky", "sky <V>", "Which way is up for look_at (default y)."),
    kw(
        "angle",
        "angle A",
        "The horizontal field of view in degrees.",
    ),
    kw(
        "aperture",
        "aperture A",
        "Focal blur: the lens size (0: everything sharp).",
    ),
    kw(
        "focal_point",
        "focal_point <P>",
        "Focal blur: the point in focus.",
    ),
    kw(
        "blur_samples",
        "blur_samples N",
        "Focal blur: rays per pixel.",
    ),
    kw(
        "confidence",
        "confidence C",
        "Focal blur and media methods 1, 2: adaptive sampling confidence.",
    ),
    kw(
        "variance",
        "variance V",
        "Focal blur and media methods 1, 2: adaptive sampling variance.",
    ),
    // lights
    kw(
        "light_source",
        "light_source { <L>, COLOUR … }",
        "A light at a location with a colour.",
    ),
    kw(
        "spotlight",
        "spotlight",
        "A cone of light towards point_at.",
    ),
    kw(
        "parallel",
        "parallel",
        "Parallel rays, as from a far sun, towards point_at.",
    ),
    kw(
        "point_at",
        "point_at <P>",
        "Where a spotlight, cylinder or parallel light aims.",
    ),
    kw(
        "radius",
        "radius R",
        "A spotlight's full-intensity cone angle (degrees).",
    ),
    kw(
        "tightness",
        "tightness T",
        "How fast a spotlight dims towards its edge.",
    ),
    kw(
        "area_light",
        "area_light <A1>, <A2>, N1, N2",
        "A rectangle of N1×N2 lights for soft shadows.",
    ),
    kw(
        "jitter",
        "jitter | jitter J",
        "Jitters area light samples; in media, how far samples move at random (default 0).",
    ),
    kw(
        "adaptive",
        "adaptive A",
        "Adaptive area light sampling depth.",
    ),
    kw("circular", "circular", "Makes an area light round."),
    kw(
        "orient",
        "orient",
        "Turns an area light to face each point lit.",
    ),
    kw("shadowless", "shadowless", "The light casts no shadows."),
    kw(
        "looks_like",
        "looks_like { OBJECT }",
        "An object drawn at the light's place (casting no shadow).",
    ),
    kw(
        "projected_through",
        "projected_through { OBJECT }",
        "Only light that passes through the object shines; the object itself is not drawn.",
    ),
    kw(
        "media_interaction",
        "media_interaction on|off",
        "Whether the light lights scattering media (default on).",
    ),
    kw(
        "media_attenuation",
        "media_attenuation on|off",
        "Whether atmospheric media and fog dim the light on its way (default off; media in objects always do).",
    ),
    kw(
        "global_lights",
        "light_group { … global_lights on }",
        "Whether the scene's other lights also light a light_group's objects (default off).",
    ),
    kw(
        "light_group",
        "light_group { light_source { … } OBJECTS [global_lights on] }",
        "Lights that light only the objects of the group (nested groups inherit them); a union otherwise.",
    ),
    // subsurface scattering (read, ignored)
    kw(
        "subsurface",
        "subsurface { translucency COLOUR | samples N, M radiosity BOOL }",
        "POV-Ray's subsurface light transport (in finish, interior, global_settings): read and ignored with a warning.",
    ),
    kw(
        "translucency",
        "translucency COLOUR",
        "How far light travels under the surface, per colour (in `subsurface`; ignored).",
    ),
    kw(
        "mm_per_unit",
        "mm_per_unit N",
        "Millimetres per scene unit for subsurface scattering (in global_settings; ignored).",
    ),
    // scene settings
    kw(
        "global_settings",
        "global_settings { assumed_gamma 1.0 … }",
        "Settings for the whole scene.",
    ),
    kw(
        "assumed_gamma",
        "assumed_gamma G",
        "The gamma colours are given in (use 1.0).",
    ),
    kw(
        "ambient_light",
        "ambient_light COLOUR",
        "Scales every finish's ambient (default white).",
    ),
    kw(
        "max_trace_level",
        "max_trace_level N",
        "Deepest reflection/refraction recursion (default 5).",
    ),
    kw(
        "adc_bailout",
        "adc_bailout A",
        "Stops tracing rays that contribute less than A.",
    ),
    kw(
        "path_tracing",
        "path_tracing { samples 64 max_depth 8 }",
        "In global_settings (rts): render with the path tracer (docs/pathtracing.md).",
    ),
    kw(
        "samples",
        "samples N",
        "path_tracing: samples per pixel (default 64); in media, `samples MIN[, MAX]` per interval (default 10).",
    ),
    kw(
        "max_depth",
        "max_depth N",
        "path_tracing: longest path in segments, camera ray included (default 8).",
    ),
    kw(
        "firefly_clamp",
        "firefly_clamp X",
        "path_tracing: largest channel value one sample may add (0: off).",
    ),
    kw(
        "pixel_filter",
        "pixel_filter \"box\" | \"gaussian\"",
        "path_tracing: the reconstruction filter (default gaussian).",
    ),
    kw(
        "background",
        "background { COLOUR }",
        "The colour of rays that hit nothing.",
    ),
    kw(
        "sky_sphere",
        "sky_sphere { pigment { … } }",
        "A pigment on an infinitely large sphere around the scene.",
    ),
    kw(
        "fog",
        "fog { distance D color COLOUR [fog_type 2 …] }",
        "Fog: constant or ground fog.",
    ),
    kw("fog_type", "fog_type T", "1 constant fog, 2 ground fog."),
    kw(
        "rainbow",
        "rainbow { direction <D> angle A width W color_map { … } [distance jitter up arc_angle falloff_angle] }",
        "A fog-like ring of colour round the direction the sunlight travels in.",
    ),
    kw(
        "width",
        "width W",
        "A rainbow's width in degrees (index 0 at its inner edge, 1 at its outer).",
    ),
    kw(
        "arc_angle",
        "arc_angle ARC",
        "How much of a rainbow's ring is kept, in degrees round its `up` (default 360).",
    ),
    kw(
        "falloff_angle",
        "falloff_angle FALL",
        "The middle of a rainbow's arc at full strength, in degrees; beyond it the arc fades out.",
    ),
    kw(
        "distance",
        "distance D",
        "The distance at which fog leaves 37% of the light.",
    ),
    kw(
        "fog_offset",
        "fog_offset O",
        "Ground fog: the height where it starts to thin.",
    ),
    kw(
        "fog_alt",
        "fog_alt A",
        "Ground fog: how fast it thins with height.",
    ),
    kw(
        "crackle",
        "crackle [form V] [metric P] [solid]",
        "Cells around random points: distance to the second nearest minus the nearest.",
    ),
    kw(
        "form",
        "crackle form <F1, F2, F3>",
        "crackle: weights of the distances to the nearest three points (default <-1, 1, 0>).",
    ),
    kw(
        "metric",
        "crackle metric P",
        "crackle: the distance exponent (2 Euclidean, 1 Manhattan).",
    ),
    kw(
        "solid",
        "crackle solid",
        "crackle: one value per cell.",
    ),
    kw(
        "offset",
        "warp { repeat D offset V }",
        "repeat warp: the shift of each copy (crackle's offset is not implemented yet).",
    ),
    kw(
        "number_of_waves",
        "number_of_waves N",
        "global_settings: wave centres of waves and ripples (1 to 10, default 10).",
    ),
    kw(
        "hf_gray_16",
        "hf_gray_16 [on]",
        "global_settings: POV-Ray's grey 16-bit output; ignored by rts (use --bit-depth 16).",
    ),
    kw(
        "tiles",
        "tiles { texture { … } tile2 texture { … } }",
        "POV-Ray's older checker of two textures.",
    ),
    kw(
        "tile2",
        "tiles { … tile2 texture { … } }",
        "Starts the second texture of `tiles`.",
    ),
    kw(
        "quick_color",
        "quick_color COLOUR",
        "POV-Ray's preview colour for low quality; no effect on the picture.",
    ),
    kw(
        "quick_colour",
        "quick_colour COLOUR",
        "POV-Ray's preview colour for low quality; no effect on the picture.",
    ),
    kw(
        "turb_depth",
        "turb_depth D",
        "Fog turbulence: where along the ray it is taken (0 camera, 1 surface; default 0.5).",
    ),
    kw(
        "radiosity",
        "global_settings { radiosity { count 35 error_bound 1.8 recursion_limit 2 } }",
        "Indirect diffuse light gathered from the surroundings (replaces `ambient`); in an object, `radiosity { importance F }`.",
    ),
    kw(
        "always_sample",
        "radiosity { always_sample on }",
        "radiosity: gather new values in the final pass where the pretrace left none close enough (default off).",
    ),
    kw(
        "brightness",
        "radiosity { brightness 1 }",
        "radiosity: multiplies the gathered light (default 1).",
    ),
    kw(
        "count",
        "radiosity { count 35 [, POOL] }",
        "radiosity: rays gathered per new value (default 35); optional pool of directions drawn from.",
    ),
    kw(
        "error_bound",
        "radiosity { error_bound 1.8 }",
        "radiosity: how far values are reused; lower is more accurate and slower (default 1.8).",
    ),
    kw(
        "gray_threshold",
        "radiosity { gray_threshold 0 }",
        "radiosity: 0 keeps the gathered colour, 1 makes it grey (default 0).",
    ),
    kw(
        "low_error_factor",
        "radiosity { low_error_factor 0.5 }",
        "radiosity: the pretrace uses error_bound times this (default 0.5).",
    ),
    kw(
        "max_sample",
        "radiosity { max_sample 2 }",
        "radiosity: brightest a gathered value may be, colour kept (default: no limit).",
    ),
    kw(
        "maximum_reuse",
        "radiosity { maximum_reuse 0.2 }",
        "radiosity: largest reuse radius, a fraction of the distance from the camera (default 0.2).",
    ),
    kw(
        "minimum_reuse",
        "radiosity { minimum_reuse 0.015 }",
        "radiosity: smallest reuse radius, a fraction of the distance from the camera (default 0.015).",
    ),
    kw(
        "nearest_count",
        "radiosity { nearest_count 5 }",
        "radiosity: the pretrace gathers where fewer values than this can be blended (1 to 20, default 5).",
    ),
    kw(
        "pretrace_start",
        "radiosity { pretrace_start 0.08 }",
        "radiosity: block size of the first pretrace pass, a fraction of the image (default 0.08).",
    ),
    kw(
        "pretrace_end",
        "radiosity { pretrace_end 0.04 }",
        "radiosity: block size of the last pretrace pass (default 0.04); passes halve the size.",
    ),
    kw(
        "recursion_limit",
        "radiosity { recursion_limit 2 }",
        "radiosity: bounces of diffuse light (1 to 20, default 2).",
    ),
    kw(
        "importance",
        "sphere { … radiosity { importance 0.5 } }",
        "radiosity: the share of gathering rays that hit this object and are computed (the rest are weighted in).",
    ),
    kw(
        "no_radiosity",
        "sphere { … no_radiosity }",
        "The object is invisible to radiosity's gathering rays.",
    ),
    kw(
        "photons",
        "global_settings { photons { spacing 0.01 } }  ·  sphere { … photons { target refraction on reflection on collect off } }  ·  light_source { … photons { refraction off } }",
        "Photon mapping: lights shoot photons at `target` objects; photons they reflect or refract are stored where they land and light those surfaces (caustics).",
    ),
    kw(
        "spacing",
        "photons { spacing 0.01 }",
        "Photons: about this distance between photons where they reach a target (times the target's multiplier).",
    ),
    kw(
        "gather",
        "photons { gather 20, 100 }",
        "Photons: the fewest photons an estimate gathers (the search radius grows until it has them) and the most it uses.",
    ),
    kw(
        "autostop",
        "photons { autostop 0 }",
        "Photons: accepted for POV-Ray scenes; rts always covers a target's whole bounding sphere.",
    ),
    kw(
        "expand_thresholds",
        "photons { expand_thresholds 0.2, 40 }",
        "Photons: accepted for POV-Ray scenes; rts grows the gather radius until `gather`'s minimum is met.",
    ),
    kw(
        "save_file",
        "photons { save_file \"scene.ph\" }",
        "Photons: read but ignored (rts shoots the photons for every render), with a warning.",
    ),
    kw(
        "load_file",
        "photons { load_file \"scene.ph\" }",
        "Photons: read but ignored (rts shoots the photons for every render), with a warning.",
    ),
    kw(
        "target",
        "photons { target [MULTIPLIER] }",
        "Photons: lights shoot photons at this object, `spacing × MULTIPLIER` apart (default 1).",
    ),
    kw(
        "refraction",
        "photons { refraction on }",
        "Photons: an object passes photons through, bent by its ior and tinted by filter/transmit; a light's `refraction off` keeps its photons from refracting.",
    ),
    kw(
        "collect",
        "photons { collect off }",
        "Photons: photons are neither stored on nor gathered from this object (use it on glass and mirrors).",
    ),
    kw(
        "pass_through",
        "photons { pass_through }",
        "Photons: photons on their way to a target pass through this object unaffected (`no_shadow` implies it).",
    ),
    kw(
        "split_union",
        "photons { split_union off }",
        "Photons: accepted for POV-Ray scenes; rts shoots at each part of a union separately.",
    ),
    kw(
        "media",
        "media { absorption C emission C scattering { … } density { … } method intervals samples … }",
        "Participating media (smoke, haze, glow): in an interior (the object must be hollow) or at top level (atmospheric).",
    ),
    kw(
        "absorption",
        "absorption COLOUR",
        "Media: how much light it absorbs per unit distance (default black).",
    ),
    kw(
        "scattering",
        "scattering { TYPE, COLOUR [eccentricity E] [extinction X] }",
        "Media: light scattered towards the viewer; 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein.",
    ),
    kw(
        "eccentricity",
        "eccentricity E",
        "Henyey-Greenstein scattering (type 5): -1 < E < 1, positive scatters forwards (default 0).",
    ),
    kw(
        "extinction",
        "extinction X",
        "Scattering: how much it also dims what lies behind (default 1).",
    ),
    kw(
        "density",
        "density { PATTERN density_map { … } | COLOUR }",
        "Media: scales its coefficients at each point; several multiply (default 1).",
    ),
    kw(
        "density_map",
        "density_map { [V COLOUR] … }",
        "A density's colour map (the same as color_map).",
    ),
    kw(
        "method",
        "method 1|2|3",
        "Media sampling: 1 random, 2 stratified with jitter, 3 adaptive (default).",
    ),
    kw(
        "intervals",
        "intervals N",
        "Media: pieces the ray's stretch is cut into (default 1).",
    ),
    kw(
        "ratio",
        "ratio R",
        "Media: share of intervals for parts lit by spotlights and cylinder lights (default 0.9).",
    ),
    kw(
        "aa_threshold",
        "aa_threshold T",
        "Media method 3: subdivide where samples differ by more (default 0.1).",
    ),
    kw(
        "aa_level",
        "aa_level L",
        "Media method 3: most subdivisions (default 3).",
    ),
    // splines
    kw(
        "spline",
        "spline { linear_spline T, <V> … }",
        "A spline through keyed values (POV-Ray's); call it as `S(T)`.",
    ),
    kw(
        "linear_spline",
        "linear_spline",
        "Spline type: straight segments (in spline, prism).",
    ),
    kw(
        "quadratic_spline",
        "quadratic_spline",
        "Spline type: the parabola through the points before, at and after each piece (spline, prism).",
    ),
    kw(
        "cubic_spline",
        "cubic_spline",
        "Spline type: cubic from the second point to the next-to-last (Catmull-Rom slopes; spline, prism).",
    ),
    kw(
        "natural_spline",
        "natural_spline",
        "Spline type: natural cubic.",
    ),
    // animation (ours; see docs/animation.md)
    kw(
        "animation",
        "animation { frames N | duration S  fps F  clock_range C0, C1  cyclic  motion_blur SHUTTER }",
        "The scene's own timeline: frame count or duration, frame rate, clock range.",
    ),
    kw("frames", "frames N | frames A, B", "Timeline length in frames (animation), or key times in frames (keyframes)."),
    kw("fps", "fps F", "Frames per second of the timeline."),
    kw("duration", "duration SECONDS", "Timeline length in seconds (with fps)."),
    kw("clock_range", "clock_range C0, C1", "The clock at the first and the last frame."),
    kw("cyclic", "cyclic", "Cyclic animation: the last frame is not the first one again (POV-Ray's +KC)."),
    kw("motion_blur", "motion_blur SHUTTER [, N]", "Average N instants over SHUTTER (0 to 1) of each frame."),
    kw(
        "keyframes",
        "keyframes { [catmull_rom|…] [seconds|frames] [hold|loop|ping_pong] key T, V [ease_in] … }",
        "A float, vector or colour keyed in time, usable wherever a value is.",
    ),
    kw("key", "key T, VALUE [easing]", "One key of a keyframes block."),
    kw("catmull_rom", "catmull_rom", "Keyframe interpolation: Catmull-Rom."),
    kw("bezier_spline", "bezier_spline", "Keyframe interpolation: Bézier with `tangent`s; in a prism, every 4 points are one cubic Bézier segment."),
    kw("step_spline", "step_spline", "Keyframe interpolation: hold each key until the next."),
    kw("hold", "hold", "Beyond the keys: keep the end values."),
    kw("loop", "loop", "Beyond the keys: repeat."),
    kw("ping_pong", "ping_pong", "Beyond the keys: repeat back and forth."),
    kw("seconds", "seconds", "Key times are in seconds."),
    kw("ease_in", "ease_in", "Easing of the segment after a key: slow start."),
    kw("ease_out", "ease_out", "Easing of the segment after a key: slow end."),
    kw("ease_in_out", "ease_in_out", "Easing of the segment after a key: slow start and end."),
    kw("ease_bezier", "ease_bezier X1, Y1, X2, Y2", "Easing by cubic-Bézier control points (as CSS)."),
    kw("tangent", "tangent V", "Tangent at a key of a bezier_spline."),
    kw(
        "camera_path",
        "camera_path { location C  look_at C | look_along  angle C  roll C  sky V }",
        "A keyed camera that stays level and never flips at the poles.",
    ),
    kw("look_along", "look_along", "A camera_path looks along its path's tangent."),
    kw("roll", "roll DEGREES", "A camera_path's roll about its view direction."),
    // later
    kw(
        "blob",
        "blob { threshold T  sphere { C, R, [strength] S … }  cylinder { A, B, R, [strength] S … } … }",
        "The surface where the summed fields of spherical and cylindrical components equal the threshold; each component's field falls from S at its centre (or axis) to 0 at radius R as S·(1 − (d/R)²)²; inside where the field is above the threshold. Components may have their own textures (blended by field) and transforms.",
    ),
    kw(
        "threshold",
        "threshold T",
        "The surface's value: a blob's surface is where the summed field equals T (default 1; inside above it), an isosurface's where the function equals T (default 0; inside below it).",
    ),
    kw(
        "strength",
        "sphere { C, R, strength S }",
        "The field of a blob component at its centre or axis (the keyword itself may be left out); negative strengths carve.",
    ),
    kw(
        "component",
        "component S, R, C",
        "POV-Ray's old spelling of a spherical blob component: strength, radius, centre.",
    ),
    kw(
        "hierarchy",
        "hierarchy [on|off]",
        "Accepted on a blob: rts always bounds many components with a hierarchy of its own.",
    ),
    kw(
        "isosurface",
        "isosurface { function { … } [contained_by { box { … } | sphere { … } }] [threshold T] [accuracy A] [max_gradient G] [open] [max_trace N | all_intersections] … }",
        "The surface where a function equals its threshold, inside where it is below, cut by its container (a box from <-1,-1,-1> to <1,1,1> unless given).",
    ),
    kw(
        "contained_by",
        "contained_by { box { A, B } | sphere { C, R } }",
        "The region an isosurface is searched in; where the function is below the threshold on it, its surface shows (unless `open`).",
    ),
    kw(
        "accuracy",
        "accuracy A",
        "How closely an isosurface's root is found along the ray (default 0.001).",
    ),
    kw(
        "max_gradient",
        "max_gradient G",
        "An upper bound of the isosurface function's slope (default 1.1): rts steps along a ray no further than the function's distance to the threshold divided by G; too low a value misses surfaces (rts warns with the measured slope).",
    ),
    kw(
        "evaluate",
        "evaluate P0, P1, P2",
        "POV-Ray's adaptive max_gradient for isosurfaces: rts takes P0 times P1 as max_gradient.",
    ),
    kw(
        "all_intersections",
        "all_intersections",
        "An isosurface reports every crossing along a ray (needed for a closed cut in CSG).",
    ),
    kw(
        "max_trace",
        "max_trace N",
        "How many crossings along a ray an isosurface reports (default 1, as in POV-Ray).",
    ),
    kw(
        "function",
        "function { EXPR } | function(A, B, …) { EXPR } | function { pigment { … } } | function { pattern { … } }",
        "A user-defined function of x, y, z (or of the named parameters), compiled once; call it as F(…) in expressions, use it as a pattern or as an isosurface's function.",
    ),
    kw(
        "pattern",
        "function { pattern { PATTERN modifiers } }",
        "A function giving a pattern's value (0 to 1) at <x, y, z>.",
    ),
    kw(
        "julia_fractal",
        "julia_fractal { <C4> [quaternion | hypercomplex] [sqr | cube | …] [max_iteration N] [precision P] [slice <N4>, D] … }",
        "The 3D slice of a 4D Julia set z ← f(z) + c; inside are the points whose orbit stays within radius 2 for max_iteration steps (defaults: quaternion sqr, 20 iterations, precision 20, slice <0,0,0,1>, 0).",
    ),
    kw("quaternion", "julia_fractal { … quaternion }", "A Julia fractal in quaternion algebra (the default; `sqr` or `cube` only)."),
    kw("hypercomplex", "julia_fractal { … hypercomplex }", "A Julia fractal in hypercomplex (bicomplex) algebra, which takes any of its functions."),
    kw("sqr", "julia_fractal { … sqr }", "The Julia fractal iterates z² + c (the default)."),
    kw("cube", "julia_fractal { … cube }", "The Julia fractal iterates z³ + c."),
    kw("reciprocal", "julia_fractal { … hypercomplex reciprocal }", "The Julia fractal iterates 1/z + c (hypercomplex only)."),
    kw("max_iteration", "max_iteration N", "How many steps an orbit must stay bounded for a point to be inside a Julia fractal (default 20, at least 1)."),
    kw("precision", "precision P", "A Julia fractal's sampling: larger is finer and slower (default 20)."),
    kw("slice", "slice <N4>, D", "The hyperplane of 4D space a Julia fractal is cut by (default <0, 0, 0, 1>, 0: w = 0)."),
    kw(
        "lathe",
        "lathe { [SPLINE] N, <x,y>… [sturm] … }",
        "A 2-D spline in the x-y plane (x the radius, y the height) revolved around the y axis; SPLINE is linear_spline (default), quadratic_spline, cubic_spline or bezier_spline.",
    ),
    kw(
        "prism",
        "prism { [SPLINE] [linear_sweep|conic_sweep] H1, H2, N, <u,v>… [open] … }",
        "Closed 2-D curves in the x-z plane swept along y from H1 to H2 (conic_sweep: scaled by y from the origin).",
    ),
    kw(
        "linear_sweep",
        "prism { linear_sweep … }",
        "Prism sweep (the default): the outline goes straight up from H1 to H2.",
    ),
    kw(
        "conic_sweep",
        "prism { conic_sweep … }",
        "Prism sweep: the outline is scaled by y, from a point at the origin to full size at y = 1.",
    ),
    kw(
        "sor",
        "sor { N, <r,h>… [open] [sturm] … }",
        "A surface of revolution around y: r² is a cubic spline over the height through the points (the first and last are control points), with flat end caps unless open.",
    ),
    kw(
        "superellipsoid",
        "superellipsoid { <E, N> }",
        "The surface (|x|^(2/E) + |y|^(2/E))^(E/N) + |z|^(2/N) = 1 within the box from −1 to 1: small exponents give a rounded box, 1 a sphere, 2 an octahedron, larger ones pinched stars.",
    ),
    kw(
        "text",
        "text { ttf \"FONT.ttf\" \"STRING\" THICKNESS, OFFSET … }",
        "3-D text: the string's glyphs in the x-y plane, baseline on y = 0 from x = 0, 1 unit per em, extruded from z = 0 to z = THICKNESS; OFFSET <x, y> is added after each character. A solid (works in CSG).",
    ),
    kw(
        "ttf",
        "text { ttf \"FONT.ttf\" … }",
        "The TrueType/OpenType font file of a text: searched in the scene's folders, -I folders, then POV-Ray's font folder (timrom.ttf, cyrvetic.ttf, crystal.ttf, povlogo.ttf); `.ttf` is added to a name without extension.",
    ),
    kw(
        "internal",
        "text { internal N … }",
        "POV-Ray's built-in font N (0 povlogo, 1 timrom, 2 cyrvetic, 3 crystal), read from POV-Ray's installed font files.",
    ),
    kw(
        "sphere_sweep",
        "sphere_sweep { linear_spline | b_spline | cubic_spline N, <P1>, R1, … [tolerance T] … }",
        "The solid a sphere fills as it moves along a spline, its radius interpolated too (linear_spline needs 2 spheres, b_spline and cubic_spline 4).",
    ),
    kw("b_spline", "sphere_sweep { b_spline N, … }", "A uniform cubic B-spline: smooth, passing near its points."),
    kw("tolerance", "tolerance T", "How closely a sphere sweep's surface is found, relative to its size (default 1e-6)."),
    kw(
        "bicubic_patch",
        "bicubic_patch { type 0|1 [flatness F] [u_steps N] [v_steps M] [accuracy A] <P1>, …, <P16> [uv_vectors <UV1>, …, <UV4>] … }",
        "A Bézier patch of 4×4 control points, drawn as 2^u_steps × 2^v_steps cells of smooth triangles (default 0: one cell). No inside.",
    ),
    kw("type", "bicubic_patch { type 1 … }", "A bicubic patch's type, 0 or 1 (both give the same picture)."),
    kw("flatness", "flatness F", "A bicubic patch's flatness (accepted; rts always subdivides fully)."),
    kw("u_steps", "u_steps N", "A bicubic patch is split into 2^N strips across its rows of points (default 0)."),
    kw("v_steps", "v_steps N", "A bicubic patch is split into 2^N strips along its rows of points (default 0)."),
    kw(
        "warp",
        "warp { turbulence T | repeat D | black_hole C, R | cylindrical | spherical | toroidal | planar … }",
        "Moves the points of a pattern before it is evaluated; several apply in the order written, with the transforms between them.",
    ),
    kw(
        "normal_map",
        "normal { PATTERN normal_map { [V NORMAL] … } }",
        "The normals a normal's pattern blends by its value (with `average`: weights).",
    ),
    kw(
        "pigment_pattern",
        "pigment_pattern { PIGMENT }",
        "A pattern whose value is the pigment's grey value (0.297 R + 0.589 G + 0.114 B).",
    ),
    kw(
        "image_pattern",
        "image_pattern { png \"FILE\" [map_type N] [interpolate 2] [once] [use_alpha] }",
        "A pattern whose value is an image's grey value (or opacity with use_alpha).",
    ),
    kw(
        "slope",
        "slope { DIRECTION [, LO, HI] [altitude DIRECTION [, LO, HI]] }",
        "A pattern of how far the surface faces a direction (1 facing it, 0.5 across, 0 away), mixed with the height along `altitude`.",
    ),
    kw(
        "altitude",
        "slope { DIRECTION altitude DIRECTION [, LO, HI] }",
        "Mixes the point's height along a direction into the slope pattern.",
    ),
    kw(
        "average",
        "pigment { average pigment_map { [W P] … } }",
        "Averages the entries of a pigment, normal or texture map, weighed by their values.",
    ),
    kw(
        "slope_map",
        "normal { PATTERN slope_map { [V, <HEIGHT, SLOPE>] … } }",
        "Turns a normal pattern's value into a height profile whose slope tilts the normal.",
    ),
    kw(
        "bump_map",
        "normal { bump_map { png \"FILE\" [bump_size B] [use_color|use_index] … } }",
        "Bumps whose heights are an image's grey values (or palette indices).",
    ),
    kw(
        "material_map",
        "texture { material_map { png \"FILE\" texture { … } … } }",
        "Textures chosen by an image's palette index at each point.",
    ),
    kw(
        "interior_texture",
        "object { … interior_texture { … } }",
        "The texture seen where a ray meets the surface from inside.",
    ),
    kw(
        "use_alpha",
        "image_pattern { … use_alpha }",
        "Takes an image pattern's value from the pixels' opacity.",
    ),
    kw(
        "use_color",
        "bump_map { … use_color }",
        "Takes heights or values from the pixels' grey value (the default).",
    ),
    kw(
        "use_colour",
        "bump_map { … use_colour }",
        "Same as use_color.",
    ),
    kw(
        "use_index",
        "bump_map { … use_index }",
        "Takes heights or values from the pixels' palette index.",
    ),
    // ------------------------------------------------------------------ built-in constants
    constant("pi", "pi", "3.14159…"),
    constant("tau", "tau", "2π."),
    constant("x", "x", "The vector <1, 0, 0>."),
    constant("y", "y", "The vector <0, 1, 0>."),
    constant("z", "z", "The vector <0, 0, 1>."),
    constant("t", "t", "The 4-vector <0, 0, 0, 1>."),
    constant("u", "u", "The 2-vector <1, 0>."),
    constant("v", "v", "The 2-vector <0, 1>."),
    constant("true", "true", "1."),
    constant("false", "false", "0."),
    constant("on", "on", "1."),
    constant("off", "off", "0."),
    constant("yes", "yes", "1."),
    constant("no", "no", "0."),
    constant(
        "clock",
        "clock",
        "The animation clock (--clock; 0 for a still).",
    ),
    constant(
        "clock_delta",
        "clock_delta",
        "The clock step between frames.",
    ),
    constant("clock_on", "clock_on", "1 when an animation is rendered."),
    constant(
        "frame_number",
        "frame_number",
        "The current frame of an animation.",
    ),
    constant(
        "initial_frame",
        "initial_frame",
        "The first frame of an animation.",
    ),
    constant(
        "final_frame",
        "final_frame",
        "The last frame of an animation.",
    ),
    constant(
        "initial_clock",
        "initial_clock",
        "The clock at the first frame.",
    ),
    constant("final_clock", "final_clock", "The clock at the last frame."),
    constant(
        "image_width",
        "image_width",
        "The width of the image in pixels.",
    ),
    constant(
        "image_height",
        "image_height",
        "The height of the image in pixels.",
    ),
    constant("version", "version", "The language version (3.7)."),
    // ------------------------------------------------------------------ built-in functions
    func("abs", "abs(A)", "Absolute value."),
    func("acos", "acos(A)", "Arc cosine, in radians."),
    func("asin", "asin(A)", "Arc sine, in radians."),
    func("atan", "atan(A)", "Arc tangent, in radians."),
    func(
        "atan2",
        "atan2(A, B)",
        "Arc tangent of A/B using both signs, in radians.",
    ),
    func("ceil", "ceil(A)", "The smallest integer ≥ A."),
    func("cos", "cos(A)", "Cosine of A radians."),
    func("cosh", "cosh(A)", "Hyperbolic cosine."),
    func("degrees", "degrees(A)", "Radians to degrees."),
    func("radians", "radians(A)", "Degrees to radians."),
    func(
        "div",
        "div(A, B)",
        "Integer division, truncated towards zero.",
    ),
    func("exp", "exp(A)", "e to the power A."),
    func("floor", "floor(A)", "The largest integer ≤ A."),
    func("int", "int(A)", "A truncated towards zero."),
    func("ln", "ln(A)", "Natural logarithm."),
    func("log", "log(A)", "Base-10 logarithm."),
    func("max", "max(A, B, …)", "The largest argument."),
    func("min", "min(A, B, …)", "The smallest argument."),
    func("mod", "mod(A, B)", "Remainder of A/B, with the sign of A."),
    func("pow", "pow(A, B)", "A to the power B."),
    func("sin", "sin(A)", "Sine of A radians."),
    func("sinh", "sinh(A)", "Hyperbolic sine."),
    func("sqrt", "sqrt(A)", "Square root."),
    func("tan", "tan(A)", "Tangent of A radians."),
    func("tanh", "tanh(A)", "Hyperbolic tangent."),
    func("acosh", "acosh(A)", "Inverse hyperbolic cosine."),
    func("asinh", "asinh(A)", "Inverse hyperbolic sine."),
    func("atanh", "atanh(A)", "Inverse hyperbolic tangent."),
    func(
        "select",
        "select(A, NEG, ZERO [, POS])",
        "Chooses by the sign of A.",
    ),
    func("vlength", "vlength(V)", "The length of a vector."),
    func("vnormalize", "vnormalize(V)", "V scaled to length 1."),
    func("vdot", "vdot(A, B)", "Dot product."),
    func("vcross", "vcross(A, B)", "Cross product."),
    func(
        "vrotate",
        "vrotate(V, <X, Y, Z>)",
        "V rotated by degrees about x, y, z.",
    ),
    func(
        "vaxis_rotate",
        "vaxis_rotate(V, AXIS, DEG)",
        "V rotated DEG degrees about AXIS.",
    ),
    func(
        "vtransform",
        "vtransform(V, TRANSFORM)",
        "The point V moved by TRANSFORM (as transforms.inc's vtransform).",
    ),
    func(
        "vinv_transform",
        "vinv_transform(V, TRANSFORM)",
        "The point V moved by the inverse of TRANSFORM (as transforms.inc's vinv_transform).",
    ),
    func(
        "inside",
        "inside(OBJECT, POINT)",
        "1 when POINT is inside the solid OBJECT (as CSG decides it), else 0.",
    ),
    func(
        "min_extent",
        "min_extent(OBJECT)",
        "The lowest corner of the object's bounding box (±1e10 when unbounded).",
    ),
    func(
        "max_extent",
        "max_extent(OBJECT)",
        "The highest corner of the object's bounding box (±1e10 when unbounded).",
    ),
    func(
        "seed",
        "seed(N)",
        "A random stream for rand, seeded with N.",
    ),
    func(
        "rand",
        "rand(STREAM)",
        "The next number in [0, 1) of a seed() stream.",
    ),
    func("str", "str(A, WIDTH, DECIMALS)", "A float as text: at least |WIDTH| characters (zero-padded when WIDTH < 0), DECIMALS decimals (six when negative, as in POV-Ray)."),
    func("concat", "concat(S1, S2, …)", "Joins strings."),
    func("strlen", "strlen(S)", "The length of a string."),
    func(
        "strcmp",
        "strcmp(S1, S2)",
        "Compares two strings: 0 when equal, else the difference of the first characters that differ (negative when S1 sorts first), as C and POV-Ray do.",
    ),
    func(
        "substr",
        "substr(S, START, LENGTH)",
        "Part of a string (START is 1-based).",
    ),
    func("chr", "chr(N)", "The character with code N."),
    func("asc", "asc(S)", "The code of the first character of S."),
    func("val", "val(S)", "The number a string holds."),
    func("strupr", "strupr(S)", "S in upper case."),
    func("strlwr", "strlwr(S)", "S in lower case."),
    func(
        "vstr",
        "vstr(N, V, SEP, WIDTH, DECIMALS)",
        "The first N components of V as text.",
    ),
    func(
        "dimensions",
        "dimensions(ARRAY)",
        "How many dimensions an array has.",
    ),
    func(
        "dimension_size",
        "dimension_size(ARRAY, D)",
        "The size of dimension D (1-based) of an array.",
    ),
    func("defined", "defined(NAME)", "1 when NAME is declared."),
    func(
        "bitwise_and",
        "bitwise_and(A, B, …)",
        "Bitwise and of integers.",
    ),
    func(
        "bitwise_or",
        "bitwise_or(A, B, …)",
        "Bitwise or of integers.",
    ),
    func(
        "bitwise_xor",
        "bitwise_xor(A, B, …)",
        "Bitwise exclusive or of integers.",
    ),
    func(
        "trace",
        "trace(OBJECT, START, DIRECTION [, NORMAL])",
        "Where the ray from START along DIRECTION first meets OBJECT (<0, 0, 0> on a miss); NORMAL, a name, receives the normal there.",
    ),
    // Warps, geometric, quilted, spiral and fractal patterns.
    func(
        "vturbulence",
        "vturbulence(LAMBDA, OMEGA, OCTAVES, <P>)",
        "The turbulence displacement vector at P.",
    ),
    kw("planar", "planar", "Pattern: 1 on the x-z plane, falling to 0 at distance 1; as a warp, drops z."),
    kw("cylindrical", "cylindrical", "Pattern: 1 on the y axis, falling to 0 at distance 1; as a warp, maps to (angle, height, distance)."),
    kw("boxed", "boxed", "Pattern: 1 at the origin, falling to 0 on the cube of side 2."),
    kw("toroidal", "warp { toroidal [major_radius R] }", "Warp: maps to (angle, tube angle, distance from the ring)."),
    kw("quilted", "quilted [control0 C0] [control1 C1]", "Pattern: cushions in each unit cube."),
    kw("control0", "quilted control0 C", "quilted: the first control of the cushion's curve (default 1)."),
    kw("control1", "quilted control1 C", "quilted: the second control of the cushion's curve (default 1)."),
    kw("spiral1", "spiral1 ARMS", "Pattern: arms winding around z like a screw thread."),
    kw("spiral2", "spiral2 ARMS", "Pattern: two spirals twisting in opposite directions."),
    kw("mandel", "mandel ITERATIONS [exponent N] [exterior T, F] [interior T, F]", "Pattern: the Mandelbrot set in the x-y plane."),
    kw("julia", "julia <RE, IM>, ITERATIONS", "Pattern: the Julia set of the parameter, in the x-y plane."),
    kw("magnet", "magnet 1|2 mandel ITERATIONS | magnet 1|2 julia <RE, IM>, ITERATIONS", "Pattern: the magnet fractals."),
    kw("exterior", "exterior TYPE, FACTOR", "Fractal pattern: the value outside the set (default 1, 1: the iteration count)."),
    kw("black_hole", "warp { black_hole CENTRE, RADIUS [strength S] [falloff F] [inverse] [repeat V] [turbulence V] }", "Warp: pulls the pattern towards a centre."),
    kw("repeat", "warp { repeat D [offset V] [flip V] }", "Warp: repeats a slab of the pattern along one axis."),
    kw("flip", "warp { repeat D flip V }", "repeat warp: mirror these axes in every other copy."),
    kw("orientation", "orientation V", "Mapping warp: the direction its z lies along (default z)."),
    kw("dist_exp", "dist_exp E", "Mapping warp: angular coordinates times distance^E (default 0)."),
    kw("major_radius", "major_radius R", "toroidal warp: the ring's radius (default 1)."),
];

/// The documentation of `word` as a keyword, function or constant (not a directive).
pub fn lookup(word: &str) -> Option<&'static Doc> {
    DOCS.iter()
        .find(|d| d.name == word && d.kind != DocKind::Directive)
}

/// The documentation of directive `#word`.
pub fn directive(word: &str) -> Option<&'static Doc> {
    DOCS.iter()
        .find(|d| d.name == word && d.kind == DocKind::Directive)
}

/// The hover text (Markdown) of a documented word.
pub fn markdown(doc: &Doc) -> String {
    let what = match doc.kind {
        DocKind::Keyword => "keyword",
        DocKind::Directive => "directive",
        DocKind::Function => "built-in function",
        DocKind::Constant => "built-in constant",
    };
    format!("```rts\n{}\n```\n{} *({what})*", doc.syntax, doc.summary)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::BUILTIN_NAMES;
    use crate::syntax::keywords::KEYWORDS;

    #[test]
    fn every_keyword_and_builtin_is_documented_once() {
        for k in KEYWORDS {
            assert!(
                lookup(k).is_some(),
                "keyword `{k}` has no entry in ide::docs::DOCS"
            );
        }
        for (i, b) in BUILTIN_NAMES.iter().enumerate() {
            let d = lookup(b).unwrap_or_else(|| panic!("built-in `{b}` has no entry"));
            let want = if crate::eval::is_builtin_function(i) {
                DocKind::Function
            } else {
                DocKind::Constant
            };
            assert_eq!(d.kind, want, "{b}");
        }
        let mut seen = std::collections::HashSet::new();
        for d in DOCS {
            assert!(
                seen.insert((d.name, d.kind == DocKind::Directive)),
                "`{}` twice",
                d.name
            );
        }
    }

    /// Every implemented word the table documents is described in docs/language.md
    /// too (written there in backticks, alone or as part of an example).
    #[test]
    fn implemented_words_appear_in_language_md() {
        let md = include_str!("../../docs/language.md");
        let words: std::collections::HashSet<&str> = md
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .collect();
        let missing: Vec<&str> = DOCS
            .iter()
            .filter(|d| !words.contains(d.name))
            .map(|d| d.name)
            .collect();
        assert!(missing.is_empty(), "not in docs/language.md: {missing:?}");
    }
}
