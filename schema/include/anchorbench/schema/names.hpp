#pragma once
// The one rule for a name that goes into CSV and Markdown tables (a row's, a part's): printable,
// without commas, quotes, '|' or control characters, and not empty.

#include <string>
#include <string_view>

namespace anchorbench::schema {

// `text` with every byte outside printable ASCII as \xNN: safe in a one-line message.
std::string Printable(std::string_view text);

// Empty if `name` may be such a name; else why not (e.g. "'a,b' holds ','", escaped printable).
std::string NameProblem(std::string_view name);

}  // namespace anchorbench::schema
