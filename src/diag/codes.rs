//! The stable diagnostic codes. Codes never change meaning once released; new problems
//! get new codes. `docs/diagnostics.md` lists them with an example each.

/// The parser expected something else here.
pub const SYNTAX_EXPECTED: &str = "rts::syntax::expected";
/// A `{`, `(`, `[` or `<` was never closed.
pub const UNCLOSED_DELIMITER: &str = "rts::syntax::unclosed_delimiter";
/// A closing `}`, `)` or `]` with no opener, or closing the wrong opener.
pub const UNMATCHED_DELIMITER: &str = "rts::syntax::unmatched_delimiter";
/// A string literal runs to the end of the line or file.
pub const UNCLOSED_STRING: &str = "rts::syntax::unclosed_string";
/// A `/*` comment is never closed.
pub const UNCLOSED_COMMENT: &str = "rts::syntax::unclosed_comment";
/// An `#if`, `#while`, `#for`, `#macro`, `#switch`, `#ifdef` or `#ifndef` without `#end`.
pub const UNCLOSED_DIRECTIVE: &str = "rts::syntax::unclosed_directive";
/// An `#end`, `#else`, `#elseif`, `#case`, `#range` or `#break` with nothing to close.
pub const STRAY_DIRECTIVE: &str = "rts::syntax::stray_directive";
/// A word that is not a keyword before `{` (a misspelled block keyword).
pub const UNKNOWN_BLOCK: &str = "rts::syntax::unknown_block";
/// A `#word` that is not a directive.
pub const UNKNOWN_DIRECTIVE: &str = "rts::syntax::unknown_directive";
/// The file is not valid UTF-8.
pub const INVALID_UTF8: &str = "rts::source::invalid_utf8";
/// A malformed escape sequence in a string.
pub const BAD_ESCAPE: &str = "rts::syntax::bad_escape";
/// A number literal that does not fit.
pub const BAD_NUMBER: &str = "rts::syntax::bad_number";
/// Brackets, blocks or expressions nested too deeply.
pub const NESTING_TOO_DEEP: &str = "rts::limit::nesting_depth";

