#pragma once

namespace cvtmesh::cli {

// Exit codes of the `cvtmesh` program (documented in README.md).
enum ExitCode : int {
  kOk = 0,
  kInternalError = 1,  // a bug or an unexpected system failure
  kUsage = 2,          // bad command line or argument value
  kInputError = 3,     // an input file is missing, unreadable or invalid
  kOutputError = 4,    // an output could not be written
  kNoMemory = 5,       // the job would need more memory than is available; nothing done
  kInterrupted = 130,  // stopped by Ctrl-C (128 + SIGINT, as shells report it); nothing written
};

}  // namespace cvtmesh::cli
