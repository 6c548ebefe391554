#!/usr/bin/env python3
"""Writes rts.tmLanguage.json from the language's word lists in the Rust sources
(src/syntax/keywords.rs: reserved keywords; src/syntax/builtins.rs: built-in constants
and functions). Run it after adding keywords: `python3 editors/vscode/syntaxes/generate.py`.
tests/lsp.rs checks the grammar knows every word."""
import json
import pathlib
import re

root = pathlib.Path(__file__).resolve().parents[3]
kw = re.findall(r'^    "([a-z_0-9]+)",', (root / "src/syntax/keywords.rs").read_text(), re.M)
b = (root / "src/syntax/builtins.rs").read_text()
b = b[b.index("BUILTIN_NAMES"):b.index("];", b.index("BUILTIN_NAMES"))]
bn = re.findall(r'"([a-z_0-9]+)"', b)
count = int(re.search(r"CONSTANT_COUNT: usize = (\d+);", (root / "src/syntax/builtins.rs").read_text()).group(1))
consts, funcs = bn[:count], bn[count:]
colour = ["color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft",
          "red", "green", "blue", "gray", "grey", "array", "optional"]


def alt(words):
    return "|".join(sorted(set(words), key=lambda w: (-len(w), w)))


NAME = "[A-Za-z_][A-Za-z0-9_]*"
g = {
    "$schema": "https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json",
    "name": "rts",
    "scopeName": "source.rts",
    "fileTypes": ["rts", "pov", "inc"],
    "patterns": [{"include": f"#{n}"} for n in
                 ["comments", "strings", "directives", "numbers", "calls", "words", "punctuation"]],
    "repository": {
        "comments": {"patterns": [
            {"name": "comment.line.double-slash.rts", "match": "//.*$"},
            {"include": "#block-comment"}]},
        "block-comment": {"name": "comment.block.rts", "begin": "/\\*", "end": "\\*/",
                          "patterns": [{"include": "#block-comment"}]},
        "strings": {"name": "string.quoted.double.rts", "begin": "\"", "end": "\"|$",
                    "patterns": [{"name": "constant.character.escape.rts",
                                  "match": "\\\\(u[0-9A-Fa-f]{4}|.)"}]},
        "directives": {"patterns": [
            {"match": "(#)\\s*(include)\\b", "captures": {"0": {"name": "keyword.control.import.rts"}}},
            {"match": f"(#)\\s*(declare|local)\\s+({NAME})",
             "captures": {"1": {"name": "keyword.control.directive.rts"},
                          "2": {"name": "keyword.control.directive.rts"},
                          "3": {"name": "variable.other.definition.rts"}}},
            {"match": f"(#)\\s*(macro)\\s+({NAME})",
             "captures": {"1": {"name": "keyword.control.directive.rts"},
                          "2": {"name": "keyword.control.directive.rts"},
                          "3": {"name": "entity.name.function.rts"}}},
            {"name": "keyword.control.directive.rts",
             "match": "#\\s*(if|ifdef|ifndef|elseif|else|end|switch|case|range|break|while|for|macro|"
                      "declare|local|undef|debug|warning|error|default|version|fopen|fclose|read|write)\\b"}]},
        "numbers": {"name": "constant.numeric.rts",
                    "match": "(?<![A-Za-z0-9_.])(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?"},
        "calls": {"patterns": [
            {"match": "\\b(" + alt(funcs) + ")\\s*(?=\\()",
             "captures": {"1": {"name": "support.function.builtin.rts"}}},
            {"match": f"\\b({NAME})\\s*(?=\\()", "captures": {"1": {"name": "entity.name.function.rts"}}}]},
        "words": {"patterns": [
            {"name": "keyword.other.rts", "match": "\\b(" + alt(kw + colour) + ")\\b"},
            {"name": "support.function.builtin.rts", "match": "\\b(" + alt(funcs) + ")\\b"},
            {"name": "constant.language.rts", "match": "\\b(" + alt(consts) + ")\\b"},
            {"name": "variable.other.rts", "match": f"\\b{NAME}\\b"}]},
        "punctuation": {"patterns": [
            {"name": "punctuation.section.block.begin.rts", "match": "\\{"},
            {"name": "punctuation.section.block.end.rts", "match": "\\}"},
            {"name": "punctuation.separator.rts", "match": ","},
            {"name": "punctuation.terminator.rts", "match": ";"},
            {"name": "keyword.operator.rts", "match": "<=|>=|!=|[-+*/=<>!&|?:]"}]},
    },
}
out = pathlib.Path(__file__).with_name("rts.tmLanguage.json")
out.write_text(json.dumps(g, indent=2) + "\n")
print(f"wrote {out}")