/// An identifier that is not declared.
pub const UNKNOWN_IDENTIFIER: &str = "rts::eval::unknown_identifier";
/// A keyword that is not valid in this block.
pub const UNKNOWN_PARAMETER: &str = "rts::eval::unknown_parameter";
/// Something that does not belong where it stands in a block.
pub const UNEXPECTED_ITEM: &str = "rts::eval::unexpected_item";
/// A value of the wrong kind.
pub const TYPE_MISMATCH: &str = "rts::eval::type_mismatch";
/// A required value is missing.
pub const MISSING_VALUE: &str = "rts::eval::missing_value";
/// A parameter given twice in the same block.
pub const DUPLICATE_PARAMETER: &str = "rts::eval::duplicate_parameter";
/// Division by zero.
pub const DIVISION_BY_ZERO: &str = "rts::eval::division_by_zero";
/// A function called outside its domain (`sqrt(-1)`, `ln(0)`, …).
pub const DOMAIN_ERROR: &str = "rts::eval::domain_error";
/// An array index outside the array.
pub const INDEX_OUT_OF_RANGE: &str = "rts::eval::index_out_of_range";
/// An array element read before it was given a value.
pub const UNINITIALIZED: &str = "rts::eval::uninitialized_element";
/// `.x`, `.red`, … on a value that has no such component.
pub const BAD_COMPONENT: &str = "rts::eval::bad_component";
/// A size, radius or count that must be positive is not.
pub const INVALID_SIZE: &str = "rts::eval::invalid_size";
/// A value outside the range the parameter accepts.
pub const OUT_OF_RANGE: &str = "rts::eval::out_of_range";
/// A macro or function called with the wrong number of arguments.
pub const ARITY: &str = "rts::eval::arity";
/// A macro declares the same parameter twice.
pub const DUPLICATE_MACRO_PARAMETER: &str = "rts::eval::duplicate_macro_parameter";
/// An attempt to redefine a built-in name or keyword.
pub const RESERVED_NAME: &str = "rts::eval::reserved_name";
/// `#error` in the scene.
pub const USER_ERROR: &str = "rts::scene::error";
/// `#warning` in the scene.
pub const USER_WARNING: &str = "rts::scene::warning";
/// `#debug` output.
pub const USER_DEBUG: &str = "rts::scene::debug";
/// An include or image file that cannot be found or read.
pub const FILE_NOT_FOUND: &str = "rts::io::file_not_found";
/// A file outside the folders a scene may read.
pub const FILE_NOT_ALLOWED: &str = "rts::io::file_not_allowed";
/// `#fopen`, `#read`, `#write` or `#fclose` misused: a file not open, opened
/// the wrong way, unreadable data, or a file that cannot be written.
pub const FILE_IO: &str = "rts::io::file_io";
/// A file a scene names that is not a regular file: a FIFO, a device or a folder
/// read, or a link or non-regular file at a name `#fopen` writes.
pub const NOT_REGULAR_FILE: &str = "rts::io::not_a_regular_file";
/// A file that includes itself, directly or not.
pub const INCLUDE_CYCLE: &str = "rts::eval::include_cycle";
/// Too many loop iterations.
pub const LOOP_LIMIT: &str = "rts::limit::loop_iterations";
/// Macros calling macros too deeply.
pub const RECURSION_LIMIT: &str = "rts::limit::macro_recursion";
/// Includes nested too deeply.
pub const INCLUDE_DEPTH: &str = "rts::limit::include_depth";
/// A scene or `#include`d file (or a file `#fopen` reads) larger than
/// `--max-source-size`.
pub const SOURCE_SIZE: &str = "rts::limit::source_size";
/// `#write` past `--max-write` bytes in all files together.
pub const WRITE_SIZE: &str = "rts::limit::write_size";
/// An array larger than allowed.
pub const ARRAY_SIZE: &str = "rts::limit::array_size";
/// Objects nested deeper than `--max-object-depth` (CSG in CSG, `clipped_by`).
pub const OBJECT_DEPTH: &str = "rts::limit::object_depth";
/// The evaluation grew the heap past `--max-memory`.
pub const MEMORY_LIMIT: &str = "rts::limit::memory";
/// More macro calls than `--max-macro-calls`.
pub const MACRO_CALLS: &str = "rts::limit::macro_calls";
/// A string longer than `--max-string-length`.
pub const STRING_LENGTH: &str = "rts::limit::string_length";
/// Evaluation stopped after `--max-errors` errors.
pub const ERROR_LIMIT: &str = "rts::limit::errors";
/// An editor's evaluation ran past its time.
pub const TIME_LIMIT: &str = "rts::limit::time";
/// An image larger than allowed.
pub const IMAGE_SIZE: &str = "rts::limit::image_size";
/// Images a scene reads that hold more pixels than `--max-image-pixels` allows.
pub const IMAGE_PIXELS: &str = "rts::limit::image_pixels";
/// A construct rts knows from POV-Ray but does not implement yet.
pub const UNSUPPORTED: &str = "rts::eval::unsupported";
/// A transform that cannot be inverted (`scale 0`, a singular matrix).
pub const DEGENERATE_TRANSFORM: &str = "rts::eval::degenerate_transform";
/// A camera whose vectors are degenerate.
pub const BAD_CAMERA: &str = "rts::eval::bad_camera";
/// A `-D NAME=VALUE` that is malformed.
pub const BAD_DEFINE: &str = "rts::cli::bad_define";
/// A `#declare` that is never used (warning).
pub const UNUSED_DECLARE: &str = "rts::lint::unused_declare";
/// A use of a name declared `deprecated` (warning with the declaration's message).
pub const DEPRECATED: &str = "rts::lint::deprecated";
/// A scene without `assumed_gamma` (warning, as POV-Ray 3.7 gives).
pub const NO_GAMMA: &str = "rts::lint::assumed_gamma_missing";
/// A scene with no light sources (warning).
pub const NO_LIGHTS: &str = "rts::lint::no_lights";
/// A `warp { }` written before any pattern.
pub const WARP_WITHOUT_PATTERN: &str = "rts::eval::warp_without_pattern";
/// A patterned texture layered over or under another texture.
pub const PATTERNED_LAYER: &str = "rts::eval::patterned_layer";
/// A `slope_map` entry that is not `[VALUE, <HEIGHT, SLOPE>]`.
pub const SLOPE_MAP_ENTRY: &str = "rts::eval::slope_map_entry";
/// Map entries whose values go down (warning).
pub const MAP_OUT_OF_ORDER: &str = "rts::lint::map_out_of_order";
/// A deprecated or ignored construct (warning).
pub const IGNORED: &str = "rts::lint::ignored";
/// Keyframe times that do not increase.
pub const KEYS_OUT_OF_ORDER: &str = "rts::anim::keys_out_of_order";
/// Keys of one `keyframes` holding different kinds of value.
pub const KEY_MIXED_TYPES: &str = "rts::anim::mixed_key_types";
/// A key outside the timeline's clock range (warning).
pub const KEY_OUTSIDE_TIMELINE: &str = "rts::anim::key_outside_timeline";

/// A `function { }` too complex to compile (stack, call or inline depth).
pub const FUNCTION_LIMIT: &str = "rts::limit::function_complexity";
/// An isosurface's `max_gradient` is below the gradient measured in its container.
pub const MAX_GRADIENT: &str = "rts::lint::max_gradient";
/// An object with media in its interior that is not `hollow`: its media is not
/// seen (warning).
pub const MEDIA_NOT_HOLLOW: &str = "rts::lint::media_not_hollow";
/// The path tracer renders a scene with media without them (warning).
pub const MEDIA_IGNORED: &str = "rts::render::media_ignored";
/// `rts render --shard I/N` of a still with an option no band can reproduce.
pub const SHARD_UNSUPPORTED: &str = "rts::shard::unsupported";
/// `rts merge`: parts rendered from different scene files (or includes, data files).
pub const MERGE_DIFFERENT_SCENE: &str = "rts::merge::different_scene";
/// `rts merge`: parts rendered with different options.
pub const MERGE_DIFFERENT_OPTIONS: &str = "rts::merge::different_options";
/// `rts merge`: rows of the image that no part holds (a shard not rendered).
pub const MERGE_MISSING_BAND: &str = "rts::merge::missing_band";
/// `rts merge`: two parts hold the same rows.
pub const MERGE_OVERLAPPING_BANDS: &str = "rts::merge::overlapping_bands";
/// `rts merge`: a part or its manifest unreadable, or changed since it was recorded.
pub const MERGE_BAD_PART: &str = "rts::merge::bad_part";
