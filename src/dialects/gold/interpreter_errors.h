// The error codes the Gold command line adds to the drive's (drive_commands.h): program control,
// storage and downloads (docs/dialects/gold-command-line.md, docs/protocol.md).
#pragma once
#include <cstdint>

namespace uprog::gold {

enum InterpreterError : int32_t {
  kErrorSyntax = 19,        // the expression does not compile (manual 1.3.2 "Command syntax error")
  kErrorNoProgram = 201,    // no program in RAM
  kErrorNoSuchEntry = 202,  // XQ## names no function, label or auto-routine
  kErrorProgramRunning = 203,    // XQ/CC while the program runs
  kErrorNotHalted = 204,         // XC while the program is not halted
  kErrorBadArguments = 205,      // XQ##f(...) with the wrong number or form of arguments
  kErrorStorage = 206,           // SV/LD/CC could not read or write the state directory
  kErrorNoStoredProgram = 207,   // CC with nothing downloaded
  kErrorLineDidNotFinish = 208,  // a command line waited or ran too long
  kErrorNoSuchVariable = 209,    // DB##RV[n]=name with an unknown name
  kErrorNoDownload = 210,        // DL= or DL##END without a DL##BEGIN on this connection
  kErrorDownloadSize = 211,      // a bad size in DL##BEGIN, or DL##END before all bytes came
  kErrorDownloadChunk = 212,     // a DL= line that is not hex pairs, or more bytes than announced
  kErrorDownloadRefused = 213,   // the image failed its CRC, format or the verifier
  kErrorRunTimeBase = 100,       // 100 + vm::RunError for a run-time error of a line
};

}  // namespace uprog::gold

namespace uprog::gold {

// The text of a registered interpreter error (interpreter_errors.def); nullptr for none.
const char* interpreter_error_text(int32_t code);

}  // namespace uprog::gold
