// User errors: one clear line, non-zero exit; programming errors keep PETSc's trace.
//
// Bad input is raised with SETERRQ(comm, PETSC_ERR_USER_INPUT or
// PETSC_ERR_FILE_OPEN, "...") and a message that names the option or file. The
// handler prints such messages once, as "<program>: error: <message>", and
// passes every other error to PETSc's traceback handler.
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

#include "vibrotherm/util/write_failure.hpp"

namespace vibrotherm {

/// Installs the handler; call right after PetscInitialize. -debug (read here)
/// adds PETSc's trace to every error and leaves HDF5's own diagnostics on.
PetscErrorCode PushUserErrorHandler(const char* program);

/// "<program>: error: <message>" from rank 0 of MPI_COMM_WORLD, for errors
/// found before PETSc runs (MPI initialised).
void PrintOneLineError(const char* program, const std::string& message);

/// The process exit code for the error code a run returned (0 on success).
int ExitCode(PetscErrorCode ierr);

/// While in scope: the output file being written, which a runtime failure's line names
/// (a full disk inside PETSc's HDF5 viewer says only "Error in HDF5 call H5Dcreate2()").
class WritingFile {
 public:
  explicit WritingFile(const std::string& path);
  ~WritingFile();
  WritingFile(const WritingFile&) = delete;
  WritingFile& operator=(const WritingFile&) = delete;

 private:
  std::string previous_;
};

}  // namespace vibrotherm

/// Runs a statement that may throw std::exception and turns the exception into
/// a PETSc error of class `code` on comm.
#define VibrothermCallCppAs(comm, code, ...)                \
  do {                                                      \
    try {                                                   \
      __VA_ARGS__;                                          \
    } catch (const std::exception& vibrotherm_exc_) {       \
      SETERRQ((comm), (code), "%s", vibrotherm_exc_.what()); \
    }                                                       \
  } while (0)

/// Input that the C++ code refuses (e.g. contact::InputError): a user-input error (exit 2).
#define VibrothermCallCpp(comm, ...) VibrothermCallCppAs(comm, PETSC_ERR_USER_INPUT, __VA_ARGS__)

/// A failure while the run writes its results (a rename or write that fails, a
/// full disk): a runtime failure, exit 1, the whole job ends.
#define VibrothermCallIo(comm, ...) VibrothermCallCppAs(comm, PETSC_ERR_FILE_WRITE, __VA_ARGS__)
