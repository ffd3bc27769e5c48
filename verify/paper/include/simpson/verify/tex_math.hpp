#pragma once
// A reader for the TeX math the paper uses, into GiNaC expressions. No maintained C++ library
// parses TeX math into a CAS expression, so this one is ours: small and table-driven.
//
// The subset: numbers; single-letter and Greek symbols with subscripts (q_\ell, q_r, q_{j+1},
// \Phi_3); implicit products, + and −, \cdot; ^ with TeX's one-token argument (h^24 is h²·4);
// {a \over b} and \frac{a}{b}; \sqrt{a}; ( ) [ ] and { } groups with \big \Big \left \right and
// friends; spacing (\, \! \; \quad) and \displaystyle ignored; array and pmatrix matrices; the
// relations =, \equiv and <, of which the last side is the formula. Anything else is an error
// naming the token.

#include <ginac/ginac.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify {

/// The symbols of the paper by name ("m", "omega", "h", "q_l", "q_r", "p", "q", ...): the parser
/// and the derived formulas share them, so that the same name is the same GiNaC symbol.
class tex_symbols {
 public:
  const GiNaC::symbol& operator[](const std::string& name);

 private:
  std::map<std::string, GiNaC::symbol> symbols_;
};

/// A formula the reader could not parse: the offending token and its offset in the TeX.
class tex_parse_error : public std::invalid_argument {
 public:
  tex_parse_error(const std::string& why, std::string token, std::size_t offset)
      : std::invalid_argument(why), token_(std::move(token)), offset_(offset) {}
  const std::string& token() const noexcept { return token_; }
  std::size_t offset() const noexcept { return offset_; }

 private:
  std::string token_;
  std::size_t offset_;
};

/// The sides of a display split at its top-level relations (=, \equiv, <), trailing punctuation
/// dropped: "p_r = A" gives {"p_r", "A"}.
std::vector<std::string> relation_sides(const std::string& tex);

/// The canonical text of an expression: its normal form as (expanded numerator)/(expanded
/// denominator), each a sum of monomials with symbols in name order and terms in a fixed order, and
/// a matrix entry by entry. GiNaC's own printing orders terms by symbol serial numbers, which
/// depend on what a process created first; reports must not.
std::string canonical_text(const GiNaC::ex& e);

/// Parses one side (no relation) into an expression; matrices are GiNaC matrices. Throws
/// tex_parse_error.
GiNaC::ex parse_tex_math(const std::string& tex, tex_symbols& symbols);

}  // namespace simpson::verify
