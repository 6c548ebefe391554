//! Hover: the documentation of a keyword, directive, built-in function or constant
//! (from [`super::docs`]), or for a user's name its definition, kind, value and where
//! it is defined.

use super::index::{Def, DefKind};
use super::lexer::{token_at, tokenize, TokKind};
use super::{docs, Analysis, Position, Range};

/// The hover text (Markdown) at `pos` and the range of the word it describes.
pub fn hover(a: &Analysis, pos: Position) -> Option<(String, Range)> {
    let text = a.text();
    let offset = a.offset(pos);
    let toks = tokenize(text);
    let tok = token_at(&toks, offset)?;
    let range = a.lines.range(text, tok.start, tok.end);
    let word = &text[tok.start..tok.end];
    match tok.kind {
        TokKind::Directive => {
            let d = docs::directive(&word[1..])?;
            Some((docs::markdown(d), range))
        }
        TokKind::Word => {
            if let Some(def) = a.index.symbol_at(a.main, offset) {
                return Some((describe(a, def), range));
            }
            let d = docs::lookup(word)?;
            Some((docs::markdown(d), range))
        }
        TokKind::Str => {
            let inc = a.index.includes.iter().find(|i| {
                i.span.file == a.main
                    && i.span.start as usize <= offset
                    && offset <= i.span.end as usize
            })?;
            let target = inc.target?;
            let f = a.sources.get(target);
            let shown = f
                .path
                .as_ref()
                .map_or(f.name.clone(), |p| p.display().to_string());
            Some((format!("includes `{shown}`"), range))
        }
        _ => None,
    }
}

/// The first line of a definition's text, shortened.
fn head(a: &Analysis, def: &Def) -> String {
    let snippet = a.sources.snippet(def.full);
    let mut line = snippet.lines().next().unwrap_or("").trim_end().to_string();
    if line.chars().count() > 120 {
        line = line.chars().take(117).collect::<String>() + "…";
    } else if snippet.lines().nth(1).is_some() && !line.ends_with('}') {
        line.push_str(" …");
    }
    line
}

/// The hover text of a user's name.
pub(super) fn describe(a: &Analysis, def: &Def) -> String {
    let name = def.name.to_string();
    let code = match def.kind {
        DefKind::Macro => format!("#macro {name}({})", def.params.join(", ")),
        DefKind::Param => format!("{name} (macro parameter)"),
        DefKind::LoopVar => head(a, def),
        DefKind::Declare | DefKind::Local => head(a, def),
    };
    let mut s = format!("```rts\n{code}\n```\n");
    let value = (def.scope.is_none())
        .then(|| a.globals.iter().find(|g| g.name == name))
        .flatten();
    match (value, def.kind) {
        (Some(g), _) => {
            s.push_str(g.kind);
            if let Some(v) = &g.value {
                s.push_str(&format!(": `{v}`"));
            }
        }
        (None, DefKind::Macro) => s.push_str("a macro"),
        (None, DefKind::Param) => s.push_str("a macro parameter"),
        (None, DefKind::LoopVar) => s.push_str("a loop variable"),
        (None, _) => match def.block {
            Some(b) => s.push_str(&format!("a `{b}` value")),
            None => s.push_str("a value"),
        },
    }
    s.push_str(&format!(
        " *({} at {})*",
        def.kind.describe(),
        a.describe_span(def.span)
    ));
    s
}
