// std::cerr without HDF5's destructor reports (hdf5_destructor_reports.hpp).
#include "hdf5_destructor_reports.hpp"

#include <cctype>
#include <iostream>
#include <mutex>
#include <streambuf>
#include <string>

namespace wpg::cli {
namespace {

// The length of the C++ name at the start of `text` (letters, digits, '_').
std::size_t nameLength(const std::string& text, std::size_t from) {
  std::size_t end = from;
  while (end < text.size() &&
         (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) {
    ++end;
  }
  return end - from;
}

// "<Name>::~<Name> - ...": what HDF5's C++ destructors print.
bool isDestructorReport(const std::string& line) {
  const std::size_t name = nameLength(line, 0);
  if (name == 0 || line.compare(name, 3, "::~") != 0) return false;
  const std::size_t destructor = nameLength(line, name + 3);
  return destructor > 0 && line.compare(name + 3 + destructor, 3, " - ") == 0;
}

// Whether a partial line may still become a report: a name, then a prefix of "::~...".
bool mayBecomeReport(const std::string& line) {
  const std::size_t name = nameLength(line, 0);
  if (name == 0) return line.empty();
  const std::string rest = line.substr(name);
  if (rest.size() < 3) return std::string("::~").compare(0, rest.size(), rest) == 0;
  return rest.compare(0, 3, "::~") == 0;
}

class FilteringBuffer : public std::streambuf {
 public:
  explicit FilteringBuffer(std::streambuf* target) : target_(target) {}

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    const char character = static_cast<char>(c);
    xsputn(&character, 1);
    return c;
  }

  std::streamsize xsputn(const char* text, std::streamsize count) override {
    std::string& line = pending();
    for (std::streamsize i = 0; i < count; ++i) {
      line += text[i];
      if (text[i] == '\n' || text[i] == '\r') {
        if (!isDestructorReport(line)) write(line);
        line.clear();
      }
    }
    return count;
  }

  // std::cerr flushes after every output: a partial line goes out unless it may still become
  // a report (then it waits for the rest of its line).
  int sync() override {
    std::string& line = pending();
    if (!line.empty() && !mayBecomeReport(line)) {
      write(line);
      line.clear();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    return target_->pubsync();
  }

 private:
  // Per thread: lines of two threads are never mixed.
  static std::string& pending() {
    thread_local std::string line;
    return line;
  }

  void write(const std::string& text) {
    std::lock_guard<std::mutex> lock(mutex_);
    target_->sputn(text.data(), static_cast<std::streamsize>(text.size()));
  }

  std::streambuf* target_;
  std::mutex mutex_;
};

}  // namespace

void dropHdf5DestructorReports() {
  static FilteringBuffer buffer(std::cerr.rdbuf());  // lives until exit, as std::cerr
  std::cerr.rdbuf(&buffer);
}

}  // namespace wpg::cli
