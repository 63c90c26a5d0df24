#pragma once
// The one exception type for bad user input (scenario files, robot files, --set overrides).
// Its message is a single line that names the file, the key (dotted path such as
// `reference[1].v`) and what was expected versus what came, e.g.
//   datasets/scenarios/x.yaml: key 'duration': expected a positive number of seconds, got -1
// The CLI prints it as is and exits with the "bad input" code.
#include <stdexcept>
#include <string>

namespace wpg::datasets {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `text` with each control character (bytes below 0x20, and 0x7f) written as a C escape
// (\n, \t, \x1b): user text echoed in a message (keys, values, file names) can then neither
// split the message's line nor drive the terminal. Backslashes are kept, so escaping twice
// changes nothing. Used wherever an InputError or a CLI usage error quotes user text.
std::string escapeControlCharacters(const std::string& text);

}  // namespace wpg::datasets
