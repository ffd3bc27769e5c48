#pragma once
// The TeX reader's vocabulary: the control sequences of math it knows, by what they are (symbols and
// their class, operators, commands it consumes without meaning, text, accents, fractions, sizes),
// the characters' classes, the delimiters and the environments. A control sequence in none of these
// is refused, named (tex_tree.cpp).

#include <simpson/verify/tex_tree.hpp>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace simpson::verify::tex_commands {

const std::map<std::string, tex_class>& symbol_commands();
const std::set<std::string>& operator_commands();
const std::set<std::string>& ignored_commands();
const std::map<std::string, std::string>& font_commands();
const std::map<std::string, std::string>& font_switches();
const std::set<std::string>& text_commands();
const std::set<std::string>& accent_commands();
const std::set<std::string>& fraction_commands();
const std::set<std::string>& sizing_commands();
std::optional<tex_class> character_class(const std::string& c);
bool is_delimiter(const tex_token& t);
tex_class delimiter_class(const std::string& d);
std::pair<std::string, std::string> environment_delimiters(const std::string& name);
bool known_environment(const std::string& name);

}  // namespace simpson::verify::tex_commands
