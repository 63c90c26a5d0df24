#pragma once
// The one check of every file wpg reads, made before anything opens it (input_file.cpp).
#include <string>

namespace wpg::datasets {

// Throws InputError, one line naming the file, unless `path` is a regular file (a symbolic link
// to one is followed) that this process may read: "PATH: cannot read: no such file", "...: it is
// a directory", "...: expected a regular file, got a FIFO (pipe)" (a FIFO would block open(2)
// until a writer comes; a device would feed a reader without end), "...: permission denied".
// Every reader of this library calls it first (through detail::openFileForReading), and so do
// the front ends for the files they hand to a script.
void checkInputFile(const std::string& path);

}  // namespace wpg::datasets
