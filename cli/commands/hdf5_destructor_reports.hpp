#pragma once
// One line per error: HDF5's C++ API (1.10) reports a failed close from its destructors on
// std::cerr ("H5File::~H5File - H5Fclose failed", "DataSet::~DataSet - H5Dclose failed"),
// whatever H5::Exception::dontPrint() says. After a failed write (a full disk, `ulimit -f`)
// every HDF5 object unwound adds such a line to the one error wpg prints: 54 lines for a
// comparison at a 4 kB file size limit. The error itself is already in wpg's message.

namespace wpg::cli {

// Gives std::cerr a buffer that drops whole lines of the form "<Name>::~<Name> - <text>" and
// passes everything else through unchanged (line by line per thread, a partial line held only
// while it could still become such a report). Call once, before any output.
void dropHdf5DestructorReports();

}  // namespace wpg::cli
