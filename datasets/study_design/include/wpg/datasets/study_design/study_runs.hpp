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
};

class StudyRuns {
 public:
  // Makes run `index` (< count): with `scenario` its scenario loaded and validated (throws
  // InputError, one line naming the study file, the run and its values, when it is refused),
  // else its index, name and swept values only. Called from any thread.
  using Maker = std::function<StudyRun(std::size_t index, bool scenario)>;

  StudyRuns() = default;
  StudyRuns(std::size_t count, Maker maker) : count_(count), maker_(std::move(maker)) {}

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // Run `index` with its scenario (a few hundred microseconds: the scenario is loaded).
  StudyRun operator[](std::size_t index) const { return maker_(index, true); }
  StudyRun front() const { return (*this)[0]; }
  StudyRun back() const { return (*this)[count_ - 1]; }
  // Run `index` without its scenario (its name and swept values: about a microsecond).
  StudyRun describe(std::size_t index) const { return maker_(index, false); }

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
