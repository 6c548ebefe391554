//! Interned identifiers: names are stored once and compared as integers.
//!
//! The built-in function and constant names are interned first, in the order of
//! [`super::builtins::BUILTIN_NAMES`], so a symbol below that list's length *is* a
//! built-in and its number indexes the list.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// An interned name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Sym(pub u32);

#[derive(Default)]
struct Interner {
    map: HashMap<Arc<str>, Sym>,
    names: Vec<Arc<str>>,
}

fn interner() -> &'static Mutex<Interner> {
    static INTERNER: OnceLock<Mutex<Interner>> = OnceLock::new();
    INTERNER.get_or_init(|| {
        let mut i = Interner::default();
        // Room for the built-ins and the names of the library files (no
        // rehashing while `colors.inc` and friends are cut).
        i.map.reserve(4096);
        i.names.reserve(4096);
        for name in super::builtins::BUILTIN_NAMES {
            i.intern(name);
        }
        Mutex::new(i)
    })
}

impl Interner {
    fn intern(&mut self, name: &str) -> Sym {
        if let Some(&s) = self.map.get(name) {
            return s;
        }
        let s = Sym(self.names.len() as u32);
        let name: Arc<str> = Arc::from(name);
        self.names.push(name.clone());
        self.map.insert(name, s);
        s
    }
}

/// The symbol for `name`.
pub fn intern(name: &str) -> Sym {
    interner()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .intern(name)
}

impl Sym {
    /// The name this symbol stands for.
    pub fn name(self) -> Arc<str> {
        let i = interner().lock().unwrap_or_else(|e| e.into_inner());
        i.names[self.0 as usize].clone()
    }

    /// Whether this is a built-in function or constant.
    pub fn is_builtin(self) -> bool {
        (self.0 as usize) < super::builtins::BUILTIN_NAMES.len()
    }
}

impl std::fmt::Display for Sym {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name())
    }
}
