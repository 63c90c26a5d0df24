#pragma once
// The wpg source tree the tests read their shipped files from (robots/, datasets/, tests/).
//
// Why a function and not a compile definition in every test: the folder is the clone's absolute
// path, and a definition on every test object puts it in ccache's key of each of them, so that a
// clone at a new path (as CI makes) compiled the 145 test objects of the sanitizer tree again
// (167 s instead of 31 s). Only source_dir.cpp carries it now.

namespace wpg_test {

// The absolute path of the source tree, without a trailing '/' (a string literal: usable in the
// initializer of any static, whatever the order of their construction).
const char* sourceDir();

}  // namespace wpg_test
