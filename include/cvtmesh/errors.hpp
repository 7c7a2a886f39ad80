// The exceptions cvtmesh throws. Each message is one line that names the file (when there is
// one) and the problem, ready to print as it is.
#pragma once

#include <stdexcept>

namespace cvtmesh {

// Base of all cvtmesh errors.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The input cannot be used: unreadable, malformed, empty, non-finite, bad indices.
struct InputError : Error {
  using Error::Error;
};

// An input file is missing, is a directory, or cannot be opened (the Python module raises
// OSError for it, ValueError for other input errors).
struct FileError : InputError {
  using InputError::InputError;
};

// An output could not be written.
struct OutputError : Error {
  using Error::Error;
};

// A setting or argument is out of its valid range.
struct InvalidArgument : Error {
  using Error::Error;
};

// The job would need more memory than is available (checked before it starts).
struct ResourceError : Error {
  using Error::Error;
};

// The caller cancelled the work (RemeshSettings::cancel); nothing was produced.
struct Cancelled : Error {
  using Error::Error;
};

}  // namespace cvtmesh
