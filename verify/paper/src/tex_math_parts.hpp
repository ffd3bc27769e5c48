#pragma once
// What the reader of math (tex_math.cpp) takes from the names' file (tex_names.cpp): a group's
// content, the refusal, letters and subscripts, upright names, differential marks, and the held
// det and tr.

#include <simpson/verify/tex_math.hpp>
#include <simpson/verify/tex_tree.hpp>

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <utility>

namespace simpson::verify::tex_reading {

/// {x} is x; {{a b}} is a b.
const tex_node& unwrapped(const tex_node& n);
tex_list unwrapped_list(const tex_list& list);

/// A construct the reader does not read: tex_error at its offset, named, with a spelling that works.
[[noreturn]] void refuse(const std::string& why, const tex_node& n, const std::string& hint = {});

/// A Greek letter's command or a letter.
bool is_greek_or_letter(const tex_node& n);
/// A subscript as a name's part ("j+1").
std::string subscript_text(const tex_node& n);
/// An upright name (\mathrm{d}, \operatorname{tr}): the font and the letters; none otherwise.
std::optional<std::pair<std::string, std::string>> upright(const tex_node& given);

/// det and tr of a named matrix: held until the matrix is put in, then evaluated.
GiNaC::ex determinant_of(const GiNaC::ex& x);
GiNaC::ex trace_of(const GiNaC::ex& x);
unsigned jacobian_serial();

/// A differential mark: d, {\rm d}, \mathrm{d}, \operatorname{d}, \partial; its order when it
/// carries one (d^2).
struct differential {
  bool partial = false;
  bool plain_d = false;  // the letter d
  int order = 1;
};
std::optional<differential> differential_of(const tex_node& given);

}  // namespace simpson::verify::tex_reading
