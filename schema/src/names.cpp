#include "anchorbench/schema/names.hpp"

#include <cstdio>

namespace anchorbench::schema {
std::string Printable(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F) {
      out += c;
    } else {
      char escaped[5];
      std::snprintf(escaped, sizeof(escaped), "\\x%02X", byte);
      out += escaped;
    }
  }
  return out;
}

std::string NameProblem(std::string_view name) {
  if (name.empty()) return "expected a name, got an empty text";
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F || c == ',' || c == '"' || c == '|') {
      // Appended, not chained with operator+ after a literal (GCC 12 warns falsely: -Wrestrict).
      std::string why = "'";
      why.append(Printable(name)).append("' holds '").append(Printable(std::string_view(&c, 1)));
      return why.append("': a name for CSV and Markdown tables holds no commas, quotes, '|' or control characters");
    }
  }
  return {};
}

}  // namespace anchorbench::schema
