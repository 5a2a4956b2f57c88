// SPDX-License-Identifier: LGPL-2.1-or-later
#include "support/occt_statics.hpp"

#include <Interface_ParamType.hxx>
#include <Interface_Static.hxx>
#include <TColStd_HSequenceOfHAsciiString.hxx>
#include <TCollection_HAsciiString.hxx>

#include <algorithm>

namespace sliceform {
namespace {

StaticsSnapshot::Value read(const std::string& name, const Handle(Interface_Static) & s) {
  StaticsSnapshot::Value v;
  v.name = name;
  v.type = static_cast<int>(s->Type());
  v.set = s->IsSetValue();
  v.integer = s->IntegerValue();
  v.real = s->RealValue();
  const Handle(TCollection_HAsciiString) text = s->HStringValue();
  v.text = text.IsNull() ? std::string() : std::string(text->ToCString());
  return v;
}

bool same(const StaticsSnapshot::Value& a, const StaticsSnapshot::Value& b) {
  return a.set == b.set && a.integer == b.integer && a.real == b.real && a.text == b.text;
}

}  // namespace

StaticsSnapshot::StaticsSnapshot() {
  const Handle(TColStd_HSequenceOfHAsciiString) names = Interface_Static::Items();
  if (names.IsNull()) return;
  for (int i = 1; i <= names->Length(); ++i) {
    const std::string name = names->Value(i)->ToCString();
    const Handle(Interface_Static) s = Interface_Static::Static(name.c_str());
    if (!s.IsNull()) values_.push_back(read(name, s));
  }
  std::sort(values_.begin(), values_.end(), [](const Value& a, const Value& b) { return a.name < b.name; });
}

int StaticsSnapshot::restore() const {
  int restored = 0;
  for (const Value& v : values_) {
    const Handle(Interface_Static) s = Interface_Static::Static(v.name.c_str());
    if (s.IsNull() || same(read(v.name, s), v)) continue;
    ++restored;
    if (!v.set) {
      s->ClearValue();
      continue;
    }
    switch (static_cast<Interface_ParamType>(v.type)) {
      case Interface_ParamInteger:
      case Interface_ParamEnum:
        s->SetIntegerValue(v.integer);
        break;
      case Interface_ParamReal:
        s->SetRealValue(v.real);
        break;
      default:
        s->SetHStringValue(new TCollection_HAsciiString(v.text.c_str()));
        break;
    }
  }
  return restored;
}

std::vector<std::string> StaticsSnapshot::describe() const {
  std::vector<std::string> out;
  for (const Value& v : values_) out.push_back(v.name + "=" + (v.set ? v.text : std::string("(unset)")));
  return out;
}

}  // namespace sliceform
