#pragma once
// The runs of a study, computed one at a time from their index (lazy): run i's name, swept
// values and scenario come from i alone (index arithmetic over the grid, the random generator
// at draw i), never from a list of every run. A study of 10^7 runs is then as small and as
// quick to start as a study of 10 (the memory does not grow with the runs), and run i is the
// same bits whichever process, shard or thread asks for it.
#include <cstddef>
#include <functional>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"

namespace wpg::datasets {

struct SweptValue {
  std::string key;    // dotted path, e.g. "reference[1].v"
  std::string value;  // the value as one line of YAML (flow style), e.g. "[0.1, 0, 0]"
  bool numeric = false;  // a plain number: `number` holds it
  double number = 0.0;
};

struct StudyRun {
  std::size_t index = 0;
  std::string name;                // <study>_<index>, zero-padded so that names sort by index
  std::vector<SweptValue> swept;   // one per Study::keys, same order
  Scenario scenario;               // base + swept values + name, loaded and validated
  // The scenario was made from the study's compiled fields (compiled_sweep.hpp), not loaded
  // from YAML: the same scenario, in microseconds.
  bool from_fields = false;
};

class StudyRuns {
 public:
  // What a Maker makes of a run: its index, name and swept values only; with its scenario
  // (made from the compiled fields where it can); with its scenario loaded from YAML (the base
  // text with every value as an override: the reference the fields must equal; tests).
  enum class Make { kDescription, kScenario, kLoadedScenario };
  // Makes run `index` (< count); a scenario is validated (throws InputError, one line naming
  // the study file, the run and its values, when it is refused). Called from any thread.
  using Maker = std::function<StudyRun(std::size_t index, Make what)>;

  StudyRuns() = default;
  StudyRuns(std::size_t count, Maker maker) : count_(count), maker_(std::move(maker)) {}

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // Run `index` with its scenario (microseconds; a run that cannot be made from the compiled
  // fields is loaded from YAML: a few hundred microseconds).
  StudyRun operator[](std::size_t index) const { return maker_(index, Make::kScenario); }
  // Run `index` with its scenario loaded from YAML, as it was before the compiled fields.
  StudyRun loaded(std::size_t index) const { return maker_(index, Make::kLoadedScenario); }
  StudyRun front() const { return (*this)[0]; }
  StudyRun back() const { return (*this)[count_ - 1]; }
  // Run `index` without its scenario (its name and swept values: about a microsecond).
  StudyRun describe(std::size_t index) const { return maker_(index, Make::kDescription); }

  // Every run in order, each made as it is reached (with its scenario).
  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = StudyRun;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = StudyRun;
    Iterator(const StudyRuns* runs, std::size_t index) : runs_(runs), index_(index) {}
    StudyRun operator*() const { return (*runs_)[index_]; }
    Iterator& operator++() {
      ++index_;
      return *this;
    }
    bool operator!=(const Iterator& other) const { return index_ != other.index_; }
    bool operator==(const Iterator& other) const { return index_ == other.index_; }

   private:
    const StudyRuns* runs_;
    std::size_t index_;
  };
  Iterator begin() const { return Iterator(this, 0); }
  Iterator end() const { return Iterator(this, count_); }

 private:
  std::size_t count_ = 0;
  Maker maker_;
};

}  // namespace wpg::datasets
