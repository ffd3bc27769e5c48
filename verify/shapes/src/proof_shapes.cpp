// The proof shapes of claims files, by name, and the checks of a record's arguments before
// anything runs: see proof_shapes.hpp and docs/claims-file.md. Each shapes_*.cpp file holds a
// family of shapes, their specs beside their bodies (shape_support.hpp); the list below names the
// files. A new shape is its spec and body in a family's file (or a new file and its line here) and
// its fixture folder in verify/tests/shapes/.

#include <simpson/shapes/proof_shapes.hpp>

#include <simpson/prove/printed_check_support.hpp>
#include <simpson/shapes/shape_support.hpp>

#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/prose_span.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace simpson::verify::detail {

using GiNaC::ex;

const std::map<std::string, proof_shape>& proof_shapes() {
  static const std::map<std::string, proof_shape> shapes = [] {
    std::map<std::string, proof_shape> all;
    // Each file of shapes lists its own (its shapes' specs beside their bodies): one line each here.
    for (const auto family : {
             &identities_shape_specs,
             &forms_shape_specs,
             &invariance_shape_specs,
             &invariance_kernel_shape_specs,
             &stability_criteria_shape_specs,
             &derivation_shape_specs,
             &explicit_shape_specs,
             &intervals_shape_specs,
             &series_shape_specs,
             &consistency_shape_specs,
             &quadrature_shape_specs,
             &sums_shape_specs,
             &emerging_shape_specs,
             &known_method_shape_specs,
             &prose_shape_specs,
             &characteristic_shape_specs,
             &variational_shape_specs}) {
      for (proof_shape& shape : family()) {
        const std::string name = shape.name;
        if (!all.emplace(name, std::move(shape)).second) throw std::logic_error("two proof shapes are named '" + name + "'");
      }
    }
    return all;
  }();
  return shapes;
}

void check_shape_arguments(const claim_record& record, const std::string& file) {
  const proof_shape& shape = proof_shapes().at(record.shape);
  for (const auto& entry : record.with) {
    const std::string& name = entry.first;  // not a structured binding: clang's C++17 lambdas cannot capture one
    const shape_argument& argument = entry.second;
    const auto it = std::find_if(shape.parameters.begin(), shape.parameters.end(), [&](const shape_parameter& p) { return p.name == name; });
    if (it == shape.parameters.end()) {
      std::string names;
      for (const shape_parameter& p : shape.parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw claims_file_error(file, argument.line, "with." + name, "not an argument of the shape '" + shape.name + "' (" + names + ")");
    }
    const bool list = it->kind == argument_kind::definitions || it->kind == argument_kind::symbols || it->kind == argument_kind::equations ||
                      it->kind == argument_kind::words;
    if (argument.list != list) {
      throw claims_file_error(file, argument.line, "with." + name, list ? "must be an array of strings" : "must be one string (a formula reference)");
    }
    if (list && argument.values.empty()) throw claims_file_error(file, argument.line, "with." + name, "must not be empty");
    if (it->pairs) {
      for (const std::string& value : argument.values) {
        const std::size_t colon = value.find(": ");
        if (colon == std::string::npos || colon == 0 || colon + 2 >= value.size()) {
          throw claims_file_error(file, argument.line, "with." + name, "'" + value + "' is not 'word: replacement'");
        }
      }
    }
    if (it->kind == argument_kind::word || it->kind == argument_kind::symbols || it->kind == argument_kind::words) continue;
    for (const std::string& value : argument.values) {  // each a reference that reads ('label#0' does not)
      try {
        parse_reference(value);
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, argument.line, "with." + name, e.what());
      }
    }
  }
  for (const shape_parameter& p : shape.parameters) {
    if (p.required && !record.with.count(p.name)) {
      throw claims_file_error(file, record.line, "with." + p.name, "missing: the shape '" + shape.name + "' needs it (" + p.meaning + ")");
    }
  }
  // Alternatives (one of the two) and companions (given exactly with another).
  for (const shape_parameter& p : shape.parameters) {
    const bool given = record.with.count(p.name) > 0;
    if (!p.instead_of.empty()) {
      const bool other = record.with.count(p.instead_of) > 0;
      if (given && other) {
        throw claims_file_error(file, record.with.at(p.name).line, "with." + p.name, "give '" + p.name + "' or '" + p.instead_of + "', not both");
      }
      if (!given && !other) {
        throw claims_file_error(file, record.line, "with." + p.instead_of,
                                "missing: the shape '" + shape.name + "' needs it, or '" + p.name + "' instead (" + p.meaning + ")");
      }
    }
    if (!p.only_with.empty() && given != (record.with.count(p.only_with) > 0)) {
      throw claims_file_error(file, given ? record.with.at(p.name).line : record.with.at(p.only_with).line, "with." + p.name,
                              given ? "given without '" + p.only_with + "'" : "missing: '" + p.only_with + "' needs it (" + p.meaning + ")");
    }
  }
  for (const shape_parameter& p : shape.parameters) {
    const auto it = record.with.find(p.name);
    if (!p.hole.empty() && it != record.with.end() && it->second.values.front().find("{" + p.hole + "}") == std::string::npos) {
      throw claims_file_error(file, it->second.line, "with." + p.name, "the sentence's pattern has no hole {" + p.hole + "}");
    }
    if ((!p.hole.empty() || p.name == "says") && it != record.with.end()) {
      try {
        check_pattern(it->second.values.front());
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, it->second.line, "with." + p.name, e.what());
      }
    }
  }
  // The words: a sentence and the property it states, both or neither.
  const auto says = record.with.find("says"), property = record.with.find("property");
  if ((says == record.with.end()) != (property == record.with.end())) {
    const bool has_says = says != record.with.end();
    throw claims_file_error(file, has_says ? says->second.line : property->second.line, has_says ? "with.property" : "with.says",
                            has_says ? "missing: the word the sentence's hole {property} must say" : "missing: the sentence that says the property");
  }
  if (says != record.with.end() && says->second.values.front().find("{property}") == std::string::npos) {
    throw claims_file_error(file, says->second.line, "with.says", "the sentence's pattern has no hole {property}");
  }
}

