// The fields a study's runs store (wpg/datasets/study_design/run_fields.hpp).
#include "wpg/datasets/study_design/run_fields.hpp"

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/nearest_name.hpp"

namespace wpg::datasets {

const std::vector<std::string>& runFieldNames() {
  static const std::vector<std::string> names = {"summary", "com",       "cop",  "feet",
                                                 "footsteps", "mpc",     "plan", "obstacles",
                                                 "goal",    "multibody"};
  return names;
}

std::vector<std::string> RunFields::names() const {
  std::vector<std::string> held;
  for (unsigned f = 0; f < kRunFieldCount; ++f) {
    if (has(static_cast<RunField>(f))) held.push_back(runFieldNames()[f]);
  }
  return held;
}

std::string RunFields::text() const {
  if (isAll()) return "all";
  std::string text;
  for (const std::string& name : names()) text += (text.empty() ? "" : ", ") + name;
  return text;
}

RunFields parseRunFields(const std::vector<std::string>& names, const std::string& where) {
  if (names.empty()) {
    throw InputError(where + ": expected a list of fields (" + RunFields::all().text() +
                     " is every one), got none");
  }
  std::vector<std::string> known = runFieldNames();
  known.push_back("all");
  unsigned bits = 0;
  for (const std::string& name : names) {
    unsigned field = 0;
    while (field < known.size() && known[field] != name) ++field;
    if (field == known.size()) {
      throw InputError(where + ": '" + name + "' is not a field" + didYouMean(name, known) +
                       " (expected some of: summary, com, cop, feet, footsteps, mpc, plan, "
                       "obstacles, goal, multibody, or all)");
    }
    const unsigned add = field == kRunFieldCount ? RunFields::all().bits_ : 1u << field;
    if ((bits & add) == add) throw InputError(where + ": field '" + name + "' is named twice");
    bits |= add;
  }
  const RunFields fields(bits);
  if (!fields.has(RunField::kSummary)) {
    throw InputError(where + ": expected 'summary' among the fields (got " + fields.text() +
                     "): every run keeps its attributes and its summary row, which --resume "
                     "and wpg merge read");
  }
  return fields;
}

std::vector<std::string> splitFieldList(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    std::string name = text.substr(start, end - start);
    const std::size_t first = name.find_first_not_of(" \t");
    const std::size_t last = name.find_last_not_of(" \t");
    names.push_back(first == std::string::npos ? "" : name.substr(first, last - first + 1));
    start = end + 1;
  }
  if (names.size() == 1 && names.front().empty()) names.clear();
  return names;
}

}  // namespace wpg::datasets
