// A production of an inferred grammar in the layout `ramus fmt` gives it, written directly.
//
// An inferred grammar holds one production per vector (hundreds to thousands of lines); passing
// them through the parser and the formatter only to lay them out was half of the inference time
// on a 64^3 grid. The rule here is the formatter's (grammar/format.cpp, `wrapped`): modules on
// one line up to column 100, continuation lines indented by 8; `[` sticks to the module after
// it and `]` to the module before it; a line that would overflow breaks before its last `[`, or
// else before the module that does not fit. Module and expression texts are the generator's
// own, which the formatter keeps (numbers keep their text). Tests compare the result with the
// formatter's on synthetic and real scans.
#pragma once

#include <string>
#include <vector>

namespace ramus::wavelet {

// `head` is the text before the successors ("  V(a, e, l, s, w) @ (...) ->"), `modules` the
// successors' module texts with "[" and "]" as modules of their own; the result ends with
// ";\n".
std::string production_layout(const std::string& head, const std::vector<std::string>& modules);

}  // namespace ramus::wavelet
