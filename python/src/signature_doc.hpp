// Docstrings in CPython's own form for a builtin: "NAME(PARAMETERS)\n--\n\nTEXT". CPython reads
// the first part as the function's __text_signature__, so inspect.signature() and help() see the
// real parameters (pybind11's own "NAME(arg: type) -> type" line, which module.cpp turns off,
// is not a form inspect reads), and __doc__ is the text alone. The types are the stub's
// (python/tetcut.pyi), which stubtest holds to these signatures.
#pragma once

#include <string>
#include <string_view>

namespace tetcut::python {

// `parameters` as in a def statement. A pybind11 method starts with "self, /": inspect sees
// pybind11's functions as bound already (their __self__ is pybind11's own record), so the
// "$self" CPython's method descriptors use would hide the first real parameter instead.
inline std::string signature_doc(std::string_view name, std::string_view parameters, std::string_view text) {
  std::string doc;
  doc.reserve(name.size() + parameters.size() + text.size() + 8);
  doc.append(name).append("(").append(parameters).append(")\n--\n\n").append(text);
  return doc;
}

}  // namespace tetcut::python
