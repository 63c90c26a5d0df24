#pragma once
// HDF5 external links followed only to regular files (external_link_guard.cpp).
#include <string>

namespace wpg::datasets::detail {

// Replaces HDF5's traversal of external links, process-wide, by one that checks the target
// before HDF5 opens it: a regular file (a FIFO, a device or a socket would block or feed the
// reader without end), at most kMaxExternalLinkDepth links deep (a link cycle between two
// files). Called once by hdf5Mutex(); every reader and writer of this library takes that.
void installExternalLinkGuard();

// Links followed inside links, at most (HDF5's own limit on soft and external links is 16).
constexpr int kMaxExternalLinkDepth = 8;

// Why the last traversal on this thread was refused, one line naming the file, the link and
// its target ("idx.h5: /runs/a_0: external link to 's0.h5': expected a regular file, got a
// FIFO"); empty when none was. Cleared by the call.
std::string takeExternalLinkRefusal();

}  // namespace wpg::datasets::detail
