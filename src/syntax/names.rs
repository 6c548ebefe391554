//! Human names for grammar rules, used in "expected …" messages. The `match` has no
//! wildcard arm, so a new rule cannot leak its internal name into a message.

use super::parser::Rule;

/// How to name what `rule` stands for in a message; `None` for rules that are never
/// worth naming on their own (their parents are named instead).
pub fn human(rule: Rule) -> Option<&'static str> {
    Some(match rule {
        Rule::EOI => "end of file",
        Rule::WHITESPACE
        | Rule::item_end
        | Rule::end_word
        | Rule::op_char
        | Rule::marked_vector => return None,
        Rule::file | Rule::one_item | Rule::only_trivia | Rule::item | Rule::body => "a statement",
        Rule::block | Rule::item_block | Rule::sized_fn => "a block",
        Rule::func_params => "a parameter list",
        Rule::fn_keyword | Rule::fn_word => "`function`",
        Rule::bracket => "`[`",
        Rule::comma => "`,`",
        Rule::semicolon => "`;`",
        Rule::directive
        | Rule::declare_d
        | Rule::undef_d
        | Rule::if_d
        | Rule::ifdef_d
        | Rule::switch_d
        | Rule::while_d
        | Rule::for_d
        | Rule::macro_d
        | Rule::include_d
        | Rule::message_d
        | Rule::default_d
        | Rule::version_d
        | Rule::fopen_d
        | Rule::fclose_d
        | Rule::read_d
        | Rule::write_d => "a directive",
        Rule::open_mode => "`read`, `write` or `append`",
        Rule::write_item => "a value to write",
        Rule::binary_kind => "a binary type (`uint8`, `sint16le`, …)",
        Rule::kw_fopen => "`fopen`",
        Rule::kw_fclose => "`fclose`",
        Rule::kw_read => "`read`",
        Rule::kw_write => "`write`",
        Rule::decl_kind => "`declare` or `local`",
        Rule::deprecated | Rule::kw_deprecated => return None,
        Rule::once_kw => "`once`",
        Rule::lvalue | Rule::ident_name | Rule::ident_raw => "a name",
        Rule::rhs => "a value",
        Rule::elseif_d | Rule::kw_elseif => "`#elseif`",
        Rule::else_d | Rule::kw_else => "`#else`",
        Rule::end_d | Rule::kw_end => "`#end`",
        Rule::ifdef_kind => "`ifdef` or `ifndef`",
        Rule::case_d | Rule::case_head | Rule::kw_case => "`#case`",
        Rule::range_head | Rule::kw_range => "`#range`",
        Rule::break_d | Rule::kw_break => "`#break`",
        Rule::param => "a parameter name",
        Rule::optional_kw => "`optional`",
        Rule::message_kind => "`debug`, `warning` or `error`",
        Rule::kw_if => "`if`",
        Rule::kw_undef => "`undef`",
        Rule::kw_switch => "`switch`",
        Rule::kw_while => "`while`",
        Rule::kw_for => "`for`",
        Rule::kw_macro => "`macro`",
        Rule::kw_include => "`include`",
        // `default { … }` may stand without its `#` (as POV-Ray reads it), so the
        // word alone opens a directive: name it so, not as a keyword to type.
        Rule::kw_default => "a directive",
        Rule::kw_version => "`version`",
        Rule::expr
        | Rule::chain
        | Rule::sum
        | Rule::la_sum
        | Rule::la_operand
        | Rule::operand
        | Rule::primary
        | Rule::paren
        | Rule::arg
        | Rule::arg_slot
        | Rule::empty_arg
        | Rule::array_elem => "an expression",
        Rule::question => "`?`",
        Rule::colon => "`:`",
        Rule::or_op
        | Rule::and_op
        | Rule::cmp_op
        | Rule::add_op
        | Rule::mul_op
        | Rule::infix
        | Rule::arith => "an operator",
        Rule::prefix_op => "`-`, `+` or `!`",
        Rule::dot => "`.`",
        Rule::index => "`[`",
        Rule::vector | Rule::plain_vector => "a vector `<…>`",
        Rule::colour | Rule::colour_kw | Rule::colour_rgb_kw => "a colour",
        Rule::colour_part | Rule::colour_part_kw => {
            "`red`, `green`, `blue`, `filter` or `transmit`"
        }
        Rule::array | Rule::array_kw => "an array",
        Rule::array_init => "`{`",
        Rule::call => "a function call",
        Rule::value_block => "a keyframes block",
        Rule::number => "a number",
        Rule::data_run
        | Rule::data_elem
        | Rule::data_next
        | Rule::data_vector
        | Rule::data_number
        | Rule::data_gap
        | Rule::data_body
        | Rule::data_text
        | Rule::data_start => "a number or a vector",
        Rule::string | Rule::string_inner => "a string",
        Rule::ident_char => return None,
        Rule::keyword | Rule::keyword_word | Rule::reserved_word => "a keyword",
    })
}
