#pragma once
// A fact an experiment publishes under a name ("table1.printed-orders"): whether the run found it so,
// the measurements behind it, and what a reader needs beside the verdict. A claims file's record
// observes one by that name (`observes = "table1.printed-orders"`); the engine makes its verdict as
// for any decider (decide.hpp: observed). The experiment computes the fact; the record only names it.
// An enclosure that decides it neither way throws enclosure_undecided (the verdict is undecided).

#include <simpson/verify/json.hpp>

#include <string>

namespace simpson::verify {

struct published_fact {
  bool holds = false;
  json evidence = json::object();  // one member per method ("numeric", "enclosure")
  std::string note;
  /// Found false, what holds instead, established by the experiment (an erratum's correction: the
  /// convention under which a printed table is reproduced); empty: a fact found false fails.
  std::string correction = {};
  /// Found so, what a reader must know beside it (a remark of class `remark_class`, a finding class's
  /// name: "wording"): the numbers right, their description another claim's finding.
  std::string remark = {};
  std::string remark_class = "wording";
};

}  // namespace simpson::verify
