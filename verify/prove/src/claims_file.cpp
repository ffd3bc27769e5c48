// The claims-file reader (claims_file.hpp), with toml++.

#include <simpson/verify/claims_file.hpp>


#include <toml++/toml.h>

#include <algorithm>
#include <map>
#include <set>

namespace simpson::verify {
namespace {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

verdict verdict_named(const std::string& text, const std::string& file, int line) {
  const std::optional<verdict> v = verdict_of_name(text);
  if (!v) throw claims_file_error(file, line, "expected", "'" + text + "' is not a verdict (holds, erratum, fails, unverifiable, ...)");
  if (!expectable(*v)) {
    throw claims_file_error(file, line, "expected",
                            "'" + text + "' is never expected: it is no judgment of the document (expect holds, erratum, fails or unverifiable)");
  }
  return *v;
}

bool is_finding_verdict(verdict v) { return is_finding(v); }

bool reads_digest_spelled(const std::string& text) {
  return text.size() == 16 && std::all_of(text.begin(), text.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

finding finding_named(const std::string& text, const std::string& file, int line) {
  const std::optional<finding> f = finding_of_name(text);
  if (f && *f != finding::none) return *f;
  throw claims_file_error(file, line, "finding",
                          "'" + text + "' is not a class of finding (erratum, wording, derivation gap, naming, unverifiable, prose)");
}

/// The fields of one record, each read once and checked for its type.
class record_reader {
 public:
  record_reader(const toml::table& table, const std::string& file) : table_(table), file_(file), line_(line_of(table)) {
    static const std::set<std::string> fields{"id",       "section",  "equation",     "statement",     "methods", "check",
                                              "expected",    "finding",       "follows_from",
                                              "typographical", "origin", "headline",  "coq_none", "shape", "with", "core", "correction",
                                              "observes", "remark", "reads", "conclusions_kept"};
    for (const auto& [key, node] : table_) {
      if (!fields.count(std::string(key.str()))) {
        throw claims_file_error(file_, line_of(node), std::string(key.str()), "not a field of a claim record (docs/claims-file.md)");
      }
    }
  }

  int line() const { return line_; }

  std::string text(const std::string& field, bool required) const {
    const toml::node* node = table_.get(field);
    if (!node) {
      if (required) throw claims_file_error(file_, line_, field, "missing (every record has it)");
      return {};
    }
    const auto* value = node->as_string();
    if (!value) throw claims_file_error(file_, line_of(*node), field, "must be a string");
    if (required && value->get().empty()) throw claims_file_error(file_, line_of(*node), field, "must not be empty");
    return value->get();
  }

  bool flag(const std::string& field) const {
    const toml::node* node = table_.get(field);
    if (!node) return false;
    const auto* value = node->as_boolean();
    if (!value) throw claims_file_error(file_, line_of(*node), field, "must be true or false");
    return value->get();
  }

  std::vector<std::string> texts(const std::string& field) const {
    const toml::node* node = table_.get(field);
    if (!node) throw claims_file_error(file_, line_, field, "missing (every record has it)");
    const auto* array = node->as_array();
    if (!array || array->empty()) throw claims_file_error(file_, line_of(*node), field, "must be a non-empty array of strings");
    std::vector<std::string> out;
    for (const toml::node& item : *array) {
      const auto* value = item.as_string();
      if (!value) throw claims_file_error(file_, line_of(item), field, "must be a non-empty array of strings");
      out.push_back(value->get());
    }
    return out;
  }

  /// `with`: a table of strings and arrays of strings.
  std::map<std::string, shape_argument> arguments() const {
    std::map<std::string, shape_argument> out;
    const toml::node* node = table_.get("with");
    if (!node) return out;
    const toml::table* with = node->as_table();
    if (!with) throw claims_file_error(file_, line_of(*node), "with", "must be a table of the shape's arguments");
    for (const auto& [key, value] : *with) {
      const std::string field = "with." + std::string(key.str());
      shape_argument a;
      a.line = line_of(value);
      if (const auto* text = value.as_string()) {
        a.values.push_back(text->get());
      } else if (const auto* array = value.as_array()) {
        a.list = true;
        for (const toml::node& item : *array) {
          const auto* text = item.as_string();
          if (!text) throw claims_file_error(file_, line_of(item), field, "must be a string or an array of strings");
          a.values.push_back(text->get());
        }
      } else {
        throw claims_file_error(file_, a.line, field, "must be a string or an array of strings");
      }
      out.emplace(std::string(key.str()), std::move(a));
    }
    return out;
  }

  /// `core`: a table (one binding) or an array of tables.
  std::vector<core_binding> core_bindings(const known_name& known) const {
    std::vector<core_binding> out;
    const toml::node* node = table_.get("core");
    if (!node) return out;
    const auto one = [&](const toml::node& item) {
      const toml::table* t = item.as_table();
      if (!t) throw claims_file_error(file_, line_of(item), "core", "must be a table { function = ..., formula = ... } or an array of them");
      core_binding b;
      b.line = line_of(item);
      for (const auto& [key, value] : *t) {
        const std::string field = "core." + std::string(key.str());
        const std::string k(key.str());
        if (k == "function" || k == "formula" || k == "potential") {
          const auto* text = value.as_string();
          if (!text || text->get().empty()) throw claims_file_error(file_, line_of(value), field, "must be a non-empty string");
          (k == "function" ? b.function : k == "formula" ? b.formula : b.potential) = text->get();
        } else if (k == "variables" || k == "parameters") {
          const auto* array = value.as_array();
          if (!array) throw claims_file_error(file_, line_of(value), field, "must be an array of symbols (TeX)");
          for (const toml::node& v : *array) {
            const auto* text = v.as_string();
            if (!text || text->get().empty()) throw claims_file_error(file_, line_of(v), field, "must be an array of symbols (TeX)");
            (k == "variables" ? b.variables : b.parameters).push_back(text->get());
          }
        } else {
          throw claims_file_error(file_, line_of(value), field, "not a field of core (function, formula, variables, parameters, potential)");
        }
      }
      if (b.function.empty()) throw claims_file_error(file_, b.line, "core.function", "missing: the name of the core's formula (simpson-verify --list-core)");
      if (b.formula.empty()) throw claims_file_error(file_, b.line, "core.formula", "missing: the printed formula it implements (a formula reference)");
      if (!known("core", b.function)) {
        throw claims_file_error(file_, line_of(*t->get("function")), "core.function", "no core formula is named '" + b.function + "' (simpson-verify --list-core)");
      }
      if (b.parameters.empty()) b.parameters = {"m", "\\omega", "h"};
      if (b.parameters.size() != 3) throw claims_file_error(file_, line_of(*t->get("parameters")), "core.parameters", "names m, omega and h: three symbols");
      if (b.potential.empty()) b.potential = "V";
      out.push_back(std::move(b));
    };
    if (const toml::array* array = node->as_array()) {
      if (array->empty()) throw claims_file_error(file_, line_of(*node), "core", "an empty list binds nothing");
      for (const toml::node& item : *array) one(item);
    } else {
      one(*node);
    }
    return out;
  }

  int line_of_field(const std::string& field) const {
    const toml::node* node = table_.get(field);
    return node ? line_of(*node) : line_;
  }

  bool has(const std::string& field) const { return table_.get(field) != nullptr; }

 private:
  const toml::table& table_;
  const std::string& file_;
  int line_;
};

bool kebab_case(const std::string& id) {
  if (id.empty() || id.front() == '-' || id.back() == '-') return false;
  for (const char c : id) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-')) return false;
  }
  return true;
}

}  // namespace

claims_file_error::claims_file_error(const std::string& file, int line, const std::string& field, const std::string& why)
    : std::invalid_argument("claims file '" + file + "', line " + std::to_string(line) + (field.empty() ? "" : ", field '" + field + "'") +
                            ": " + why),
      file_(file),
      line_(line),
      field_(field) {}

namespace {

/// [document], when the file has one (its [symbols] then required).
std::optional<claims_document> read_document(const toml::table& file_table, const std::string& file) {
  const toml::node* document = file_table.get("document");
  if (!document) return std::nullopt;
  const toml::table* d = document->as_table();
  if (!d) throw claims_file_error(file, line_of(*document), "document", "must be a table");
  if (!file_table.get("symbols")) throw claims_file_error(file, line_of(*document), "symbols", "missing: a [document] declares its symbols in [symbols]");
  claims_document out;
  out.line = line_of(*document);
  for (const auto& [key, node] : *d) {
    if (key.str() != "title") throw claims_file_error(file, line_of(node), "document." + std::string(key.str()), "not a field of [document] (title)");
  }
  const toml::node* title = d->get("title");
  if (!title || !title->as_string() || title->as_string()->get().empty()) {
    throw claims_file_error(file, title ? line_of(*title) : out.line, "document.title", "missing: a phrase the document prints (its title)");
  }
  out.title = title->as_string()->get();
  return out;
}

/// [symbols], when the file has it. A name is declared once, or twice as a function and a symbol.
std::optional<claims_symbols> read_symbols(const toml::table& file_table, const std::string& file) {
  const toml::node* symbols = file_table.get("symbols");
  if (!symbols) return std::nullopt;
  const toml::table* s = symbols->as_table();
  if (!s) throw claims_file_error(file, line_of(*symbols), "symbols", "must be a table");
  claims_symbols out;
  out.line = line_of(*symbols);
  std::map<std::string, std::set<std::string>> seen;  // name: the lists it is in
  for (const auto& [key, node] : *s) {
    const std::string field = "symbols." + std::string(key.str());
    if (key.str() != "positive" && key.str() != "real" && key.str() != "functions" && key.str() != "solutions") {
      throw claims_file_error(file, line_of(node), field, "not a field of [symbols] (positive, real, functions, solutions)");
    }
    const toml::array* names = node.as_array();
    if (!names) throw claims_file_error(file, line_of(node), field, "must be an array of symbol names");
    for (const toml::node& item : *names) {
      const auto* name = item.as_string();
      if (!name || name->get().empty()) throw claims_file_error(file, line_of(item), field, "must be an array of symbol names");
      std::set<std::string>& lists = seen[name->get()];
      // A solution is a function (applied); either may also be a symbol (a state: q(t), dq/dt).
      const bool as_function = key.str() == "functions" || key.str() == "solutions";
      const bool earlier_function = lists.count("functions") > 0 || lists.count("solutions") > 0;
      const bool state = lists.size() == 1 && earlier_function != as_function;  // a function and a symbol
      if (!lists.empty() && !state) throw claims_file_error(file, line_of(item), field, "'" + name->get() + "' is declared twice");
      lists.insert(std::string(key.str()));
      (key.str() == "positive" ? out.positive : key.str() == "real" ? out.real : key.str() == "functions" ? out.functions : out.solutions)
          .push_back(name->get());
    }
  }
  return out;
}

}  // namespace

std::vector<claim_record> read_claims_file(const std::string& text, const std::string& file, const known_name& known) {
  return read_claims_contents(text, file, known).records;
}

claims_file_contents read_claims_contents(const std::string& text, const std::string& file, const known_name& known) {
  toml::table document;
  try {
    document = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw claims_file_error(file, static_cast<int>(e.source().begin.line), "", std::string(e.description()));
  }
  for (const auto& [key, node] : document) {
    if (key.str() != "claim" && key.str() != "document" && key.str() != "symbols") {
      throw claims_file_error(file, line_of(node), std::string(key.str()), "not a table of a claims file ([document], [symbols], [[claim]])");
    }
  }
  claims_file_contents contents;
  contents.document = read_document(document, file);
  contents.symbols = read_symbols(document, file);
  const toml::array* claims = document["claim"].as_array();
  if (!claims || claims->empty()) throw claims_file_error(file, 1, "claim", "no [[claim]] record");
  std::vector<claim_record> records;
  std::map<std::string, int> line_of_id;
  for (const toml::node& node : *claims) {
    const toml::table* table = node.as_table();
    if (!table) throw claims_file_error(file, line_of(node), "claim", "must be a table ([[claim]])");
    const record_reader read(*table, file);
    claim_record r;
    r.line = read.line();
    r.file = file;
    r.id = read.text("id", true);
    if (!kebab_case(r.id)) throw claims_file_error(file, read.line_of_field("id"), "id", "'" + r.id + "' is not kebab-case (a-z, 0-9, -)");
    if (!line_of_id.emplace(r.id, r.line).second) {
      throw claims_file_error(file, read.line_of_field("id"), "id",
                              "'" + r.id + "' is already the id of the record at line " + std::to_string(line_of_id[r.id]));
    }
    r.section = read.text("section", true);
    r.equation = read.text("equation", true);
    r.methods = read.texts("methods");
    r.check = read.text("check", false);
    r.shape = read.text("shape", false);
    r.observes = read.text("observes", false);
    const int deciders = !r.check.empty() + !r.shape.empty() + !r.observes.empty();
    if (deciders != 1) {
      const std::string second = !r.shape.empty() && !r.check.empty() ? "check" : "observes";  // the field one too many
      throw claims_file_error(file, r.line, deciders == 0 ? "shape" : second,
                              deciders == 0 ? "missing: a record names the proof shape, the observed fact or the bespoke check that decides it"
                                            : "a record names one of a shape, an observed fact and a check, not two");
    }
    if (!r.check.empty() && !known("check", r.check)) throw claims_file_error(file, read.line_of_field("check"), "check", "no check is named '" + r.check + "'");
    if (!r.shape.empty() && !known("shape", r.shape)) {
      throw claims_file_error(file, read.line_of_field("shape"), "shape", "no proof shape is named '" + r.shape + "' (docs/claims-file.md)");
    }
    if (!r.observes.empty() && !known("observes", r.observes)) {
      throw claims_file_error(file, read.line_of_field("observes"), "observes",
                              "no experiment publishes a fact named '" + r.observes + "' (simpson-verify --list-facts)");
    }
    // A shape record may leave its statement out: the reports then show the TeX it reads.
    r.statement = read.text("statement", r.shape.empty());
    r.with = read.arguments();
    if (r.shape.empty() && !r.with.empty()) throw claims_file_error(file, read.line_of_field("with"), "with", "arguments without a shape");
    // Without `expected` a claim is to hold: a file of such records validates a derivation (exit 0
    // when every claim holds) instead of guarding a judged paper against regressions.
    const std::string expected = read.text("expected", false);
    if (!expected.empty()) {
      r.expected = verdict_named(expected, file, read.line_of_field("expected"));
      r.expected_given = true;
    }
    const std::string kind = read.text("finding", false);
    const bool is_finding = expectable(r.expected) && is_finding_verdict(r.expected);
    if (!kind.empty()) r.kind = finding_named(kind, file, read.line_of_field("finding"));
    if (is_finding && kind.empty()) {
      throw claims_file_error(file, read.line_of_field("expected"), "finding",
                              "missing: an expected '" + to_string(r.expected) + "' is a finding, and says its class");
    }
    // A claim expected to hold may carry a remark: its class is one a remark can have.
    if (!is_finding && !kind.empty() && !(r.expected == verdict::holds && remark_class(r.kind))) {
      throw claims_file_error(file, read.line_of_field("finding"), "finding",
                              r.expected == verdict::holds ? "'" + kind + "' is no class of a remark on a claim that holds (wording, naming, derivation gap)"
                                                           : "given for a claim expected to " + to_string(r.expected));
    }
    r.follows_from = read.text("follows_from", false);
    if (r.follows_from == r.id) throw claims_file_error(file, read.line_of_field("follows_from"), "follows_from", "a claim cannot follow from itself");
    r.typographical = read.flag("typographical");
    // An erratum that changes none of the text's conclusions: the claims that draw them.
    if (read.has("conclusions_kept")) {
      r.conclusions_kept = read.texts("conclusions_kept");
      if (r.expected != verdict::erratum) {
        throw claims_file_error(file, read.line_of_field("conclusions_kept"), "conclusions_kept",
                                "given for a claim whose expected verdict is " + to_string(r.expected) +
                                    ": only an erratum names the conclusions it leaves standing");
      }
    }
    const std::string origin = read.text("origin", false);
    if (origin == "harness") {
      r.origin = claim_origin::harness;
    } else if (origin == "beyond") {
      r.origin = claim_origin::beyond;
    } else if (!origin.empty() && origin != "paper") {
      throw claims_file_error(file, read.line_of_field("origin"), "origin", "'" + origin + "' is not 'paper', 'beyond' or 'harness'");
    }
    // A claim in the section beyond the paper is not the paper's: its record says whose it is.
    if (r.section == "beyond" && r.origin == claim_origin::paper) {
      throw claims_file_error(file, origin.empty() ? read.line_of_field("section") : read.line_of_field("origin"), "origin",
                              "a claim of the section 'beyond' is not the paper's: say origin = \"beyond\" (or \"harness\")");
    }
    r.headline = read.flag("headline");
    r.coq_none = read.text("coq_none", false);
    r.core = read.core_bindings(known);
    // An erratum's content: the correction it is expected to have. Only an expected erratum has one.
    r.correction = read.text("correction", false);
    if (!r.correction.empty() && r.expected != verdict::erratum) {
      throw claims_file_error(file, read.line_of_field("correction"), "correction",
                              "given for a claim whose expected verdict is " + to_string(r.expected) + ": only an expected erratum records its correction");
    }
    r.remark = read.text("remark", false);
    if (!r.remark.empty() && !(r.expected == verdict::holds && r.kind != finding::none)) {
      throw claims_file_error(file, read.line_of_field("remark"), "remark",
                              "given for a claim not expected to hold with a remark: a remark's record says expected = \"holds\" and its class in `finding`");
    }
    r.reads = read.text("reads", false);
    if (!r.reads.empty() && !reads_digest_spelled(r.reads)) {
      throw claims_file_error(file, read.line_of_field("reads"), "reads", "'" + r.reads + "' is not a digest of what the claim reads (16 hexadecimal digits)");
    }
    records.push_back(std::move(r));
  }
  // Every cause named exists, and following the links never comes back.
  // (Every cause first, then the walks: a walk must never meet a cause that is not a record. The
  // fuzzer found that looking one up with operator[] made it one.)
  std::map<std::string, const claim_record*> by_id;
  for (const claim_record& r : records) by_id.emplace(r.id, &r);
  for (const claim_record& r : records) {
    if (!r.follows_from.empty() && by_id.find(r.follows_from) == by_id.end()) {
      throw claims_file_error(file, r.line, "follows_from", "no record has the id '" + r.follows_from + "'");
    }
    for (const std::string& kept : r.conclusions_kept) {
      if (by_id.find(kept) == by_id.end()) throw claims_file_error(file, r.line, "conclusions_kept", "no record has the id '" + kept + "'");
      if (kept == r.id) throw claims_file_error(file, r.line, "conclusions_kept", "an erratum is not a conclusion it leaves standing");
    }
  }
  for (const claim_record& r : records) {
    if (r.follows_from.empty()) continue;
    std::set<std::string> seen{r.id};
    for (const claim_record* at = by_id.at(r.follows_from); at; at = at->follows_from.empty() ? nullptr : by_id.at(at->follows_from)) {
      if (!seen.insert(at->id).second) {
        throw claims_file_error(file, r.line, "follows_from",
                                "following the causes from '" + r.id + "' comes back to '" + at->id + "' (a cycle)");
      }
    }
  }
  contents.records = std::move(records);
  return contents;
}


}  // namespace simpson::verify