std::string check_shape_formulas(const claim_record& record, const std::string& file, const tex_document& document,
                                 const claim_declarations& declared) {
  // Read as the shape will read them when it runs (shape_reader): the definitions put in, every
  // symbol declared; what a shape checks only when it runs is checked here, before anything runs.
  // The document's own faults (TeX that does not read) name the document and its line, not the record.
  const shape_call call{record.id, record.statement, record.with, std::make_shared<const claim_declarations>(declared)};
  std::optional<shape_reader> read;
  try {
    read.emplace(call, document);
  } catch (const document_error&) {
    throw;
  } catch (const argument_error& e) {
    throw claims_file_error(file, record.with.at(e.argument).line, "with." + e.argument, e.what());
  } catch (const std::invalid_argument& e) {
    const auto where = record.with.find("where");
    throw claims_file_error(file, where != record.with.end() ? where->second.line : record.line, where != record.with.end() ? "with.where" : "with",
                            e.what());
  }
  const std::set<std::string>& positive = declared.positive;
  const proof_shape& shape = proof_shapes().at(record.shape);
  std::string principal;
  std::map<std::string, unsigned> rows;  // of each matrix argument
  for (const shape_parameter& p : shape.parameters) {
    const auto it = record.with.find(p.name);
    if (it == record.with.end() || p.kind == argument_kind::definitions) continue;  // the definitions: read above
    const std::string field = "with." + p.name;
    const int line = it->second.line;
    try {
      switch (p.kind) {
        case argument_kind::formula:
        case argument_kind::matrix:
        case argument_kind::condition: {
          const referenced_formula f = read->raw(p.name);
          if (p.name == shape.principal) principal = "$" + folded_space(f.tex) + "$ (" + f.locator + ")";
          if (p.kind == argument_kind::matrix) {
            const ex m = read->formula(p.name);
            if (!GiNaC::is_a<GiNaC::matrix>(m) || GiNaC::ex_to<GiNaC::matrix>(m).rows() != GiNaC::ex_to<GiNaC::matrix>(m).cols()) {
              throw claims_file_error(file, line, field, f.locator + " is not a square matrix");
            }
            rows[p.name] = GiNaC::ex_to<GiNaC::matrix>(m).rows();
            if (p.size != 0 && rows[p.name] != p.size) {
              throw claims_file_error(file, line, field, fmt::format("{} is {} x {}, not {} x {}", f.locator, rows[p.name], rows[p.name], p.size, p.size));
            }
          }
          if (!p.free_of.empty() && record.with.count(p.free_of)) {
            const ex value = read->formula(p.name);
            if (GiNaC::normal(value).is_zero()) throw claims_file_error(file, line, field, f.locator + " is 0");
            for (const GiNaC::symbol& s : read->symbols(p.free_of)) {
              if (value.has(s)) {
                throw claims_file_error(file, line, field, f.locator + " depends on " + s.get_name() + ", one of the symbols of '" + p.free_of + "'");
              }
            }
          }
          if (p.kind == argument_kind::condition && f.sides.size() != 3) {
            throw claims_file_error(file, line, field, f.locator + " is not a condition 'a < x < b' (it has " + std::to_string(f.sides.size()) + " sides)");
          }
          if (p.positive && declared.complete) {
            for (const std::string& name : symbol_names(f.value)) {
              if (!positive.count(name)) throw claims_file_error(file, line, field, "the symbol '" + name + "' is not declared positive in [symbols]");
            }
          }
          break;
        }
        case argument_kind::definitions:
        case argument_kind::words: break;
        case argument_kind::equations: {
          std::string shown;
          for (const referenced_formula& f : read->equations(p.name)) {
            if (f.sides.size() < 2) throw claims_file_error(file, line, field, f.locator + " is not an equation 'a = b'");
            shown += (shown.empty() ? "" : "; ") + ("$" + folded_space(f.tex) + "$ (" + f.locator + ")");
          }
          if (p.name == shape.principal) principal = shown;
          break;
        }
        case argument_kind::word:
          if (!p.words.empty() && std::find(p.words.begin(), p.words.end(), it->second.values.front()) == p.words.end()) {
            throw claims_file_error(file, line, field, "'" + it->second.values.front() + "' is not one of: " + fmt::format("{}", fmt::join(p.words, ", ")));
          }
          break;
        case argument_kind::symbols: {
          read->symbols(p.name);  // each one symbol, and declared
          if (p.size != 0 && it->second.values.size() != p.size) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols, not {}", it->second.values.size(), p.size));
          }
          if (!p.same_size_as.empty() && rows.count(p.same_size_as) && it->second.values.size() != rows[p.same_size_as]) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols for the {} rows of '{}'", it->second.values.size(),
                                                                   rows[p.same_size_as], p.same_size_as));
          }
          if (!p.same_size_as.empty() && !rows.count(p.same_size_as) && record.with.count(p.same_size_as) &&
              it->second.values.size() != record.with.at(p.same_size_as).values.size()) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols for the {} of '{}'", it->second.values.size(),
                                                                   record.with.at(p.same_size_as).values.size(), p.same_size_as));
          }
          if (!p.among.empty() && record.with.count(p.among)) {
            const std::vector<GiNaC::symbol> allowed = read->symbols(p.among);
            for (const GiNaC::symbol& s : read->symbols(p.name)) {
              const bool found = std::any_of(allowed.begin(), allowed.end(), [&](const GiNaC::symbol& a) { return a.get_name() == s.get_name(); });
              if (!found) throw claims_file_error(file, line, field, "'" + s.get_name() + "' is not one of the symbols of '" + p.among + "'");
            }
          }
          break;
        }
      }
    } catch (const claims_file_error&) {
      throw;
    } catch (const document_error&) {
      throw;
    } catch (const std::invalid_argument& e) {
      throw claims_file_error(file, line, field, e.what());
    }
  }
  if (shape.bind) {  // what the shape settles of its notation before it runs
    try {
      shape.bind(*read, call);
    } catch (const argument_error& e) {
      const auto it = record.with.find(e.argument);
      throw claims_file_error(file, it != record.with.end() ? it->second.line : record.line, "with." + e.argument, e.what());
    } catch (const document_error&) {
      throw;
    } catch (const std::invalid_argument& e) {
      throw claims_file_error(file, record.line, "with", e.what());
    }
  }
  return principal;
}

}  // namespace simpson::verify::detail