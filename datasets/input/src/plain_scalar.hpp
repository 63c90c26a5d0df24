#pragma once
// Scalars of the resolved scenario written without yaml-cpp's plain-scalar test. Emitter::
// Write(std::string) matches every character of a string against the regular expressions that
// decide whether it may be written plain; for the keys and numbers of a resolved scenario
// (some 110 per run, e.g. push_step_single_support_samples: 0.8139936945103369) that test was
// 80 % of emitting it, 5 % of a batch study. The strings these helpers take are mostly ones
// that the test always passes, so they write them the way yaml-cpp writes a plain scalar.
#include <string>

#include <yaml-cpp/emitter.h>

namespace wpg::datasets::detail {

// out << text, to the byte: a string that yaml-cpp surely writes plain (letters, digits and
// _ . + - only, and not a null word, a lone '-' start or an empty string) is written as
// yaml-cpp writes a number (Emitter::WriteIntegralType: the node's indentation or separator,
// the text, the end of the scalar, as Write(std::string) does for a plain one) without the
// test; any other through Write(std::string).
void emitScalar(YAML::Emitter& out, const std::string& text);

// out << YAML::Key << key << YAML::Value, to the byte (emitScalar for the key).
void emitKey(YAML::Emitter& out, const std::string& key);

}  // namespace wpg::datasets::detail
