//! What several benches share.

use rts::eval::{self, EvalOptions};
use rts::source::SourceMap;
use std::path::Path;

/// `examples/NAME` read, parsed, evaluated and built (panics when it cannot be
/// read: a bench has nothing to measure then).
pub fn example_world(name: &str) -> rts::build::World {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name);
    let mut sources = SourceMap::new();
    let id = eval::load_file(&mut sources, &path, name.into())
        .unwrap_or_else(|_| panic!("cannot read {}", path.display()));
    let text = sources.get(id).text.clone();
    let (file, _) = rts::syntax::parse(&text, id);
    let scene = eval::eval(&file, id, &mut sources, &EvalOptions::default()).scene;
    rts::build::build(&scene)
}
