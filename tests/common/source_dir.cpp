// The one test object compiled with the source tree's path (source_dir.hpp says why).
#include "source_dir.hpp"

namespace wpg_test {

const char* sourceDir() { return WPG_SOURCE_DIR; }

}  // namespace wpg_test
