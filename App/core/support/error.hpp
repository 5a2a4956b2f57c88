// SPDX-License-Identifier: LGPL-2.1-or-later
// The one error type of the core. Every failure the user can cause (a file that is not a
// model, a mesh that is not closed, a parameter out of range) becomes a sliceform::Error
// with a message meant for the user and a kind the CLI maps to an exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace sliceform {

enum class ErrorKind {
  BadInput,      // the model file cannot be read or is not a usable solid
  BadParameter,  // a parameter is out of range or inconsistent
  Geometry,      // a geometric operation failed on valid input (a bug or OCCT limit)
  Unbuildable,   // a usable model that no buildable design fits at these settings
  Io,            // an output cannot be written
  Cancelled,     // the user stopped the run
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace sliceform
