// Plain scalars without yaml-cpp's test (plain_scalar.hpp).
#include "plain_scalar.hpp"

#include <ostream>

namespace wpg::datasets::detail {
namespace {

// What yaml-cpp's IsValidPlainScalar (emitterutils.cpp; ComputeStringFormat's Auto format)
// accepts in a block and in a flow collection, with room to spare: not empty, not a null word
// (~ null Null NULL), not longer than 1024 characters (Write(std::string) makes those long
// keys), '-' at the start only before another character, and only characters that none of
// its start, end or disallowed patterns (`, [ ] { } # & * ! | > ' " % @ : ? blanks, breaks, tabs,
// non-printable and non-ASCII bytes) contain.
bool surelyPlain(const std::string& text) {
  if (text.empty() || text.size() > 1024) return false;
  if (text == "null" || text == "Null" || text == "NULL") return false;
  if (text[0] == '-' && text.size() == 1) return false;
  for (const char c : text) {
    const bool allowed = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                         (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '+' || c == '-';
    if (!allowed) return false;
  }
  return true;
}

// The text, through the stream of Emitter::WriteIntegralType (which writes it as it is: the
// emitters here never ask for hexadecimal or octal integers, whose prefix it would add).
struct Verbatim {
  const std::string& text;
};

std::ostream& operator<<(std::ostream& stream, const Verbatim& verbatim) {
  return stream << verbatim.text;
}

}  // namespace

void emitScalar(YAML::Emitter& out, const std::string& text) {
  if (surelyPlain(text)) {
    out.WriteIntegralType(Verbatim{text});
  } else {
    out << text;
  }
}

void emitKey(YAML::Emitter& out, const std::string& key) {
  out << YAML::Key;
  emitScalar(out, key);
  out << YAML::Value;
}

}  // namespace wpg::datasets::detail
