// SPDX-License-Identifier: LGPL-2.1-or-later
// OCCT's data-exchange settings (write.step.unit, write.surfacecurve.mode, ...) are
// process-wide statics (Interface_Static). Inside FreeCAD they are FreeCAD's settings too:
// a value the core leaves changed changes every later STEP/IGES export of the session.
// StaticsSnapshot records every one of them; restore() puts back each value that differs.
#pragma once

#include <string>
#include <vector>

namespace sliceform {

class StaticsSnapshot {
 public:
  // Records the value of every Interface_Static defined now.
  StaticsSnapshot();
  // Puts back every recorded value that changed since; returns how many it put back.
  // Statics defined after the snapshot are left as they are (at their defaults).
  int restore() const;
  // "name=value" for every recorded static, in name order (for tests and messages).
  std::vector<std::string> describe() const;

  struct Value {
    std::string name;
    int type;          // Interface_ParamType
    bool set;          // IsSetValue()
    int integer;       // IntegerValue(): integers and enumerations
    double real;       // RealValue()
    std::string text;  // HStringValue(): the value as text, every type
  };

 private:
  std::vector<Value> values_;
};

// Takes a snapshot when made and restores it when it goes out of scope, also on exceptions.
class StaticsRestorer {
 public:
  StaticsRestorer() = default;
  StaticsRestorer(const StaticsRestorer&) = delete;
  StaticsRestorer& operator=(const StaticsRestorer&) = delete;
  ~StaticsRestorer() { snapshot_.restore(); }

 private:
  StaticsSnapshot snapshot_;
};

}  // namespace sliceform
